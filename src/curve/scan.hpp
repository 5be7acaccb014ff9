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
#include "geometry/point_sets.hpp"
#include "io/int_points.hpp"

#include <memory>
#include <optional>
#include <cstdint>
#include <string>
#include <vector>

namespace scalecert::internal {

// Why the walk hands a scene over to the hull model, which then decides with the same output.
// Every hand-over is returned (WalkResult), counted per reason in this process
// (handover_counts) and reported under SCALECERT_TIMING.
enum class Handover : int {
    PointCount,           // a polyhedron with fewer than 4 or more than the limit of points
    Range,                // lo <= 0 or lo > hi
    SeedsCoincide,        // d = 0: every pair overlaps, there is no curve to walk
    SeedNotProved,        // a seed that a few extreme points cannot prove interior
    NormalBeyondDoubles,  // a normal whose coordinates overflow a double
    ZeroOrHugeNormal,     // a support query's filter bound is 0 or not finite
    CurveNotAbove0,       // the curve is <= 0 at lo1/2^k for k < 64
    StartLpNoOptimum,     // the start LP is unbounded or infeasible
    StartLpUnsettled,     // the start LP's column generation did not settle in 400 rounds
    StartFaceMissesD,     // the start piece does not hold d at its ρ1
    NotFacetNormal,       // a normal that is not a facet normal of the Minkowski sum
    FaceNeverHoldsD,
    IdenticalLines,  // d on a face's edge all along a piece
    ZeroLengthPiece,
    NoExitEdge,
    CornerAtSwitch,  // d at a corner of a face at a switch point
    NoNeighbour,     // no neighbouring face within a quarter turn
    ReachesZero,     // the curve reaches ρ2 <= 0 at a switch point
    MissesSwitch,    // the next line misses the switch point
    NoTurn,          // the next line does not turn the curve
    NoContinuation,  // the next piece does not continue the curve
    WrapOnOldPlane,  // gift wrapping met a point on the old plane
    WrapUnsettled,   // gift wrapping did not settle in 200 steps
    NormalTwice,     // a normal walked twice
};
constexpr int kHandoverReasons = static_cast<int>(Handover::NormalTwice) + 1;
// The reason in words ("d at a corner of a face at a switch point").
const char* handover_text(Handover h);
// Where the walk stopped: the reason, and the polyhedron it concerns (0, 1; -1: both or none).
struct WalkStop {
    Handover reason;
    int polyhedron = -1;
    std::string text() const;  // "P1: seed not proved inside"
};
// The walk's model, or where it stopped.
struct WalkResult {
    std::optional<WalkModel> model;
    std::optional<WalkStop> stop;
};
// Hand-overs in this process so far, per reason (index: the Handover value).
std::vector<std::uint64_t> handover_counts();

// The model of the curve: Model::lines holds the lines of the pieces walked (sorted by normal),
// Model::scan the points; the polyhedra carry no hull. Enough for build_curve and curve_json.
// The walk proves the curve over I1 and the growth distance, and over `cover` too when given
// (ρ1 > 0 ranges outside I1 that queries need). Where it cannot, the result holds the reason
// instead of a model; it throws nothing but std::bad_alloc.
WalkResult scan_model(std::shared_ptr<const CompactScene> sc,
                      const std::optional<std::pair<Q, Q>>& cover = std::nullopt);

// The points of a compact scene behind the walk's bounding-volume trees, for the measures
// (measures.hpp) of scenes too large for a hull: every support query exact (filter, then the few
// candidates in integers), no hull built. Building the trees is linear (a radix sort of Morton
// codes); argmax scans every point exactly for a normal beyond doubles.
class CloudPoints final : public PointSets {
  public:
    explicit CloudPoints(std::shared_ptr<const CompactScene> sc);
    ~CloudPoints() override;
    Vec3q point(int i, int k) const override;
    D3 dpoint(int i, int k) const override;
    const Vec3q& seed(int i) const override;
    const Z& scale(int i) const override;
    Vec3z zpoint(int i, int k) const override;
    int argmax(int i, const Vec3z& n) const override;
    int dargmax(int i, const D3& d) const override;
    std::uint64_t support_queries() const;  // exact support queries so far
    struct Trees;                           // the two trees (scan.cpp)
    const Trees& trees() const { return *t_; }

  private:
    std::shared_ptr<const CompactScene> sc_;
    std::unique_ptr<Trees> t_;
};

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
inline bool walk_by_default(size_t n1, size_t n2) {
    return n1 + n2 >= kScanFromPoints || n1 * n2 >= kScanFromPointProduct;
}

}  // namespace scalecert::internal
