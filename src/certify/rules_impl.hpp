// Inside the claim rules (rules.cpp and kinds/): the convex rules' state and the questions they
// share (memberships, the exact distance and depth with their fallbacks, the proved curve's
// switch points), each kind's rule declared here and defined in its own file beside its
// description.
#pragma once
#include "certify/claim.hpp"
#include "certify/compound_judge.hpp"
#include "certify/judgements.hpp"
#include "geometry/measures.hpp"

#include <limits>
#include <optional>
#include <vector>

namespace scalecert::internal {

inline Vec3q diff(const Vec3q& a, const Vec3q& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Q dot3(const Vec3q& a, const Vec3q& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

struct ConvexRules::Impl {
    Impl(const ClaimModels& m, const Tolerance& tolerance) : models(m), tol(tolerance) {}
    const ClaimModels& models;
    Tolerance tol;
    long distance_fallbacks = 0, depth_fallbacks = 0;
    using Curve = ClaimModels::Curve;
    std::optional<std::vector<ExactSwitch>> switches;  // the whole curve's switch points (built on first use)
    std::vector<ExactSwitch> walk_switches;

    // The two exact polyhedra, with no contact line: the measures' fallbacks.
    const Model& hulls() const { return models.hulls(); }
    // The whole curve on the hull model (within the limits: Session::claim_hull).
    Curve whole() const { return {&models.hull_model(), &models.hull_curve(), Q(0), std::nullopt}; }
    // The point set for the measures: the cloud's trees on a walked scene (exact for every
    // normal), else the exact polyhedra's vertices.
    const PointSets& points() const { return posed ? *posed : models.points(); }
    // A claim at poses (CLAIMS.md, "Poses") is judged by the same rules from support queries on
    // the moved points (PosedPoints: no model is built for the pose), each proof a support proof
    // that the checker verifies on the moved vertices: a verdict's is its depth's. The proved
    // distances' rounds are unbounded there (each adds a point: they always close).
    const PosedPoints* posed = nullptr;
    static constexpr int kAll = std::numeric_limits<int>::max();
    // Is x in P_i(ρ)? With its proof when asked.
    bool member(int i, const Q& rho, const Vec3q& x, Json* proof) const {
        if (!posed) return models.member(i, rho, x, proof);
        const std::optional<bool> in = membership_by_points(*posed, i, rho, x, proof, kAll);
        if (!in) throw std::logic_error("certify-fp: a posed membership did not close");
        return *in;
    }
    // The exact verdict; at poses, the depth's.
    Verdict exact_verdict(const Q& r1, const Q& r2) {
        if (!posed) return models.verdict(r1, r2);
        return depth_of(r1, r2).state;
    }

    // Whether x is in P1(ρ1) and y in P2(ρ2) (or, at an absolute tolerance, within it of them),
    // with their proofs in *proof when given. `known`: the exact closest points, with their
    // weights when known: a claimed point within the tolerance of its body's is near at once.
    // m.in1, m.in2 (and m.near1, m.near2: outside, within the tolerance).
    void members(const Q& r1, const Q& r2, const Vec3q& x, const Vec3q& y, Membership& g, Json* proof,
                 const ExactDistance* known = nullptr) const {
        auto one = [&](int i, const Q& r, const Vec3q& v, Json* pj, bool& near) {
            near = false;
            if (sgn(tol.abs) > 0 && known) {
                const auto& w = i == 0 ? known->w1 : known->w2;
                const Vec3q d = diff(v, i == 0 ? known->p1 : known->p2);
                if (!w.empty() && dot3(d, d) <= tol.abs * tol.abs) {
                    // Near its body's closest point; in the body, it is said to be in it. Beyond
                    // the slab between the closest points (u = p2 − p1: max over P1 of u·y is
                    // u·p1, min over P2 is u·p2) it is outside at once; else it is placed exactly.
                    const Vec3q u = diff(known->p2, known->p1);
                    const Q along = i == 0 ? Q(dot3(u, v) - dot3(u, known->p1)) : Q(dot3(u, known->p2) - dot3(u, v));
                    near = sgn(known->squared) > 0 && sgn(along) > 0 ? true : !member(i, r, v, nullptr);
                    if (pj) *pj = Json{{"near", weights_json(w)}};
                    return true;
                }
            }
            if (member(i, r, v, pj)) return true;
            near = sgn(tol.abs) > 0 && near_proof(points(), i, r, v, tol.abs, pj);
            return near;
        };
        Json p1, p2;
        g.in1 = one(0, r1, x, proof ? &p1 : nullptr, g.near1);
        g.in2 = one(1, r2, y, proof ? &p2 : nullptr, g.near2);
        if (proof) *proof = Json{{"P1", std::move(p1)}, {"P2", std::move(p2)}};
    }

    // The exact switch points where V proves the curve: every break of ρ2 = f(ρ1) at ρ1 > 0
    // with ρ2 > 0, inside I1 or not, with its contact (on the whole curve: built once).
    std::vector<ExactSwitch> switches_of(const Curve& V) const {
        std::vector<ExactSwitch> out;
        const auto& P = V.curve->env.pieces;
        for (size_t k = 0; k + 1 < P.size(); ++k) {
            const Q& x = *P[k].to;
            const ContactLine &L = V.model->lines[P[k].line], &R = V.model->lines[P[k + 1].line];
            const Q y = L.at(x);
            if (sgn(x) <= 0 || !V.proves(x)) continue;
            if (sgn(y) <= 0) break;  // f descends: nothing touches from here on
            out.push_back({x, y, contact_at(*V.model, L, R, x, y).label});
        }
        return out;
    }
    const std::vector<ExactSwitch>& exact_switches(const Curve& V) {
        if (!V.whole()) {
            walk_switches = switches_of(V);
            return walk_switches;
        }
        if (!switches) switches = switches_of(V);
        return *switches;
    }

    // The exact distance, proved from the points' supports; CGAL's QP over every hull vertex when
    // the proof does not close (counted).
    ExactDistance exact_distance_of(const Q& r1, const Q& r2) {
        if (posed) {
            const std::optional<ProvedDistance> pd = proved_distance(*posed, r1, r2, kAll);
            if (!pd) throw std::logic_error("certify-fp: a posed distance did not close");
            return pd->d;
        }
        if (std::optional<ProvedDistance> pd = proved_distance(points(), r1, r2)) return pd->d;
        ++distance_fallbacks;
        return exact_distance(hulls(), r1, r2);
    }
    // The depth with what proves it (measured_depth); when the distance's proof does not close,
    // from CGAL's exact distance and the EPA on the hull's vertices (counted).
    MeasuredDepth depth_of(const Q& r1, const Q& r2) {
        if (posed) {
            const std::optional<MeasuredDepth> md = measured_depth(*posed, r1, r2, kAll);
            if (!md) throw std::logic_error("certify-fp: a posed depth did not close");
            return *md;
        }
        if (std::optional<MeasuredDepth> d = measured_depth(points(), r1, r2)) return *d;
        ++depth_fallbacks;
        return depth_from_distance(HullPoints(hulls()), exact_distance(hulls(), r1, r2), r1, r2);
    }

    // Where the curve reaches ρ2 = 0: on its last piece (it goes on as one line from there).
    static Q zero_crossing(const Curve& V) {
        const ContactLine& L = V.model->lines[V.curve->env.pieces.back().line];
        return std::max(Q(0), Q(-L.intercept / L.slope));
    }

    // ρ1 with f(ρ1) = y (f is strictly decreasing), or none outside f's range over ρ1 ≥ 0; f as
    // V has it (the exact curve where V proves it).
    static std::optional<Q> inverse(const Curve& V, const Q& y) {
        for (const EnvPiece& p : V.curve->env.pieces) {
            const ContactLine& L = V.model->lines[p.line];
            const Q x = (y - L.intercept) / L.slope;
            if (x >= p.from && (!p.to || x <= *p.to)) return x;
        }
        return std::nullopt;
    }

    // The rules, kind by kind (kinds/).
    void verdict(const TypedClaim& c, Judged& g, Proof* proof);
    void growth(const TypedClaim& c, Judged& g, Proof* proof);
    void curve_point(const TypedClaim& c, Judged& g, Proof* proof);
    void switch_point(const TypedClaim& c, Judged& g, Proof* proof);
    void curve(const TypedClaim& c, Judged& g, Proof* proof);
    void plane(const TypedClaim& c, Judged& g, Proof* proof);
    void witness(const TypedClaim& c, Judged& g, Proof* proof);
    void distance(const TypedClaim& c, Judged& g, Proof* proof);
    void depth(const TypedClaim& c, Judged& g, Proof* proof);
    void signed_distance(const TypedClaim& c, Judged& g, Proof* proof);
};

}  // namespace scalecert::internal
