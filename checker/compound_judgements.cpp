// A compound judgements file (kind "compound_judgements"; certificates/FORMAT.md, "A compound
// judgements file"): certify-fp's judgements on two objects made of parts, each re-derived from
// its claim and its proof by CLAIMS.md's rules ("Objects made of parts"). Weights lie in one part,
// over the part's own points; a block of part pairs is judged by the largest normal·x over its P1
// parts at ρ1 (c1) and the least over its P2 parts at ρ2 (c2), each a scan of the parts' vertices.
#include "formats.hpp"
#include "judging.hpp"
#include "json.hpp"
#include "numbers.hpp"
#include "parts.hpp"

#include <algorithm>

namespace scalecert_check {
namespace {
// max over the parts first..last of object i, scaled by rho about the object's seed, of n·x (n a
// nonzero rational): n·s + rho max over their vertices of n·(v − s), a scan of those vertices.
Q block_reach(Context& cx, const CompoundScene& cs, int i, const V3& n, const Q& rho, size_t first, size_t last) {
    const Scene& sc = cs.sc;
    cx.spend_ops(12, vsize(n) + vsize(sc.s[i]) + qsize(rho) + 2 * limbs(sc.Dj));
    mpz_class L;
    const Z3 u = ints(integral(n, &L));
    const std::vector<int> verts = cs.verts(i, first, last);
    cx.spend(5.0 * static_cast<double>(verts.size()));  // the list itself, and the scan's gathering through it
    const std::vector<int> best = sc.scan[i]->argmax(cx, u, &verts);
    Q h(sc.support_at(cx, i, u, best[0]), sc.Dj * L);  // max over the vertices of u·(v − s), over L
    h.canonicalize();
    return dot(n, sc.s[i]) + rho * h;
}
// The least over the same parts of n·x.
Q block_floor(Context& cx, const CompoundScene& cs, int i, const V3& n, const Q& rho, size_t first, size_t last) {
    return -block_reach(cx, cs, i, {-n[0], -n[1], -n[2]}, rho, first, last);
}
// s + rho (Σ w v − s) for weights over part k of object i (indices into the part's own points).
V3 part_point(Context& cx, const CompoundScene& cs, int i, size_t k, const Q& rho, const J& w,
              const std::string& where, std::vector<int>* used = nullptr) {
    const Scene& sc = cs.sc;
    const std::array<Q, 3> c =
        combination(cx, sc, i, w, where, used, cs.start[i][k], cs.start[i][k + 1] - cs.start[i][k]);
    cx.spend_ops(12, vsize(sc.s[i]) + qsize(rho) + std::max({qsize(c[0]), qsize(c[1]), qsize(c[2])}) +
                         limbs(sc.scan[i]->D()));
    const Q D(sc.scan[i]->D());
    V3 x;
    for (int d = 0; d < 3; ++d) x[d] = sc.s[i][d] + rho * (c[d] / D - sc.s[i][d]);
    return x;
}
// [k, j]: a part of P1 and a part of P2.
std::array<size_t, 2> part_pair(Context& cx, const CompoundScene& cs, const J& j, const std::string& where) {
    cx.claim(j.is_array() && j.size() == 2, where + " is [P1 part, P2 part]");
    return {index(cx, j[0], cs.parts(0), where + "[0]"), index(cx, j[1], cs.parts(1), where + "[1]")};
}
// Is x in object i at rho? {"part": k, "in": weights} combining to x in part k, or
// {"out": [a normal per part]}, x strictly beyond each part's extent along its normal.
bool member(Context& cx, const CompoundScene& cs, int i, const Q& rho, const V3& x, const J& p,
            const std::string& where) {
    cx.claim(p.is_object(), where + " is an object");
    if (p.contains("out")) {
        shape(cx, p, where, {"out"});
        const J& o = at(p, "out");
        cx.claim(o.is_array() && o.size() == cs.parts(i), where + ".out has a normal for each part");
        for (size_t k = 0; k < o.size(); ++k) {
            const std::string wk = where + ".out[" + std::to_string(k) + "]";
            const V3 n = normal(cx, o[k], wk);
            cx.spend_ops(3, vsize(n) + vsize(x));
            cx.claim(dot(n, x) > block_reach(cx, cs, i, n, rho, k, k),
                     wk + ": the point lies strictly beyond the part's extent along the normal");
        }
        return false;
    }
    shape(cx, p, where, {"part", "in"});
    const size_t k = index(cx, at(p, "part"), cs.parts(i), where + ".part");
    cx.claim(part_point(cx, cs, i, k, rho, at(p, "in"), where + ".in") == x, where + ".in combines to the point");
    return true;
}

// Blocks {"P1_parts", "P2_parts", "normal"} covering every part pair once, in increasing (first
// P1 part, first P2 part) order; ok(c1, c2, n) judges each block by the largest n·x over its P1
// parts at rho1 (c1) and the least over its P2 parts at rho2 (c2).
template <class Ok>
void check_blocks(Context& cx, const CompoundScene& cs, const Q& r1, const Q& r2, const J& bs, const std::string& where,
                  Ok ok) {
    const size_t m = cs.parts(0), n = cs.parts(1);
    cx.claim(bs.is_array() && !bs.empty(), where + " is a nonempty list");
    cx.spend(static_cast<double>(m) * static_cast<double>(n) / 8);
    std::vector<bool> covered(m * n, false);
    size_t count = 0;
    std::array<size_t, 2> previous{0, 0};
    for (size_t e = 0; e < bs.size(); ++e) {
        const std::string w = where + "[" + std::to_string(e) + "]";
        shape(cx, bs[e], w, {"P1_parts", "P2_parts", "normal"});
        const std::array<size_t, 2> ra = part_range(cx, at(bs[e], "P1_parts"), m, w + ".P1_parts"),
                                    rb = part_range(cx, at(bs[e], "P2_parts"), n, w + ".P2_parts");
        cx.claim(e == 0 || std::array<size_t, 2>{ra[0], rb[0]} > previous,
                 w + " comes after the block before it (by first P1 part, then first P2 part)");
        previous = {ra[0], rb[0]};
        cx.spend(static_cast<double>(ra[1] - ra[0] + 1) * static_cast<double>(rb[1] - rb[0] + 1));
        for (size_t a = ra[0]; a <= ra[1]; ++a)
            for (size_t b = rb[0]; b <= rb[1]; ++b) {
                if (covered[a * n + b])  // (the message only when it fails: a block may cover 10^8 pairs)
                    cx.claim(false, w + " covers the pair (" + std::to_string(a) + ", " + std::to_string(b) +
                                        ") a second time");
                covered[a * n + b] = true;
                ++count;
            }
        const V3 nv = nonzero_vector(cx, at(bs[e], "normal"), w + ".normal");
        const Q c1 = block_reach(cx, cs, 0, nv, r1, ra[0], ra[1]), c2 = block_floor(cx, cs, 1, nv, r2, rb[0], rb[1]);
        ok(c1, c2, nv, w);
    }
    cx.claim(count == m * n, where + " covers every part pair (" + std::to_string(count) + " of " +
                                 std::to_string(m * n) + ")");
}

bool judge(Context& cx, const CompoundScene& cs, const Rules& R, const J& cl, const J& pr, const std::string& where) {
    const Scene& sc = cs.sc;
    cx.claim(cl.is_object() && cl.contains("kind") && cl["kind"].is_string(), where + ".claim has a kind");
    cx.claim(pr.is_object(), where + ".proof is an object");
    const std::string kind = cl["kind"].get<std::string>();
    const std::string wc = where + ".claim", wp = where + ".proof";
    if (kind == "verdict") {
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "verdict"});
        const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
        // (at() reads a key that shape() has seen: the proof's verdict is looked up first.)
        cx.claim(pr.contains("verdict") && pr.find("verdict")->is_string() && at(cl, "verdict").is_string(),
                 where + ": verdicts are strings");
        const std::string c = at(cl, "verdict").get<std::string>(), v = pr.find("verdict")->get<std::string>();
        cx.claim(c == "separated" || c == "touching" || c == "overlapping" || c == "intersecting",
                 wc + ".verdict is separated, touching, overlapping or intersecting");
        if (v == "overlapping") {
            // A point inside a part of each: strictly positive weights on points spanning 3
            // dimensions lie inside their hull, hence inside the part, and scaling keeps it inside.
            shape(cx, pr, wp, {"verdict", "pair", "interior"});
            const std::array<size_t, 2> kj = part_pair(cx, cs, at(pr, "pair"), wp + ".pair");
            const J& in = at(pr, "interior");
            shape(cx, in, wp + ".interior", {"P1", "P2"});
            std::vector<int> used[2];
            const V3 x = part_point(cx, cs, 0, kj[0], r1, at(in, "P1"), wp + ".interior.P1", &used[0]);
            const V3 y = part_point(cx, cs, 1, kj[1], r2, at(in, "P2"), wp + ".interior.P2", &used[1]);
            cx.claim(x == y, wp + ".interior is one point of both parts");
            for (int i = 0; i < 2; ++i)
                cx.claim(affine_dim(cx, sc, i, used[i]) == 3,
                         wp + ".interior." + kPoly[i] + " uses points spanning 3 dimensions (an interior point)");
        } else if (v == "touching" || v == "separated") {
            // Every pair apart by a plane (weakly: no interiors meet; strictly: none meets); touching
            // also needs a common point of one pair.
            const bool touching = v == "touching";
            if (touching) shape(cx, pr, wp, {"verdict", "blocks", "pair", "witness"});
            else shape(cx, pr, wp, {"verdict", "blocks"});
            check_blocks(cx, cs, r1, r2, at(pr, "blocks"), wp + ".blocks",
                         [&](const Q& c1, const Q& c2, const V3&, const std::string& w) {
                             cx.spend_ops(1, qsize(c1) + qsize(c2));
                             if (touching) cx.claim(c1 <= c2, w + ": the plane separates its block's pairs (weakly)");
                             else cx.claim(c1 < c2, w + ": the plane separates its block's pairs strictly");
                         });
            if (touching) {
                const std::array<size_t, 2> kj = part_pair(cx, cs, at(pr, "pair"), wp + ".pair");
                const J& wt = at(pr, "witness");
                shape(cx, wt, wp + ".witness", {"P1", "P2"});
                cx.claim(part_point(cx, cs, 0, kj[0], r1, at(wt, "P1"), wp + ".witness.P1") ==
                             part_point(cx, cs, 1, kj[1], r2, at(wt, "P2"), wp + ".witness.P2"),
                         wp + ".witness is a point of both parts");
            }
        } else {
            cx.claim(false, wp + ".verdict is separated, touching or overlapping");
        }
        return c == "intersecting" ? v != "separated" : c == v;
    }
    if (kind == "separating_plane") {
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "normal"}, {"offset"});
        cx.claim(pr.empty(), wp + " is empty (the checker computes the extents)");
        const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
        const V3 n = nonzero_vector(cx, at(cl, "normal"), wc + ".normal");
        const Q c1 = block_reach(cx, cs, 0, n, r1, 0, cs.parts(0) - 1),
                c2 = block_floor(cx, cs, 1, n, r2, 0, cs.parts(1) - 1);
        bool right = c1 < c2;
        if (cl.contains("offset")) {
            const Q d = num(cx, at(cl, "offset"), wc + ".offset");
            right = right && c1 < d && d < c2;
        }
        return right;
    }
    if (kind == "witness_point") {
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "point"});
        shape(cx, pr, wp, {"P1", "P2"});
        const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
        const V3 x = point(cx, at(cl, "point"), wc + ".point");
        const bool in1 = member(cx, cs, 0, r1, x, at(pr, "P1"), wp + ".P1"),
                   in2 = member(cx, cs, 1, r2, x, at(pr, "P2"), wp + ".P2");
        return in1 && in2;
    }
    if (kind == "distance") {
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "value"}, {"closest"});
        const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
        const Q c = num(cx, at(cl, "value"), wc + ".value");
        cx.claim(pr.contains("squared"), wp + ".squared is present");
        const Q E = num(cx, *pr.find("squared"), wp + ".squared");
        cx.claim(sgn(E) >= 0, wp + ".squared is >= 0");
        if (sgn(E) > 0) shape(cx, pr, wp, {"squared", "pair", "P1", "P2", "apart"}, {"closest"});
        else shape(cx, pr, wp, {"squared", "pair", "P1", "P2"}, {"closest"});
        cx.claim(cl.contains("closest") == pr.contains("closest"),
                 wp + ".closest is there exactly when the claim has closest points");
        // The upper bound: two points of the objects, sqrt(E) apart.
        const std::array<size_t, 2> kj = part_pair(cx, cs, at(pr, "pair"), wp + ".pair");
        const V3 p = part_point(cx, cs, 0, kj[0], r1, at(pr, "P1"), wp + ".P1"),
                 q = part_point(cx, cs, 1, kj[1], r2, at(pr, "P2"), wp + ".P2");
        const V3 pq{q[0] - p[0], q[1] - p[1], q[2] - p[2]};
        cx.spend_ops(6, 2 * vsize(pq));
        cx.claim(dot(pq, pq) == E, wp + ": the points P1 and P2 are sqrt(squared) apart");
        // The lower bound: every pair at least sqrt(E) apart, gap(u) >= sqrt(E) |u| over each block.
        if (sgn(E) > 0)
            check_blocks(cx, cs, r1, r2, at(pr, "apart"), wp + ".apart",
                         [&](const Q& c1, const Q& c2, const V3& u, const std::string& w) {
                             const Q gap = c2 - c1;
                             cx.spend_ops(6, 2 * qsize(gap) + qsize(E) + 2 * vsize(u));
                             cx.claim(sgn(gap) > 0 && gap * gap >= E * dot(u, u),
                                      w + ": its pairs are at least sqrt(squared) apart along the normal");
                         });
        bool right = R.close_sq(cx, c, E);
        if (cl.contains("closest")) {
            const J& cp = at(cl, "closest");
            cx.claim(cp.is_array() && cp.size() == 2, wc + ".closest is [point, point]");
            const V3 a = point(cx, cp[0], wc + ".closest[0]"), b = point(cx, cp[1], wc + ".closest[1]");
            const J& pc = at(pr, "closest");
            shape(cx, pc, wp + ".closest", {"P1", "P2"});
            const bool in1 = member(cx, cs, 0, r1, a, at(pc, "P1"), wp + ".closest.P1"),
                       in2 = member(cx, cs, 1, r2, b, at(pc, "P2"), wp + ".closest.P2");
            const V3 ab{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
            cx.spend_ops(6, 2 * vsize(ab));
            right = right && in1 && in2 && R.within_above(cx, dot(ab, ab), E);
        }
        return right;
    }
    cx.claim(false, wc + ".kind is verdict, separating_plane, witness_point or distance (the claims on objects made "
                         "of parts)");
    return false;
}
}  // namespace

void check_compound_judgements(Context& cx, const J& c) {
    shape(cx, c, "", {"format", "kind", "tolerance", "judgements", "scene"});
    const CompoundScene cs = read_compound_scene(cx, at(c, "scene"));
    Rules R{num(cx, at(c, "tolerance"), "tolerance")};
    cx.claim(sgn(R.tol) >= 0, "tolerance is >= 0");
    const J& js = at(c, "judgements");
    const size_t rights = judge_all(cx, js, [&](const J& cl, const J& pr, const std::string& w) {
        return judge(cx, cs, R, cl, pr, w);
    });
    cx.summary = "; compound judgements: " + std::to_string(rights) + " right, " + std::to_string(js.size() - rights) +
                 " wrong, tolerance " + tolerance_shown(R.tol) + "; " + std::to_string(cs.parts(0)) + " x " +
                 std::to_string(cs.parts(1)) + " part pairs";
}
}  // namespace scalecert_check
