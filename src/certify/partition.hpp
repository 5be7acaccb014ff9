// Stage 6: the certified partition of I1 × I2.
#pragma once
#include "certify/query.hpp"
#include "geometry/polygon2.hpp"

namespace scalecert::internal {

struct SeparatedRegion {
    size_t piece;            // index into TouchingCurve::pieces; its line's normal separates the region
    std::vector<Pt2> verts;  // closed polygon, counter-clockwise; the points on the curve excluded
};

// The witnesses that prove a curve over its range [lo, hi] (the pieces' lines are lower bounds;
// these, common points, upper bounds; the set of meeting pairs is convex): a partition's over I1,
// a judgement's over its window.
struct CurveWitnesses {
    std::vector<Witness> switch_witnesses;  // one per switch point with ρ2 > 0 (touching)
    // Per curve piece with a contact: a point of the touching set in the relative interiors of
    // both contact features (every feature vertex weighted > 0), at contact_rho1.
    std::vector<std::optional<Witness>> piece_witnesses;
    // Per curve piece whose ρ2 falls from > 0 to ≤ 0 along it: a witness at the crossing (x0, 0),
    // the seed s2 on P1(x0), so that the piece is proved touching all the way down to ρ2 = 0.
    std::vector<std::optional<Witness>> zero_witnesses;
    // At (lo, f(lo)) and (hi, f(hi)) when f > 0; at lo when f(lo) <= 0, at (lo, 0) instead.
    std::optional<Witness> end_witness[2];
};

struct Partition : CurveWitnesses {
    std::vector<Pt2> overlap;                // convex polygon (may be empty, a point or a segment)
    std::vector<Witness> overlap_witnesses;  // one per vertex of `overlap`
    std::vector<SeparatedRegion> separated;  // nonempty interiors only
    std::optional<Witness> growth_witness;   // at (ρ*, ρ*) when ρ* > 0
    SeedWeights seeds;                       // the seeds proved inside
};

// Clips a convex polygon (counter-clockwise) to ρ2 ≥ a·ρ1 + b (above = true) or ≤. Drops repeated
// and collinear vertices; the result starts at its lowest, then leftmost vertex.
std::vector<Pt2> clip(const std::vector<Pt2>& poly, const Q& a, const Q& b, bool above);

// I1 × I2 ∩ {ρ2 >= curve} (`rect` is I1 × I2, normalized), in time linear in the curve's pieces.
std::vector<Pt2> overlap_region(const Model& m, const TouchingCurve& c, const std::vector<Pt2>& rect);

Partition build_partition(const Model& m, const TouchingCurve& c);
// The witnesses of c's pieces, switch points and ends (seeds: the seeds' weights, for the walk).
CurveWitnesses curve_witnesses(const Model& m, const TouchingCurve& c, const SeedWeights& seeds);

}  // namespace scalecert::internal
