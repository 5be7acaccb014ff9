// The engine's filtered predicates in one place: every floating-point filter's error bound, with
// the proof that it dominates the true rounding error, and the one exact fallback chain (128-bit
// integers with overflow checks, then GMP). Models: Geogram's numerics/predicates.cpp (a filter
// with a stated bound, then an exact stage) and CGAL's filtered kernels.
//
// A filter may only answer when its computed value clears its bound; otherwise the exact stage
// decides. Each bound below is the proven worst case times a safety factor (stated, and checked
// by a static_assert), so that a slip of a few ulps in the reasoning cannot make a filter lie.
// The counts of filtered and exact decisions are engine statistics, reported with each model
// ("decided_by_filter", "decided_exactly"); each is kept by the object that decides, so that
// threads share none: Polyhedron::cmp_filtered/cmp_exact (1), LineStats::arc_signs_* (2),
// StageCounts of the fast and quick queries (4, 5) and ScanStats (7).
//
// Notation: u = 2^-53 (the unit roundoff of double), γ_n = n·u / (1 − n·u) (Higham): a sum of n
// rounded products, or a product of n rounded factors, is within γ_n of the exact value
// relative to the sum of the magnitudes.
#pragma once
#include "numeric/small_int.hpp"

#include <cstdint>

namespace scalecert::internal::filter {

constexpr double kUnit = 0x1p-53;
constexpr double gamma(int n) { return n * kUnit / (1 - n * kUnit); }

// ---- The bounds, one per predicate ----------------------------------------------------------

// 1. Support comparison (polyhedron.cpp, hill climbing): sign of n·x_w − n·x_v. n and x are the
//    doubles of exact integers (each rounded once), a·b + c·d + e·f is summed in doubles:
//    |fl(n·x) − n·x| ≤ γ5·Σ|n_k x_k| per value (two input roundings, a product, two sums), so the
//    difference errs by at most 2γ5 of the magnitudes plus one rounding of it: < 1.2e-15·Σ.
constexpr double kSupportRel = 1e-14;
static_assert(kSupportRel > 8 * (2 * gamma(5) + kUnit), "support filter bound");

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

// 4. Queries against the curve and against the lines (fast_query.cpp): a·ρ1 + b − ρ2 and
//    n·d − ρ1·h1 − ρ2·h2 from the nearest doubles of exact values (one rounding each) and exact
//    doubles ρ: within γ4 of the magnitudes, < 4.5e-16; and a breakpoint test with the same bound.
constexpr double kQueryRel = 1e-12;
static_assert(kQueryRel > 1000 * gamma(4), "query filter bound");

// 5. Queries from the scene alone (quick_query.cpp, GJK in doubles): the points' doubles are
//    within u of the exact differences q = v − s, and each formula adds a few roundings, so a
//    separating gap and a tetrahedron's cofactor are within 20·2^-52 (4.4e-15) of the magnitudes
//    named there (the gap's sum of |terms|, the cofactor's permanent): factors 2.2 and 22.
constexpr double kQuickGapRel = 1e-14;
constexpr double kQuickDetRel = 1e-13;
static_assert(kQuickGapRel > 2 * 40 * kUnit && kQuickDetRel > 20 * 40 * kUnit, "quick query bounds");

// 6. Gauss-map candidate boxes (gauss_map.cpp): not a sign, a completeness filter. Boxes of arcs
//    on the unit sphere are padded by kArcBoxPad, far above the rounding of the few operations
//    forming them (normalisations and cross products of unit vectors: < 1e-15), so that no
//    crossing pair is missed; the crossing itself is then decided by predicate 2.
constexpr double kArcBoxPad = 1e-7;

// 7. Exact support queries on a point cloud (scan.cpp): n·x for integer points |x| ≤ 2^53 (exact
//    doubles) and n rounded once: |fl(n·x) − n·x| ≤ (u + γ3)·Σ|n_k|·max|x_k| < 4.01u·B, and a
//    box's bound Σ max(n_k lo_k, n_k hi_k) errs as much. The filter uses E = kScanSupport·B = 8u·B:
//    a true maximiser's value is at least best − 2e ≥ best − 2E (the candidate margin), and its
//    box's bound at least best − 3e ≥ best − 4E (the pruning margin). Factor 2.
constexpr double kScanSupport = 0x1p-50;
static_assert(kScanSupport > 1.9 * (kUnit + gamma(3)), "scan support bound");

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

}  // namespace scalecert::internal::filter
