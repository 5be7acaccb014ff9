// A compound judgements file (kind "compound_judgements"; certificates/FORMAT.md, "A compound
// judgements file"): certify-fp's judgements on two objects made of parts, each re-derived from
// its claim and its proof by CLAIMS.md's rules ("Objects made of parts"); a penetration depth is
// one part pair's, proved as on two convex polytopes. Weights lie in one part,
// over the part's own points; a block of part pairs is judged by the largest normal·x over its P1
// parts at ρ1 (c1) and the least over its P2 parts at ρ2 (c2), each a scan of the parts' vertices.
#include "formats.hpp"
#include "judging.hpp"
#include "json.hpp"
#include "numbers.hpp"
#include "parts.hpp"
#include "rounded.hpp"

#include <optional>

namespace scalecert_check {
namespace {
// max over the parts first..last of object i, scaled by rho about the object's seed, of n·x (n a
// nonzero rational): n·s + rho (max over their vertices of n·v − n·s), each part's maximum a scan
// of its vertices. With u = L n integral, max n·v = (max u·v) / L.
Q block_reach(Context& cx, const CompoundScene& cs, int i, const V3& n, const Q& rho, size_t first, size_t last) {
    mpz_class L;
    const Z3 u = ints(integral(n, &L));
    const Q t = cs.top(cx, i, u, first, last);
    cx.spend_ops(8, vsize(n) + vsize(cs.s[i]) + qsize(rho) + qsize(t) + limbs(L));
    const Q ns = dot(n, cs.s[i]);
    return ns + rho * (t / L - ns);
}
// The least over the same parts of n·x.
Q block_floor(Context& cx, const CompoundScene& cs, int i, const V3& n, const Q& rho, size_t first, size_t last) {
    return -block_reach(cx, cs, i, {-n[0], -n[1], -n[2]}, rho, first, last);
}
// s + rho (Σ w v − s) for weights over part k of object i (indices into the part's own points).
V3 part_point(Context& cx, const CompoundScene& cs, int i, size_t k, const Q& rho, const J& w, const std::string& where,
              std::vector<int>* used = nullptr) {
    return body_point(cx, cs.part(i, k), cs.s[i], rho, w, where, used);
}
// [k, j]: a part of P1 and a part of P2.
std::array<size_t, 2> part_pair(Context& cx, const CompoundScene& cs, const J& j, const std::string& where) {
    cx.claim(j.is_array() && j.size() == 2, where + " is [P1 part, P2 part]");
    return {index(cx, j[0], cs.parts(0), where + "[0]"), index(cx, j[1], cs.parts(1), where + "[1]")};
}
// Is x in object i at rho (or within abs of it)? {"part": k, "in": weights} combining to x in part
// k; at abs > 0 {"part": k, "near": weights} combining to a point of part k within abs of x; or
// {"out": [a normal per part]}, x strictly beyond each part's extent along its normal (at abs > 0,
// more than abs beyond).
bool member(Context& cx, const CompoundScene& cs, int i, const Q& rho, const V3& x, const J& p,
            const std::string& where, const Q& abs) {
    cx.claim(p.is_object(), where + " is an object");
    if (p.contains("out")) {
        shape(cx, p, where, {"out"});
        const J& o = at(p, "out");
        cx.claim(o.is_array() && o.size() == cs.parts(i), where + ".out has a normal for each part");
        for (size_t k = 0; k < o.size(); ++k) {
            const std::string wk = where + ".out[" + std::to_string(k) + "]";
            const V3 n = normal(cx, o[k], wk);
            beyond(cx, n, x, block_reach(cx, cs, i, n, rho, k, k), abs, wk);
        }
        return false;
    }
    if (sgn(abs) > 0 && p.contains("near")) {
        shape(cx, p, where, {"part", "near"});
        const size_t k = index(cx, at(p, "part"), cs.parts(i), where + ".part");
        return near_enough(cx, x, part_point(cx, cs, i, k, rho, at(p, "near"), where + ".near"), abs, where);
    }
    shape(cx, p, where, {"part", "in"});
    const size_t k = index(cx, at(p, "part"), cs.parts(i), where + ".part");
    cx.claim(part_point(cx, cs, i, k, rho, at(p, "in"), where + ".in") == x, where + ".in combines to the point");
    return true;
}

// The two objects of the scene, scaled.
class Objects : public Bodies {
  public:
    Objects(const CompoundScene& cs, const Q& abs) : Bodies(abs), cs_(cs) {}
    Q reach(Context& cx, int i, const V3& n, const Q& rho) const override {
        return block_reach(cx, cs_, i, n, rho, 0, cs_.parts(i) - 1);
    }
    bool member(Context& cx, int i, const Q& rho, const V3& x, const J& p, const std::string& where) const override {
        return scalecert_check::member(cx, cs_, i, rho, x, p, where, abs);
    }

  private:
    const CompoundScene& cs_;
};

// Blocks {"P1_parts", "P2_parts", "normal"} covering every part pair once, in increasing (first
// P1 part, first P2 part) order; ok(c1, c2, n) judges each block by the largest n·x over its P1
// parts at rho1 (c1) and the least over its P2 parts at rho2 (c2).
template <class Ok>
void check_blocks(Context& cx, const CompoundScene& cs, const Q& r1, const Q& r2, const J& bs, const std::string& where,
                  Ok ok) {
    cx.claim(bs.is_array() && !bs.empty(), where + " is a nonempty list");
    PairCover cover(cx, cs.parts(0), cs.parts(1));
    for (size_t e = 0; e < bs.size(); ++e) {
        const std::string w = where + "[" + std::to_string(e) + "]";
        shape(cx, bs[e], w, {"P1_parts", "P2_parts", "normal"});
        const auto [ra, rb] = cover.next(cx, bs[e], w, "block");
        const V3 nv = nonzero_vector(cx, at(bs[e], "normal"), w + ".normal");
        const Q c1 = block_reach(cx, cs, 0, nv, r1, ra[0], ra[1]), c2 = block_floor(cx, cs, 1, nv, r2, rb[0], rb[1]);
        ok(c1, c2, nv, w);
    }
    cover.complete(cx, where + " covers every part pair");
}

bool judge(Context& cx, const CompoundScene& cs, const Rules& R, const Judgement& j) {
    const J &cl = j.claim, &pr = j.proof;
    const std::string &kind = j.kind, &where = j.where, &wc = j.wc, &wp = j.wp;
    if (cl.contains("pose1") || cl.contains("pose2")) {
        // At poses: the same claim without them, on the objects moved by them (every vertex of
        // every part recomputed, the seeds too; the parts keep their vertices' places).
        J bare;
        const std::array<std::optional<Pose>, 2> pose = claim_poses(cx, cl, wc, bare);
        return judge(cx, cs.posed(cx, pose), R, Judgement{bare, pr, kind, where, wc, wp});
    }
    const Objects bodies(cs, R.abs);
    if (kind == "verdict") {
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "verdict"});
        const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
        // (at() reads a key that shape() has seen: the proof's verdict is looked up first.)
        cx.claim(pr.contains("verdict") && pr.find("verdict")->is_string() && at(cl, "verdict").is_string(),
                 where + ": verdicts are strings");
        const std::string c = at(cl, "verdict").get<std::string>(), v = pr.find("verdict")->get<std::string>();
        check_claimed_verdict(cx, c, wc);
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
                cx.claim(affine_dim(cx, cs.part(i, kj[i]), used[i]) == 3,
                         wp + ".interior." + kPoly[i] + " uses points spanning 3 dimensions (an interior point)");
        } else if (v == "touching" || v == "separated") {
            // Every pair apart by a plane (weakly: no interiors meet; strictly: none meets); touching
            // also needs a common point of one pair.
            const bool touching = v == "touching";
            if (touching)
                shape(cx, pr, wp, {"verdict", "blocks", "pair", "witness"});
            else
                shape(cx, pr, wp, {"verdict", "blocks"});
            check_blocks(cx, cs, r1, r2, at(pr, "blocks"), wp + ".blocks",
                         [&](const Q& c1, const Q& c2, const V3&, const std::string& w) {
                             cx.spend_ops(1, qsize(c1) + qsize(c2));
                             if (touching)
                                 cx.claim(c1 <= c2, w + ": the plane separates its block's pairs (weakly)");
                             else
                                 cx.claim(c1 < c2, w + ": the plane separates its block's pairs strictly");
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
        return verdict_right(c, v);
    }
    if (kind == "separating_plane") return judge_separating_plane(cx, bodies, R, j);
    if (kind == "witness_point") return judge_witness_point(cx, bodies, j);
    if (kind == "distance") {
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "value"}, {"closest"});
        const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
        const Q c = num(cx, at(cl, "value"), wc + ".value");
        cx.claim(pr.contains("squared"), wp + ".squared is present");
        const Q E = num(cx, *pr.find("squared"), wp + ".squared");
        cx.claim(sgn(E) >= 0, wp + ".squared is >= 0");
        if (sgn(E) > 0)
            shape(cx, pr, wp, {"squared", "pair", "P1", "P2", "apart"}, {"closest"});
        else
            shape(cx, pr, wp, {"squared", "pair", "P1", "P2"}, {"closest"});
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
            const Closest cp = closest_points(cx, bodies, j, r1, r2);
            const V3 ab{cp.b[0] - cp.a[0], cp.b[1] - cp.a[1], cp.b[2] - cp.a[2]};
            cx.spend_ops(6, 2 * vsize(ab));
            right = right && cp.in && R.within_above(cx, dot(ab, ab), E, 2);
        }
        return right;
    }
    if (kind == "penetration_depth") {
        // A contact: the depth of one part pair, judged as a depth on two convex polytopes, the
        // parts scaled about their objects' seeds (every proof index into a part's own points).
        shape(cx, cl, wc, {"kind", "rho1", "rho2", "parts", "value"}, {"direction"});
        const Q r1 = positive(cx, cl, "rho1", wc), r2 = positive(cx, cl, "rho2", wc);
        const std::array<size_t, 2> kj = part_pair(cx, cs, at(cl, "parts"), wc + ".parts");
        const Q c = num(cx, at(cl, "value"), wc + ".value");
        std::optional<V3> dir;
        if (cl.contains("direction")) dir = nonzero_vector(cx, at(cl, "direction"), wc + ".direction");
        return judge_depth(cx, cs.pair(cx, kj[0], kj[1]), R, pr, wp, r1, r2, c, dir);
    }
    cx.claim(false, wc + ".kind is verdict, separating_plane, witness_point, distance or penetration_depth (the "
                         "claims on objects made of parts)");
    return false;
}
}  // namespace

void check_compound_judgements(Context& cx, const J& c) {
    shape(cx, c, "", {"format", "kind", "tolerance", "judgements", "scene"}, {"abs_tolerance"});
    const CompoundScene cs = read_compound_scene(cx, at(c, "scene"));
    const Rules R = read_rules(cx, c);
    const J& js = at(c, "judgements");
    // Parts with radii (rounded.cpp): each pair judged as two objects with a radius.
    const size_t rights =
        cs.rounded()
            ? judge_all(
                  cx, js,
                  {"verdict", "separating_plane", "witness_point", "distance", "penetration_depth", "signed_distance"},
                  [&](const Judgement& j) { return judge_rounded_parts(cx, cs, R, j); })
            : judge_all(cx, js, {"verdict", "separating_plane", "witness_point", "distance", "penetration_depth"},
                        [&](const Judgement& j) { return judge(cx, cs, R, j); });
    cx.summary = "; compound judgements: " + judged(rights, js.size(), R) + "; " + std::to_string(cs.parts(0)) + " x " +
                 std::to_string(cs.parts(1)) + " part pairs";
}
}  // namespace scalecert_check
