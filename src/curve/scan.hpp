// Stage 3, output-sensitive: the contact lines of the touching curve only, found by walking along
// it (no hull, no Gauss-map overlay). Cost grows with the pieces of the curve over the range it
// reports, times the cost of an exact support query (a bounding-volume tree over the points,
// double filter with a proven bound, exact stage on the few candidates).
//
// The walk is its own proof. A piece with normal n holds over [xl, xr] when, for every x there,
// d lies in the face G(x) = x·(F1 − s1) + y(x)·(s2 − F2) of the Minkowski sum with normal n (F1,
// F2: the exact support polygons of n); then the pair touches at (x, y(x)), so the curve is that
// line there. Consecutive pieces share their end points, and their union covers I1 and the
// growth distance. A floating-point free start (an exact LP by column generation at ρ1 = lo1)
// and the next normal at each switch (exact gift wrapping about the exit edge of G) only propose;
// the intervals decide.
#pragma once
#include "curve/contact_lines.hpp"
#include "io/int_points.hpp"

#include <memory>
#include <optional>
#include <stdexcept>

namespace scalecert::internal {

// The scan path meets something it does not handle (a curve vertex where d is at a corner of a
// face, identical lines, a range where ρ2 ≤ 0, a seed it cannot prove interior quickly):
// build_model on the full scene decides instead, with the same output.
struct NeedHull : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The model of the curve: Model::lines holds the lines of the pieces walked (sorted by normal),
// Model::scan the points; the polyhedra carry no hull. Enough for build_curve and curve_json.
// Throws InputError for a scene the hull path would refuse too (fewer than 4 points, lo > hi),
// and NeedHull.
// The walk proves the curve over I1 and the growth distance, and over `cover` too when given
// (ρ1 > 0 ranges outside I1 that queries need).
Model scan_model(std::shared_ptr<const CompactScene> sc, const std::optional<std::pair<Q, Q>>& cover = std::nullopt);

// Both seeds proved strictly inside from a few extreme points (as scan_model does); false means
// "not proved" (the hull decides), not "outside".
bool scan_seeds_proved(const CompactScene& sc);

// Weights > 0 on a few extreme points of polyhedron i (at most 14, spanning 3 dimensions) whose
// weighted mean is its seed: the seed in the interior, as scan_model proved it. Sorted by index.
std::vector<std::pair<int, Q>> scan_seed_weights(const CompactScene& sc, int i);

// From this many points (both polyhedra together) the scan path is the faster one: the command
// and the library take it by default (scalecert-bench --sizes). So they do from this product of
// the two point counts: the Minkowski sum may then have about that many facets, and the hull path
// builds a line for each (crossed 999-gon prisms, 1,998 points: 2.3 s on the hull path, 0.2 s on
// the walk, scalecert-bench --queries).
constexpr size_t kScanFromPoints = 2000;
constexpr size_t kScanFromPointProduct = 250000;
inline bool walk_by_default(size_t n1, size_t n2) { return n1 + n2 >= kScanFromPoints || n1 * n2 >= kScanFromPointProduct; }

}  // namespace scalecert::internal
