// The engine's filtered predicates in one place: every floating-point filter's error bound, with
// the proof that it dominates the true rounding error, the named predicates that apply them
// (filter, then exact stage), and the one exact fallback chain (128-bit integers with overflow
// checks, then GMP). Models: Geogram's numerics/predicates.cpp (a filter with a stated bound,
// then an exact stage) and CGAL's filtered kernels.
//
// A filter may only answer when its computed value clears its bound; otherwise the exact stage
// decides. Each bound below is the proven worst case times a safety factor (stated, and checked
// by a static_assert), so that a slip of a few ulps in the reasoning cannot make a filter lie.
//
// Statistics: every predicate counts each decision, by stage, into a PredicateStats (one counter
// pair per predicate, below). A PredicateStats belongs to the object that decides (a Polyhedron,
// a model's LineStats or ScanStats, a FastCurve, FastDirect or QuickScene, a compound region's
// or locator's statistics), so that threads share none; sums over objects are explicit
// (operator+=). The statistics each model reports ("decided_by_filter", "decided_exactly") are
// read from them.
//
// The predicates (their filters are in this file; an exact stage that is a whole algorithm of a
// higher layer is named where it is):
//   1. support_cmp             sign of n·x_w − n·x_v                 (Polyhedron::climb, argmax)
//   2. arc_side                sign of (u × x)·p on a Gauss arc       (contact_lines.cpp)
//   3. line_certainly_dominated  a line below another for all ρ1 ≥ 0   (contact_lines.cpp)
//   4. curve_side, lines_side  a query pair against the curve, the lines (FastCurve, FastDirect)
//   5. quick_gap_certified, quick_cofactor_sign: GJK's certificates  (tools/quick_query.cpp)
//   6. the Gauss-map candidate boxes: a completeness filter, no sign (gauss_map.cpp)
//   7. ScanSupportFilter       which points may maximise n·x          (scan.cpp)
//   8. half_plane_side         a scaling pair against a part pair's half-plane (compound/region.cpp, locate.cpp)
//   9. scaled_enclosure        a scaled coordinate s + ρ(x − s) enclosed in doubles (certify/compound_judge.cpp)
//  10. a depth surface's planes: each triangle's offset N·a and squared distance (N·a)²/N·N in
//      CGAL's Interval_nt under upward rounding (geometry/measures.cpp, checked_surface). An
//      enclosure by construction, so no bound is stated here: integers start from their
//      truncated doubles widened by one ulp, and the interval decides a sign or an order only
//      when it excludes the other.
//  11. pose_certainly_nonsingular  det R ≠ 0 for a pose              (io/scene.cpp, pose_singular)
//  12. boxes_certainly_apart   two posed boxes more than m apart along an axis (engines/mujoco_judge.cpp)
//
// Notation: u = 2^-53 (the unit roundoff of double), γ_n = n·u / (1 − n·u) (Higham): a sum of n
// rounded products, or a product of n rounded factors, is within γ_n of the exact value
// relative to the sum of the magnitudes.
#pragma once
#include "numeric/double3.hpp"
#include "numeric/small_int.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace scalecert::internal::filter {

constexpr double kUnit = 0x1p-53;
constexpr double gamma(int n) { return n * kUnit / (1 - n * kUnit); }

// ---- The bounds, one per predicate ----------------------------------------------------------

// 1. Support comparison (polyhedron.cpp, hill climbing): sign of n·x_w − n·x_v. n and x are the
//    doubles of exact integers, each converted once: get_d truncates (< 2u relative), a cast of
//    an int64 rounds (≤ u). Each value a·b + c·d + e·f is then a product and two sums in doubles:
//    |fl(n·x) − n·x| ≤ γ7·Σ|n_k x_k| (2u + 2u + u for a term, 2u for the sums), and the
//    difference errs by at most γ7 of both magnitudes plus one rounding u of itself. The filter
//    answers when |diff| > kSupportRel·(Σ_w + Σ_v) (magnitudes as computed, within 5u of the true
//    ones). Non-finite values (integers beyond 2^1024) never pass: comparisons with NaN or inf
//    bounds are false. Safety factor 5 over 2γ7 + u.
constexpr double kSupportRel = 1e-14;
static_assert(kSupportRel > 5 * (2 * gamma(7) + kUnit), "support filter bound");

// 2. Gauss-arc side (contact_lines.cpp): sign of (u × x)·p for arcs' end normals u, their plane
//    normal p and the crossing direction x. u and p are direction_d of exact integers (scaled by
//    a power of two, truncated: 2u relative per component). x is either direction_d of the
//    exact cross product, or the double cross product of the two planes' normals when that is
//    not too short: |x_d| > kArcDirectionMin·|p_a||p_b|. The double cross product errs by at most
//    γ2 + 4u < 7u relative to |p_a||p_b|, hence by < 7u / kArcDirectionMin relative to |x|; the
//    side's own evaluation adds γ4 + 6u. With kArcDirectionMin = 1e-4 the total is < 8e-12 of
//    |u||x||p|, under kArcRel by a factor of 12. (It was 1e-10, which let nearly parallel edges,
//    1e-10 < sin < 1e-5, through with a direction wrong by up to 8e-6: see CHANGES.)
constexpr double kArcRel = 1e-10;
constexpr double kArcDirectionMin = 1e-4;
static_assert(kArcRel > 10 * (7 * kUnit / kArcDirectionMin + gamma(4) + 6 * kUnit), "arc side bound");

// 3. Which lines can be on the curve (contact_lines.cpp, undominated): slopes and intercepts are
//    ratios of exact integers formed from their mantissas and exponents, within 4u relative; a
//    line is dropped only when margins of kDominatedRel prove it below another everywhere.
constexpr double kDominatedRel = 1e-12;
static_assert(kDominatedRel > 100 * 4 * kUnit, "dominated-line bound");

// 4. Queries against the curve and against the lines (certify/classify.cpp): a·ρ1 + b − ρ2 and
//    n·d − ρ1·h1 − ρ2·h2 from the nearest doubles of exact values (one rounding each) and exact
//    doubles ρ: within γ4 of the magnitudes, < 4.5e-16; and a breakpoint test with the same bound.
//    The absolute term kQueryTiny covers underflow, where relative bounds fail: a product or a
//    nearest double of an exact value that falls below 2^-1022 errs by at most 2^-1075 absolutely
//    (gradual underflow), a handful of such errors is < 2^-1070 ≈ 1e-322, under kQueryTiny by a
//    factor of 10^22. Non-finite values never pass (comparisons with NaN are false).
constexpr double kQueryRel = 1e-12;
constexpr double kQueryTiny = 1e-300;
static_assert(kQueryRel > 1000 * gamma(4), "query filter bound");
static_assert(kQueryTiny > 1e20 * 0x1p-1070, "query underflow term");

// 5. Queries from the scene alone (quick_query.cpp, GJK in doubles): the points' doubles are
//    within u of the exact differences q = v − s, and each formula adds a few roundings, so a
//    separating gap and a tetrahedron's cofactor are within 20·2^-52 (4.4e-15) of the magnitudes
//    named there (the gap's sum of |terms|, the cofactor's permanent): factors 2.2 and 22.
//    Relative bounds need the absence of underflow: a magnitude below kQuickTiny is never
//    certified. Above it, the few roundings that underflow err by < 2^-1070 absolutely each, far
//    under the slack left by the factors (1.2·40u·kQuickTiny ≈ 5e-264). kQuickGjkIterations caps
//    GJK's loop: a heuristic that cannot affect correctness (GJK only proposes; a proposal is
//    accepted only by the two tests above, and an unfinished one goes to the exact model).
constexpr double kQuickGapRel = 1e-14;
constexpr double kQuickDetRel = 1e-13;
constexpr double kQuickTiny = 1e-250;
constexpr int kQuickGjkIterations = 64;
static_assert(kQuickGapRel > 2 * 40 * kUnit && kQuickDetRel > 20 * 40 * kUnit, "quick query bounds");
static_assert(1.2 * 40 * kUnit * kQuickTiny > 1e20 * 0x1p-1070, "quick query underflow");

// 6. Gauss-map candidate boxes (gauss_map.cpp): not a sign, a completeness filter: every pair of
//    arcs that cross must be a candidate (extra candidates only cost time: each is then decided
//    by predicate 2). So each constant may err only towards larger boxes or more pairs.
//    kArcBoxPad: boxes of arcs on the unit sphere are padded by it, far above the rounding of the
//      few operations forming them (direction_d's 2u per component, normalisations and cross
//      products of unit vectors: < 1e-15 each) and of the losses below (< 1e-12).
//    kArcDegenerate: an arc whose ends' computed cross product is shorter gets the whole sphere
//      as its box (conservative: any box holding the arc is correct).
//    kArcExtremeSkip: the extreme of coordinate k on the arc's great circle (normal p) lies at
//      ±(e_k − p_k·p)/|e_k − p_k·p|; when that length is below kArcExtremeSkip the extreme is not
//      added. Then every point x of the circle (x·p = 0) has |x_k| = |x·(e_k − p_k·p)| < 1e-12
//      (plus rounding), so the ends' range of x_k misses the arc's by < 2e-12 ≪ kArcBoxPad.
//    kArcExtremeSlack: an extreme is added when it is on the arc within this slack. Adding a
//      point not on the arc only enlarges the box. A true extreme x* rejected has a computed side
//      value < −slack while its true one is ≥ 0, so it lies within the error of the side (< 1e-8
//      when |a×b| ≥ 1e-6) of an end; x_k's drop from x* to that end is quadratic in the distance
//      (x_k is a sinusoid of amplitude ≤ 1 along the circle, stationary at x*): < 1e-16. When
//      |a×b| < 1e-6 and the arc is short (θ < 1e-6), x_k varies over it by less than θ²/8 beyond
//      its ends' values.
//    kArcIllConditioned: an arc longer than a quarter turn (a·b < 0) whose computed |a×b| is below
//      it gets the whole sphere as its box. Near a half turn p = a×b is ill-conditioned: a and b
//      err by < 3u per component (direction_d, normalisation), so p errs by < 10u absolute and its
//      direction by < 10u/|a×b|, which above kArcIllConditioned is < 1.2e-10, far under
//      kArcBoxPad; below it the direction, and so which half of the circle the arc takes, is not
//      known (knife edges of dihedral angle < 1e-5). Short arcs (a·b > 0) need no p: they stay
//      within θ²/8 of their ends' box, as above.
//    kArcBrutePairs, kArcGridMax, kArcGridMinMean: how candidates are enumerated (every pair of
//      boxes for few arcs, else a uniform grid of at most kArcGridMax cells per axis sized by the
//      mean box). Heuristics for speed only: both enumerations return exactly the pairs whose
//      boxes overlap (the grid's cell index is monotone in the coordinate, so two overlapping
//      intervals share a cell, clamping included), sorted and without repeats.
constexpr double kArcBoxPad = 1e-7;
constexpr double kArcDegenerate = 1e-300;
constexpr double kArcIllConditioned = 1e-5;
constexpr double kArcExtremeSkip = 1e-12;
constexpr double kArcExtremeSlack = 1e-9;
constexpr std::size_t kArcBrutePairs = 4096;
constexpr double kArcGridMax = 128.0;
constexpr double kArcGridMinMean = 1e-9;
static_assert(kArcBoxPad > 1e4 * 2 * kArcExtremeSkip && kArcBoxPad > 1e6 * 10 * kUnit, "arc box padding");
static_assert(kArcBoxPad > 100 * (10 * kUnit / kArcIllConditioned), "ill-conditioned arcs");

// 7. Exact support queries on a point cloud (scan.cpp): n·x for integer points |x| ≤ 2^53 (exact
//    doubles) and n converted from GMP integers (mpz_get_d and mpz_get_d_2exp truncate: within 2u
//    relative; a power-of-two scaling of n past the double range is exact):
//    |fl(n·x) − n·x| ≤ (2u + γ3)·Σ|n_k|·max|x_k| < 5.01u·B, and a box's bound
//    Σ max(n_k lo_k, n_k hi_k) errs as much. The filter uses E = kScanSupport·B = 8u·B: a true
//    maximiser's value is at least best − 2e ≥ best − 2E (the candidate margin), and its box's
//    bound at least best − 3e ≥ best − 4E (the pruning margin). Factor 1.5 (8u over 5.01u).
//    kScanPruneEvery: the candidate list is pruned (to values ≥ best − 2E) once it exceeds this
//    many entries: for memory only; a pruned point is below the final candidate floor too (best
//    only grows), so the candidates compared exactly are the same whenever pruning happens.
constexpr double kScanSupport = 0x1p-50;
constexpr std::size_t kScanPruneEvery = 64;
static_assert(kScanSupport > 1.5 * (2 * kUnit + gamma(3)), "scan support bound");

// 8. A scaling pair (x, y) against a part pair's half-plane a·x + b·y >= c (compound/region.cpp):
//    a, b, c, x, y are exact rationals read by region_double (mpq's get_d truncates: within 2u
//    relative), each 0 or a finite normal double, else not a number (never certified). Then each
//    product is within (1 + 2u)²(1 + u) − 1 < 5.1u of its exact value, or, where it falls below
//    2^-1022, within 2^-1022 absolutely; the two sums add γ2 of the magnitudes: in all under
//    7.2u·(|ax| + |by| + |c|) + 3·2^-1022. The filter answers when |f| > kHalfPlaneRel·(computed
//    magnitudes) + kQueryTiny: factor 10 over 8u (the computed magnitudes are within 5.1u of the
//    true ones), and kQueryTiny ≫ 3·2^-1022.
constexpr double kHalfPlaneRel = 1e-14;
static_assert(kHalfPlaneRel > 10 * 8 * kUnit && kQueryTiny > 1e6 * 3 * 0x1p-1022, "half-plane filter bound");

// 9. A scaled coordinate E = S + R(X − S) enclosed in doubles without forming it (the scaled boxes
//    of the parts, certify/compound_judge.cpp): s, ρ, x are the exact S, R, X read by
//    region_double (each 0 or a normal double within 2u relative, else not a number), and in
//    doubles t = fl(x − s), p = fl(ρ t), e = fl(s + p). Then |x − s − (X − S)| ≤ 2u(|X| + |S|),
//    and t's rounding adds u|x − s|: |t − (X − S)| < 3.01u(|X| + |S|). p = ρt(1 + δ), |δ| ≤ u,
//    plus at most 2^-1074 where it underflows, and ρ errs by 2u from R: |p − R(X − S)| <
//    6.1u|R|(|X| + |S|) + 2^-1074. The last sum adds u|s + p| ≤ 1.01u|e|, and s errs by 2u|S|. In
//    all |e − E| < 2u|S| + 6.1u|R|(|X| + |S|) + 1.01u|e| + 2^-1074, and with each exact magnitude
//    within (1 + 2.01u) of its double, < 6.2u·m + 2^-1074 for m = |s| + |ρ|(|x| + |s|) + |e|,
//    whose computed value is within γ4 of m. The enclosure is e ∓ (kScaledRel·m + kQueryTiny),
//    each end rounded outward by one unit in the last place: factor 10 over 6.2u(1 + 1.01γ4), and
//    kQueryTiny ≫ 2^-1074 (also the products of magnitudes that underflow). An e or a bound that
//    is not finite gives no enclosure: both ends not a number, so every comparison with them is
//    false and the exact ends decide.
constexpr double kScaledRel = 1e-14;
static_assert(kScaledRel > 10 * 6.2 * kUnit * (1 + 1.01 * gamma(4)) && kQueryTiny > 1e6 * 0x1p-1074,
              "scaled coordinate bound");

// 11. A pose's R nonsingular (io/scene.cpp, pose_singular): the sign of det R, nonzero, from the
//    doubles a_ij of its exact entries x_ij (mpq's get_d truncates: |a − x| < 2u|x|), each 0 or
//    of magnitude in [2^-250, 2^250] (else unsure), so every product of three is normal and no sum
//    overflows. det is the cofactor expansion a00(a11 a22 − a12 a21) − a01(…) + a02(…): each of its
//    six products of three inputs errs by (1 + 2u)^3 from the inputs and takes at most five
//    roundings (two products, the inner difference, the outer two sums), so |fl(det) − det R| ≤
//    γ11·P with P = Σ over the six products of |x x x| (Higham: 3·2u + 5u ≤ 11u to first order).
//    P's own computed value (the same expansion on magnitudes) is within γ11 of P. The filter
//    answers "nonsingular" when |fl(det)| > kPoseDetRel·fl(P): factor above 100 over 2γ11/(1 − γ11).
//    A rotation's det is ±1 with P at most 6: the filter decides every pose a program holds but the
//    near-singular ones, which the integers decide.
constexpr double kPoseDetRel = 0x1p-40;
static_assert(kPoseDetRel > 100 * 2 * gamma(11) / (1 - gamma(11)), "pose determinant bound");
constexpr double kPoseEntryMin = 0x1p-250, kPoseEntryMax = 0x1p250;
// true when det R is certainly nonzero (filter 11), false when unsure.
inline bool pose_certainly_nonsingular(const double (&a)[3][3]) {
    for (const auto& row : a)
        for (double x : row)
            if (x != 0 && !(std::fabs(x) >= kPoseEntryMin && std::fabs(x) <= kPoseEntryMax)) return false;
    const double d = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                     a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                     a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    auto m = [&a](int r, int c) { return std::fabs(a[r][c]); };
    const double p = m(0, 0) * (m(1, 1) * m(2, 2) + m(1, 2) * m(2, 1)) +
                     m(0, 1) * (m(1, 0) * m(2, 2) + m(1, 2) * m(2, 0)) +
                     m(0, 2) * (m(1, 0) * m(2, 1) + m(1, 1) * m(2, 0));
    return std::fabs(d) > kPoseDetRel * p;
}

// 12. Two posed boxes apart by more than m ≥ 0 (engines/mujoco_judge.cpp: a geom pair without a
//    contact, its signed distance at least the margin m, decided without the exact distance).
//    A box [lo, hi] (exact doubles) at a pose [M | t] (exact doubles) lies in the world box whose
//    upper end along axis i is U_i = t_i + Σ_j max(M_ij lo_j, M_ij hi_j) and lower end L_i = t_i +
//    Σ_j min(…), exactly; every point of the posed box is between them, whatever M is. With every
//    input 0 or of magnitude in [2^-250, 2^250] (else unsure) each product is normal and no sum
//    overflows, so each computed end carries each term through at most four roundings (the
//    product, three sums): |Ũ_i − U_i| ≤ γ4·S_i with S_i = |t_i| + Σ_j max|M_ij b_j|, and the
//    computed S̃_i ≥ (1 − γ4)·S_i. If another box's lower end exceeds this one's upper end by more
//    than m along an axis, the two are more than m apart (the distance of two sets is at least the
//    gap of their projections). The filter forms T = fl(fl(L̃'_i − Ũ_i) − m) (two roundings, within
//    γ2 of the exact difference relative to |L̃'| + |Ũ| + m) and answers "apart by more than m" when
//    T > kBoxRel·fl(|L̃'_i| + |Ũ_i| + m + S̃_i + S̃'_i) (five roundings): kBoxRel is above 100 times
//    the largest of those relative errors, each divided by what the roundings of the bound lose;
//    2^-1000 more covers a rounding of a subnormal difference (each within 2^-1075).
constexpr double kBoxRel = 0x1p-40;
static_assert(kBoxRel > 100 * (gamma(2) + gamma(4) / (1 - gamma(4))) / (1 - gamma(5)), "posed box bound");
// A box at a pose, enclosed (filter 12): the computed ends lo, hi and magnitudes s per world axis;
// ok false when an input is out of the filter's range.
struct PosedBox {
    double lo[3], hi[3], s[3];
    bool ok = false;
};
inline PosedBox posed_box(const double (&M)[9], const double (&t)[3], const double (&lo)[3], const double (&hi)[3]) {
    PosedBox b;
    auto in_range = [](double x) { return x == 0 || (std::fabs(x) >= kPoseEntryMin && std::fabs(x) <= kPoseEntryMax); };
    for (int k = 0; k < 9; ++k)
        if (!in_range(M[k])) return b;
    for (int k = 0; k < 3; ++k)
        if (!in_range(t[k]) || !in_range(lo[k]) || !in_range(hi[k])) return b;
    for (int i = 0; i < 3; ++i) {
        double u = t[i], l = t[i], s = std::fabs(t[i]);
        for (int j = 0; j < 3; ++j) {
            const double a = M[3 * i + j] * lo[j], c = M[3 * i + j] * hi[j];
            u += std::max(a, c);
            l += std::min(a, c);
            s += std::max(std::fabs(a), std::fabs(c));
        }
        b.hi[i] = u;
        b.lo[i] = l;
        b.s[i] = s;
    }
    b.ok = true;
    return b;
}
// true when the posed boxes a and b are certainly more than m ≥ 0 apart (filter 12), false when unsure.
inline bool boxes_certainly_apart(const PosedBox& a, const PosedBox& b, double m) {
    if (!a.ok || !b.ok || !(m >= 0) || m > kPoseEntryMax) return false;
    for (int i = 0; i < 3; ++i)
        for (const auto& [below, above] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
            const double T = (above->lo[i] - below->hi[i]) - m;
            const double B =
                kBoxRel * (std::fabs(above->lo[i]) + std::fabs(below->hi[i]) + m + above->s[i] + below->s[i]) +
                0x1p-1000;
            if (T > B) return true;
        }
    return false;
}

// ---- Statistics: one counter pair per predicate, per deciding object -------------------------

enum class Predicate : unsigned {
    SupportCmp,        // 1
    ArcSide,           // 2
    DominatedLine,     // 3 (filtered: a line dropped; exact: kept, built exactly)
    CurveSide,         // 4, FastCurve
    LinesGap,          // 4, FastDirect
    QuickCertificate,  // 5 (exact: the model decided)
    ScanSupport,       // 7 (filtered: points ruled out; exact: candidates formed exactly)
    HalfPlaneSide,     // 8, compound pair polygons
    Count
};
constexpr const char* kPredicateNames[] = {"support_cmp", "arc_side",          "dominated_line", "curve_side",
                                           "lines_gap",   "quick_certificate", "scan_support",   "half_plane_side"};
static_assert(sizeof(kPredicateNames) / sizeof(kPredicateNames[0]) == static_cast<unsigned>(Predicate::Count));

struct PredicateCounts {
    std::uint64_t filtered = 0, exact = 0;  // decisions by the filter, by the exact stage
    PredicateCounts& operator+=(const PredicateCounts& o) { return filtered += o.filtered, exact += o.exact, *this; }
};

// Not shared between threads: one per deciding object; merge with +=.
class PredicateStats {
  public:
    PredicateCounts& operator[](Predicate p) { return c_[static_cast<unsigned>(p)]; }
    const PredicateCounts& operator[](Predicate p) const { return c_[static_cast<unsigned>(p)]; }
    void filtered(Predicate p, std::uint64_t n = 1) { (*this)[p].filtered += n; }
    void exact(Predicate p, std::uint64_t n = 1) { (*this)[p].exact += n; }
    PredicateStats& operator+=(const PredicateStats& o) {
        for (unsigned k = 0; k < c_.size(); ++k) c_[k] += o.c_[k];
        return *this;
    }

  private:
    std::array<PredicateCounts, static_cast<unsigned>(Predicate::Count)> c_{};
};

// ---- The exact stage: 128 bits with overflow checks, else GMP ---------------------------------

// Σ a_i·b_i accumulated in 128 bits; ok() turns false at the first overflow.
class Acc128 {
  public:
    Acc128& add(I128 a, I128 b) {
        I128 t;
        ok_ = ok_ && mul_ok(a, b, t) && add_ok(v_, t, v_);
        return *this;
    }
    Acc128& sub(I128 a, I128 b) {
        I128 t;
        ok_ = ok_ && mul_ok(a, b, t) && sub_ok(v_, t, v_);
        return *this;
    }
    bool ok() const { return ok_; }
    I128 value() const { return v_; }

  private:
    I128 v_ = 0;
    bool ok_ = true;
};

// The sign of an exact expression: `small` fills an Acc128 (128-bit stage); when it overflows,
// `gmp` computes the sign with GMP.
template <class Small, class Gmp>
int exact_sign(Small&& small, Gmp&& gmp) {
    Acc128 a;
    small(a);
    if (a.ok()) return sgn128(a.value());
    return gmp();
}

// A filtered predicate: the filter's sign when it is certain (nonzero), else the exact stage's,
// each decision counted under p. Every predicate with a filter and an exact stage is one call of
// it, so no caller sees the filter's "unsure" nor forgets the exact stage or the count. (The
// filters alone, in `bounds`, are for their wrappers and the tests of their bounds.)
template <class Filter, class Exact>
int filtered(Predicate p, Filter&& filter, Exact&& exact, PredicateStats& st) {
    if (const int f = filter()) return st.filtered(p), f;
    st.exact(p);
    return exact();
}

// ---- The predicates ---------------------------------------------------------------------------

// 1. n·x in doubles with its error bound (bound 1), for support_cmp.
struct SupportApprox {
    double value, err;
};
inline SupportApprox support_approx(const double* n, const double* x) {
    const double a = n[0] * x[0], b = n[1] * x[1], c = n[2] * x[2];
    return {a + b + c, kSupportRel * (std::fabs(a) + std::fabs(b) + std::fabs(c))};
}
// Sign of n·x_w − n·x_v: the filter on their approximations, else exact() (the exact sign).
template <class Exact>
inline int support_cmp(const SupportApprox& w, const SupportApprox& v, Exact&& exact, PredicateStats& st) {
    auto filter = [&] {
        const double diff = w.value - v.value, tol = w.err + v.err;
        return diff > tol ? 1 : diff < -tol ? -1 : 0;
    };
    return filtered(Predicate::SupportCmp, filter, exact, st);
}

// 2. Sign of (u × x)·p, or of (x × u)·p when x_first: doubles ud, xd, pd approximating u, x, p as
// bound 2 says; exact_x() gives x exactly (called only when the filter cannot decide). V: Vec3s
// (128 bits, then GMP on overflow) or Vec3z (GMP).
template <class V, class ExactX>
int arc_side(const D3& ud, const D3& xd, const D3& pd, bool x_first, const V& u, ExactX&& exact_x, const V& p,
             PredicateStats& st) {
    auto filter = [&] {
        const D3 c = x_first ? crossd(xd, ud) : crossd(ud, xd);
        const double v = dotd(c, pd), bound = kArcRel * normd(ud) * normd(xd) * normd(pd);
        return v > bound ? 1 : v < -bound ? -1 : 0;
    };
    auto exact = [&] {
        const V x = exact_x();
        auto gmp = [&] {
            const Vec3z xz = as_z(x), uz = as_z(u);
            return sgn(dotz(x_first ? cross(xz, uz) : cross(uz, xz), as_z(p)));
        };
        if constexpr (std::is_same_v<V, Vec3s>) {
            // u × x exactly in 128 bits (|u|, |x| < 2^62), then its dot with p, checked
            return exact_sign(
                [&](Acc128& acc) {
                    for (int k = 0; k < 3; ++k) acc.add(x_first ? cross_k(x, u, k) : cross_k(u, x, k), p[k]);
                },
                gmp);
        }
        return gmp();
    };
    return filtered(Predicate::ArcSide, filter, exact, st);
}

// 3. The line y = a_i·x + b_i certainly below y = a_j·x + b_j for every x ≥ 0, from doubles within
// 4u of the exact slopes and intercepts (bound 3): a larger slope and a larger intercept, each
// with a margin of kDominatedRel. One-sided: false means "keep the line" (its exact stage is to
// build it exactly); undominated (contact_lines.cpp) applies it in a sweep.
inline double dominated_lower(double a) { return a - kDominatedRel * std::fabs(a); }  // below the true value
inline double dominated_upper(double a) { return a + kDominatedRel * std::fabs(a); }  // above it

namespace bounds {
// 4. A pair (ρ1, ρ2) against the envelope piece y = a·ρ1 + b (nearest doubles of the exact slope
// and intercept; ρ exact doubles): +1 when certainly below it (separated), −1 certainly above
// (overlapping), 0 when the filter cannot tell. Bound 4.
inline int curve_side_filter(double a, double b, double r1, double r2) {
    const double f = a * r1 + b;
    const double err = kQueryRel * (std::fabs(a * r1) + std::fabs(b)) + kQueryTiny;
    if (r2 < f - err) return 1;
    if (r2 > f + err) return -1;
    return 0;
}
// Whether ρ1 is too close to a breakpoint (nearest double `bk` of the exact one) for the piece to
// be certain. Bound 4.
inline bool near_breakpoint(double bk, double r1, bool right_of) {
    return (right_of ? r1 - bk : bk - r1) <= kQueryRel * std::fabs(r1);
}
// The sign of n·d − ρ1·h1 − ρ2·h2 (nearest doubles nd, h1, h2; ρ exact), 0 when uncertain. Bound 4.
inline int lines_gap_filter(double nd, double h1, double h2, double r1, double r2) {
    const double t1 = r1 * h1, t2 = r2 * h2;
    const double g = nd - t1 - t2;
    const double err = kQueryRel * (std::fabs(nd) + std::fabs(t1) + std::fabs(t2)) + kQueryTiny;
    if (g > err) return 1;
    if (g < -err) return -1;
    return 0;  // uncertain, or not a number
}

// 5. GJK's certificates from the scene (tools/quick_query.cpp), bound 5; one-sided (false: the
// exact model decides). A separating gap g computed with magnitudes `scale`, certainly > 0:
inline bool quick_gap_certified(double g, double scale) {
    return std::isfinite(g) && std::isfinite(scale) && scale > kQuickTiny && g > kQuickGapRel * scale;
}
// The sign of a cofactor det computed with permanent `perm` of its magnitudes, 0 when uncertain.
inline int quick_cofactor_sign(double det, double perm) {
    const double bound = kQuickDetRel * perm;
    if (!std::isfinite(det) || !std::isfinite(bound) || !(bound > kQuickTiny) || std::fabs(det) <= bound) return 0;
    return det > 0 ? 1 : -1;
}

}  // namespace bounds

// 4. The side of (ρ1, ρ2) against the curve, from the envelope piece y = a·ρ1 + b at ρ1 (trusted:
// ρ1 not near a breakpoint, so the piece is the one): +1 below it (separated), −1 above
// (overlapping), else exact() (0 touching). Counted as CurveSide.
template <class Exact>
int curve_side(double a, double b, double r1, double r2, bool trusted, Exact&& exact, PredicateStats& st) {
    return filtered(
        Predicate::CurveSide, [&] { return trusted ? bounds::curve_side_filter(a, b, r1, r2) : 0; }, exact, st);
}
// 4. The side of (ρ1, ρ2) from every contact line (nearest doubles nd, h1, h2 of each): +1 when
// some line's gap is certainly positive (separated), −1 when every one is certainly negative
// (overlapping), else exact(). Counted as LinesGap.
template <class Exact>
int lines_side(const std::vector<double>& nd, const std::vector<double>& h1, const std::vector<double>& h2, double r1,
               double r2, Exact&& exact, PredicateStats& st) {
    auto filter = [&] {
        bool all_negative = true;
        for (size_t i = 0; i < nd.size(); ++i) {
            const int g = bounds::lines_gap_filter(nd[i], h1[i], h2[i], r1, r2);
            if (g > 0) return 1;
            if (g == 0) all_negative = false;
        }
        return all_negative ? -1 : 0;
    };
    return filtered(Predicate::LinesGap, filter, exact, st);
}

// 7. Exact support on a point cloud: B = Σ|n_k|·max|x_k| (computed), E = kScanSupport·B. A point
// whose computed value is below best − 2E, and a box whose computed bound is below best − 4E,
// holds no maximiser (bound 7); the candidates left are compared exactly by the caller, who
// counts them (filtered: points ruled out; exact: candidates).
struct ScanSupportFilter {
    double E;
    explicit ScanSupportFilter(double B) : E(kScanSupport * B) {}
    bool candidate(double v, double best) const { return v >= best - 2 * E; }
    double floor(double best) const { return best - 2 * E; }
    bool box_excluded(double ub, double best) const { return ub < best - 4 * E; }
};

namespace bounds {
// 8. The sign of a·x + b·y − c from region_double values (bound 8), 0 when uncertain (or not a
// number): half_plane_side's filter.
inline int half_plane_side_filter(double a, double b, double c, double x, double y) {
    const double t1 = a * x, t2 = b * y;
    const double f = t1 + t2 - c;
    const double err = kHalfPlaneRel * (std::fabs(t1) + std::fabs(t2) + std::fabs(c)) + kQueryTiny;
    if (f > err) return 1;
    if (f < -err) return -1;
    return 0;
}
}  // namespace bounds
// 8. The sign of a·x + b·y − c: the filter on the doubles, else exact() (the exact sign), counted.
template <class Exact>
inline int half_plane_side(double a, double b, double c, double x, double y, Exact&& exact, PredicateStats& st) {
    return filtered(
        Predicate::HalfPlaneSide, [&] { return bounds::half_plane_side_filter(a, b, c, x, y); }, exact, st);
}
// 9. Doubles lo <= S + R(X − S) <= hi from the region_double values s, ρ, x of S, R, X (bound 9);
// both not a number when the doubles cannot enclose it.
struct Enclosure {
    double lo, hi;
};
inline Enclosure scaled_enclosure(double s, double rho, double x) {
    const double e = s + rho * (x - s);
    const double err =
        kScaledRel * (std::fabs(s) + std::fabs(rho) * (std::fabs(x) + std::fabs(s)) + std::fabs(e)) + kQueryTiny;
    if (!std::isfinite(e) || !std::isfinite(err)) return {std::nan(""), std::nan("")};
    return {std::nextafter(e - err, -INFINITY), std::nextafter(e + err, INFINITY)};
}
// A rational's double for filter 8: mpq's get_d when that is 0 for 0 or a finite normal double,
// else not a number (so that the filter never answers).
template <class Rational>
double region_double(const Rational& q) {
    const double d = q.get_d();
    if (sgn(q) == 0) return 0.0;
    return std::isfinite(d) && std::fabs(d) >= 0x1p-1022 ? d : std::nan("");
}

}  // namespace scalecert::internal::filter
