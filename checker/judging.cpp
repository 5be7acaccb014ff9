#include "judging.hpp"

#include "numbers.hpp"
#include "scene.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <cstdio>

namespace scalecert_check {
bool Rules::close(Context& cx, const Q& c, const Q& e) const {
    cx.spend_ops(3, qsize(c) + qsize(e) + qsize(tol));
    const Q d = c - e;
    return (sgn(d) < 0 ? Q(-d) : d) <= tol * (sgn(e) < 0 ? Q(-e) : e);
}
int sign_minus_sqrt(const Q& a, const Q& k, const Q& E) {
    const int sk = sgn(E) == 0 ? 0 : sgn(k);  // the sign of k·√E
    if (sk == 0) return sgn(a);
    if (sgn(a) != sk) return sgn(a) > sk ? 1 : -1;
    const int m = cmp(a * a, k * k * E);  // |a| against |k|·√E
    return sk > 0 ? m : -m;
}
bool Rules::close_sq(Context& cx, const Q& c, const Q& E) const {
    cx.spend_ops(8, 2 * qsize(c) + qsize(E) + 2 * qsize(tol) + 2 * qsize(abs));
    if (sgn(abs) > 0) return sign_minus_sqrt(c - abs, 1 + tol, E) <= 0 && sign_minus_sqrt(c + abs, 1 - tol, E) >= 0;
    if (sgn(c) < 0) return false;
    const Q lo = 1 - tol, hi = 1 + tol;
    return (sgn(lo) <= 0 || lo * lo * E <= c * c) && c * c <= hi * hi * E;
}
bool Rules::within_above(Context& cx, const Q& x, const Q& E, int apart) const {
    cx.spend_ops(12, qsize(x) + qsize(E) + 2 * qsize(tol) + 2 * qsize(abs));
    const Q k = 1 + tol;
    if (sgn(abs) == 0) return E <= x && x <= k * k * E;
    const Q m = apart * abs;  // √x <= k√E + m: x <= k²E + m² + 2km√E
    return sign_minus_sqrt(x - k * k * E - m * m, 2 * k * m, E) <= 0;
}
bool Rules::close_signed(Context& cx, const Q& c, int s, const Q& E) const {
    cx.spend_ops(8, 2 * qsize(c) + qsize(E) + 2 * qsize(tol) + 2 * qsize(abs));
    // c − abs − tol√E <= s√E <= c + abs + tol√E
    return sign_minus_sqrt(c - abs, s + tol, E) <= 0 && sign_minus_sqrt(c + abs, s - tol, E) >= 0;
}
bool Rules::close_value(Context& cx, const Q& c, int s, const Q& E, const Q& k) const {
    cx.spend_ops(14, 2 * qsize(c) + qsize(E) + 2 * qsize(k) + 2 * qsize(tol) + 2 * qsize(abs));
    // With σ the sign of x = k + s√E, |x| = σx, and |c − x| <= abs + tol·σx is two bounds on x,
    // each of the form a + b√E <= 0 with t = tol·σ:
    //   c − x <= abs + t·x:  (c − abs − (1 + t)k) − (1 + t)s√E <= 0
    //   x − c <= abs + t·x:  ((1 − t)k − c − abs) + (1 − t)s√E <= 0
    const Q t = tol * sign_minus_sqrt(k, Q(-s), E), up = 1 + t, down = 1 - t;
    return sign_minus_sqrt(c - abs - up * k, up * s, E) <= 0 && sign_minus_sqrt(down * k - c - abs, -down * s, E) <= 0;
}
int sign_two_roots(const Q& a, const Q& b, const Q& A, const Q& c, const Q& E) {
    const int u = sign_minus_sqrt(a, -b, A);  // the sign of u = a + b√A
    const int v = sgn(E) == 0 ? 0 : sgn(c);   // the sign of v = c√E
    if (u == 0) return v;
    if (v == 0 || u == v) return u;
    // Opposite signs: u + v has the sign of the larger in magnitude, and
    // u² − v² = (a² + b²A − c²E) + 2ab√A.
    const int d = sign_minus_sqrt(a * a + b * b * A - c * c * E, -2 * a * b, A);
    return d == 0 ? 0 : d > 0 ? u : v;
}
bool Rules::within_abs(Context& cx, const Q& x, const Q& N) const {
    cx.spend_ops(6, qsize(x) + qsize(N) + 2 * qsize(abs));
    return sign_minus_sqrt(x, abs, N) <= 0;
}

Rules read_rules(Context& cx, const J& c) {
    Rules R{num(cx, at(c, "tolerance"), "tolerance"), 0};
    cx.claim(sgn(R.tol) >= 0, "tolerance is >= 0");
    if (c.contains("abs_tolerance")) {
        R.abs = num(cx, at(c, "abs_tolerance"), "abs_tolerance");
        cx.claim(sgn(R.abs) > 0, "abs_tolerance, when given, is > 0 (a file judged exactly has none)");
    }
    return R;
}

namespace {
std::string tolerance_shown(const Q& tol) {
    const std::string t = tol.get_str();
    if (t.size() <= 40) return t;
    char b[64];
    std::snprintf(b, sizeof b, "%.6g", nearest(tol));
    return std::string("~") + b + " (an exact fraction of " + std::to_string(t.size()) + " characters)";
}
}  // namespace

std::string judged(size_t rights, size_t total, const Rules& R) {
    return std::to_string(rights) + " right, " + std::to_string(total - rights) + " wrong, tolerance " +
           tolerance_shown(R.tol) + (sgn(R.abs) > 0 ? ", abs_tolerance " + tolerance_shown(R.abs) : "");
}

double vsize(const V3& v) { return std::max({qsize(v[0]), qsize(v[1]), qsize(v[2])}); }

V3 integral(const V3& n, mpz_class* scale) {
    mpz_class L = 1;
    for (const Q& c : n) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), c.get_den_mpz_t());
    *scale = L;
    return {n[0] * L, n[1] * L, n[2] * L};
}

Q positive(Context& cx, const J& o, const char* key, const std::string& where) {
    const Q q = num(cx, at(o, key), where + "." + key);
    cx.claim(sgn(q) > 0, where + "." + key + " is > 0");
    return q;
}

V3 nonzero_vector(Context& cx, const J& j, const std::string& where) {
    const V3 n = point(cx, j, where);
    cx.claim(nonzero(n), where + " is nonzero");
    return n;
}

// With u = L n integral: max over the vertices of u·(v − s_i), over D* (support_at), then over L.
Q reach(Context& cx, const Scene& sc, int i, const V3& n, const Q& rho) {
    cx.spend_ops(12, vsize(n) + vsize(sc.s[i]) + qsize(rho) + 2 * limbs(sc.Dj));
    mpz_class L;
    const Z3 u = ints(integral(n, &L));
    const std::vector<int> best = sc.scan[i]->argmax(cx, u);
    Q h(sc.support_at(cx, i, u, best[0]), sc.Dj * L);
    h.canonicalize();
    return dot(n, sc.s[i]) + rho * h;
}

Q reach_min(Context& cx, const Scene& sc, int i, const V3& n, const Q& rho) {
    return -reach(cx, sc, i, {-n[0], -n[1], -n[2]}, rho);
}

V3 body_point(Context& cx, const Scan& P, const V3& s, const Q& rho, const J& w, const std::string& where,
              std::vector<int>* used) {
    const std::array<Q, 3> c = combination(cx, P, w, where, used);
    cx.spend_ops(12, vsize(s) + qsize(rho) + std::max({qsize(c[0]), qsize(c[1]), qsize(c[2])}) + limbs(P.D()));
    const Q D(P.D());
    V3 x;
    for (int k = 0; k < 3; ++k) x[k] = s[k] + rho * (c[k] / D - s[k]);
    return x;
}

bool near_enough(Context& cx, const V3& x, const V3& y, const Q& abs, const std::string& where) {
    cx.spend_ops(8, vsize(x) + vsize(y) + 2 * qsize(abs));
    const V3 d = {x[0] - y[0], x[1] - y[1], x[2] - y[2]};
    cx.claim(dot(d, d) <= abs * abs, where + ".near combines to a point within abs_tolerance of the point");
    return true;
}

void beyond(Context& cx, const V3& n, const V3& x, const Q& h, const Q& abs, const std::string& where) {
    if (sgn(abs) == 0) {
        cx.spend_ops(3, vsize(n) + vsize(x));
        const Q gap = dot(n, x) - h;
        cx.claim(sgn(gap) > 0, where + ": the point lies strictly beyond the body's extent along the normal");
        return;
    }
    cx.spend_ops(8, vsize(n) + vsize(x) + qsize(h) + 2 * qsize(abs));
    const Q gap = dot(n, x) - h;
    cx.claim(sgn(gap) > 0 && gap * gap > abs * abs * dot(n, n),
             where + ": the point lies more than abs_tolerance beyond the body's extent along the normal");
}

void check_claimed_verdict(Context& cx, const std::string& c, const std::string& wc) {
    cx.claim(c == "separated" || c == "touching" || c == "overlapping" || c == "intersecting" || c == "not_overlapping",
             wc + ".verdict is separated, touching, overlapping, intersecting or not_overlapping");
}

bool judge_separating_plane(Context& cx, const Bodies& B, const Rules& R, const Judgement& j) {
    const J &cl = j.claim, &pr = j.proof;
    const std::string &wc = j.wc, &wp = j.wp;
    shape(cx, cl, wc, {"kind", "rho1", "rho2", "normal"}, {"offset"});
    cx.claim(pr.empty(), wp + " is empty (the checker computes the extents)");
    const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
    const V3 n = nonzero_vector(cx, at(cl, "normal"), wc + ".normal");
    const Q c1 = B.reach(cx, 0, n, r1), c2 = B.reach_min(cx, 1, n, r2);
    const std::optional<Q> d =
        cl.contains("offset") ? std::optional<Q>(num(cx, at(cl, "offset"), wc + ".offset")) : std::nullopt;
    if (sgn(R.abs) == 0) return c1 < c2 && (!d || (c1 < *d && *d < c2));
    // Each body within abs of its side: c1 − d <= abs·|n| and d − c2 <= abs·|n| (with no offset,
    // for some d: c1 − c2 <= 2·abs·|n|).
    const Q N = dot(n, n);
    if (!d) return R.within_abs(cx, c1 - c2, 4 * N);
    return R.within_abs(cx, c1 - *d, N) && R.within_abs(cx, *d - c2, N);
}

bool judge_witness_point(Context& cx, const Bodies& B, const Judgement& j) {
    const J &cl = j.claim, &pr = j.proof;
    const std::string &wc = j.wc, &wp = j.wp;
    shape(cx, cl, wc, {"kind", "rho1", "rho2", "point"});
    shape(cx, pr, wp, {"P1", "P2"});
    const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
    const V3 x = point(cx, at(cl, "point"), wc + ".point");
    const bool in1 = B.member(cx, 0, r1, x, at(pr, "P1"), wp + ".P1"),
               in2 = B.member(cx, 1, r2, x, at(pr, "P2"), wp + ".P2");
    return in1 && in2;
}

Closest closest_points(Context& cx, const Bodies& B, const Judgement& j, const Q& r1, const Q& r2) {
    const std::string &wc = j.wc, &wp = j.wp;
    const J& cp = at(j.claim, "closest");
    cx.claim(cp.is_array() && cp.size() == 2, wc + ".closest is [point, point]");
    const V3 a = point(cx, cp[0], wc + ".closest[0]"), b = point(cx, cp[1], wc + ".closest[1]");
    const J& pc = at(j.proof, "closest");
    shape(cx, pc, wp + ".closest", {"P1", "P2"});
    const bool in1 = B.member(cx, 0, r1, a, at(pc, "P1"), wp + ".closest.P1"),
               in2 = B.member(cx, 1, r2, b, at(pc, "P2"), wp + ".closest.P2");
    return {a, b, in1 && in2};
}
void check_no_answer(Context& cx, const Judgement& j) {
    shape(cx, j.proof, j.wp, {"no_answer"});
    cx.claim(at(j.proof, "no_answer").is_string(), j.wp + ".no_answer is a string");
    const std::string f = at(j.proof, "no_answer").get<std::string>();
    static const std::map<std::string, std::set<std::string>> answers = {
        {"growth_distance", {"value"}},
        {"curve_point", {"rho2"}},
        {"switch_point", {"rho1", "rho2"}},
        {"separating_plane", {"normal", "offset"}},
        {"witness_point", {"point"}},
        {"distance", {"value", "closest"}},
        {"penetration_depth", {"value", "direction"}},
        {"signed_distance", {"value", "at_least", "below"}}};
    const auto k = answers.find(j.kind);
    cx.claim(k != answers.end() && k->second.count(f) == 1,
             j.wp + ".no_answer names a field where a " + j.kind + " claim answers");
    // The rest of the claim is a claim of its kind, as certify-fp writes it: its fields only, and
    // the scalings it was asked at exact numbers > 0 (the judgement is wrong either way, but the
    // file states no claim certify-fp could not have judged).
    static const std::map<std::string, std::set<std::string>> fields = {
        {"growth_distance", {"kind", "value"}},
        {"curve_point", {"kind", "rho1", "rho2"}},
        {"switch_point", {"kind", "rho1", "rho2", "contact"}},
        {"separating_plane", {"kind", "rho1", "rho2", "normal", "offset", "pose1", "pose2"}},
        {"witness_point", {"kind", "rho1", "rho2", "point", "pose1", "pose2"}},
        {"distance", {"kind", "rho1", "rho2", "value", "closest", "pose1", "pose2"}},
        {"penetration_depth", {"kind", "rho1", "rho2", "parts", "value", "direction", "pose1", "pose2"}},
        {"signed_distance", {"kind", "rho1", "rho2", "value", "at_least", "below", "pose1", "pose2"}}};
    const auto kf = fields.find(j.kind);
    cx.claim(kf != fields.end(), j.wc + ".kind is a kind with answers");
    const std::set<std::string>& known = kf->second;
    cx.claim(j.claim.is_object(), j.wc + " is an object");
    for (const auto& [key, value] : j.claim.items())
        cx.claim(known.count(key) == 1, j.wc + "." + key + " is a field of a " + j.kind + " claim");
    for (const char* r : {"rho1", "rho2"})
        if (known.count(r) && f != r) positive(cx, j.claim, r, j.wc);
    if (j.claim.contains("pose1") || j.claim.contains("pose2")) {
        J bare;
        claim_poses(cx, j.claim, j.wc, bare);  // poses as a judged claim's: exact, R nonsingular
    }
    cx.claim(j.claim.contains(f), j.wc + " has the field " + f);
    const J& v = j.claim[f];
    if (v.is_null()) return;
    const std::string wf = j.wc + "." + f;
    cx.claim(f == "normal" || f == "direction", wf + " is null");
    cx.claim(v.is_array() && v.size() == 3, wf + " is null or three zeros");
    for (const J& x : v) cx.claim(sgn(num(cx, x, wf)) == 0, wf + " is null or three zeros");
}
namespace {
// h_M(n) = max over P1(r1) of n·x − min over P2(r2) of n·y: the depth along n times |n| (< 0: the
// plane separates).
Q hM(Context& cx, const Scene& sc, const V3& n, const Q& r1, const Q& r2) {
    return reach(cx, sc, 0, n, r1) + reach(cx, sc, 1, {-n[0], -n[1], -n[2]}, r2);
}

// A closed surface of triangles over points of the Minkowski difference P1(r1) − P2(r2), each
// triangle's plane at least sqrt(E) from the origin, which it has on its inner side. The radial
// projection of such a surface covers every direction (its degree is its total solid angle over
// 4π, > 0 as every triangle's is), so along every unit u some point t·u of it, hence of the
// difference, has t >= sqrt(E): the depth is at least sqrt(E).
void check_lower_bound(Context& cx, const Scene& sc, const Q& r1, const Q& r2, const Q& E, const J& proof,
                       const std::string& where) {
    const J& pts = at(proof, "points");
    const J& tris = at(proof, "triangles");
    cx.claim(pts.is_array() && pts.size() >= 4, where + ".points has at least 4 points");
    cx.claim(tris.is_array() && tris.size() >= 4, where + ".triangles has at least 4 triangles");
    // In integers, so that no point or triangle pays for the seeds' digits more than once: a point
    // of M is z = c0 + y with c0 = (1 − r1) s1 − (1 − r2) s2 (the same for all) and y = r1 v − r2 w.
    // Over Dy = lcm(b1 D1, b2 D2) (r_i = a_i/b_i, D_i the vertices' common denominator, X = D_i v):
    // Y = Dy y = k1 X_v − k2 X_w, k_i = a_i Dy/(b_i D_i). A triangle's N = (Y_b − Y_a) × (Y_c − Y_a)
    // is Dy² times the true one (c0 cancels), and with c0 = C/Dc its offset N·(c0 + y_a) is
    // N·W_a/(Dy³ Dc), W_a = Dy C + Dc Y_a. So off > 0 iff N·W_a > 0, and off² >= E |N|² iff
    // q (N·W_a)² >= p Dy² Dc² |N|² for E = p/q. Counted before each product, by its operands' limbs.
    auto prod = [](double la, double lb) { return 2 + la * lb; };
    const mpz_class b1 = r1.get_den(), b2 = r2.get_den();
    cx.spend_ops(
        14, vsize(sc.s[0]) + vsize(sc.s[1]) + qsize(r1) + qsize(r2) + limbs(sc.scan[0]->D()) + limbs(sc.scan[1]->D()));
    mpz_class Dy, d1 = b1 * sc.scan[0]->D(), d2 = b2 * sc.scan[1]->D();
    mpz_lcm(Dy.get_mpz_t(), d1.get_mpz_t(), d2.get_mpz_t());
    const mpz_class k1 = r1.get_num() * (Dy / d1), k2 = r2.get_num() * (Dy / d2);
    V3 c0;
    for (int c = 0; c < 3; ++c) c0[c] = (1 - r1) * sc.s[0][c] - (1 - r2) * sc.s[1][c];
    mpz_class Dc = 1;
    for (const Q& c : c0) mpz_lcm(Dc.get_mpz_t(), Dc.get_mpz_t(), c.get_den_mpz_t());
    Z3 DyC;
    for (int c = 0; c < 3; ++c) DyC[c] = Dy * (c0[c].get_num() * (Dc / c0[c].get_den()));
    const mpz_class T = E.get_num() * Dy * Dy * Dc * Dc, q = E.get_den();
    const double lk = std::max(limbs(k1), limbs(k2)), lDc = limbs(Dc),
                 lDyC = std::max({limbs(DyC[0]), limbs(DyC[1]), limbs(DyC[2])});
    cx.spend(50 * (lDyC + 1) * (limbs(E.get_num()) + 4 * limbs(Dy) + 2 * lDc + 1));
    std::vector<Z3> Y, W;
    std::vector<double> yl, wl;
    for (size_t k = 0; k < pts.size(); ++k) {
        const std::string w = where + ".points[" + std::to_string(k) + "]";
        cx.claim(pts[k].is_array() && pts[k].size() == 2, w + " is [vertex of P1, vertex of P2]");
        const size_t a = index(cx, pts[k][0], sc.count(0), w), b = index(cx, pts[k][1], sc.count(1), w);
        const Z3 &Xa = sc.scan[0]->X(a), &Xb = sc.scan[1]->X(b);
        double lx = 0;
        for (int c = 0; c < 3; ++c) lx = std::max({lx, limbs(Xa[c]), limbs(Xb[c])});
        cx.spend(100 + 6 * prod(lk, lx) + 3 * prod(lDc, lk + lx + 1));
        Z3 y, wv;
        double ly = 0, lw = 0;
        for (int c = 0; c < 3; ++c) {
            y[c] = k1 * Xa[c] - k2 * Xb[c];
            wv[c] = DyC[c] + Dc * y[c];
            ly = std::max(ly, limbs(y[c]));
            lw = std::max(lw, limbs(wv[c]));
        }
        Y.push_back(std::move(y));
        W.push_back(std::move(wv));
        yl.push_back(ly);
        wl.push_back(lw);
    }
    const double lT = limbs(T), lq = limbs(q);
    std::map<std::pair<size_t, size_t>, int> edges;
    for (size_t t = 0; t < tris.size(); ++t) {
        const std::string w = where + ".triangles[" + std::to_string(t) + "]";
        cx.claim(tris[t].is_array() && tris[t].size() == 3, w + " is 3 point indices");
        size_t v[3];
        for (int k = 0; k < 3; ++k) v[k] = index(cx, tris[t][k], Y.size(), w);
        const double ly = 1 + std::max({yl[v[0]], yl[v[1]], yl[v[2]]}), ln = 2 * ly + 1, lnw = ln + wl[v[0]] + 1;
        cx.spend(200 + 6 * prod(ly, ly) + 3 * prod(ln, wl[v[0]]) + prod(lnw, lnw) + prod(lq, 2 * lnw) +
                 3 * prod(ln, ln) + prod(lT, 2 * ln + 2));
        Z3 e1, e2;
        for (int c = 0; c < 3; ++c) e1[c] = Y[v[1]][c] - Y[v[0]][c], e2[c] = Y[v[2]][c] - Y[v[0]][c];
        const Z3 N = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        const mpz_class off = dotz(N, W[v[0]]);
        cx.claim(sgn(off) > 0, w + " has the origin strictly on its inner side");
        cx.claim(q * off * off >= T * dotz(N, N), w + "'s plane lies at least the depth from the origin");
        for (int k = 0; k < 3; ++k)
            cx.claim(++edges[{v[k], v[(k + 1) % 3]}] == 1, w + ": each directed edge is used once");
    }
    for (const auto& [e, n] : edges)
        cx.claim(edges.count({e.second, e.first}) == 1,
                 where + ".triangles form a closed surface (every edge is shared with opposite orientation)");
}

}  // namespace

// A penetration depth (FORMAT.md, "A judgements file"), judged on the bodies B: {"separated": n}
// (a claim of depth on a separated pair is wrong), a touching pair's supporting plane and common
// point, or an overlapping pair's depth along its direction and the exact EPA's closed surface
// (check_lower_bound). c the claimed value, dir the claimed direction if any.
std::optional<Q> proved_depth(Context& cx, const Scene& sc, const J& pr, const std::string& wp, const Q& r1,
                              const Q& r2) {
    if (pr.contains("separated")) {
        shape(cx, pr, wp, {"separated"});
        const V3 n = normal(cx, at(pr, "separated"), wp + ".separated");
        cx.claim(sgn(hM(cx, sc, n, r1, r2)) < 0, wp + ".separated: the plane separates the pair strictly");
        return std::nullopt;
    }
    Q E;
    if (pr.contains("common")) {
        shape(cx, pr, wp, {"squared", "direction", "common"});
        cx.claim(num(cx, at(pr, "squared"), wp + ".squared") == 0, wp + ".squared is 0 for a touching pair");
        const V3 n = normal(cx, at(pr, "direction"), wp + ".direction");
        cx.claim(sgn(hM(cx, sc, n, r1, r2)) == 0, wp + ".direction: the plane supports both bodies");
        const J& cm = at(pr, "common");
        shape(cx, cm, wp + ".common", {"P1", "P2"});
        cx.claim(body_point(cx, sc, 0, r1, at(cm, "P1"), wp + ".common.P1") ==
                     body_point(cx, sc, 1, r2, at(cm, "P2"), wp + ".common.P2"),
                 wp + ".common is a point of both bodies");
        E = 0;
    } else {
        shape(cx, pr, wp, {"squared", "direction", "points", "triangles"});
        E = num(cx, at(pr, "squared"), wp + ".squared");
        cx.claim(sgn(E) > 0, wp + ".squared is > 0");
        const V3 n = normal(cx, at(pr, "direction"), wp + ".direction");
        const Q g = hM(cx, sc, n, r1, r2);
        cx.spend_ops(4, 2 * qsize(g) + qsize(E) + 2 * vsize(n));
        cx.claim(sgn(g) > 0 && g * g == E * dot(n, n), wp + ".direction: the depth along it is sqrt(squared)");
        check_lower_bound(cx, sc, r1, r2, E, pr, wp);
    }
    return E;
}

bool judge_depth(Context& cx, const Scene& sc, const Rules& R, const J& pr, const std::string& wp, const Q& r1,
                 const Q& r2, const Q& c, const std::optional<V3>& dir) {
    const std::optional<Q> depth = proved_depth(cx, sc, pr, wp, r1, r2);
    if (!depth) return false;  // a depth claimed of a separated pair
    const Q& E = *depth;
    bool right = R.close_sq(cx, c, E);
    if (dir) {
        const Q g = hM(cx, sc, *dir, r1, r2);
        cx.spend_ops(4, 2 * qsize(g) + 2 * vsize(*dir));
        Q along = g * g / dot(*dir, *dir);
        if (sgn(g) < 0) along = -along;
        right = right && R.within_above(cx, along, E);
    }
    return right;
}

// The closest points p, q and the slab between them (judging.hpp).
Q proved_distance_sq(Context& cx, const Scene& sc, const J& pr, const std::string& wp, const Q& r1, const Q& r2) {
    const Q E = num(cx, at(pr, "squared"), wp + ".squared");
    const V3 p = body_point(cx, sc, 0, r1, at(pr, "P1"), wp + ".P1"),
             q = body_point(cx, sc, 1, r2, at(pr, "P2"), wp + ".P2");
    cx.spend_ops(12, 2 * (vsize(p) + vsize(q)) + qsize(E));
    const V3 u = sub(q, p);
    cx.claim(dot(u, u) == E, wp + ".squared is |q − p|² of its closest points");
    if (sgn(E) > 0) {
        cx.claim(reach(cx, sc, 0, u, r1) == dot(u, p), wp + ": no point of P1 lies beyond p along q − p");
        cx.claim(reach_min(cx, sc, 1, u, r2) == dot(u, q), wp + ": no point of P2 lies before q along q − p");
    }
    return E;
}

}  // namespace scalecert_check
