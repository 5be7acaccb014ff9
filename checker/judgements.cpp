// A judgements file (kind "judgements"; certificates/FORMAT.md, "A judgements file"): certify-fp's
// judgements on two convex polytopes, each re-derived from its claim and its proof by CLAIMS.md's
// rules and the file's tolerance; the file's "right" must be the judgement these rules give. The
// scene and its seeds' interior weights are a partition's; a verdict's proof is a query answer's
// certificate (query.cpp), a curve proof is a partition's curve over a window (curve.cpp). A scene
// whose objects carry a radius is judged by rounded.cpp.
#include "curve.hpp"
#include "formats.hpp"
#include "judging.hpp"
#include "json.hpp"
#include "numbers.hpp"
#include "rounded.hpp"
#include "scene.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>

namespace scalecert_check {
namespace {
// Is x in P_i(rho), or within abs of it? Proved by {"in": weights} combining to x; at abs > 0 by
// {"near": weights} combining to a point within abs of x; or by {"out": normal} whose plane x lies
// strictly beyond (at abs > 0: more than abs beyond).
bool member(Context& cx, const Scene& sc, int i, const Q& rho, const V3& x, const J& p, const std::string& where,
            const Q& abs) {
    cx.claim(p.is_object() && p.size() == 1 &&
                 (p.contains("in") || p.contains("out") || (sgn(abs) > 0 && p.contains("near"))),
             where + (sgn(abs) > 0 ? " is {\"in\": weights}, {\"near\": weights} or {\"out\": normal}"
                                   : " is {\"in\": weights} or {\"out\": normal}"));
    if (p.contains("in")) {
        cx.claim(body_point(cx, sc, i, rho, at(p, "in"), where + ".in") == x, where + ".in combines to the point");
        return true;
    }
    if (p.contains("near")) {
        const V3 y = body_point(cx, sc, i, rho, at(p, "near"), where + ".near");
        return near_enough(cx, x, y, abs, where);
    }
    const V3 n = normal(cx, at(p, "out"), where + ".out");
    beyond(cx, n, x, reach(cx, sc, i, n, rho), abs, where + ".out");
    return false;
}

// The two polytopes of the scene, scaled.
class Polytopes : public Bodies {
  public:
    Polytopes(const Scene& sc, const Q& abs) : Bodies(abs), sc_(sc) {}
    Q reach(Context& cx, int i, const V3& n, const Q& rho) const override {
        return scalecert_check::reach(cx, sc_, i, n, rho);
    }
    bool member(Context& cx, int i, const Q& rho, const V3& x, const J& p, const std::string& where) const override {
        return scalecert_check::member(cx, sc_, i, rho, x, p, where, abs);
    }

  private:
    const Scene& sc_;
};

// A curve proof: the exact curve over its window [a, b] (check_curve), 0 <= a < b.
struct Window {
    CurveFacts f;
    Q a, b;
    // f <= 0 at b: nothing touches from b on, so no switch point lies beyond it.
    bool reaches_zero() const { return sgn(f.end_rho2[1]) <= 0; }
};
Window curve_window(Context& cx, const Scene& sc, const J& pr, const std::string& wp) {
    shape(cx, pr, wp, {"rho1", "rho1_double", "pieces", "switch_points", "curve_ends"});
    const std::vector<Q> r = fields(cx, pr, "rho1", 2, wp);
    cx.claim(sgn(r[0]) >= 0 && r[0] < r[1], wp + ".rho1 is a window [a, b] with 0 <= a < b");
    return {check_curve(cx, sc, pr, r[0], r[1], wp + ".", wp + ".rho1"), r[0], r[1]};
}
std::pair<Q, Q> scaling_pair(Context& cx, const J& j, const std::string& where) {
    cx.claim(j.is_array() && j.size() == 2, where + " is [rho1, rho2]");
    const Q x = num(cx, j[0], where), y = num(cx, j[1], where);
    cx.claim(sgn(x) > 0 && sgn(y) > 0, where + " has scalings > 0");
    return {x, y};
}
std::string claimed_contact(Context& cx, const J& o, const std::string& where) {
    const std::string c = contact_string(cx, at(o, "contact"), where + ".contact");
    cx.claim(c.find_first_not_of("VEF") == std::string::npos, where + ".contact is two of V, E, F");
    return c;
}

// A curve claim, by CLAIMS.md's "Curve claims" (rules 1-4), against the curve proved over a
// window holding the claimed range [lo, hi] with room on both sides (so every switch point of f
// in the closed range is known, and whether lo or hi is one).
bool judge_curve(Context& cx, const Rules& R, const J& cl, const Window& W, const std::string& wc,
                 const std::string& wp) {
    struct Seg {
        Q x0, y0, x1, y1;
        std::optional<std::string> label;
    };
    std::vector<Seg> segs;
    std::vector<std::pair<Q, Q>> claimed;  // the claimed switch points
    if (cl.contains("vertices")) {
        shape(cx, cl, wc, {"kind", "vertices"}, {"switch_points"});
        const J& v = at(cl, "vertices");
        cx.claim(v.is_array() && v.size() >= 2, wc + ".vertices has at least 2 points");
        std::vector<std::pair<Q, Q>> p;
        for (size_t i = 0; i < v.size(); ++i)
            p.push_back(scaling_pair(cx, v[i], wc + ".vertices[" + std::to_string(i) + "]"));
        for (size_t i = 0; i + 1 < p.size(); ++i) {
            cx.claim(p[i].first < p[i + 1].first, wc + ".vertices: rho1 increases");
            segs.push_back({p[i].first, p[i].second, p[i + 1].first, p[i + 1].second, std::nullopt});
        }
        for (size_t i = 1; i + 1 < p.size(); ++i)  // bends: where the polyline's slope changes
            if ((p[i].second - p[i - 1].second) * (p[i + 1].first - p[i].first) !=
                (p[i + 1].second - p[i].second) * (p[i].first - p[i - 1].first))
                claimed.push_back(p[i]);
    } else {
        shape(cx, cl, wc, {"kind", "pieces"}, {"switch_points"});
        const J& ps = at(cl, "pieces");
        cx.claim(ps.is_array() && !ps.empty(), wc + ".pieces is a nonempty list");
        for (size_t i = 0; i < ps.size(); ++i) {
            const std::string w = wc + ".pieces[" + std::to_string(i) + "]";
            shape(cx, ps[i], w, {"rho1", "slope", "intercept"}, {"contact"});
            const J& r = at(ps[i], "rho1");
            cx.claim(r.is_array() && r.size() == 2, w + ".rho1 is [from, to]");
            const Q x0 = num(cx, r[0], w + ".rho1"), x1 = num(cx, r[1], w + ".rho1");
            const Q a = num(cx, at(ps[i], "slope"), w + ".slope"),
                    b = num(cx, at(ps[i], "intercept"), w + ".intercept");
            cx.claim(sgn(x0) > 0 && x0 < x1, w + ".rho1 is a range of scalings > 0");
            cx.claim(segs.empty() || x0 == segs.back().x1, w + " starts where the piece before ends");
            const Q y0 = a * x0 + b, y1 = a * x1 + b;
            cx.claim(sgn(y0) > 0 && sgn(y1) > 0, w + " stays at rho2 > 0");
            if (!segs.empty()) claimed.push_back({x0, segs.back().y1});  // the value there is the left piece's
            std::optional<std::string> label;
            if (ps[i].contains("contact")) label = claimed_contact(cx, ps[i], w);
            segs.push_back({x0, y0, x1, y1, label});
        }
    }
    const Q lo = segs.front().x0, hi = segs.back().x1;
    if (cl.contains("switch_points")) {
        const J& sw = at(cl, "switch_points");
        cx.claim(sw.is_array(), wc + ".switch_points is a list");
        claimed.clear();
        for (size_t i = 0; i < sw.size(); ++i) {
            const auto p = scaling_pair(cx, sw[i], wc + ".switch_points[" + std::to_string(i) + "]");
            cx.claim(lo <= p.first && p.first <= hi, wc + ".switch_points lie in the claimed range");
            claimed.push_back(p);
        }
    }
    cx.claim(W.a < lo && hi < W.b, wp + ".rho1 holds the claimed range with room on both sides");
    const CurveFacts& f = W.f;
    // 1. f > 0 over the range: f descends, so at hi.
    const bool positive = sgn(f.at(cx, hi)) > 0;
    // 2. The values, at the segments' ends and at f's switch points inside them (found by binary
    // search: the switch points are in increasing rho1).
    auto first = [&](const Q& x, bool or_at) {  // the first switch point with rho1 > x (or_at: >= x)
        size_t lo = 0, hi = f.switches.size();
        while (lo < hi) {
            const size_t mid = (lo + hi) / 2;
            cx.spend_ops(1, qsize(x) + qsize(f.switches[mid].x));
            if (f.switches[mid].x > x || (or_at && f.switches[mid].x == x))
                hi = mid;
            else
                lo = mid + 1;
        }
        return lo;
    };
    auto first_after = [&](const Q& x) { return first(x, false); };
    bool within = true;
    for (const Seg& s : segs) {
        within = within && R.close(cx, s.y0, f.at(cx, s.x0)) && R.close(cx, s.y1, f.at(cx, s.x1));
        for (size_t k = first_after(s.x0); k < f.switches.size() && f.switches[k].x < s.x1; ++k) {
            const auto& sw = f.switches[k];
            cx.spend_ops(6, qsize(s.x0) + qsize(s.x1) + qsize(s.y0) + qsize(s.y1) + qsize(sw.x));
            within = within && R.close(cx, s.y0 + (s.y1 - s.y0) * (sw.x - s.x0) / (s.x1 - s.x0), sw.y);
        }
    }
    // 3. Switch points: exact ones in [lo, hi] paired with claimed ones, each the other's nearest
    // in rho1 (ties: the first listed).
    std::vector<const CurveFacts::Switch*> exact;
    for (size_t k = first(lo, true); k < f.switches.size() && f.switches[k].x <= hi; ++k)
        exact.push_back(&f.switches[k]);
    // (Linear searches, each comparison counted: quadratic only in what the claim lists.)
    auto nearest_claimed = [&](const Q& x) {
        size_t b = 0;
        for (size_t i = 1; i < claimed.size(); ++i) {
            cx.spend_ops(4, qsize(claimed[i].first) + qsize(claimed[b].first) + qsize(x));
            if (abs(claimed[i].first - x) < abs(claimed[b].first - x)) b = i;
        }
        return b;
    };
    auto nearest_exact = [&](const Q& x) {
        size_t b = 0;
        for (size_t i = 1; i < exact.size(); ++i) {
            cx.spend_ops(4, qsize(exact[i]->x) + qsize(exact[b]->x) + qsize(x));
            if (abs(exact[i]->x - x) < abs(exact[b]->x - x)) b = i;
        }
        return b;
    };
    bool switches_right = true;
    std::vector<bool> used(claimed.size(), false);
    for (size_t i = 0; i < exact.size(); ++i) {
        const bool at_end = exact[i]->x == lo || exact[i]->x == hi;
        size_t k = 0;
        if (claimed.empty() || nearest_exact(claimed[k = nearest_claimed(exact[i]->x)].first) != i) {
            if (!at_end) switches_right = false;  // missed
            continue;
        }
        used[k] = true;
        if (!R.close(cx, claimed[k].first, exact[i]->x) || !R.close(cx, claimed[k].second, exact[i]->y))
            switches_right = false;  // misplaced
    }
    for (bool u : used) switches_right = switches_right && u;  // none extra
    // 4. Each claimed contact is f's at its segment's midpoint (a switch point's there).
    bool contacts_right = true;
    for (const Seg& s : segs) {
        if (!s.label) continue;
        const Q mid = (s.x0 + s.x1) / 2;
        std::string e = positive ? f.contacts[f.piece_at(cx, mid)] : std::string("none");
        const size_t k = first_after(mid);
        if (k > 0 && f.switches[k - 1].x == mid) e = f.switches[k - 1].contact;
        contacts_right = contacts_right && *s.label == e;
    }
    return positive && within && switches_right && contacts_right;
}

// A switch-point claim is right when some exact switch point matches it: both coordinates within
// the tolerance (|c − x| <= tol·x) and the contact, when claimed. Every ρ1 = x with
// |c1 − x| <= tol·x lies in [c1/(1 + tol), c1/(1 − tol)] (beyond c1/(1 + tol) without end when
// tol >= 1), so the window must hold that range strictly inside (or start at 0, or go on to where
// the curve reaches ρ2 <= 0, past which there is no switch point): then every switch point that
// could match is listed.
bool judge_switch_point(Context& cx, const Rules& R, const J& cl, const Window& W, const std::string& wc,
                        const std::string& wp) {
    shape(cx, cl, wc, {"kind", "rho1", "rho2"}, {"contact"});
    const Q c1 = positive(cx, cl, "rho1", wc), c2 = positive(cx, cl, "rho2", wc);
    std::optional<std::string> label;
    if (cl.contains("contact")) label = claimed_contact(cx, cl, wc);
    cx.spend_ops(4, 2 * qsize(c1) + 2 * qsize(R.tol));
    const Q lo = c1 / (1 + R.tol);
    // (Strictly: the window lists the switch points strictly inside it.)
    cx.claim(sgn(W.a) == 0 || W.a < lo, wp + ".rho1 starts below every rho1 within the tolerance of the claim");
    cx.claim(W.reaches_zero() || (R.tol < 1 && c1 / (1 - R.tol) < W.b),
             wp + ".rho1 ends beyond every rho1 within the tolerance of the claim");
    for (const auto& sw : W.f.switches)
        if (R.close(cx, c1, sw.x) && R.close(cx, c2, sw.y) && (!label || *label == sw.contact)) return true;
    return false;
}

// One judgement; returns whether the claim is right by the rules.
bool judge(Context& cx, const Scene& sc, const Rules& R, const Judgement& j);

// A claim at poses ("pose1", "pose2": [R | t] by rows, R nonsingular): judged as the same claim
// without them on the scene with each polyhedron moved by its pose, the seed too (posed_scene,
// every vertex recomputed). A verdict's proof is then {"depth": a depth proof}, whose state is
// the verdict: a separating normal, a touching pair's depth 0, an overlapping pair's depth > 0.
bool judge_at_poses(Context& cx, const Scene& sc, const Rules& R, const Judgement& j) {
    const J &cl = j.claim, &pr = j.proof;
    cx.claim(j.kind == "verdict" || j.kind == "separating_plane" || j.kind == "witness_point" || j.kind == "distance" ||
                 j.kind == "penetration_depth" || j.kind == "signed_distance",
             j.wc +
                 ": poses are on claims of kind verdict, separating_plane, witness_point, distance, "
                 "penetration_depth or signed_distance");
    J bare;
    const std::array<std::optional<Pose>, 2> pose = claim_poses(cx, cl, j.wc, bare);
    const Scene posed = posed_scene(cx, sc, pose);
    const Judgement jb{bare, pr, j.kind, j.where, j.wc, j.wp};
    if (j.kind != "verdict") return judge(cx, posed, R, jb);
    shape(cx, bare, j.wc, {"kind", "rho1", "rho2", "verdict"});
    shape(cx, pr, j.wp, {"depth"});
    const Q r1 = positive(cx, bare, "rho1", j.wc), r2 = positive(cx, bare, "rho2", j.wc);
    cx.claim(at(bare, "verdict").is_string(), j.wc + ".verdict is a string");
    const std::string c = at(bare, "verdict").get<std::string>();
    check_claimed_verdict(cx, c, j.wc);
    const std::optional<Q> E = proved_depth(cx, posed, at(pr, "depth"), j.wp + ".depth", r1, r2);
    return verdict_right(c, !E ? "separated" : sgn(*E) == 0 ? "touching" : "overlapping");
}

// A signed distance (CLAIMS.md): proved apart by a distance proof ({"distance": ...}, E > 0: s√E
// with s = 1), or meeting by a depth proof ({"depth": ...}: touching, s = 0, or overlapping,
// s = −1 and E the squared depth); then the claimed value, or bound, against s√E.
bool judge_signed_distance(Context& cx, const Scene& sc, const Rules& R, const Judgement& j) {
    const J &cl = j.claim, &pr = j.proof;
    shape(cx, cl, j.wc, {"kind", "rho1", "rho2"}, {"value", "at_least", "below"});
    const int given = cl.contains("value") + cl.contains("at_least") + cl.contains("below");
    cx.claim(given == 1, j.wc + " has one of value, at_least and below");
    const char* key = cl.contains("value") ? "value" : cl.contains("at_least") ? "at_least" : "below";
    const Q r1 = positive(cx, cl, "rho1", j.wc), r2 = positive(cx, cl, "rho2", j.wc);
    const Q c = num(cx, at(cl, key), j.wc + "." + key);
    int s = 0;
    Q E;
    if (pr.contains("distance")) {
        shape(cx, pr, j.wp, {"distance"});
        shape(cx, at(pr, "distance"), j.wp + ".distance", {"squared", "P1", "P2"});
        E = proved_distance_sq(cx, sc, at(pr, "distance"), j.wp + ".distance", r1, r2);
        cx.claim(sgn(E) > 0, j.wp + ".distance proves the objects apart (squared > 0)");
        s = 1;
    } else {
        shape(cx, pr, j.wp, {"depth"});
        const std::optional<Q> D = proved_depth(cx, sc, at(pr, "depth"), j.wp + ".depth", r1, r2);
        cx.claim(D.has_value(), j.wp + ".depth proves the objects meet");
        E = *D;
        s = sgn(E) == 0 ? 0 : -1;
    }
    cx.spend_ops(8, 2 * qsize(c) + qsize(E) + 2 * qsize(R.abs));
    if (std::string(key) == "value") return R.close_signed(cx, c, s, E);
    if (std::string(key) == "at_least") return sign_minus_sqrt(c - R.abs, s, E) <= 0;  // s√E >= c − abs
    return sign_minus_sqrt(c + R.abs, s, E) > 0;                                       // s√E < c + abs
}

bool judge(Context& cx, const Scene& sc, const Rules& R, const Judgement& j) {
    const J &cl = j.claim, &pr = j.proof;
    const std::string &kind = j.kind, &where = j.where, &wc = j.wc, &wp = j.wp;
    if (cl.contains("pose1") || cl.contains("pose2")) return judge_at_poses(cx, sc, R, j);
    const Polytopes bodies(sc, R.abs);
    if (kind == "verdict") {
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "verdict"});
        shape(cx, pr, wp, {"verdict", "certificate"});
        const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
        cx.claim(at(cl, "verdict").is_string() && at(pr, "verdict").is_string(), where + ": verdicts are strings");
        const std::string c = at(cl, "verdict").get<std::string>(), v = at(pr, "verdict").get<std::string>();
        check_claimed_verdict(cx, c, wc);
        cx.claim(v == "separated" || v == "touching" || v == "overlapping",
                 wp + ".verdict is separated, touching or overlapping");
        check_verdict(cx, sc, r1, r2, v, at(pr, "certificate"));
        return verdict_right(c, v);
    }
    if (kind == "growth_distance") {
        shape(cx, cl, wc, {"kind", "value"});
        shape(cx, pr, wp, {"value"}, {"normal", "witness"});
        const Q c = num(cx, at(cl, "value"), wc + ".value");
        cx.claim(sgn(c) >= 0, wc + ".value is >= 0");
        const Q g = num(cx, at(pr, "value"), wp + ".value");
        if (sgn(g) == 0) {
            cx.claim(!pr.contains("normal") && !pr.contains("witness"),
                     wp + ": a growth distance of 0 has no normal or witness");
            cx.claim(sc.s[0] == sc.s[1], wp + ": a growth distance of 0 needs coinciding seeds");
        } else {
            cx.claim(sgn(g) > 0 && pr.contains("normal") && pr.contains("witness"), wp + " has a normal and a witness");
            const V3 n = normal(cx, at(pr, "normal"), wp + ".normal");
            mpz_class H[2];
            sc.support(cx, n, H);
            cx.spend_ops(4, limbs(sc.Delta[0]) + limbs(sc.Delta[1]) + limbs(sc.Delta[2]) + limbs(H[0]) + limbs(H[1]) +
                                qsize(g) + vsize(n));
            cx.claim(sgn(H[0] + H[1]) > 0, wp + ".normal: h1 + h2 > 0");
            cx.claim(Q(dotz(ints(n), sc.Delta)) == g * Q(H[0] + H[1]),
                     wp + ": n·d = value (h1 + h2), so (rho, rho) is separated below it");
            cx.claim(check_witness(cx, sc, at(pr, "witness"), wp + ".witness") == P2{g, g},
                     wp + ".witness is at (value, value)");
        }
        return R.close(cx, c, g);
    }
    if (kind == "separating_plane") return judge_separating_plane(cx, bodies, R, j);
    if (kind == "witness_point") return judge_witness_point(cx, bodies, j);
    if (kind == "distance") {
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "value"}, {"closest"});
        const bool closest = cl.contains("closest");
        if (closest)
            shape(cx, pr, wp, {"squared", "P1", "P2", "closest"});
        else
            shape(cx, pr, wp, {"squared", "P1", "P2"});
        const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
        const Q c = num(cx, at(cl, "value"), wc + ".value");
        const Q E = proved_distance_sq(cx, sc, pr, wp, r1, r2);
        bool right = R.close_sq(cx, c, E);
        if (closest) {
            const Closest cp = closest_points(cx, bodies, j, r1, r2);
            cx.spend_ops(6, 2 * (vsize(cp.a) + vsize(cp.b)));
            const V3 ab = sub(cp.b, cp.a);
            right = right && cp.in && R.within_above(cx, dot(ab, ab), E, 2);
        }
        return right;
    }
    if (kind == "penetration_depth") {
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "value"}, {"direction"});
        const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
        const Q c = num(cx, at(cl, "value"), wc + ".value");
        std::optional<V3> dir;
        if (cl.contains("direction")) dir = nonzero_vector(cx, at(cl, "direction"), wc + ".direction");
        return judge_depth(cx, sc, R, pr, wp, r1, r2, c, dir);
    }
    if (kind == "signed_distance") return judge_signed_distance(cx, sc, R, j);
    if (kind == "curve") return judge_curve(cx, R, cl, curve_window(cx, sc, pr, wp), wc, wp);
    if (kind == "switch_point") return judge_switch_point(cx, R, cl, curve_window(cx, sc, pr, wp), wc, wp);
    if (kind == "curve_point") {  // a line `curve RHO1 RHO2`: rho2 is f(rho1), exactly (tolerance 0)
        shape(cx, cl, wc, {"kind", "rho1", "rho2"});
        const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
        const Window W = curve_window(cx, sc, pr, wp);
        cx.claim(W.a <= r1 && r1 <= W.b, wp + ".rho1 holds the claimed rho1");
        const Q f = W.f.at(cx, r1);
        return sgn(f) > 0 && R.close(cx, r2, f);
    }
    cx.claim(false, wc + ".kind is verdict, growth_distance, separating_plane, witness_point, distance, "
                         "penetration_depth, signed_distance, curve, switch_point or curve_point");
    return false;
}
}  // namespace

void check_judgements(Context& cx, const J& c) {
    shape(cx, c, "", {"format", "kind", "tolerance", "judgements", "seed_interior", "scene"}, {"abs_tolerance"});
    const Scene sc = read_scene(cx, at(c, "scene"), true);
    const J& js = at(c, "judgements");
    if (sc.rounded) {  // objects with a radius (rounded.cpp): the six kinds of a pair, and the growth distance
        check_rounded_seeds(cx, sc, at(c, "seed_interior"));
        const Rules R = read_rules(cx, c);
        const size_t rights = judge_all(cx, js,
                                        {"verdict", "separating_plane", "witness_point", "distance",
                                         "penetration_depth", "signed_distance", "growth_distance"},
                                        [&](const Judgement& j) { return judge_rounded(cx, sc, R, j); });
        cx.summary = "; judgements on objects with a radius: " + judged(rights, js.size(), R);
        return;
    }
    check_seed_interior(cx, sc, at(c, "seed_interior"));
    const Rules R = read_rules(cx, c);
    const size_t rights = judge_all(cx, js,
                                    {"verdict", "growth_distance", "separating_plane", "witness_point", "distance",
                                     "penetration_depth", "signed_distance", "curve", "switch_point", "curve_point"},
                                    [&](const Judgement& j) { return judge(cx, sc, R, j); });
    // What the file proves, in the line the checker prints: the judgements and their tolerance.
    cx.summary = "; judgements: " + judged(rights, js.size(), R);
}
}  // namespace scalecert_check
