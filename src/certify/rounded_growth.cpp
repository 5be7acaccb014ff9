// The growth distance of two objects with a radius (rounded.hpp, rounded_growth; CLAIMS.md,
// "Objects with a radius"). With t = 1/ρ, d = s2 − s1 and K = (C1 − s1) − (C2 − s2), the pair at
// (ρ, ρ) is g(t) = dist(t·d, K) against R0 = r1 + r2 (times ρ): t* is where the ray t·d leaves
// K ⊕ B(R0). Near t* the point of K nearest t·d lies on one affine piece A of K (a vertex, an edge
// or a facet of it, named by the closest points' vertices), so t* is a root of
// |P⊥(t·d − p0)|² = R0², a quadratic with rational coefficients: t* = α + β√Δ. Each root is tried
// as a proof: a nearest point q of K as weights in Q(√c) on each object's points, n = t·d − q with
// |n|² = R0² and every point of K on n·k ≤ n·q (the objects' own supports). No double decides.
#include "certify/certificate.hpp"
#include "certify/rounded.hpp"

#include <limits>

namespace scalecert::internal {

namespace {
constexpr int kAll = std::numeric_limits<int>::max();

// a + b√c for the one c of a computation.
struct F {
    Q a, b;
};
F fadd(const F& x, const F& y) { return {x.a + y.a, x.b + y.b}; }
F fsub(const F& x, const F& y) { return {x.a - y.a, x.b - y.b}; }
F fmul(const F& x, const F& y, const Z& c) { return {x.a * y.a + x.b * y.b * Q(c), x.a * y.b + x.b * y.a}; }
F fscale(const F& x, const Q& k) { return {x.a * k, x.b * k}; }
int fsign(const F& x, const Z& c) { return sign_minus_sqrt(x.a, Q(-x.b), Q(c)); }
using FV = std::array<F, 3>;
F fdot(const FV& x, const Vec3q& v) {
    return {x[0].a * v[0] + x[1].a * v[1] + x[2].a * v[2], x[0].b * v[0] + x[1].b * v[1] + x[2].b * v[2]};
}

Q dotq(const Vec3q& a, const Vec3q& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3q subq(const Vec3q& a, const Vec3q& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3q axpy(const Vec3q& y, const Q& k, const Vec3q& x) { return {y[0] + k * x[0], y[1] + k * x[1], y[2] + k * x[2]}; }

// √Δ (Δ > 0 rational) as m·√c: c a natural number with no square factor below 2^10 (a perfect
// square gives c = 1).
std::pair<Q, Z> root_of(const Q& D) {
    Z c = D.get_num() * D.get_den();
    Q m = Q(1) / Q(D.get_den());
    if (mpz_perfect_square_p(c.get_mpz_t())) {
        Z r;
        mpz_sqrt(r.get_mpz_t(), c.get_mpz_t());
        return {m * Q(r), Z(1)};
    }
    for (unsigned long p = 2; p < 1024; ++p) {
        const Z pp = Z(p) * Z(p);
        while (mpz_divisible_p(c.get_mpz_t(), pp.get_mpz_t())) {
            c /= pp;
            m *= Q(p);
        }
    }
    return {m, c};
}

// Solves M x = b exactly for the columns of M (5 rows), each b in its span: x, or none when the
// columns are dependent or some b is not in their span.
std::optional<std::vector<std::vector<Q>>> solve(const std::vector<std::array<Q, 5>>& cols,
                                                 const std::vector<std::array<Q, 5>>& rhs) {
    const size_t m = cols.size(), k = rhs.size();
    std::vector<std::vector<Q>> A(5, std::vector<Q>(m + k));
    for (size_t r = 0; r < 5; ++r) {
        for (size_t j = 0; j < m; ++j) A[r][j] = cols[j][r];
        for (size_t j = 0; j < k; ++j) A[r][m + j] = rhs[j][r];
    }
    size_t row = 0;
    std::vector<size_t> pivot;
    for (size_t j = 0; j < m; ++j) {
        size_t p = row;
        while (p < 5 && sgn(A[p][j]) == 0) ++p;
        if (p == 5) return std::nullopt;  // dependent columns
        std::swap(A[p], A[row]);
        for (size_t r = 0; r < 5; ++r) {
            if (r == row || sgn(A[r][j]) == 0) continue;
            const Q f = A[r][j] / A[row][j];
            for (size_t c = j; c < m + k; ++c) A[r][c] -= f * A[row][c];
        }
        pivot.push_back(row++);
    }
    for (size_t r = row; r < 5; ++r)
        for (size_t j = 0; j < k; ++j)
            if (sgn(A[r][m + j]) != 0) return std::nullopt;  // not in the span
    std::vector<std::vector<Q>> x(k, std::vector<Q>(m));
    for (size_t j = 0; j < m; ++j)
        for (size_t s = 0; s < k; ++s) x[s][j] = A[pivot[j]][m + s] / A[pivot[j]][j];
    return x;
}

struct Attempt {
    const ExactScene& sc;
    Vec3q d;
    Q R0;
};

// The proof at t = α + β√c, when it holds: weights in Q(√c) on each object's points (some of
// I1, I2) of a point q of K with n = t·d − q, |n|² = R0², and max over P1's points of n·v = n·q1,
// min over P2's of n·w = n·q2.
// q(t) = X + t·PUd is the projection of t·d on A (X = P⊥p0, PUd = d − P⊥d).
std::optional<RoundedGrowth> prove(const Attempt& at, const std::vector<int>& I1, const std::vector<int>& I2,
                                   const F& t, const Z& c, const Vec3q& X, const Vec3q& PUd) {
    const ExactScene& sc = at.sc;
    if (fsign(t, c) <= 0) return std::nullopt;
    const std::vector<Vec3q>&P1 = sc.P[0].points, &P2 = sc.P[1].points;
    const size_t n1 = I1.size(), n2 = I2.size();
    // Each subset of I1 ∪ I2 with a point of each, largest first: Σλ v − Σμ w = q − d, Σλ = Σμ = 1.
    std::vector<unsigned> masks;
    for (unsigned s = 1; s < (1u << (n1 + n2)); ++s)
        if ((s & ((1u << n1) - 1)) && (s >> n1)) masks.push_back(s);
    std::stable_sort(masks.begin(), masks.end(),
                     [](unsigned x, unsigned y) { return __builtin_popcount(x) > __builtin_popcount(y); });
    FV q;
    for (int k = 0; k < 3; ++k) q[k] = fadd(F{X[k], Q(0)}, fscale(t, PUd[k]));
    for (unsigned mask : masks) {
        std::vector<std::array<Q, 5>> cols;
        std::vector<std::pair<int, int>> which;  // (object, index)
        for (size_t k = 0; k < n1 + n2; ++k) {
            if (!(mask >> k & 1)) continue;
            const bool one = k < n1;
            const Vec3q& v = one ? P1[size_t(I1[k])] : P2[size_t(I2[k - n1])];
            const Q s = one ? Q(1) : Q(-1);
            cols.push_back({s * v[0], s * v[1], s * v[2], Q(one ? 1 : 0), Q(one ? 0 : 1)});
            which.push_back({one ? 0 : 1, one ? I1[k] : I2[k - n1]});
        }
        // The right side q − d = B0 + √c·B1.
        std::array<Q, 5> B0{q[0].a - at.d[0], q[1].a - at.d[1], q[2].a - at.d[2], Q(1), Q(1)},
            B1{q[0].b, q[1].b, q[2].b, Q(0), Q(0)};
        const auto x = solve(cols, {B0, B1});
        if (!x) continue;
        std::vector<F> w;
        bool nonneg = true;
        for (size_t j = 0; j < cols.size() && nonneg; ++j) {
            w.push_back(F{(*x)[0][j], (*x)[1][j]});
            nonneg = fsign(w.back(), c) >= 0;
        }
        if (!nonneg) continue;
        // q1 = Σλ v, q2 = Σμ w; n = t·d − q.
        FV q1{}, q2{};
        for (size_t j = 0; j < w.size(); ++j) {
            const auto [i, k] = which[j];
            const Vec3q& v = sc.P[i].points[size_t(k)];
            FV& o = i == 0 ? q1 : q2;
            for (int a = 0; a < 3; ++a) o[a] = fadd(o[a], fscale(w[j], v[a]));
        }
        FV n;
        for (int a = 0; a < 3; ++a) n[a] = fsub(fscale(t, at.d[a]), q[a]);
        F nn{Q(0), Q(0)};
        for (int a = 0; a < 3; ++a) nn = fadd(nn, fmul(n[a], n[a], c));
        if (fsign(fsub(nn, F{at.R0 * at.R0, Q(0)}), c) != 0) continue;
        auto dotf = [&](const FV& x, const FV& y) {
            F r{Q(0), Q(0)};
            for (int a = 0; a < 3; ++a) r = fadd(r, fmul(x[a], y[a], c));
            return r;
        };
        const F h1 = dotf(n, q1), h2 = dotf(n, q2);
        bool supports = true;
        for (const Vec3q& v : P1)
            if (supports && fsign(fsub(fdot(n, v), h1), c) > 0) supports = false;
        for (const Vec3q& v : P2)
            if (supports && fsign(fsub(fdot(n, v), h2), c) < 0) supports = false;
        if (!supports) return std::nullopt;
        // ρ* = 1/t = (α − β√c)/(α² − β²c).
        RoundedGrowth g;
        const Q den = t.a * t.a - t.b * t.b * Q(c);
        g.rho = {t.a / den, Q(-t.b) / den, sgn(t.b) == 0 ? Z(0) : c};
        if (sgn(g.rho.b) == 0) g.rho.c = 0;
        Json W[2] = {Json::array(), Json::array()};
        for (size_t j = 0; j < w.size(); ++j)
            W[which[j].first].push_back(
                Json::array({which[j].second, to_exact_string(w[j].a), to_exact_string(w[j].b)}));
        g.proof = Json{{"value", surd_json(g.rho)}, {"P1", std::move(W[0])}, {"P2", std::move(W[1])}};
        return g;
    }
    return std::nullopt;
}

// The roots t = α ± β√Δ of |P⊥(t·d − p0)|² = R0² on the affine span of the feature I1, I2, each
// tried as a proof; the nearest root's double, for the next probe.
std::optional<RoundedGrowth> try_feature(const Attempt& at, const std::vector<int>& I1, const std::vector<int>& I2,
                                         std::vector<double>& roots) {
    const ExactScene& sc = at.sc;
    const std::vector<Vec3q>&P1 = sc.P[0].points, &P2 = sc.P[1].points;
    const Vec3q p0 = subq(subq(P1[size_t(I1[0])], sc.P[0].seed), subq(P2[size_t(I2[0])], sc.P[1].seed));
    std::vector<Vec3q> e;
    auto add_dir = [&](Vec3q u) {
        for (const Vec3q& b : e) u = axpy(u, Q(-dotq(u, b) / dotq(b, b)), b);
        if (sgn(dotq(u, u)) != 0) e.push_back(u);
    };
    for (size_t k = 1; k < I1.size(); ++k) add_dir(subq(P1[size_t(I1[k])], P1[size_t(I1[0])]));
    for (size_t k = 1; k < I2.size(); ++k) add_dir(subq(P2[size_t(I2[0])], P2[size_t(I2[k])]));
    Vec3q D = at.d, X = p0;  // P⊥d, P⊥p0
    for (const Vec3q& b : e) {
        D = axpy(D, Q(-dotq(at.d, b) / dotq(b, b)), b);
        X = axpy(X, Q(-dotq(p0, b) / dotq(b, b)), b);
    }
    const Q a2 = dotq(D, D), a1 = -2 * dotq(D, X), a0 = dotq(X, X) - at.R0 * at.R0;
    if (sgn(a2) == 0) return std::nullopt;
    const Q disc = a1 * a1 - 4 * a2 * a0;
    if (sgn(disc) < 0) return std::nullopt;
    const Q alpha = -a1 / (2 * a2), beta = Q(1) / (2 * a2);
    F plus, minus;
    Z c = 0;
    if (sgn(disc) == 0) {
        plus = minus = F{alpha, Q(0)};
    } else {
        const auto [m, cc] = root_of(disc);
        c = cc;
        if (c == 1) {
            plus = F{alpha + beta * m, Q(0)}, minus = F{alpha - beta * m, Q(0)}, c = 0;
        } else {
            plus = F{alpha, beta * m}, minus = F{alpha, Q(-beta * m)};
        }
    }
    for (const F& t : {plus, minus}) {
        roots.push_back(surd_double({t.a, t.b, c}));
        if (std::optional<RoundedGrowth> g = prove(at, I1, I2, t, c, X, subq(at.d, D))) return g;
    }
    return std::nullopt;
}
}  // namespace

Json surd_json(const QuadSurd& x) {
    return Json{{"a", to_exact_string(x.a)}, {"b", to_exact_string(x.b)}, {"c", x.c.get_str()}};
}

std::string surd_text(const QuadSurd& x) {
    if (sgn(x.b) == 0) return to_exact_string(x.a);
    const std::string root = "sqrt(" + x.c.get_str() + ")";
    const std::string b = sgn(x.b) < 0 ? to_exact_string(Q(-x.b)) : to_exact_string(x.b);
    std::string s = sgn(x.a) == 0 ? (sgn(x.b) < 0 ? "-" : "") : to_exact_string(x.a) + (sgn(x.b) < 0 ? " - " : " + ");
    return s + (b == "1" ? root : b + "*" + root);
}

double surd_double(const QuadSurd& x) {
    if (sgn(x.b) == 0 || x.c == 0) return to_double_rn(x.a);
    const Q E = x.b * x.b * Q(x.c);
    return sgn(x.b) > 0 ? sqrt_minus_rn(E, Q(-x.a)) : -sqrt_minus_rn(E, x.a);
}

RoundedGrowth rounded_growth(const ExactScene& sc, const RoundedPoints& S) {
    const Vec3q d = subq(sc.P[1].seed, sc.P[0].seed);
    if (sgn(dotq(d, d)) == 0) {  // the seeds coincide: every pair (ρ, ρ) overlaps
        RoundedGrowth g;
        g.rho = {Q(0), Q(0), Z(0)};
        g.proof = Json{{"value", surd_json(g.rho)}};
        return g;
    }
    const Attempt at{sc, d, Q(sc.P[0].radius + sc.P[1].radius)};
    // g(t) − R0's sign at t = 1/ρ from the hulls' proved distance at (ρ, ρ) (ρ·g(t) apart), with
    // the closest points' vertices when the hulls are apart.
    auto probe = [&](const Q& t, std::vector<int>& I1, std::vector<int>& I2) {
        const Q rho = Q(1) / t;
        const std::optional<ProvedDistance> pd = proved_distance(S, rho, rho, kAll);
        if (!pd) throw std::logic_error("rounded_growth: the distance did not close");
        I1.clear(), I2.clear();
        for (const auto& [k, w] : pd->d.w1) I1.push_back(k);
        for (const auto& [k, w] : pd->d.w2) I2.push_back(k);
        if (sgn(pd->d.squared) == 0) I1.clear();
        return cmp(pd->d.squared, rho * rho * at.R0 * at.R0);
    };
    // t_lo with g < R0 (0: the seeds are interior), t_hi with g > R0; probes between them.
    Q lo = 0;
    std::optional<Q> hi;
    Q t = 1;
    for (int step = 0; step < 2000; ++step) {
        std::vector<int> I1, I2;
        const int s = probe(t, I1, I2);
        std::vector<double> roots;
        if (!I1.empty() && !I2.empty())
            if (std::optional<RoundedGrowth> g = try_feature(at, I1, I2, roots)) return *g;
        if (s > 0)
            hi = t;
        else
            lo = t;
        if (!hi) {
            t = t * 2;
            continue;
        }
        // The next probe: a root of this feature strictly inside (lo, hi) on even steps, else the midpoint.
        std::optional<Q> pick;
        if (step % 2 == 0)
            for (double r : roots)
                if (std::isfinite(r) && r > 0) {
                    const Q x = exact_from_double(r);
                    if (lo < x && x < *hi && x != t && (!pick || abs(Q(x - t)) < abs(Q(*pick - t)))) pick = x;
                }
        t = pick ? *pick : Q((lo + *hi) / 2);
    }
    throw std::logic_error("rounded_growth: no feature proved the growth distance");
}

}  // namespace scalecert::internal
