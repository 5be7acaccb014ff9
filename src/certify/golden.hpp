// Golden data for a scene: its exact answers where floating-point code is most likely wrong.
#pragma once
#include "certify/certificate.hpp"
#include "certify/claims.hpp"
#include "certify/compound_judge.hpp"

#include <string>
#include <vector>

namespace scalecert::internal {

// Which pairs golden data holds. Every pair lies in the closed rectangle I1 × I2 (pairs that
// would leave it are dropped). Near the boundary of the touching set, at each sampled point
// (ρ1, ρ2) of it: the point itself ("on"), and the pairs above and below it in ρ2 at ρ2·2^-k,
// right and left of it in ρ1 at ρ1·2^-k, for each k in `offsets`. Plus the rectangle's four
// corners. Convex objects: the curve's points at `verticals` values of ρ1 spread evenly over the
// part of I1 where the curve lies in I2, at every switch point in the rectangle, and where the
// curve enters and leaves it (so each piece of the curve that crosses the rectangle has points
// near both its ends); and the rectangle's centre when the curve misses it. Objects made of parts:
// on `verticals` values of ρ1 spread evenly over I1 and at the region's switch points, the ends of
// the meeting set strictly inside I2.
struct GoldenPoints {
    int verticals = 7;
    std::vector<int> offsets{4, 12, 20, 30, 40, 52};
};
constexpr int kMaxGoldenVerticals = 1000;
constexpr size_t kMaxGoldenOffsets = 20;
constexpr int kMaxGoldenOffset = 1074;  // 2^-1074: the least positive double
// InputError naming the bad value ("golden: --verticals ...").
void validate(const GoldenPoints& p);
// The double nearest v, or its neighbour toward the inside when that one lies in [lo, hi] and v's
// nearest does not (a pair in the rectangle stays there when a program rounds it).
double double_in(const Q& v, const Q& lo, const Q& hi);
// "4,12,20" as offsets (InputError otherwise).
std::vector<int> parse_offsets(const std::string& text);

// The document (the curve document, or on parts the region document), its "queries", and two
// CSV texts of the same rows: decimals (the doubles asked and the answers there rounded) and
// rationals as integer numerator and denominator columns. Each row is a pair of the exact point
// rounded to the nearest doubles (kept in the rectangle) with the exact answers there: the verdict
// and the measure (kind distance, depth, touching or overlapping: the exact square and its root as
// a rounded double), and beside it the closest points and, between two convex objects, the
// separating plane through their midpoint (distance), the common point (touching), the depth's
// direction (depth); on parts the part pair of the closest points.
struct GoldenAnswers {
    Json curve, queries;
    std::string csv, rational_csv;
};
// The curve (m, c) is the one the engine built (the walk's or the hull model's); verdicts, curve
// values and the measures come from `models`, as claims are judged.
GoldenAnswers golden_answers(const ExactScene& s, const Model& m, const TouchingCurve& c, const ClaimModels& models,
                             const GoldenPoints& points);

// Objects made of parts: `region` is the region document (compound_region_json, with its union).
// A penetration depth of objects made of parts is not defined here: kind "overlapping", no value.
// The work the judge does for them is bounded, as it is done (CompoundJudge::counts(); InputError
// in the judgement that passes a limit): pairs judged by their facet normals or tried with a slab,
// exact distances, and box comparisons (each at most about 10 µs, 300 µs and 35 ns: a few seconds
// in all).
constexpr long kMaxGoldenJudgements = 200000;
constexpr long kMaxGoldenDistances = 10000;
constexpr long kMaxGoldenBoxComparisons = 50000000;
GoldenAnswers golden_answers_parts(const CompoundRegion& r, CompoundJudge& judge, Json region,
                                   const GoldenPoints& points);

}  // namespace scalecert::internal
