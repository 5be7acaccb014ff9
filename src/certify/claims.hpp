// Certifying a floating-point program's claims: each marked right or wrong, exactly
// (certificates/CLAIMS.md holds the rules).
#pragma once
#include "certify/certificate.hpp"
#include "certify/query.hpp"
#include "geometry/point_sets.hpp"

#include <functional>
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
// fractions p/q are exact always. `tolerance` (a relative error, >= 0) accepts numeric values within it; verdicts,
// labels, planes and witness points must be exactly right.
// Options: the public ClaimOptions (numbers, tolerance >= 0, json).
using scalecert::ClaimOptions;
// What claims are checked against: the hull model and its curve over all ρ1 > 0 (built on first
// use), and the exact verdict and curve value at a pair (Session::claim_models takes them from the
// walk where it proved the curve: no hull for verdicts on a large scene).
struct ClaimModels {
    std::function<const HullModel&()> model;
    std::function<const TouchingCurve&()> curve;
    std::function<Verdict(const Q&, const Q&)> verdict;
    std::function<Q(const Q&)> curve_value;
    std::function<Q()> growth;  // ρ*
    // Support queries for planes, distances and depths (measures.hpp): the hull model's vertices,
    // or on a walked scene the points' trees, with no hull.
    std::function<const PointSets&()> points;
    // The model whose scene and seed weights a judgements certificate states (the walk's on a
    // walked scene: the same points in the same order as the hull model's).
    std::function<const Model&()> document;
    // A verdict's query certificate, on the model that proves it.
    std::function<std::pair<const Model*, QueryAnswer>(const Q&, const Q&)> certified_query;
    // The growth distance's proof (judgements.hpp, growth_proof), on the model that proves it.
    std::function<Json()> growth_proof;
    // The two exact polyhedra with no contact line (build_hulls, or the hull model's): membership
    // of witness and closest points, and the exact distance's fallback.
    std::function<const Model&()> hulls;
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
    std::function<Curve(const Q&, const Q&)> curve_around;
    // Is x in P_i(ρ)? With its proof (judgements.hpp, membership_proof) in *proof when given:
    // from the walk's point trees on a walked scene whose hulls are not built, else the hulls.
    std::function<bool(int, const Q&, const Vec3q&, Json*)> member;
    static ClaimModels of(const HullModel& m, const TouchingCurve& c);
};
// Is x in P_i(ρ) on the exact polyhedra of m (a hull model, or build_hulls's), with its proof.
bool hull_member(const Model& m, int i, const Q& rho, const Vec3q& x, Json* proof);
// (*count, when given: the number of claims. *certificate, when given: the judgements
// certificate, kind "judgements" (judgements.hpp, FORMAT.md): the proof of every judgement.)
std::string certify_fp(const ClaimModels& models, const std::string& claims, const std::string& name,
                       const ClaimOptions& opt, long* wrong, long* count = nullptr, std::string* certificate = nullptr);
inline std::string certify_fp(const HullModel& m, const TouchingCurve& c, const std::string& claims,
                              const std::string& name, const ClaimOptions& opt, long* wrong) {
    return certify_fp(ClaimModels::of(m, c), claims, name, opt, wrong);
}
inline std::string certify_fp(const HullModel& m, const TouchingCurve& c, const std::string& claims,
                              const std::string& name, Numbers numbers, bool json, long* wrong) {
    return certify_fp(m, c, claims, name, ClaimOptions{numbers, Q(0), json}, wrong);
}
// The same claims on two objects made of parts (CLAIMS.md, "Objects made of parts"): verdict,
// separating_plane, witness_point and distance (the least over the part pairs), at any
// (ρ1, ρ2) > 0; the line format's verdict lines. The certificate is of kind "compound_judgements".
class CompoundJudge;
std::string certify_fp(CompoundJudge& judge, const std::string& claims, const std::string& name,
                       const ClaimOptions& opt, long* wrong, long* count = nullptr, std::string* certificate = nullptr);
}  // namespace scalecert::internal
