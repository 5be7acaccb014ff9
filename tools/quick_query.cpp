#include "quick_query.hpp"

#include "numeric/predicates.hpp"

#include "numeric/double3.hpp"

#include <cmath>

namespace scalecert::internal {

namespace {
D3 rounded(const Vec3q& v) { return {to_double_rn(v[0]), to_double_rn(v[1]), to_double_rn(v[2])}; }

// A point w = ρ1 q1_i − ρ2 q2_j − d of P1(ρ1) − P2(ρ2), in doubles, with its vertex pair and a
// componentwise bound W ≥ ρ1|q1_i| + ρ2|q2_j| + |d| on the magnitudes it was computed from.
struct Pt {
    D3 w, W;
    int i, j;
};

// GJK's simplex step (the origin against the newest point a = s.back()): keeps the sub-simplex
// nearest the origin and sets the next search direction v; true when the tetrahedron encloses it.
// Only a proposal: its rounding is not trusted, the certificate is checked apart.
void line_step(std::vector<Pt>& s, const Pt& b, const Pt& a, D3& v) {
    const D3 ab = subd(b.w, a.w), ao = negd(a.w);
    if (dotd(ab, ao) > 0)
        s = {b, a}, v = crossd(crossd(ab, ao), ab);
    else
        s = {a}, v = ao;
}
void triangle_step(std::vector<Pt>& s, D3& v) {
    const Pt c = s[0], b = s[1], a = s[2];
    const D3 ab = subd(b.w, a.w), ac = subd(c.w, a.w), ao = negd(a.w), abc = crossd(ab, ac);
    if (dotd(crossd(abc, ac), ao) > 0) {
        if (dotd(ac, ao) > 0)
            s = {c, a}, v = crossd(crossd(ac, ao), ac);
        else
            line_step(s, b, a, v);
    } else if (dotd(crossd(ab, abc), ao) > 0) {
        line_step(s, b, a, v);
    } else if (dotd(abc, ao) > 0) {
        s = {c, b, a}, v = abc;
    } else {
        s = {b, c, a}, v = negd(abc);
    }
}
bool simplex_step(std::vector<Pt>& s, D3& v) {
    if (s.size() == 2) {
        const Pt b = s[0], a = s[1];
        line_step(s, b, a, v);
        return false;
    }
    if (s.size() == 3) {
        triangle_step(s, v);
        return false;
    }
    const Pt d = s[0], c = s[1], b = s[2], a = s[3];
    const D3 ab = subd(b.w, a.w), ac = subd(c.w, a.w), ad = subd(d.w, a.w), ao = negd(a.w);
    if (dotd(crossd(ab, ac), ao) > 0) {
        s = {c, b, a};
        triangle_step(s, v);
        return false;
    }
    if (dotd(crossd(ac, ad), ao) > 0) {
        s = {d, c, a};
        triangle_step(s, v);
        return false;
    }
    if (dotd(crossd(ad, ab), ao) > 0) {
        s = {b, d, a};
        triangle_step(s, v);
        return false;
    }
    return true;
}

// |a|·(|b| × |c|) expanded with absolute values: bounds every term of det(a, b, c).
double permanent(const D3& a, const D3& b, const D3& c) {
    return a[0] * (b[1] * c[2] + b[2] * c[1]) + a[1] * (b[0] * c[2] + b[2] * c[0]) + a[2] * (b[0] * c[1] + b[1] * c[0]);
}
}  // namespace

QuickScene::QuickScene(const ExactScene& scene) : scene_(scene) {
    for (const Vec3q& v : scene.P[0].points) q1_.push_back(rounded(sub(v, scene.P[0].seed)));
    for (const Vec3q& w : scene.P[1].points) q2_.push_back(rounded(sub(w, scene.P[1].seed)));
    d_ = rounded(sub(scene.P[1].seed, scene.P[0].seed));
}

QuickScene::~QuickScene() = default;

Verdict QuickScene::classify(double r1, double r2) const {
    // Error budget: q1_, q2_, d_ are within 2^-53 relative of the exact values, and each formula
    // below adds a few roundings, so the true errors stay under 20 units of 2^-53 (4.4e-15) of
    // the magnitudes named; the bounds are predicates.hpp's 5. Values too small for relative bounds
    // (underflow) or not finite are never certified.
    auto support = [&](const D3& v) {
        Pt p{{}, {}, 0, 0};
        double best1 = -INFINITY, best2 = INFINITY;
        for (size_t i = 0; i < q1_.size(); ++i)
            if (double x = dotd(v, q1_[i]); x > best1) best1 = x, p.i = static_cast<int>(i);
        for (size_t j = 0; j < q2_.size(); ++j)
            if (double x = dotd(v, q2_[j]); x < best2) best2 = x, p.j = static_cast<int>(j);
        const D3 &a = q1_[p.i], &b = q2_[p.j];
        for (int k = 0; k < 3; ++k) {
            p.w[k] = r1 * a[k] - r2 * b[k] - d_[k];
            p.W[k] = r1 * std::fabs(a[k]) + r2 * std::fabs(b[k]) + std::fabs(d_[k]);
        }
        return p;
    };
    // Separated by the plane of normal n: n·d − ρ1·max n·q1 − ρ2·max(−n·q2) > 0, over all vertices.
    auto separates = [&](const D3& n) {
        double h1 = -INFINITY, h2 = -INFINITY, m1 = 0, m2 = 0;
        for (const D3& q : q1_) {
            h1 = std::max(h1, dotd(n, q));
            m1 = std::max(m1, std::fabs(n[0] * q[0]) + std::fabs(n[1] * q[1]) + std::fabs(n[2] * q[2]));
        }
        for (const D3& q : q2_) {
            h2 = std::max(h2, -dotd(n, q));
            m2 = std::max(m2, std::fabs(n[0] * q[0]) + std::fabs(n[1] * q[1]) + std::fabs(n[2] * q[2]));
        }
        const double g = dotd(n, d_) - r1 * h1 - r2 * h2;
        const double scale =
            std::fabs(n[0] * d_[0]) + std::fabs(n[1] * d_[1]) + std::fabs(n[2] * d_[2]) + r1 * m1 + r2 * m2;
        return filter::bounds::quick_gap_certified(g, scale);
    };
    // The origin strictly inside the tetrahedron: 0 = Σ λ_k w_k with every λ_k > 0, i.e. the four
    // cofactors (−1)^k det(w without k) nonzero and of one sign.
    auto encloses = [&](const std::vector<Pt>& s) {
        int sign = 0;
        for (int k = 0; k < 4; ++k) {
            const Pt* o[3];
            for (int m = 0, t = 0; m < 4; ++m)
                if (m != k) o[t++] = &s[static_cast<size_t>(m)];
            const double det = dotd(o[0]->w, crossd(o[1]->w, o[2]->w)) * (k % 2 ? -1 : 1);
            const int sk = filter::bounds::quick_cofactor_sign(det, permanent(o[0]->W, o[1]->W, o[2]->W));
            if (sk == 0) return false;
            if (sign && sk != sign) return false;
            sign = sk;
        }
        return true;
    };
    // Predicate 5: GJK in doubles certifies a separating plane or a tetrahedron about the origin;
    // else the exact model decides.
    auto gjk = [&] {
        bool separated = false, overlapping = false;
        if (std::isfinite(r1) && std::isfinite(r2) && r1 > 0 && r2 > 0) {
            D3 v = dotd(d_, d_) > 0 ? negd(d_) : D3{1, 0, 0};
            std::vector<Pt> s{support(v)};
            v = negd(s[0].w);
            for (int iter = 0; iter < filter::kQuickGjkIterations; ++iter) {
                if (!(dotd(v, v) > 0) || !std::isfinite(dotd(v, v)))
                    break;  // the origin on the simplex: too close to call
                const Pt p = support(v);
                if (dotd(p.w, v) < 0) {
                    separated = separates(v);
                    break;
                }
                s.push_back(p);
                if (simplex_step(s, v)) {
                    overlapping = encloses(s);
                    break;
                }
            }
        }
        return separated ? 1 : overlapping ? -1 : 0;
    };
    auto exact = [&] {
        if (!model_) model_ = std::make_unique<Model>(build_model(scene_));
        return verdict_sign(query_direct(*model_, exact_from_double(r1), exact_from_double(r2)));
    };
    return verdict_of_sign(filter::filtered(filter::Predicate::QuickCertificate, gjk, exact, stats));
}

}  // namespace scalecert::internal
