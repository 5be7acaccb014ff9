// Golden data for a scene: its exact answers where floating-point code is most likely wrong.
#pragma once
#include "certify/certificate.hpp"
#include "certify/claims.hpp"
#include "certify/compound_judge.hpp"

#include <string>

namespace scalecert::internal {

// The curve document (curve_json), and its "queries": at 7 values of ρ1 spread over I1 and at every
// switch point, the pair on the curve and the pairs above and below it at relative distances 2^-k
// (k = 4, 12, 20, 30, 40, 52), each with its exact verdict and, at its nearest doubles, the exact
// verdict ("verdict_at_doubles") and the exact distance or penetration depth ("measure_at_doubles":
// kind distance, depth or touching, the exact square and its root as an MPFR-rounded double).
// The CSV holds those doubles, verdicts and roots, one pair a line.
struct GoldenAnswers {
    Json curve, queries;
    std::string csv;
};
// The curve (m, c) is the one the engine built (the walk's or the hull model's); verdicts, curve
// values and the measures come from `models`, as claims are judged.
GoldenAnswers golden_answers(const ExactScene& s, const Model& m, const TouchingCurve& c, const ClaimModels& models);

// Objects made of parts: `region` is the region document (compound_region_json, with its union),
// and "queries" are taken where the objects' meeting set ends along verticals: at 7 values of ρ1
// spread over I1 and at every switch point's ρ1, each end strictly inside I2 of an interval of ρ2
// where they meet (the ends of the part pairs' polygons' intervals, merged), and the pairs above
// and below it at relative distances 2^-k as for convex objects. Each with its exact verdict and,
// at its nearest doubles, the exact verdict and measure: the distance (the least over the part
// pairs) when separated, 0 when touching, kind "overlapping" with no value when they overlap (a
// penetration depth of objects made of parts is not defined here).
// Each vertical once. The work the judge does for them is bounded, as it is done
// (CompoundJudge::counts(); InputError in the judgement that passes a limit): pairs judged by their
// facet normals or tried with a slab, exact distances, and box comparisons (each at most about
// 10 µs, 300 µs and 35 ns: a few seconds in all).
constexpr long kMaxGoldenJudgements = 200000;
constexpr long kMaxGoldenDistances = 10000;
constexpr long kMaxGoldenBoxComparisons = 50000000;
GoldenAnswers golden_answers_parts(const CompoundRegion& r, CompoundJudge& judge, Json region);

}  // namespace scalecert::internal
