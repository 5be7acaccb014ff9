// The paper's Step 2: the shortest path between inner ellipsoids. Floating point (Eigen), then
// rounded to rationals and checked exactly; only the segment's ends leave this file, and they are
// used only after the exact check.
#pragma once
#include "geometry/bodies.hpp"

#include <array>
#include <optional>
#include <string>

namespace scalecert::internal {

struct InnerEllipsoid {
    std::array<double, 3> center;
    std::array<std::array<double, 3>, 3> matrix;  // E = {matrix·u + center : |u| ≤ 1}
};

struct EllipsoidPath {
    InnerEllipsoid E[2];  // in P1(lo1) and P2(lo2)
    double distance;      // between the ellipsoids (0 when they meet)
    Vec3q v1, v2;         // the segment's ends, exact (dyadic), pulled slightly into the ellipsoids
};

// Maximum-volume ellipsoid inscribed in polyhedron i scaled by lo_i (log-barrier gradient
// method), then the closest points of the two (projected gradient). When the ellipsoids meet,
// the segment joins their centres. None when floating point fails (overflow, a seed not inside
// in doubles).
std::optional<EllipsoidPath> ellipsoid_path(const Bodies& m);

}  // namespace scalecert::internal
