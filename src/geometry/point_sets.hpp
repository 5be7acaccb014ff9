// The points of the two polyhedra as the measures see them (measures.hpp, gjk.hpp): exact support
// queries, the points and the seeds, whatever holds them — the hull model's vertices (HullPoints,
// here), or bounding-volume trees over all the points of a large scene, with no hull at all
// (CloudPoints, curve/scan.hpp). A measure proved on either is proved: every decision is an exact
// support query or exact arithmetic on the points it names.
#pragma once
#include "geometry/bodies.hpp"
#include "numeric/double3.hpp"

#include <optional>

namespace scalecert::internal {

class PointSets {
  public:
    virtual ~PointSets() = default;
    virtual Vec3q point(int i, int k) const = 0;  // point k of polyhedron i, exactly
    virtual D3 dpoint(int i, int k) const = 0;    // the same, near enough for a guess
    virtual const Vec3q& seed(int i) const = 0;
    // A positive integer whose product with every point of polyhedron i is integral.
    virtual const Z& scale(int i) const = 0;
    // scale(i) times point k of polyhedron i: integers.
    virtual Vec3z zpoint(int i, int k) const;
    // The smallest index of a point of polyhedron i maximising n·x, exactly.
    virtual int argmax(int i, const Vec3z& n) const = 0;
    // A point nearly maximising d·x: a guess for GJK, never a decision.
    virtual int dargmax(int i, const D3& d) const = 0;
};

// The vertices of the exact polyhedra: a hull model's, or build_hulls's (no contact line), or two
// polyhedra and seeds held elsewhere (a compound's part pair, with no copy).
class HullPoints final : public PointSets {
  public:
    explicit HullPoints(const Bodies& m) : HullPoints(m.P[0], m.P[1], m.s[0], m.s[1]) {}
    HullPoints(const Polyhedron& A, const Polyhedron& B, const Vec3q& s1, const Vec3q& s2) : P_{&A, &B}, s_{&s1, &s2} {}
    Vec3q point(int i, int k) const override { return P_[i]->points[static_cast<size_t>(k)]; }
    D3 dpoint(int i, int k) const override {
        const auto& d = P_[i]->dpts[static_cast<size_t>(k)];
        const double s = P_[i]->scale.get_d();
        return {d[0] / s, d[1] / s, d[2] / s};
    }
    const Vec3q& seed(int i) const override { return *s_[i]; }
    const Z& scale(int i) const override { return P_[i]->scale; }
    Vec3z zpoint(int i, int k) const override { return P_[i]->ipts[static_cast<size_t>(k)]; }
    int argmax(int i, const Vec3z& n) const override { return P_[i]->argmax(n).front(); }
    int dargmax(int i, const D3& d) const override {
        const Polyhedron& P = *P_[i];
        int best = P.vertices.front();
        double bv = -INFINITY;
        for (int v : P.vertices) {
            const auto& x = P.dpts[static_cast<size_t>(v)];
            const double t = d[0] * x[0] + d[1] * x[1] + d[2] * x[2];
            if (t > bv) bv = t, best = v;
        }
        return best;
    }

  private:
    const Polyhedron* P_[2];
    const Vec3q* s_[2];
};

// Another point set with polyhedron i moved by a pose [R_i | t_i] (none: where it is): point k
// is R·p_k + t, the seed likewise. Support queries go to the base set along Rᵀn (max over k of
// n·(R p_k + t) = n·t + max (Rᵀn)·p_k: the same maximisers), so a pose costs a query nothing but
// its arithmetic. The pose is held in integers: L the lcm of its denominators and D the base's
// scale(i), the moved points over D·L are L·R·X + D·L·t for the base's integer points X, and
// L·Rᵀn is a positive multiple of Rᵀn for an integer n: no rational arithmetic per query or
// point. R must be nonsingular.
class PosedPoints final : public PointSets {
  public:
    PosedPoints(const PointSets& base, const std::array<std::optional<Pose>, 2>& poses);
    Vec3q point(int i, int k) const override;
    D3 dpoint(int i, int k) const override;
    const Vec3q& seed(int i) const override { return posed_[i] ? seed_[i] : base_.seed(i); }
    const Z& scale(int i) const override { return posed_[i] ? scale_[i] : base_.scale(i); }
    Vec3z zpoint(int i, int k) const override;
    int argmax(int i, const Vec3z& n) const override;
    int dargmax(int i, const D3& d) const override;

  private:
    const PointSets& base_;
    bool posed_[2] = {false, false};
    Z LR_[2][3][3];  // L·R, integers
    Z DLt_[2][3];    // D·L·t, integers
    double dpose_[2][3][4];
    Vec3q seed_[2];
    Z scale_[2];
};

}  // namespace scalecert::internal
