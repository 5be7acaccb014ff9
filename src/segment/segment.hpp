// The paper's Section III: the touching curve seen along a segment v1 → v2 between interior
// points (the seeds, or any segment given). t1(ρ1) is where the segment leaves P1(ρ1) (as a
// fraction of its length from v1), t2(ρ2) where it leaves P2(ρ2) from v2; both exact and
// piecewise linear in ρ (t = ρ·t_s for the seed segment, the paper's Remark).
#pragma once
#include "geometry/ellipsoid.hpp"
#include "curve/envelope.hpp"

#include <optional>

namespace scalecert::internal {

struct LinearPiece {
    Q from, to, slope, intercept;
};  // y = slope·x + intercept on [from, to]

struct Segment {
    Vec3q v1, v2;
    std::vector<LinearPiece> t[2];  // t1 over I1, t2 over I2
    std::string kind = "explicit";  // "seeds", "ellipsoids", "explicit"
    std::string note;               // e.g. why the ellipsoid path fell back to the seeds
    std::optional<EllipsoidPath> path;
};

// The segment named by --segment: "seeds", "ellipsoids" (the paper's Step 2, falling back to the
// seeds when its rounded ends fail the exact check), or explicit ends.
Segment segment_by_kind(const HullModel& m, const std::string& kind);

// Throws InputError when v_i is not strictly inside P_i(lo_i) (then it is inside P_i(ρ) for every
// ρ in I_i, since the polyhedra grow with ρ about interior seeds).
Segment make_segment(const HullModel& m, const Vec3q& v1, const Vec3q& v2);
Q eval(const std::vector<LinearPiece>& f, const Q& x);

// The decision curve in the (t1, t2) plane: the image of the part of the touching curve inside
// I1 × I2, as a polyline (exact vertices, in increasing t1).
std::vector<std::array<Q, 2>> t_curve(const Model& m, const TouchingCurve& c, const Segment& s);

// Signed estimate along the segment: (1 − t1 − t2) times its length; > 0 a gap, < 0 penetration.
// Returned as the exact fraction 1 − t1 − t2 (the length is √|v2 − v1|², irrational in general).
// ρ with t_i(ρ) = t (t_i increases strictly); none when t is outside t_i(I_i).
std::optional<Q> rho_from_t(const Segment& s, int i, const Q& t);

Q directional_gap(const Segment& s, const Q& rho1, const Q& rho2);

// The contact point on the curve at each of its vertices (ends and switch points) with ρ2 > 0:
// the loci of contact points (the paper's Fig. 7) run between them.
std::vector<std::array<Q, 2>> curve_vertices(const Model& m, const TouchingCurve& c);

}  // namespace scalecert::internal
