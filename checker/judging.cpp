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
Q reach(Context& cx, const Scene& sc, int i, const V3& n, const Q& rho, const std::vector<int>* verts) {
    cx.spend_ops(12, vsize(n) + vsize(sc.s[i]) + qsize(rho) + 2 * limbs(sc.Dj));
    mpz_class L;
    const Z3 u = ints(integral(n, &L));
    // a list of vertices: the list itself, and the scan's gathering through it
    if (verts) cx.spend(5.0 * static_cast<double>(verts->size()));
    const std::vector<int> best = sc.scan[i]->argmax(cx, u, verts);
    Q h(sc.support_at(cx, i, u, best[0]), sc.Dj * L);
    h.canonicalize();
    return dot(n, sc.s[i]) + rho * h;
}

V3 body_point(Context& cx, const Scene& sc, int i, const Q& rho, const J& w, const std::string& where,
              std::vector<int>* used, size_t base, size_t count) {
    const std::array<Q, 3> c = combination(cx, sc, i, w, where, used, base, count);
    cx.spend_ops(
        12, vsize(sc.s[i]) + qsize(rho) + std::max({qsize(c[0]), qsize(c[1]), qsize(c[2])}) + limbs(sc.scan[i]->D()));
    const Q D(sc.scan[i]->D());
    V3 x;
    for (int k = 0; k < 3; ++k) x[k] = sc.s[i][k] + rho * (c[k] / D - sc.s[i][k]);
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
    cx.claim(c == "separated" || c == "touching" || c == "overlapping" || c == "intersecting",
             wc + ".verdict is separated, touching, overlapping or intersecting");
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
    static const std::map<std::string, std::set<std::string>> answers = {{"growth_distance", {"value"}},
                                                                         {"curve_point", {"rho2"}},
                                                                         {"switch_point", {"rho1", "rho2"}},
                                                                         {"separating_plane", {"normal", "offset"}},
                                                                         {"witness_point", {"point"}},
                                                                         {"distance", {"value", "closest"}},
                                                                         {"penetration_depth", {"value", "direction"}}};
    const auto k = answers.find(j.kind);
    cx.claim(k != answers.end() && k->second.count(f) == 1,
             j.wp + ".no_answer names a field where a " + j.kind + " claim answers");
    cx.claim(j.claim.contains(f), j.wc + " has the field " + f);
    const J& v = j.claim[f];
    if (v.is_null()) return;
    const std::string wf = j.wc + "." + f;
    cx.claim(f == "normal" || f == "direction", wf + " is null");
    cx.claim(v.is_array() && v.size() == 3, wf + " is null or three zeros");
    for (const J& x : v) cx.claim(sgn(num(cx, x, wf)) == 0, wf + " is null or three zeros");
}
}  // namespace scalecert_check
