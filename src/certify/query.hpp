// Stage 5: exact three-state queries with certificates.
#pragma once
#include <optional>
#include "curve/envelope.hpp"

namespace scalecert::internal {

using scalecert::Verdict;  // the public enum
const char* verdict_name(Verdict v);

// A common point of P1(ρ1) and P2(ρ2): point = s1 + ρ1 Σ λ_i (v_i − s1) = s2 + ρ2 Σ μ_j (w_j − s2),
// weights over vertex indices (only the nonzero ones).
struct Witness {
    Q rho1, rho2;
    Vec3q point;
    std::vector<std::pair<int, Q>> w1, w2;
};

// The plane n·x = offset with P1(ρ1) ⊆ {n·x ≤ c1} and P2(ρ2) ⊆ {n·x ≥ c2}; c1 < c2 separates,
// c1 = c2 touches.
struct PlaneCert {
    size_t line;
    Q c1, c2, offset;
    int support1, support2;  // a vertex of P1 attaining c1, of P2 attaining c2
};

struct QueryAnswer {
    Verdict verdict;
    Q rho1, rho2;
    std::optional<PlaneCert> plane;  // separated, touching
    std::optional<Witness> witness;  // touching (at ρ), overlapping (at a smaller pair)
};

// With the curve: a search over its pieces. Requires ρ1, ρ2 > 0.
QueryAnswer query(const Model& m, const TouchingCurve& c, const Q& rho1, const Q& rho2, bool with_certificate = true);
// Where the ray t·(ρ1, ρ2), t > 0, meets the highest of the envelope's lines (the largest t over
// its pieces): the curve's crossing when the lines hold the curve there. The line's index.
std::pair<Q, size_t> ray_crossing(const Model& m, const TouchingCurve& c, const Q& rho1, const Q& rho2);
// Without a curve: the maximum over all contact lines (verdict only).
Verdict query_direct(const Model& m, const Q& rho1, const Q& rho2);
// A verdict as the sign the predicates give (predicates.hpp): separated +1, touching 0,
// overlapping −1; and back.
inline int verdict_sign(Verdict v) { return v == Verdict::Separated ? 1 : v == Verdict::Touching ? 0 : -1; }
inline Verdict verdict_of_sign(int s) {
    return s > 0 ? Verdict::Separated : s == 0 ? Verdict::Touching : Verdict::Overlapping;
}

PlaneCert plane_certificate(const Model& m, size_t line, const Q& rho1, const Q& rho2);
// A common point at a point on the line's contact (touching) — or, with line = npos, anywhere.
Witness make_witness(const Model& m, const Q& rho1, const Q& rho2, size_t line);
// A common point of conv(vertices i1 of P1(ρ1)) and conv(vertices i2 of P2(ρ2)); with interior,
// one in both relative interiors, every listed vertex weighted > 0.
// The same, none when those points hold no common point (make_witness throws then: a bug).
std::optional<Witness> try_witness(const Model& m, const Q& rho1, const Q& rho2, const std::vector<int>& i1,
                                   const std::vector<int>& i2, bool interior = false);
Witness make_witness(const Model& m, const Q& rho1, const Q& rho2, const std::vector<int>& i1,
                     const std::vector<int>& i2, bool interior);

// Weights > 0 whose weighted mean is the seed of polyhedron i, over vertices spanning 3
// dimensions: on the hull path every hull vertex, on the walk a few extreme points.
std::vector<std::pair<int, Q>> seed_weights(const Model& m, int i);
// Both seeds' weights: what every certificate shows of the seeds ("seed_interior").
struct SeedWeights {
    std::vector<std::pair<int, Q>> w[2];
};
SeedWeights seed_weights(const Model& m);
// The witness w moved to (ρ1, ρ2) ≥ (w.rho1, w.rho2): the same point, which lies in P_i(ρ) for
// every ρ ≥ w's as the seed is inside. Its weights become (w.ρ/ρ)·λ + (1 − w.ρ/ρ)·σ, σ the seed
// weights (Σσ(v − s) = 0), merged by index.
// (ρ2 may be 0 only where w's is: P2(0) is the seed, and w's P2 weights stay.)
Witness lift_witness(const Witness& w, const Q& rho1, const Q& rho2, const std::vector<std::pair<int, Q>> seed[2]);
// A touching pair at or below-left of the curve point at ρ1 > 0, with its witness: (ρ1, f(ρ1)) when
// f(ρ1) > 0, else (x0, 0) where the curve's line at ρ1 reaches 0 (x0 ≤ ρ1). The curve must be
// proved there (on the walk: walk_covers).
Witness witness_below(const Model& m, const TouchingCurve& c, const Q& rho1);

}  // namespace scalecert::internal
