// The two exact polyhedra of a convex scene and their seeds: what the measures (distances, depths,
// membership, planes), the double GJK and the inner ellipsoids need, with no contact line. The
// curve's models (curve/contact_lines.hpp) hold them: the hull model's are built (build_hulls),
// the walk's are empty (its points are in its cloud, point_sets.hpp's CloudPoints).
#pragma once
#include "geometry/polyhedron.hpp"
#include "io/scene.hpp"

namespace scalecert::internal {

struct Bodies {
    ExactScene scene;  // on the scan path: seeds and ranges only (the points are in the walk's model)
    Polyhedron P[2];
    Vec3q s[2];
    Vec3q d;  // s2 − s1
    // The seeds and d in integers, for fast support values: s_i·scale_i = sz[i] / sden[i] and
    // d = dz / dden.
    Vec3z sz[2], dz;
    Z sden[2], dden;
};

// d = s2 − s1, and sz, sden, dz, dden (above) from the seeds b.s and the scales b.P[i].scale.
void set_seeds_in_integers(Bodies& b);

}  // namespace scalecert::internal
