// A compound partition (kind "compound_partition"; certificates/FORMAT.md, "A compound
// partition"). Two objects made of convex parts, every part of object i scaled about its one seed
// s_i (which need lie in no part). The objects meet at (ρ1, ρ2) iff some part pair (A, B) does,
// and the file proves each pair's meeting set M in the rectangle on its own: an entry covers a
// block of pairs (P1 parts a0..a1 × P2 parts b0..b1) and lists normals n, each giving, over the
// vertices of the block's parts, the half-plane ρ1 hA(n) + ρ2 hB(n) >= n·d (hA over the P1 parts,
// hB over the P2 parts: never smaller than one pair's, so a point outside the half-plane is
// separated for every pair of the block). The rectangle cut by them all is recomputed here and
// must be the listed polygon: outside it some normal separates. A block of more than one pair
// must cut it to nothing; a single pair's polygon carries a witness at each corner, and the set of
// (x, ρ1, ρ2) with x in A(ρ1) ∩ B(ρ2) is convex, so the pair meets on the whole polygon. The
// blocks must cover every pair exactly once. So a point of the rectangle is in the overlap region
// iff it lies in some listed polygon. The growth set is recomputed from the polygons.
#include "formats.hpp"
#include "judging.hpp"
#include "json.hpp"
#include "numbers.hpp"
#include "parts.hpp"
#include "polygon.hpp"

#include <algorithm>
#include <utility>

namespace scalecert_check {
void check_compound_partition(Context& cx, const J& c) {
    shape(cx, c, "", {"format", "kind", "pairs", "growth_set", "scene"}, {"statistics"});
    const CompoundScene cs = read_compound_scene(cx, at(c, "scene"));
    if (c.contains("statistics")) {
        const J& st = at(c, "statistics");
        shape(cx, st, "statistics", {"pairs", "pruned", "built", "entries", "witness_fallbacks"});
        for (const char* k : {"pairs", "pruned", "built", "entries", "witness_fallbacks"})
            cx.claim(natural(at(st, k)), std::string("statistics.") + k + " is a count");
    }
    const size_t m = cs.parts(0), n = cs.parts(1);
    const std::vector<P2> rect = rectangle(cs.lo, cs.hi);
    PairCover cover(cx, m, n);
    struct Diagonal {
        Q from, to;
        size_t a, b;
    };
    std::vector<Diagonal> diag;  // each listed polygon where it meets ρ1 = ρ2
    size_t meeting = 0;
    const J& pairs = at(c, "pairs");
    cx.claim(pairs.is_array() && !pairs.empty(), "pairs is a nonempty list");
    for (size_t e = 0; e < pairs.size(); ++e) {
        const std::string w = "pairs[" + std::to_string(e) + "]";
        const J& pe = pairs[e];
        shape(cx, pe, w, {"P1_parts", "P2_parts", "normals", "vertices", "vertices_double", "witnesses"});
        const auto [ra, rb] = cover.next(cx, pe, w, "entry");
        // The half-planes of the block's normals: hA(n) = max over its P1 parts' vertices of
        // n·v − n·s1, hB(n) = max over its P2 parts' vertices of −n·w + n·s2.
        const J& ns = at(pe, "normals");
        cx.claim_lazy(ns.is_array(), [&] { return w + ".normals is a list"; });
        std::vector<P2> poly = rect;
        for (size_t k = 0; k < ns.size(); ++k) {
            const V3 nv = normal(cx, ns[k], w + ".normals[" + std::to_string(k) + "]");
            const Z3 u = ints(nv), mu{-u[0], -u[1], -u[2]};
            const Q a = cs.top(cx, 0, u, ra[0], ra[1]), b = cs.top(cx, 1, mu, rb[0], rb[1]);
            cx.spend_ops(6, vsize(nv) + vsize(cs.s[0]) + vsize(cs.s[1]) + qsize(a) + qsize(b));
            const Q ns1 = dot(nv, cs.s[0]), ns2 = dot(nv, cs.s[1]);
            if (!poly.empty()) poly = cut(cx, poly, a - ns1, b + ns2, ns2 - ns1);
        }
        cx.claim_lazy(polygon(cx, pe, w) == poly,
                      [&] { return w + ".vertices is the rectangle cut by its normals' half-planes"; });
        const J& wit = at(pe, "witnesses");
        cx.claim_lazy(wit.is_array() && wit.size() == poly.size(), [&] { return w + " has a witness at each vertex"; });
        if (poly.empty()) continue;
        cx.claim_lazy(ra[0] == ra[1] && rb[0] == rb[1],
                      [&] { return w + " is one pair: a block of pairs must meet nowhere in the rectangle"; });
        const Scene sc = cs.pair(cx, ra[0], rb[0]);
        for (size_t k = 0; k < poly.size(); ++k) {
            const std::string wk = w + ".witnesses[" + std::to_string(k) + "]";
            cx.claim_lazy(check_witness(cx, sc, wit[k], wk) == poly[k], [&] { return wk + " is at its vertex"; });
        }
        ++meeting;
        std::vector<P2> d = cut(cx, cut(cx, poly, Q(-1), Q(1), Q(0)), Q(1), Q(-1), Q(0));  // on ρ1 = ρ2
        if (!d.empty()) {
            Q t0 = d[0][0], t1 = d[0][0];
            for (const P2& x : d) t0 = std::min(t0, x[0]), t1 = std::max(t1, x[0]);
            diag.push_back({t0, t1, ra[0], rb[0]});
        }
    }
    cover.complete(cx, "the entries cover every part pair");
    // The growth set: where the objects meet on ρ1 = ρ2, the union of the pairs' intervals, each
    // with the pair that meets at its start (the least start, then the first pair by part).
    std::sort(diag.begin(), diag.end(), [](const Diagonal& x, const Diagonal& y) {
        return x.from != y.from ? x.from < y.from : std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
    });
    std::vector<Diagonal> merged;
    for (const Diagonal& d : diag) {
        if (!merged.empty() && d.from <= merged.back().to) {
            if (d.to > merged.back().to) merged.back().to = d.to;
        } else {
            merged.push_back(d);
        }
    }
    const J& gs = at(c, "growth_set");
    cx.claim(gs.is_array() && gs.size() == merged.size(),
             "growth_set has one interval per connected piece of the overlap region on rho1 = rho2 (" +
                 std::to_string(merged.size()) + ")");
    for (size_t k = 0; k < merged.size(); ++k) {
        const std::string w = "growth_set[" + std::to_string(k) + "]";
        shape(cx, gs[k], w, {"from", "from_double", "to", "to_double", "first_contact"});
        cx.claim(field(cx, gs[k], "from", w) == merged[k].from && field(cx, gs[k], "to", w) == merged[k].to,
                 w + " is the interval recomputed from the pairs");
        const J& fc = at(gs[k], "first_contact");
        shape(cx, fc, w + ".first_contact", {"P1_part", "P2_part"});
        cx.claim(index(cx, at(fc, "P1_part"), m, w + ".first_contact.P1_part") == merged[k].a &&
                     index(cx, at(fc, "P2_part"), n, w + ".first_contact.P2_part") == merged[k].b,
                 w + ".first_contact is the first pair meeting at its start");
    }
    cx.summary = "; compound: " + std::to_string(m) + " x " + std::to_string(n) + " part pairs, " +
                 std::to_string(meeting) + " meeting somewhere in I1 x I2";
}
}  // namespace scalecert_check
