// Objects with a radius (CLAIMS.md, "Objects with a radius"): each object is every point within
// ρr of its scaled hull C(ρ), so the pair's signed distance is the hulls' signed distance s·√E
// (measures.hpp) minus R = ρ1 r1 + ρ2 r2, and every claim kind at a pair is judged from the hulls'
// proved measures and R, in squares with signs. The hulls may be flat: a sphere's is one point,
// a capsule's two.
#pragma once
#include "certify/claim.hpp"
#include "certify/golden.hpp"
#include "geometry/measures.hpp"
#include "geometry/polyhedron.hpp"
#include "io/scene.hpp"

#include <functional>
#include <memory>
#include <optional>

namespace scalecert::internal {

// One object's (or one part's) points as the measures see them, built once and shared by the
// pairs it is in: points that span 3 dimensions are held as their exact polyhedron (support
// queries climb it), any others (a point, a segment, a flat polygon) as points, every one scanned.
struct RoundedBody {
    std::vector<Vec3q> pts;
    std::vector<Vec3z> zpts;  // pts · scale
    std::vector<D3> dpts;
    Z scale;
    Vec3q seed;
    std::optional<Polyhedron> hull;  // when the points span 3 dimensions
    std::vector<Vec3z> basis;        // a basis of the span of the points' differences
};
// Throws InputError after `label` ("NAME: P1") when the points are flat and the radius is not > 0.
std::shared_ptr<const RoundedBody> rounded_body(const std::vector<Vec3q>& points, const Vec3q& seed, const Q& radius,
                                                const std::string& label);

// The points of two objects (or parts) as the measures see them.
class RoundedPoints final : public PointSets {
  public:
    // Throws InputError after `name` when an object without a radius is flat.
    RoundedPoints(const ExactScene& sc, const std::string& name);
    RoundedPoints(std::shared_ptr<const RoundedBody> a, std::shared_ptr<const RoundedBody> b);
    Vec3q point(int i, int k) const override { return obj_[i]->pts[static_cast<size_t>(k)]; }
    D3 dpoint(int i, int k) const override { return obj_[i]->dpts[static_cast<size_t>(k)]; }
    const Vec3q& seed(int i) const override { return obj_[i]->seed; }
    const Z& scale(int i) const override { return obj_[i]->scale; }
    Vec3z zpoint(int i, int k) const override { return obj_[i]->zpts[static_cast<size_t>(k)]; }
    int argmax(int i, const Vec3z& n) const override;
    int dargmax(int i, const D3& d) const override;
    // The dimension of the hulls' Minkowski difference C1 − C2 in S (these points, or them at
    // poses: the sum of the hulls' spans), and for a flat one a nonzero integer vector orthogonal to it.
    std::pair<int, Vec3z> difference_span(const PointSets& S) const;
    // Whether x is strictly inside object i's hull (false for a flat one).
    bool strictly_inside(int i, const Vec3q& x) const;
    // For x strictly inside object i's hull: Polyhedron::interior_weights.
    std::vector<std::pair<int, Q>> interior_weights(int i, const Vec3q& x) const;

    const RoundedBody& body(int i) const { return *obj_[i]; }

  private:
    std::shared_ptr<const RoundedBody> obj_[2];
    int rank_ = 0;
    Vec3z flat_normal_{};
};

// The hulls' measure at (ρ1, ρ2) on S (RoundedPoints, or it at poses): apart, the proved
// distance; meeting with C1 − C2 of full dimension, the depth (measured_depth); meeting with a
// flat difference, touching (depth 0: `flat` is orthogonal to it, and h_M(±flat) = 0).
MeasuredDepth hull_measure(const PointSets& S, int difference_rank, const Vec3z& flat, const Q& rho1, const Q& rho2);

// The pair's state from the hulls' measure and R: hulls apart by √E, separated when E > R²,
// touching when E = R², else overlapping; hulls that meet overlap when R > 0.
Verdict rounded_verdict(const MeasuredDepth& hulls, const Q& R);
// The hulls' signed distance as s·√E (s = 1 apart, 0 touching, −1 overlapping).
std::pair<int, Q> hull_signed(const MeasuredDepth& hulls);

// Is x in object i of S at ρ (within m = ρr of its hull), or within tol.abs more (`near`)? Its
// proof: {"within": weights} of the hull's point nearest x, {"near": the same}, or {"out":
// normal}, the direction from that point to x.
bool rounded_member(const PointSets& S, int i, const Q& rho, const Q& m, const Vec3q& x, const Tolerance& tol,
                    bool& near, Json* proof);
// The proof of a pair's hulls' signed distance: apart, their proved distance ({"distance": ...},
// which the verdict against R needs, not a separating plane alone); meeting, their depth proof
// ({"depth": ...}).
Json rounded_hulls_proof(const MeasuredDepth& md, const Q& rho1, const Q& rho2);

// A plane claim's rule on objects with a radius: the hulls' extents c1, c2 along n widened by
// m1·|n| and m2·|n| (|n| = √N). Exact: strictly between them; within abs: each object within
// abs·|n| of its side (no offset: c1 + m1|n| − (c2 − m2|n|) ≤ 2·abs·|n|).
bool rounded_plane_right(const Tolerance& tol, const Q& c1, const Q& c2, const Q& m1, const Q& m2, const Vec3q& n,
                         const std::optional<Q>& offset);

// Checks an object with a radius the engine will judge: its seed in the interior of the object
// (within less than r of the hull; without a radius, strictly inside its hull). InputError after `name`.
void check_rounded(const ExactScene& sc, const RoundedPoints& S, const std::string& name);

// A QuadSurd (claim.hpp) as {"a", "b", "c"}, each an exact string.
Json surd_json(const QuadSurd& x);
// "a + b*sqrt(c)" ("a" when b = 0).
std::string surd_text(const QuadSurd& x);
// The double nearest it (MPFR: display only).
double surd_double(const QuadSurd& x);

// The growth distance ρ* of two objects with a radius (CLAIMS.md, "Objects with a radius"): the
// scaling ρ at which P1(ρ) and P2(ρ) touch, exactly, with its proof for the judgements file
// (FORMAT.md): {"value": ρ*} when the seeds coincide (ρ* = 0), else {"value", "P1", "P2"}, the
// weights in Q(√c) of a point q of K = (C1 − s1) − (C2 − s2) nearest t*·d (t* = 1/ρ*,
// d = s2 − s1), |t*·d − q| = r1 + r2 and K on q's side of the plane through q normal to it.
struct RoundedGrowth {
    QuadSurd rho;
    Json proof;
};
RoundedGrowth rounded_growth(const ExactScene& sc, const RoundedPoints& S);

// The rules on two convex objects with radii (not both 0): the kinds at a pair and at poses
// (verdict, separating_plane, witness_point, distance, penetration_depth, signed_distance).
class RoundedRules final : public ClaimRules {
  public:
    RoundedRules(std::shared_ptr<const ExactScene> scene, std::shared_ptr<const RoundedPoints> points,
                 const Tolerance& tolerance);
    ~RoundedRules() override;
    Judged judge(const TypedClaim& c, Proof* proof = nullptr) override;
    const ExactScene* parts() const override { return nullptr; }
    std::optional<std::array<int, 2>> part_pair(const std::optional<std::array<int, 2>>& given,
                                                const std::string& where) const override;
    std::string certificate(Json entries) const override;
    std::string refusal(ClaimType t) const override;

  private:
    std::shared_ptr<const ExactScene> scene_;
    std::shared_ptr<const RoundedPoints> points_;
    std::optional<RoundedGrowth> growth_;  // found on the first growth_distance claim
};

// Golden data on objects with a radius (golden.hpp): their touching set is curved, so it is
// sampled, not drawn. At `verticals` values of ρ1 spread evenly over I1, where the set crosses
// ρ1 × I2, bisection on ρ2 with exact verdicts gives an exact pair on each side of it (`below`
// separated, `above` not), 2^-60 of I2 apart, or the touching pair itself when a midpoint hits it;
// the pairs near each sample (its midpoint and the offsets 2^-k of each coordinate, in I1 × I2)
// rounded to doubles, each with its exact verdict and signed distance s·√E − R (the hulls' s, E
// and R exactly, the value as a rounded double). The document is the samples'.
GoldenAnswers rounded_golden(const ExactScene& sc, const RoundedPoints& S, const GoldenPoints& points);
// The same sampling from any exact verdict and value: on objects made of parts with radii
// (rounded_parts.hpp) the value is a pair's signed distance (`pair_signed_distance`, with the pair):
// the nearest pair's when the objects are apart (their distance), else the pair deciding the verdict.
struct GoldenValue {
    Verdict verdict = Verdict::Separated;
    int s = 0;
    Q E, R;
    int a = -1, b = -1;  // the pair, on parts
};
GoldenAnswers sampled_golden(const ExactScene& sc, const std::function<Verdict(const Q&, const Q&)>& verdict,
                             const std::function<GoldenValue(const Q&, const Q&)>& state, const GoldenPoints& points);

// What the claim kinds of the curve say on objects with a radius (refusal's words).
extern const char* const kRoundedKinds;

}  // namespace scalecert::internal
