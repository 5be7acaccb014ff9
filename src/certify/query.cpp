#include "certify/query.hpp"
#include "certify/model_points.hpp"

#include "curve/scan.hpp"

#include <map>

#include "geometry/witness.hpp"

namespace scalecert::internal {

const char* verdict_name(Verdict v) {
    switch (v) {
    case Verdict::Separated: return "separated";
    case Verdict::Touching: return "touching";
    default: return "overlapping";
    }
}

PlaneCert plane_certificate(const Model& m, size_t line, const Q& rho1, const Q& rho2) {
    const ContactLine& L = m.lines[line];
    const Vec3q n = to_q(L.normal);
    PlaneCert p;
    p.line = line;
    p.c1 = dot(n, m.s[0]) + rho1 * L.h1;
    p.c2 = dot(n, m.s[1]) - rho2 * L.h2;
    p.offset = (p.c1 + p.c2) / 2;
    p.support1 = L.feat1.front();
    p.support2 = L.feat2.front();
    return p;
}

static Vec3q scaled(const Vec3q& v, const Vec3q& s, const Q& rho) {
    return {s[0] + rho * (v[0] - s[0]), s[1] + rho * (v[1] - s[1]), s[2] + rho * (v[2] - s[2])};
}

std::optional<Witness> try_witness(const Model& m, const Q& rho1, const Q& rho2, const std::vector<int>& i1,
                                   const std::vector<int>& i2, bool interior) {
    std::vector<Vec3q> A, B;
    for (int i : i1) A.push_back(scaled(m.pt(0, static_cast<size_t>(i)), m.s[0], rho1));
    for (int j : i2) B.push_back(scaled(m.pt(1, static_cast<size_t>(j)), m.s[1], rho2));
    auto cp = interior ? interior_common_point(A, B) : common_point(A, B);
    if (!cp) return std::nullopt;
    Witness w;
    w.rho1 = rho1;
    w.rho2 = rho2;
    Vec3q x{Q(0), Q(0), Q(0)}, y{Q(0), Q(0), Q(0)};
    for (size_t k = 0; k < i1.size(); ++k)
        if (sgn(cp->lambda[k])) {
            w.w1.push_back({i1[k], cp->lambda[k]});
            for (int c = 0; c < 3; ++c) x[c] += cp->lambda[k] * A[k][c];
        }
    for (size_t k = 0; k < i2.size(); ++k)
        if (sgn(cp->mu[k])) {
            w.w2.push_back({i2[k], cp->mu[k]});
            for (int c = 0; c < 3; ++c) y[c] += cp->mu[k] * B[k][c];
        }
    if (x != y) throw std::logic_error("LP witness is not a common point");
    w.point = x;
    return w;
}

Witness make_witness(const Model& m, const Q& rho1, const Q& rho2, const std::vector<int>& i1,
                     const std::vector<int>& i2, bool interior) {
    std::optional<Witness> w = try_witness(m, rho1, rho2, i1, i2, interior);
    if (!w)
        throw std::logic_error(interior ? "the contact features' relative interiors do not meet on the curve"
                                        : "no common point where the curve says the polyhedra meet");
    return std::move(*w);
}

Witness make_witness(const Model& m, const Q& rho1, const Q& rho2, size_t line) {
    if (line == size_t(-1)) return make_witness(m, rho1, rho2, m.P[0].vertices, m.P[1].vertices, false);
    return make_witness(m, rho1, rho2, m.lines[line].feat1, m.lines[line].feat2, false);
}

std::vector<std::pair<int, Q>> seed_weights(const Model& m, int i) { return points_of(m).seed_weights(m, i); }

SeedWeights seed_weights(const Model& m) { return {{seed_weights(m, 0), seed_weights(m, 1)}}; }

Witness lift_witness(const Witness& w, const Q& rho1, const Q& rho2, const std::vector<std::pair<int, Q>> seed[2]) {
    if (rho1 < w.rho1 || rho2 < w.rho2 || sgn(rho1) <= 0 || sgn(rho2) < 0 || (sgn(rho2) == 0 && sgn(w.rho2) != 0))
        throw std::logic_error("lift_witness: not a larger pair");
    Witness out = w;
    out.rho1 = rho1;
    out.rho2 = rho2;
    auto mix = [](const std::vector<std::pair<int, Q>>& lam, const std::vector<std::pair<int, Q>>& sigma, const Q& t) {
        std::map<int, Q> sum;  // index order: deterministic
        for (const auto& [k, q] : lam) sum[k] += t * q;
        if (t != 1)
            for (const auto& [k, q] : sigma) sum[k] += (Q(1) - t) * q;
        std::vector<std::pair<int, Q>> v;
        for (const auto& [k, q] : sum)
            if (sgn(q)) v.push_back({k, q});
        return v;
    };
    out.w1 = mix(w.w1, seed[0], w.rho1 / rho1);
    if (sgn(rho2) > 0) out.w2 = mix(w.w2, seed[1], w.rho2 / rho2);  // at ρ2 = 0 P2(0) is its seed, whatever the weights
    return out;
}

Witness witness_below(const Model& m, const TouchingCurve& c, const Q& rho1) {
    const size_t line = c.env.pieces[c.env.locate(rho1)].line;
    const ContactLine& L = m.lines[line];
    const Q f = L.at(rho1);
    if (sgn(f) > 0) return make_witness(m, rho1, f, line);
    return make_witness(m, -L.intercept / L.slope, Q(0), line);
}

std::pair<Q, size_t> ray_crossing(const Model& m, const TouchingCurve& c, const Q& rho1, const Q& rho2) {
    Q best = -1;
    size_t best_line = 0;
    for (const EnvPiece& p : c.env.pieces) {
        const ContactLine& L = m.lines[p.line];
        Q t = L.intercept / (rho2 - L.slope * rho1);
        if (t > best) best = t, best_line = p.line;
    }
    return {best, best_line};
}

QueryAnswer query(const Model& m, const TouchingCurve& c, const Q& rho1, const Q& rho2, bool with_certificate) {
    QueryAnswer r;
    r.rho1 = rho1;
    r.rho2 = rho2;
    size_t k = c.env.locate(rho1);
    size_t line = c.env.pieces[k].line;
    Q f = m.lines[line].at(rho1);
    int s = cmp(rho2, f);
    r.verdict = s < 0 ? Verdict::Separated : s == 0 ? Verdict::Touching : Verdict::Overlapping;
    if (!with_certificate) return r;
    if (r.verdict != Verdict::Overlapping) r.plane = plane_certificate(m, line, rho1, rho2);
    if (r.verdict == Verdict::Touching) r.witness = make_witness(m, rho1, rho2, line);
    if (r.verdict == Verdict::Overlapping) {
        // The ray t·(ρ1, ρ2) meets the curve at t* < 1; a common point of P1(t*ρ1), P2(t*ρ2) lies in
        // the interiors of P1(ρ1) and P2(ρ2), since P(ρ') ⊂ int P(ρ) for ρ' < ρ.
        if (sgn(m.d[0]) == 0 && sgn(m.d[1]) == 0 && sgn(m.d[2]) == 0) {
            Witness w;  // coincident seeds: the seed itself, at t = 0
            w.rho1 = 0;
            w.rho2 = 0;
            w.point = m.s[0];
            w.w1 = {{m.P[0].vertices.front(), Q(1)}};
            w.w2 = {{m.P[1].vertices.front(), Q(1)}};
            r.witness = w;
        } else {
            // f(tρ1) = tρ2 on some envelope piece: t = b / (ρ2 − a ρ1), the largest over the pieces
            // (each line is ≤ f, so its own crossing t is ≤ t*, with equality on the active piece).
            const auto [best, best_line] = ray_crossing(m, c, rho1, rho2);
            r.witness = make_witness(m, best * rho1, best * rho2, best_line);
        }
    }
    return r;
}

Verdict query_direct(const Model& m, const Q& rho1, const Q& rho2) {
    int best = -1;
    for (const ContactLine& L : m.lines) {
        int s = cmp(L.nd, rho1 * L.h1 + rho2 * L.h2);  // sign of the gap along L.normal
        if (s > 0) return Verdict::Separated;
        best = std::max(best, s);
    }
    return best == 0 ? Verdict::Touching : Verdict::Overlapping;
}

}  // namespace scalecert::internal
