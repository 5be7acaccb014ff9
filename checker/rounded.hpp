// A judgements file on objects with a radius (certificates/FORMAT.md, "Objects with a radius";
// CLAIMS.md, "Objects with a radius"): object i is every point within ρ r_i of its scaled hull
// C_i(ρ), so each judgement is re-derived from a proof about the hulls and R = ρ1 r1 + ρ2 r2.
#pragma once
#include "context.hpp"

namespace scalecert_check {
struct Scene;
struct CompoundScene;
struct Rules;
struct Judgement;

// The file's seed_interior: for an object with a radius r > 0, {"within": weights} of a point of
// its hull nearer the seed than r; for one with radius 0, the weights of a polyhedron's seed.
void check_rounded_seeds(Context& cx, const Scene& sc, const J& j);
// One judgement of a verdict, separating_plane, witness_point, distance, penetration_depth or
// signed_distance claim, at a pair or at poses: whether the claim is right by the rules.
bool judge_rounded(Context& cx, const Scene& sc, const Rules& R, const Judgement& j);
// One judgement on objects made of parts with radii (FORMAT.md, "Parts with radii"; CLAIMS.md,
// "Parts with radii"): each pair of parts judged as two objects with a radius.
bool judge_rounded_parts(Context& cx, const CompoundScene& cs, const Rules& R, const Judgement& j);
}  // namespace scalecert_check
