// Stage 5: exact three-state queries with certificates.
#pragma once
#include "scalecert/envelope.hpp"

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

struct QueryResult {
    Verdict verdict;
    Q rho1, rho2;
    std::optional<PlaneCert> plane;     // separated, touching
    std::optional<Witness> witness;     // touching (at ρ), overlapping (at a smaller pair)
};

// With the curve: a search over its pieces. Requires ρ1, ρ2 > 0.
QueryResult query(const Model& m, const Curve& c, const Q& rho1, const Q& rho2, bool with_certificate = true);
// Without a curve: the maximum over all contact lines (verdict only).
Verdict query_direct(const Model& m, const Q& rho1, const Q& rho2);

PlaneCert plane_certificate(const Model& m, size_t line, const Q& rho1, const Q& rho2);
// A common point at a point on the line's contact (touching) — or, with line = npos, anywhere.
Witness make_witness(const Model& m, const Q& rho1, const Q& rho2, size_t line);
// A common point of conv(vertices i1 of P1(ρ1)) and conv(vertices i2 of P2(ρ2)); with interior,
// one in both relative interiors, every listed vertex weighted > 0.
Witness make_witness(const Model& m, const Q& rho1, const Q& rho2, const std::vector<int>& i1, const std::vector<int>& i2,
                     bool interior);

}  // namespace scalecert::internal
