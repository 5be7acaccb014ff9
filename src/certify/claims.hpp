// Certifying a floating-point program's claims: each marked right or wrong, exactly
// (certificates/CLAIMS.md holds the rules).
#pragma once
#include "certify/certificate.hpp"
#include "certify/query.hpp"
#include "geometry/point_sets.hpp"

#include <memory>
#include <optional>
#include <string>

namespace scalecert::internal {

// Marks a floating-point program's claims right or wrong, exactly, and reports the exact values
// and errors (text, or JSON with `json`); the number of wrong claims in *wrong. Two formats:
// - JSON (text starting with '{'): {"format": "scalecert-claims-1", "claims": [...]} with the kinds
//   verdict, curve, curve_point, switch_point, growth_distance, separating_plane, witness_point,
//   distance and penetration_depth (certificates/CLAIMS.md);
// - lines ('#' comments): 'RHO1 RHO2 VERDICT' (separated | touching | overlapping | intersecting,
//   = not separated), 'curve RHO1 RHO2' (a claimed point of the touching curve) or 'growth RHO'.
// A JSON number or a decimal of the line format is the binary value ClaimOptions::numbers reads
// (the double strtod gives by default: what the program that wrote it held). JSON strings and
// fractions p/q are exact always. `tolerance` (a relative error, >= 0) accepts numeric values within
// it, `abs_tolerance` (a length) points, lengths and planes within it (CLAIMS.md, "Tolerances");
// verdicts and labels must be exactly right.
// Options: the public ClaimOptions (numbers, tolerance, abs_tolerance, json, certificate).
using scalecert::ClaimOptions;
// What the claim rules ask of a convex scene, one question a method: the exact verdict and curve
// value at a pair, the models that prove them, the points for the measures. Session answers each
// from the least model it needs (the walk where it proved the curve: no hull for verdicts on a
// large scene); HullClaimModels from a hull model and its curve over all ρ1 > 0.
class ClaimModels {
  public:
    virtual ~ClaimModels() = default;
    // The hull model and its curve over all ρ1 > 0 (built on first use).
    virtual const HullModel& hull_model() const = 0;
    virtual const TouchingCurve& hull_curve() const = 0;
    // The exact verdict at (ρ1, ρ2), and the curve's ρ2 at ρ1.
    virtual Verdict verdict(const Q& rho1, const Q& rho2) const = 0;
    virtual Q curve_value(const Q& rho1) const = 0;
    virtual Q growth() const = 0;  // ρ*
    // Support queries for planes, distances and depths (measures.hpp): the hull model's vertices,
    // or on a walked scene the points' trees, with no hull.
    virtual const PointSets& points() const = 0;
    // The model whose scene and seed weights a judgements certificate states (the walk's on a
    // walked scene: the same points in the same order as the hull model's).
    virtual const Model& document() const = 0;
    // A verdict's query certificate, on the model that proves it.
    virtual std::pair<const Model*, QueryAnswer> certified_query(const Q& rho1, const Q& rho2) const = 0;
    // The growth distance's proof (judgements.hpp, growth_proof), on the model that proves it.
    virtual Json growth_proof() const = 0;
    // The two exact polyhedra with no contact line (build_hulls, or the hull model's): membership
    // of witness and closest points, and the exact distance's fallback.
    virtual const Model& hulls() const = 0;
    // The curve proved over curve_proof's window around [lo, hi] (Session::curve_around): the
    // model, the curve, and the ρ1 range where that curve is the exact one (lo_proved = 0 and no
    // hi_proved on the hull model).
    struct Curve {
        const Model* model;
        const TouchingCurve* curve;
        Q lo_proved;
        std::optional<Q> hi_proved;
        bool whole() const { return sgn(lo_proved) == 0 && !hi_proved; }
        bool proves(const Q& x) const { return x >= lo_proved && (!hi_proved || x <= *hi_proved); }
    };
    virtual Curve curve_around(const Q& lo, const Q& hi) const = 0;
    // Is x in P_i(ρ)? With its proof (judgements.hpp, membership_proof) in *proof when given.
    virtual bool member(int i, const Q& rho, const Vec3q& x, Json* proof) const = 0;
};
// Every answer from one hull model and its curve (both must outlive it).
class HullClaimModels final : public ClaimModels {
  public:
    HullClaimModels(const HullModel& m, const TouchingCurve& c);
    const HullModel& hull_model() const override { return m_; }
    const TouchingCurve& hull_curve() const override { return c_; }
    Verdict verdict(const Q& rho1, const Q& rho2) const override;
    Q curve_value(const Q& rho1) const override;
    Q growth() const override { return c_.growth.value; }
    const PointSets& points() const override { return *points_; }
    const Model& document() const override { return m_; }
    std::pair<const Model*, QueryAnswer> certified_query(const Q& rho1, const Q& rho2) const override;
    Json growth_proof() const override;
    const Model& hulls() const override { return m_; }
    Curve curve_around(const Q&, const Q&) const override { return {&m_, &c_, Q(0), std::nullopt}; }
    bool member(int i, const Q& rho, const Vec3q& x, Json* proof) const override;

  private:
    const HullModel& m_;
    const TouchingCurve& c_;
    std::shared_ptr<const PointSets> points_;
};
// Is x in P_i(ρ) on the exact polyhedra of m (a hull model, or build_hulls's), with its proof.
bool hull_member(const Model& m, int i, const Q& rho, const Vec3q& x, Json* proof);
// (*count, when given: the number of claims. *certificate, when given: the judgements
// certificate, kind "judgements" (judgements.hpp, FORMAT.md): the proof of every judgement.)
std::string certify_fp(const ClaimModels& models, const std::string& claims, const std::string& name,
                       const ClaimOptions& opt, long* wrong, long* count = nullptr, std::string* certificate = nullptr);
inline std::string certify_fp(const HullModel& m, const TouchingCurve& c, const std::string& claims,
                              const std::string& name, const ClaimOptions& opt, long* wrong) {
    return certify_fp(HullClaimModels(m, c), claims, name, opt, wrong);
}
inline std::string certify_fp(const HullModel& m, const TouchingCurve& c, const std::string& claims,
                              const std::string& name, Numbers numbers, bool json, long* wrong) {
    return certify_fp(m, c, claims, name, ClaimOptions{numbers, Q(0), json}, wrong);
}
// The same claims on two objects made of parts (CLAIMS.md, "Objects made of parts"): verdict,
// separating_plane, witness_point, distance (the least over the part pairs) and penetration_depth
// (of one part pair), at any (ρ1, ρ2) > 0; the line format's verdict lines. The certificate is of
// kind "compound_judgements".
class CompoundJudge;
std::string certify_fp(CompoundJudge& judge, const std::string& claims, const std::string& name,
                       const ClaimOptions& opt, long* wrong, long* count = nullptr, std::string* certificate = nullptr);
}  // namespace scalecert::internal
