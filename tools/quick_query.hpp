// One exact query straight from the scene, with no model and no curve: a floating-point GJK on
// the scaled vertices proposes a certificate, and a filter with a proven error bound accepts it.
//   separated   — a direction n with n·d − ρ1·h1(n) − ρ2·h2(n) > 0 (h over all vertices);
//   overlapping — four points a − b of P1(ρ1) − P2(ρ2) whose tetrahedron holds the origin
//                 strictly inside, so the origin is interior to P1(ρ1) − P2(ρ2).
// When neither is proven (touching, or too close to call) the exact model is built once and
// decides. The answer is always the exact one.
#pragma once
#include "numeric/double3.hpp"
#include "certify/classify.hpp"

#include <array>
#include <memory>

namespace scalecert::internal {

// Not for concurrent use: the counts and the lazily built model are per object (one per thread).
class QuickScene {
  public:
    explicit QuickScene(const ExactScene& scene);
    ~QuickScene();
    Verdict classify(double rho1, double rho2) const;  // ρ1, ρ2 > 0 (their exact values)
    // quick_certificate: filtered = certified by GJK and the filter; exact = model built or used
    mutable filter::PredicateStats stats;
    StageCounts counts() const { return stats[filter::Predicate::QuickCertificate]; }

  private:
    ExactScene scene_;
    std::vector<D3> q1_, q2_;  // v − s1 and w − s2 rounded to nearest (relative error ≤ 2^-53 per component)
    D3 d_{};                   // s2 − s1 rounded to nearest
    mutable std::unique_ptr<Model> model_;  // built on the first undecided query
};

}  // namespace scalecert::internal
