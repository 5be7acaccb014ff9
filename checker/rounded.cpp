// Judgements on objects with a radius (rounded.hpp): each proof is one about the hulls, in the
// forms judgements.cpp checks (a distance proof, a depth proof), and each rule of CLAIMS.md's table
// compares a number of the form a + b·√E (or with two roots) exactly, by squaring with signs.
#include "rounded.hpp"

#include "judging.hpp"
#include "json.hpp"
#include "numbers.hpp"
#include "parts.hpp"
#include "scene.hpp"

#include <optional>

namespace scalecert_check {
namespace {
// Is x in object i at rho: within m = rho·r_i of its scaled hull C_i(rho), or within abs more?
// Proved by {"within": weights}, whose point p = s + rho (Σ w v − s) of the hull has |x − p| <= m;
// at abs > 0 by {"near": weights}, |x − p| <= m + abs; or by {"out": n}, with
// n·x − max over C_i(rho) of n·y > (m + abs)·|n|: every point of the hull is farther than m + abs
// from x. Compared in squares (m + abs >= 0).
bool in_object(Context& cx, const Scene& sc, int i, const Q& rho, const V3& x, const J& p, const std::string& where,
               const Q& abs) {
    const bool near = sgn(abs) > 0 && p.is_object() && p.contains("near");
    cx.claim(p.is_object() && p.size() == 1 && (p.contains("within") || p.contains("out") || near),
             where + (sgn(abs) > 0 ? " is {\"within\": weights}, {\"near\": weights} or {\"out\": normal}"
                                   : " is {\"within\": weights} or {\"out\": normal}"));
    const Q m = rho * sc.r[i];
    if (p.contains("out")) {
        const V3 n = normal(cx, at(p, "out"), where + ".out");
        const Q h = reach(cx, sc, i, n, rho);
        cx.spend_ops(12, 2 * vsize(n) + vsize(x) + qsize(h) + 2 * qsize(m) + 2 * qsize(abs));
        cx.claim(sign_minus_sqrt(dot(n, x) - h, m + abs, dot(n, n)) > 0,
                 where + ".out: the point lies more than rho·radius" + (sgn(abs) > 0 ? " + abs_tolerance" : "") +
                     " beyond the hull's extent along the normal");
        return false;
    }
    const char* key = near ? "near" : "within";
    const V3 y = body_point(cx, sc, i, rho, at(p, key), where + "." + key);
    const Q far = near ? m + abs : m;
    cx.spend_ops(8, vsize(x) + vsize(y) + 2 * qsize(far));
    const V3 d = sub(x, y);
    cx.claim(dot(d, d) <= far * far, where + "." + key + " combines to a point within rho·radius" +
                                         (near ? " + abs_tolerance" : "") + " of the point");
    return true;
}

// The hulls' signed distance s·√E at (r1, r2) (s = 1 apart, 0 touching, −1 overlapping).
struct Signed {
    int s;
    Q E;
};
// By the proof {"distance": a distance proof} of a squared distance E > 0 (apart), or {"depth": a
// depth proof} of a touching pair (E = 0) or of an overlapping one (E the squared depth). A depth
// proof's {"separated": n} shows the hulls apart but not how far, which the radii need: refused.
Signed hulls(Context& cx, const Scene& sc, const J& pr, const std::string& wp, const Q& r1, const Q& r2) {
    if (pr.contains("distance")) {
        shape(cx, pr, wp, {"distance"});
        const J& d = at(pr, "distance");
        shape(cx, d, wp + ".distance", {"squared", "P1", "P2"});
        const Q E = proved_distance_sq(cx, sc, d, wp + ".distance", r1, r2);
        cx.claim(sgn(E) > 0, wp + ".distance proves the hulls apart (squared > 0)");
        return {1, E};
    }
    shape(cx, pr, wp, {"depth"});
    const J& d = at(pr, "depth");
    cx.claim(!d.contains("separated"),
             wp + ".depth is a touching or overlapping pair's (hulls apart take a distance proof: the radii need "
                  "how far apart they are)");
    const std::optional<Q> E = proved_depth(cx, sc, d, wp + ".depth", r1, r2);
    return {sgn(*E) == 0 ? 0 : -1, *E};
}

// The pair's state: the objects are D − R apart, D = √E the hulls' distance. Hulls that overlap
// make the objects overlap; hulls that touch make them overlap when R > 0 (a ball of radius > 0
// about a common point lies in one object and meets the other's interior) and touch when R = 0
// (two parts of radius 0).
std::string pair_state(Context& cx, const Signed& h, const Q& R) {
    if (h.s < 0 || (h.s == 0 && sgn(R) > 0)) return "overlapping";
    if (h.s == 0) return "touching";
    cx.spend_ops(2, qsize(h.E) + 2 * qsize(R));
    const int c = cmp(h.E, R * R);
    return c > 0 ? "separated" : c == 0 ? "touching" : "overlapping";
}

// Numbers a + b√c of Q(√c), c the proof's natural number.
struct Root {
    Q a, b;
};
Root operator+(const Root& x, const Root& y) { return {x.a + y.a, x.b + y.b}; }
Root operator-(const Root& x, const Root& y) { return {x.a - y.a, x.b - y.b}; }
Root times(const Root& x, const Root& y, const Q& c) { return {x.a * y.a + x.b * y.b * c, x.a * y.b + x.b * y.a}; }
int sign_of(const Root& x, const Q& c) { return sign_minus_sqrt(x.a, -x.b, c); }
using RV = std::array<Root, 3>;

// The growth distance ρ* (CLAIMS.md, "Objects with a radius"). The proof's `value` {a, b, c} is
// ρ* = a + b√c (c a natural number, not a perfect square unless b = c = 0). ρ* = 0: the seeds
// coincide. Else, with t = 1/ρ*, d = s2 − s1 and K = (C1 − s1) − (C2 − s2): `P1` and `P2` are
// weights [k, a, b] (a + b√c >= 0, summing to 1) of points q1 of C1 and q2 of C2, so
// q = (q1 − s1) − (q2 − s2) is a point of K; n = t·d − q has |n|² = (r1 + r2)², and every vertex
// v of P1 has n·v <= n·q1 and every vertex w of P2 n·w >= n·q2, so K lies in n·k <= n·q: q is
// the point of K nearest t·d, which is r1 + r2 from K. g(t) = dist(t·d, K) is convex with
// g(0) < r1 + r2 (the seeds are interior: seed_interior), so t is the one t > 0 at which it
// reaches r1 + r2: for ρ < ρ* the pair (ρ, ρ) is separated, at ρ* touching, beyond it overlapping.
Root checked_growth(Context& cx, const Scene& sc, const J& pr, const std::string& wp, Q& c) {
    shape(cx, pr, wp, {"value"}, {"P1", "P2"});
    const J& v = at(pr, "value");
    shape(cx, v, wp + ".value", {"a", "b", "c"});
    const Root rho{num(cx, at(v, "a"), wp + ".value.a"), num(cx, at(v, "b"), wp + ".value.b")};
    c = num(cx, at(v, "c"), wp + ".value.c");
    cx.spend_ops(4, 2 * qsize(rho.a) + 2 * qsize(rho.b) + 2 * qsize(c));
    cx.claim(sgn(c) >= 0 && c.get_den() == 1, wp + ".value.c is a natural number");
    cx.claim((sgn(rho.b) == 0) == (sgn(c) == 0), wp + ".value: b and c are 0 together");
    cx.claim(sgn(c) == 0 || !mpz_perfect_square_p(c.get_num_mpz_t()), wp + ".value.c is not a perfect square");
    const V3 d = sub(sc.s[1], sc.s[0]);
    if (sgn(rho.a) == 0 && sgn(rho.b) == 0) {
        cx.claim(!nonzero(d), wp + ".value is 0 only where the seeds coincide");
        cx.claim(!pr.contains("P1") && !pr.contains("P2"), wp + " of a growth distance 0 is its value alone");
        return rho;
    }
    cx.claim(pr.contains("P1") && pr.contains("P2"), wp + " has P1 and P2 (the weights of the nearest point)");
    cx.claim(nonzero(d), wp + ": the seeds differ (else the growth distance is 0)");
    cx.claim(sign_of(rho, c) > 0, wp + ".value is > 0");
    // t = 1/ρ* = (a − b√c)/(a² − b²c): c is no perfect square, so a² − b²c != 0.
    const Q den = rho.a * rho.a - rho.b * rho.b * c;
    const Root t{rho.a / den, -rho.b / den};
    RV q1, q2;
    for (int i = 0; i < 2; ++i) {
        const std::string w = wp + "." + kPoly[i];
        const J& ws = at(pr, kPoly[i]);
        cx.claim(ws.is_array() && !ws.empty(), w + " is a nonempty list of [index, a, b]");
        RV& o = i == 0 ? q1 : q2;
        o = {Root{}, Root{}, Root{}};
        Root sum{};
        std::vector<bool> seen(sc.count(i), false);
        for (size_t k = 0; k < ws.size(); ++k) {
            const std::string wk = w + "[" + std::to_string(k) + "]";
            const J& e = ws[k];
            cx.claim(e.is_array() && e.size() == 3, wk + " is [index, a, b]");
            const size_t idx = index(cx, e[0], sc.count(i), wk + "[0]");
            cx.claim(!seen[idx], wk + "[0] is named once");
            seen[idx] = true;
            const Root x{num(cx, e[1], wk + "[1]"), num(cx, e[2], wk + "[2]")};
            cx.spend_ops(12, 4 * (qsize(x.a) + qsize(x.b) + qsize(c)) + limbs(sc.scan[i]->D()));
            cx.claim(sign_of(x, c) >= 0, wk + " is a weight >= 0");
            sum = sum + x;
            const Z3 X = sc.scan[i]->X(idx);
            const Q D(sc.scan[i]->D());
            for (int a = 0; a < 3; ++a) o[a] = o[a] + Root{x.a * X[a] / D, x.b * X[a] / D};
        }
        cx.claim(sum.a == 1 && sgn(sum.b) == 0, w + ": the weights sum to 1");
    }
    // n = t·d − q, q = (q1 − s1) − (q2 − s2).
    RV n;
    Root nn{};
    for (int a = 0; a < 3; ++a) {
        const Root qa = (q1[a] - Root{sc.s[0][a], Q(0)}) - (q2[a] - Root{sc.s[1][a], Q(0)});
        n[a] = Root{t.a * d[a], t.b * d[a]} - qa;
        nn = nn + times(n[a], n[a], c);
    }
    const Q R0 = sc.r[0] + sc.r[1];
    cx.spend_ops(20, 4 * (qsize(nn.a) + qsize(nn.b) + qsize(R0)));
    cx.claim(nn.a == R0 * R0 && sgn(nn.b) == 0, wp + ": |t·d − q|² is (r1 + r2)², t = 1/value");
    // Every vertex on q's side: max over P1 of n·v is n·q1, min over P2 of n·w is n·q2 (in D_i·n·v).
    for (int i = 0; i < 2; ++i) {
        const Q D(sc.scan[i]->D());
        Root h{};
        const RV& qi = i == 0 ? q1 : q2;
        for (int a = 0; a < 3; ++a) h = h + times(n[a], qi[a], c);
        h = Root{h.a * D, h.b * D};
        for (size_t k = 0; k < sc.count(i); ++k) {
            const Z3 X = sc.scan[i]->X(k);
            Root nx{};
            for (int a = 0; a < 3; ++a) nx = nx + Root{n[a].a * X[a], n[a].b * X[a]};
            cx.spend_ops(10, 2 * (qsize(nx.a) + qsize(nx.b) + qsize(h.a) + qsize(h.b) + qsize(c)));
            const int s = sign_of(nx - h, c);
            cx.claim(i == 0 ? s <= 0 : s >= 0,
                     wp + "." + kPoly[i] + ": vertex " + std::to_string(k) +
                         (i == 0 ? " lies beyond n·q1 along n = t·d − q" : " lies below n·q2 along n = t·d − q"));
        }
    }
    return rho;
}
}  // namespace

void check_rounded_seeds(Context& cx, const Scene& sc, const J& j) {
    shape(cx, j, "seed_interior", {"P1", "P2"});
    for (int i = 0; i < 2; ++i) {
        const std::string w = std::string("seed_interior.") + kPoly[i];
        const J& p = at(j, kPoly[i]);
        if (sgn(sc.r[i]) == 0) {  // a polyhedron
            check_seed_weights(cx, sc, i, p, w);
            continue;
        }
        // A point y of the hull with |s − y| < r: the ball of radius r − |s − y| about s lies in
        // the object.
        shape(cx, p, w, {"within"});
        const V3 y = body_point(cx, sc, i, Q(1), at(p, "within"), w + ".within");
        cx.spend_ops(8, vsize(y) + vsize(sc.s[i]) + 2 * qsize(sc.r[i]));
        const V3 d = sub(sc.s[i], y);
        cx.claim(dot(d, d) < sc.r[i] * sc.r[i],
                 w + ".within combines to a point nearer the seed than the radius (the seed is interior)");
    }
}

bool judge_rounded(Context& cx, const Scene& sc, const Rules& R, const Judgement& j) {
    const J &cl = j.claim, &pr = j.proof;
    const std::string &kind = j.kind, &wc = j.wc, &wp = j.wp;
    if (kind == "growth_distance") {  // a scaling: the relative tolerance alone
        shape(cx, cl, wc, {"kind", "value"});
        const Q claimed = num(cx, at(cl, "value"), wc + ".value");
        cx.claim(sgn(claimed) >= 0, wc + ".value is >= 0");
        Q c;
        const Root rho = checked_growth(cx, sc, pr, wp, c);
        const Rules rel{R.tol, Q(0)};
        return rel.close_value(cx, claimed, sgn(rho.b), rho.b * rho.b * c, rho.a);
    }
    // At poses: the same claim on the scene moved by them (the hulls move, the radii stay).
    if (cl.contains("pose1") || cl.contains("pose2")) {
        J bare;
        const std::array<std::optional<Pose>, 2> pose = claim_poses(cx, cl, wc, bare);
        const Scene posed = posed_scene(cx, sc, pose);
        return judge_rounded(cx, posed, R, Judgement{bare, pr, kind, j.where, wc, wp});
    }
    if (kind == "verdict")
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "verdict"});
    else if (kind == "separating_plane")
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "normal"}, {"offset"});
    else if (kind == "witness_point")
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "point"});
    else if (kind == "distance")
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "value"}, {"closest"});
    else if (kind == "penetration_depth")
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "value"}, {"direction"});
    else
        shape(cx, cl, wc, {"kind", "rho1", "rho2"}, {"value", "at_least", "below"});
    const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
    cx.spend_ops(3, qsize(r1) + qsize(r2) + qsize(sc.r[0]) + qsize(sc.r[1]));
    const Q m1 = r1 * sc.r[0], m2 = r2 * sc.r[1], Rr = m1 + m2;  // the radii at (r1, r2), and R
    const Q k = 1 + R.tol;

    if (kind == "verdict") {
        cx.claim(at(cl, "verdict").is_string(), wc + ".verdict is a string");
        const std::string c = at(cl, "verdict").get<std::string>();
        check_claimed_verdict(cx, c, wc);
        return verdict_right(c, pair_state(cx, hulls(cx, sc, pr, wp, r1, r2), Rr));
    }
    if (kind == "separating_plane") {
        // P1 reaches c1 + m1·|n|, P2 starts at c2 − m2·|n|, c1 and c2 the hulls' extents.
        cx.claim(pr.empty(), wp + " is empty (the checker computes the extents)");
        const V3 n = nonzero_vector(cx, at(cl, "normal"), wc + ".normal");
        const Q c1 = reach(cx, sc, 0, n, r1), c2 = reach_min(cx, sc, 1, n, r2), N = dot(n, n);
        std::optional<Q> o;
        if (cl.contains("offset")) o = num(cx, at(cl, "offset"), wc + ".offset");
        cx.spend_ops(12, 2 * (qsize(c1) + qsize(c2) + qsize(N) + qsize(Rr) + qsize(R.abs)) + (o ? qsize(*o) : 0));
        if (sgn(R.abs) == 0) {  // strictly between
            if (!o) return sign_minus_sqrt(c2 - c1, m1 + m2, N) > 0;
            return sign_minus_sqrt(*o - c1, m1, N) > 0 && sign_minus_sqrt(c2 - *o, m2, N) > 0;
        }
        // Each object within abs·|n| of its side (with no offset: for some offset).
        if (!o) return sign_minus_sqrt(c1 - c2, 2 * R.abs - m1 - m2, N) <= 0;
        return sign_minus_sqrt(c1 - *o, R.abs - m1, N) <= 0 && sign_minus_sqrt(*o - c2, R.abs - m2, N) <= 0;
    }
    if (kind == "witness_point") {
        shape(cx, pr, wp, {"P1", "P2"});
        const V3 x = point(cx, at(cl, "point"), wc + ".point");
        const bool in1 = in_object(cx, sc, 0, r1, x, at(pr, "P1"), wp + ".P1", R.abs),
                   in2 = in_object(cx, sc, 1, r2, x, at(pr, "P2"), wp + ".P2", R.abs);
        return in1 && in2;
    }
    if (kind == "distance") {
        const bool closest = cl.contains("closest");
        if (closest)
            shape(cx, pr, wp, {"squared", "P1", "P2", "closest"});
        else
            shape(cx, pr, wp, {"squared", "P1", "P2"});
        const Q c = num(cx, at(cl, "value"), wc + ".value");
        const Q E = proved_distance_sq(cx, sc, pr, wp, r1, r2);
        // The objects are √E − R apart when the hulls are farther apart than R, else they meet (0).
        cx.spend_ops(2, qsize(E) + 2 * qsize(Rr));
        const bool apart = E > Rr * Rr;
        // A length: at abs = 0 one below 0 is wrong, as on plain polyhedra.
        bool right = (sgn(R.abs) > 0 || sgn(c) >= 0) &&
                     (apart ? R.close_value(cx, c, 1, E, -Rr) : R.close_value(cx, c, 0, Q(0), Q(0)));
        if (!closest) return right;
        const J& cp = at(cl, "closest");
        cx.claim(cp.is_array() && cp.size() == 2, wc + ".closest is [point, point]");
        const V3 a = point(cx, cp[0], wc + ".closest[0]"), b = point(cx, cp[1], wc + ".closest[1]");
        const J& pc = at(pr, "closest");
        shape(cx, pc, wp + ".closest", {"P1", "P2"});
        const bool in1 = in_object(cx, sc, 0, r1, a, at(pc, "P1"), wp + ".closest.P1", R.abs),
                   in2 = in_object(cx, sc, 1, r2, b, at(pc, "P2"), wp + ".closest.P2", R.abs);
        cx.spend_ops(30, 2 * (vsize(a) + vsize(b) + qsize(E) + qsize(Rr) + qsize(k) + qsize(R.abs)));
        const V3 ab = sub(b, a);
        const Q x = dot(ab, ab);
        // |b − a| <= k(√E − R) + 2·abs apart: (kR − 2·abs) + √x − k√E <= 0; <= 2·abs when they meet.
        const bool near = apart ? sign_two_roots(k * Rr - 2 * R.abs, 1, x, -k, E) <= 0 : x <= 4 * R.abs * R.abs;
        return right && in1 && in2 && near;
    }
    if (kind == "penetration_depth") {
        const Q c = num(cx, at(cl, "value"), wc + ".value");
        std::optional<V3> dir;
        if (cl.contains("direction")) dir = nonzero_vector(cx, at(cl, "direction"), wc + ".direction");
        const Signed h = hulls(cx, sc, pr, wp, r1, r2);
        if (pair_state(cx, h, Rr) == "separated") return false;  // no depth
        // The depth R − s√E; a length: at abs = 0 one below 0 is wrong.
        bool right = (sgn(R.abs) > 0 || sgn(c) >= 0) && R.close_value(cx, c, -h.s, h.E, Rr);
        if (dir) {
            // Moved along u by t, P2 parts from P1 once t >= t(u) + R, t(u) = h_M(u)/|u| the hulls'
            // signed extent (h_M(u) = g below): right when t(u) + R <= k·(R − s√E) + abs, that is
            // (R − kR − abs) + sign(g)·√(g²/|u|²) + k·s·√E <= 0.
            const V3& u = *dir;
            const Q g = reach(cx, sc, 0, u, r1) - reach_min(cx, sc, 1, u, r2);
            cx.spend_ops(30, 2 * (qsize(g) + vsize(u) + qsize(h.E) + qsize(Rr) + qsize(k) + qsize(R.abs)));
            right = right && sign_two_roots(Rr - k * Rr - R.abs, sgn(g), g * g / dot(u, u), k * h.s, h.E) <= 0;
        }
        return right;
    }
    // signed_distance: x = s√E − R.
    const int given = cl.contains("value") + cl.contains("at_least") + cl.contains("below");
    cx.claim(given == 1, wc + " has one of value, at_least and below");
    const std::string key = cl.contains("value") ? "value" : cl.contains("at_least") ? "at_least" : "below";
    const Q c = num(cx, at(cl, key.c_str()), wc + "." + key);
    const Signed h = hulls(cx, sc, pr, wp, r1, r2);
    if (key == "value") return R.close_value(cx, c, h.s, h.E, -Rr);
    cx.spend_ops(8, 2 * (qsize(c) + qsize(R.abs) + qsize(Rr)) + qsize(h.E));
    if (key == "at_least") return sign_minus_sqrt(c - R.abs + Rr, h.s, h.E) <= 0;  // x >= c − abs
    return sign_minus_sqrt(c + R.abs + Rr, h.s, h.E) > 0;                          // x < c + abs
}

namespace {
// Part k of object i at rho, its box widened by rho·r_k: lo[3], hi[3], from the part's vertices'
// extremes along the axes (a scan each).
std::array<Q, 6> widened_box(Context& cx, const CompoundScene& cs, int i, size_t k, const Q& rho) {
    std::array<Q, 6> b;
    const Q m = rho * cs.r[i][k];
    for (int a = 0; a < 3; ++a) {
        Z3 u{0, 0, 0};
        u[static_cast<size_t>(a)] = 1;
        const Q hi = cs.top(cx, i, u, k, k);
        u[static_cast<size_t>(a)] = -1;
        const Q lo = -cs.top(cx, i, u, k, k);
        const Q& s = cs.s[i][static_cast<size_t>(a)];
        cx.spend_ops(8, 4 * (qsize(s) + qsize(rho) + qsize(m)) + qsize(hi) + qsize(lo));
        b[static_cast<size_t>(a)] = s + rho * (lo - s) - m;
        b[static_cast<size_t>(3 + a)] = s + rho * (hi - s) + m;
    }
    return b;
}
std::array<std::vector<std::array<Q, 6>>, 2> all_widened(Context& cx, const CompoundScene& cs, const Q& r1,
                                                         const Q& r2) {
    std::array<std::vector<std::array<Q, 6>>, 2> out;
    for (int i = 0; i < 2; ++i)
        for (size_t k = 0; k < cs.parts(i); ++k)
            out[static_cast<size_t>(i)].push_back(widened_box(cx, cs, i, k, i ? r2 : r1));
    return out;
}
// The squared distance between two boxes (0 when they meet): a lower bound on their parts'.
Q gap_sq(Context& cx, const std::array<Q, 6>& A, const std::array<Q, 6>& B) {
    Q g = 0;
    for (size_t a = 0; a < 3; ++a) {
        const Q d = B[a] > A[3 + a] ? Q(B[a] - A[3 + a]) : A[a] > B[3 + a] ? Q(A[a] - B[3 + a]) : Q(0);
        cx.spend_ops(4, 4 * qsize(d));
        g += d * d;
    }
    return g;
}
// Every pair (a, b) not `listed` has widened boxes whose squared distance G passes ok(G), tested on
// the objects' boxes (each the box of its parts' widened boxes) first, then on part a's box against
// P2's, then on the pair's: a box holds its parts, so a farther box pair holds for every pair in
// it (ok holds for any G' >= G when it holds for G). A failure names `where`, the pair and what
// its boxes fail to be (`held`).
template <class Ok>
void unlisted_pairs(Context& cx, const CompoundScene& cs, const Q& r1, const Q& r2, const std::vector<bool>& listed,
                    Ok ok, const std::string& where, const char* held) {
    const auto boxes = all_widened(cx, cs, r1, r2);
    std::array<Q, 6> whole[2];
    for (int i = 0; i < 2; ++i) {
        whole[i] = boxes[static_cast<size_t>(i)][0];
        for (const auto& b : boxes[static_cast<size_t>(i)])
            for (size_t a = 0; a < 3; ++a) {
                if (b[a] < whole[i][a]) whole[i][a] = b[a];
                if (b[3 + a] > whole[i][3 + a]) whole[i][3 + a] = b[3 + a];
            }
    }
    if (ok(gap_sq(cx, whole[0], whole[1]))) return;
    for (size_t a = 0; a < cs.parts(0); ++a) {
        if (ok(gap_sq(cx, boxes[0][a], whole[1]))) continue;
        for (size_t b = 0; b < cs.parts(1); ++b) {
            if (listed[a * cs.parts(1) + b]) continue;
            cx.claim(ok(gap_sq(cx, boxes[0][a], boxes[1][b])), where + ": parts " + std::to_string(a) + " and " +
                                                                   std::to_string(b) +
                                                                   ", not listed, have widened boxes " + held);
        }
    }
}

// {"pair": [a, b], "hulls": a hulls proof}: the pair and its hulls' signed distance at (r1, r2).
struct PairProof {
    size_t a, b;
    Signed h;
    Q R;
};
PairProof pair_proof(Context& cx, const CompoundScene& cs, const J& e, const std::string& w, const Q& r1, const Q& r2) {
    shape(cx, e, w, {"pair", "hulls"});
    const J& pj = at(e, "pair");
    cx.claim(pj.is_array() && pj.size() == 2, w + ".pair is [P1 part, P2 part]");
    const size_t a = index(cx, pj[0], cs.parts(0), w + ".pair[0]"), b = index(cx, pj[1], cs.parts(1), w + ".pair[1]");
    const Scene sc = cs.pair(cx, a, b);
    const Signed h = hulls(cx, sc, at(e, "hulls"), w + ".hulls", r1, r2);
    cx.spend_ops(3, 2 * (qsize(r1) + qsize(r2)) + qsize(cs.r[0][a]) + qsize(cs.r[1][b]));
    return {a, b, h, r1 * cs.r[0][a] + r2 * cs.r[1][b]};
}
// Is x in object i at rho? {"part": k, "within" or "near": weights} (in part k, by in_object), or
// {"out": [for each part, {"out": normal}]} (in none).
int member_of(Context& cx, const CompoundScene& cs, int i, const Q& rho, const V3& x, const J& p, const std::string& w,
              const Q& abs) {
    cx.claim(p.is_object(), w + " is an object");
    if (p.contains("out")) {
        shape(cx, p, w, {"out"});
        const J& o = at(p, "out");
        cx.claim(o.is_array() && o.size() == cs.parts(i), w + ".out has an entry for each part");
        for (size_t k = 0; k < o.size(); ++k) {
            const std::string wk = w + ".out[" + std::to_string(k) + "]";
            cx.claim(o[k].is_object() && o[k].contains("out"), wk + " is {\"out\": normal}");
            in_object(cx, i ? cs.pair(cx, 0, k) : cs.pair(cx, k, 0), i, rho, x, o[k], wk, abs);
        }
        return -1;
    }
    cx.claim(p.contains("part"), w + " has part (or out)");
    const size_t k = index(cx, at(p, "part"), cs.parts(i), w + ".part");
    J rest = p;
    rest.erase("part");
    cx.claim(!rest.contains("out"), w + " is in a part (within or near), not out");
    in_object(cx, i ? cs.pair(cx, 0, k) : cs.pair(cx, k, 0), i, rho, x, rest, w, abs);
    return static_cast<int>(k);
}
}  // namespace

bool judge_rounded_parts(Context& cx, const CompoundScene& cs, const Rules& R, const Judgement& j) {
    const J &cl = j.claim, &pr = j.proof;
    const std::string &kind = j.kind, &wc = j.wc, &wp = j.wp;
    if (kind == "penetration_depth" || kind == "signed_distance") {
        // One part pair: the rule of two objects with a radius on its two parts (at the claim's poses).
        cx.claim(cl.contains("parts"), wc + ".parts is present (a contact of one part pair)");
        const J& pj = at(cl, "parts");
        cx.claim(pj.is_array() && pj.size() == 2, wc + ".parts is [P1 part, P2 part]");
        const size_t a = index(cx, pj[0], cs.parts(0), wc + ".parts[0]"),
                     b = index(cx, pj[1], cs.parts(1), wc + ".parts[1]");
        J bare = cl;
        bare.erase("parts");
        return judge_rounded(cx, cs.pair(cx, a, b), R, Judgement{bare, pr, kind, j.where, wc, wp});
    }
    if (cl.contains("pose1") || cl.contains("pose2")) {
        J bare;
        const std::array<std::optional<Pose>, 2> pose = claim_poses(cx, cl, wc, bare);
        return judge_rounded_parts(cx, cs.posed(cx, pose), R, Judgement{bare, pr, kind, j.where, wc, wp});
    }
    if (kind == "verdict")
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "verdict"});
    else if (kind == "separating_plane")
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "normal"}, {"offset"});
    else if (kind == "witness_point")
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "point"});
    else if (kind == "distance")
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "value"}, {"closest"});
    else
        cx.claim(false, wc + ".kind is verdict, separating_plane, witness_point, distance, penetration_depth or "
                             "signed_distance (the claims on parts with radii)");
    const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
    if (kind == "verdict") {
        // Overlapping: one pair that overlaps. Separated or touching: every pair whose widened boxes
        // meet listed, none overlapping (touching: one touching); the others apart by their boxes.
        shape(cx, pr, wp, {"verdict", "pairs"});
        cx.claim(at(pr, "verdict").is_string() && at(cl, "verdict").is_string(), wp + ": verdicts are strings");
        const std::string c = at(cl, "verdict").get<std::string>(), v = at(pr, "verdict").get<std::string>();
        check_claimed_verdict(cx, c, wc);
        cx.claim(v == "separated" || v == "touching" || v == "overlapping",
                 wp + ".verdict is separated, touching or overlapping");
        const J& ps = at(pr, "pairs");
        cx.claim(ps.is_array() && (v != "overlapping" || ps.size() == 1),
                 wp + ".pairs is a list (one pair overlapping)");
        std::vector<bool> listed(cs.parts(0) * cs.parts(1), false);
        bool touching = false;
        for (size_t e = 0; e < ps.size(); ++e) {
            const std::string w = wp + ".pairs[" + std::to_string(e) + "]";
            const PairProof p = pair_proof(cx, cs, ps[e], w, r1, r2);
            const size_t at_ab = p.a * cs.parts(1) + p.b;
            cx.claim(!listed[at_ab], w + ".pair is listed once");
            listed[at_ab] = true;
            const std::string st = pair_state(cx, p.h, p.R);
            if (v == "overlapping") {
                cx.claim(st == "overlapping", w + ": the pair overlaps");
                continue;
            }
            cx.claim(st != "overlapping", w + ": the pair does not overlap");
            cx.claim(v == "touching" || st == "separated", w + ": the pair is separated");
            touching = touching || st == "touching";
        }
        if (v == "touching") cx.claim(touching, wp + ".pairs has a touching pair");
        if (v != "overlapping")
            unlisted_pairs(
                cx, cs, r1, r2, listed, [](const Q& G) { return sgn(G) > 0; }, wp, "apart");
        return verdict_right(c, v);
    }
    if (kind == "separating_plane") {
        // Right for every pair: each part of P1 reaches c1_a + m_a·|n|, each of P2 starts at
        // c2_b − m_b·|n| (c the hulls' extents), compared pair by pair.
        cx.claim(pr.empty(), wp + " is empty (the checker computes the extents)");
        const V3 n = nonzero_vector(cx, at(cl, "normal"), wc + ".normal");
        std::optional<Q> o;
        if (cl.contains("offset")) o = num(cx, at(cl, "offset"), wc + ".offset");
        const Q N = dot(n, n);
        std::vector<std::array<Q, 2>> top(cs.parts(0)), bottom(cs.parts(1));  // {extent, rho·r}
        for (size_t a = 0; a < cs.parts(0); ++a) top[a] = {reach(cx, cs.pair(cx, a, 0), 0, n, r1), r1 * cs.r[0][a]};
        for (size_t b = 0; b < cs.parts(1); ++b)
            bottom[b] = {reach_min(cx, cs.pair(cx, 0, b), 1, n, r2), r2 * cs.r[1][b]};
        for (size_t a = 0; a < top.size(); ++a)
            for (size_t b = 0; b < bottom.size(); ++b) {
                const Q &c1 = top[a][0], &m1 = top[a][1], &c2 = bottom[b][0], &m2 = bottom[b][1];
                cx.spend_ops(12, 2 * (qsize(c1) + qsize(c2) + qsize(N) + qsize(m1) + qsize(m2) + qsize(R.abs)) +
                                     (o ? qsize(*o) : 0));
                bool ok;
                if (sgn(R.abs) == 0)
                    ok = o ? sign_minus_sqrt(*o - c1, m1, N) > 0 && sign_minus_sqrt(c2 - *o, m2, N) > 0
                           : sign_minus_sqrt(c2 - c1, m1 + m2, N) > 0;
                else
                    ok =
                        o ? sign_minus_sqrt(c1 - *o, R.abs - m1, N) <= 0 && sign_minus_sqrt(*o - c2, R.abs - m2, N) <= 0
                          : sign_minus_sqrt(c1 - c2, 2 * R.abs - m1 - m2, N) <= 0;
                if (!ok) return false;
            }
        return true;
    }
    if (kind == "witness_point") {
        shape(cx, pr, wp, {"P1", "P2"});
        const V3 x = point(cx, at(cl, "point"), wc + ".point");
        const int k1 = member_of(cx, cs, 0, r1, x, at(pr, "P1"), wp + ".P1", R.abs),
                  k2 = member_of(cx, cs, 1, r2, x, at(pr, "P2"), wp + ".P2", R.abs);
        return k1 >= 0 && k2 >= 0;
    }
    // distance: the nearest pair's √E − R, every other pair as far (by its hulls, or its widened
    // boxes' distance √G); 0 when the pair meets.
    const bool closest = cl.contains("closest");
    const Q c = num(cx, at(cl, "value"), wc + ".value");
    cx.claim(pr.is_object() && pr.contains("pair") && pr.contains("hulls"), wp + " has pair and hulls");
    const PairProof best = pair_proof(cx, cs, J{{"pair", at(pr, "pair")}, {"hulls", at(pr, "hulls")}}, wp, r1, r2);
    const bool apart = pair_state(cx, best.h, best.R) == "separated";
    if (apart)
        shape(cx, pr, wp, {"pair", "hulls", "others"}, {"closest"});
    else
        shape(cx, pr, wp, {"pair", "hulls"}, {"closest"});
    cx.claim(closest == pr.contains("closest"), wp + ".closest is there exactly when the claim has closest points");
    if (apart) {
        const J& os = at(pr, "others");
        cx.claim(os.is_array(), wp + ".others is a list");
        std::vector<bool> listed(cs.parts(0) * cs.parts(1), false);
        listed[best.a * cs.parts(1) + best.b] = true;
        for (size_t e = 0; e < os.size(); ++e) {
            const std::string w = wp + ".others[" + std::to_string(e) + "]";
            const PairProof p = pair_proof(cx, cs, os[e], w, r1, r2);
            cx.claim(!listed[p.a * cs.parts(1) + p.b], w + ".pair is listed once");
            listed[p.a * cs.parts(1) + p.b] = true;
            cx.spend_ops(30, 2 * (qsize(p.h.E) + qsize(best.h.E) + qsize(p.R) + qsize(best.R)));
            // √E − R >= √E* − R*: (R* − R) + √E − √E* >= 0, the pair apart.
            cx.claim(p.h.s > 0 && sign_two_roots(best.R - p.R, 1, p.h.E, -1, best.h.E) >= 0,
                     w + ": the pair is at least as far apart as the nearest");
        }
        // √G >= √E − R: R + √G − √E >= 0.
        unlisted_pairs(
            cx, cs, r1, r2, listed,
            [&](const Q& G) {
                cx.spend_ops(30, 2 * (qsize(G) + qsize(best.h.E) + qsize(best.R)));
                return sign_two_roots(best.R, 1, G, -1, best.h.E) >= 0;
            },
            wp, "at least the distance apart");
    }
    // A length: at abs = 0 one below 0 is wrong.
    bool right = (sgn(R.abs) > 0 || sgn(c) >= 0) &&
                 (apart ? R.close_value(cx, c, 1, best.h.E, -best.R) : R.close_value(cx, c, 0, Q(0), Q(0)));
    if (!closest) return right;
    const J& cp = at(cl, "closest");
    cx.claim(cp.is_array() && cp.size() == 2, wc + ".closest is [point, point]");
    const V3 a = point(cx, cp[0], wc + ".closest[0]"), b = point(cx, cp[1], wc + ".closest[1]");
    const J& pc = at(pr, "closest");
    shape(cx, pc, wp + ".closest", {"P1", "P2"});
    const bool in1 = member_of(cx, cs, 0, r1, a, at(pc, "P1"), wp + ".closest.P1", R.abs) >= 0,
               in2 = member_of(cx, cs, 1, r2, b, at(pc, "P2"), wp + ".closest.P2", R.abs) >= 0;
    const Q k = 1 + R.tol;
    cx.spend_ops(30, 2 * (vsize(a) + vsize(b) + qsize(best.h.E) + qsize(best.R) + qsize(k) + qsize(R.abs)));
    const V3 ab = sub(b, a);
    const Q x = dot(ab, ab);
    const bool near = apart ? sign_two_roots(k * best.R - 2 * R.abs, 1, x, -k, best.h.E) <= 0 : x <= 4 * R.abs * R.abs;
    return right && in1 && in2 && near;
}
}  // namespace scalecert_check
