#include "curve.hpp"

#include "json.hpp"
#include "numbers.hpp"
#include "scene.hpp"

#include <algorithm>
#include <iterator>
#include <set>

namespace scalecert_check {
namespace {
// The contact at a switch point between pieces with normals n and m, both touching at (ρ1, ρ2):
// P_i(ρ_i) ∩ P_j(ρ_j) lies on both planes, so on their common line ℓ (n × m). On polyhedron i the
// vertices maximising both normals (A_i, all of them) scale onto ℓ, spanning a segment S_i; the
// touching set is T = S_1 ∩ S_2, and the contact feature of i is the smallest face holding T: S_i
// (E) when T reaches into S_i's interior, else the one end it meets (V). Returns the letters, and
// in g the vertices of each feature.
std::string switch_contact(Context& cx, const Scene& sc, const V3& n, const V3& m, const Q rho[2],
                           const std::vector<int> A[2], std::vector<int> g[2], const std::string& where) {
    const V3 uq = cross(n, m);
    cx.claim(nonzero(uq), where + ": the neighbouring pieces' normals are not parallel");
    const Z3 u = ints(uq), minus_u{-u[0], -u[1], -u[2]};
    // A vertex's place on ℓ is t_k = u·(s_i + ρ_i (v_k − s_i)), which increases with u·v_k since
    // ρ_i > 0 (ρ1 >= lo1 > 0; ρ2 > 0 at a touching switch): the ends of S_i are the vertices of A_i
    // extreme along u and −u, which the exact scan finds. D* t_k = (1 − ρ_i) u·S_i + ρ_i u·X_k E_i.
    std::vector<int> top[2], bottom[2];
    Q lo[2], hi[2];
    for (int i = 0; i < 2; ++i) {
        cx.claim(!A[i].empty(),
                 where + ": some vertex of " + kPoly[i] + " attains both neighbouring pieces' support values");
        top[i] = sc.scan[i]->argmax(cx, u, &A[i]);
        bottom[i] = sc.scan[i]->argmax(cx, minus_u, &A[i]);
        const Q us(dotz(u, sc.S[i]));
        auto place = [&](int k) -> Q {
            sc.spend_at(cx, i, k);
            return (1 - rho[i]) * us + rho[i] * Q(dotz(u, sc.scan[i]->X(static_cast<size_t>(k))) * sc.E[i]);
        };
        hi[i] = place(top[i][0]);
        lo[i] = place(bottom[i][0]);
    }
    const Q tlo = std::max(lo[0], lo[1]), thi = std::min(hi[0], hi[1]);
    cx.claim(tlo <= thi, where + ": the contact features of P1 and P2 meet");
    std::string label;
    for (int i = 0; i < 2; ++i) {
        const bool edge = lo[i] < hi[i] && thi > lo[i] && tlo < hi[i];
        // all of S_i, or the vertices at the end T meets (t_k == lo_i: bottom; t_k == hi_i: top)
        g[i] = edge ? A[i] : thi == lo[i] ? bottom[i] : top[i];
        label += edge ? 'E' : 'V';
    }
    return label;
}
}  // namespace

CurveFacts check_curve(Context& cx, const Scene& sc, const J& c, const Q& lo, const Q& hi, const std::string& pre,
                       const std::string& range_name) {
    const J& pieces = at(c, "pieces");
    cx.claim(pieces.is_array() && !pieces.empty(), pre + "pieces is a nonempty list");
    CurveFacts cf;
    std::vector<Line>& lines = cf.lines;
    std::vector<V3>& normals = cf.normals;
    std::vector<std::array<Q, 2>>& ranges = cf.ranges;
    // each piece's maximisers on P1, P2 (in the scene's cache)
    std::vector<std::array<const std::vector<int>*, 2>> maxi;
    for (size_t k = 0; k < pieces.size(); ++k) {
        const J& p = pieces[k];
        std::string w = pre + "pieces[" + std::to_string(k) + "]";
        cx.claim(p.is_object() && p.contains("contact"), w + ".contact is present");
        const bool touches = !at(p, "contact").is_null();
        if (touches)
            shape(cx, p, w,
                  {"rho1", "rho1_double", "slope", "slope_double", "intercept", "intercept_double", "contact",
                   "features", "contact_witness", "normal", "h1", "h1_double", "h2", "h2_double", "support_vertices"},
                  {"closed_form", "same_line_normals", "zero_witness"});
        else
            shape(cx, p, w,
                  {"rho1", "rho1_double", "slope", "slope_double", "intercept", "intercept_double", "contact", "normal",
                   "h1", "h1_double", "h2", "h2_double", "support_vertices"},
                  {"closed_form", "same_line_normals", "zero_witness"});
        annotation_string(cx, p, "closed_form", w);
        cf.contacts.emplace_back();
        V3 n = normal(cx, at(p, "normal"), w + ".normal");
        mpz_class H[2];  // D* h1, D* h2
        const std::vector<int>* f[2];
        const Scene::Support* own = sc.support(cx, n, H, f);
        const Q h1 = field(cx, p, "h1", w);
        cx.claim_lazy(sc.over(h1, H[0]) && sgn(H[0]) > 0,
                      [&] { return w + ".h1 = max n.(v - s1) over P1, recomputed: " + sc.value(H[0]).get_str(); });
        const Q h2 = field(cx, p, "h2", w);
        cx.claim_lazy(sc.over(h2, H[1]) && sgn(H[1]) > 0,
                      [&] { return w + ".h2 = max -n.(w - s2) over P2, recomputed: " + sc.value(H[1]).get_str(); });
        // The line from h1, h2 (now known to be the recomputed values): slope −h1/h2, and the
        // intercept b with b h2 = n·d.
        const Q a = field(cx, p, "slope", w);
        cx.claim(a == -h1 / h2, w + ".slope = -h1/h2");
        const Q b = field(cx, p, "intercept", w);
        cx.claim(sc.over(b * h2, dotz(ints(n), sc.Delta)), w + ".intercept = n.d/h2");
        const Line L{a, b};
        std::vector<Q> r = fields(cx, p, "rho1", 2, w);
        cx.claim(r[0] < r[1] || (pieces.size() == 1 && r[0] == r[1]), w + ".rho1 is a nonempty range");
        const J& sv = at(p, "support_vertices");
        shape(cx, sv, w + ".support_vertices", {"P1", "P2"});
        for (int i = 0; i < 2; ++i)
            cx.claim(has(*f[i], static_cast<int>(
                                    index(cx, at(sv, kPoly[i]), sc.count(i), w + ".support_vertices." + kPoly[i]))),
                     w + ".support_vertices attain the support values");
        // The contact features G1, G2: the vertices maximising every listed normal with this line.
        // Every touching normal maximises on the touching set T, so T lies in G1(ρ1) ∩ G2(ρ2)
        // whatever normals are listed; the witness below, a point of T in the relative interiors of
        // both, shows no smaller face holds T (a list missing a touching normal cannot have one).
        // Each direction's maximisers enter the intersection once (a normal listed again, or a
        // multiple of one, has the same maximisers): the intersections cost no more than the scans.
        std::vector<int> Gs[2];
        const std::vector<int>* G[2] = {f[0], f[1]};
        if (p.contains("same_line_normals")) {
            const J& sl = at(p, "same_line_normals");
            // At most four: each must shrink G1 or G2 to a proper face, of lower dimension, so more
            // are never needed, and each costs a scan of every vertex.
            cx.claim(sl.is_array() && !sl.empty() && sl.size() <= 4,
                     w + ".same_line_normals is a list of 1 to 4 normals");
            std::set<const Scene::Support*> seen{own};
            for (const J& o : sl) {
                V3 m = normal(cx, o, w + ".same_line_normals[]");
                mpz_class g[2];  // D* h1(m), D* h2(m): the same line iff h2 > 0, −h1 = a h2 and m·d = b h2
                const std::vector<int>* fm[2];
                const Scene::Support* dir = sc.support(cx, m, g, fm);
                cx.claim(sgn(g[1]) > 0 && -g[0] * L.a.get_den() == L.a.get_num() * g[1] &&
                             dotz(ints(m), sc.Delta) * L.b.get_den() == L.b.get_num() * g[1],
                         w + ".same_line_normals give the same line");
                bool shrinks = false;  // (a direction listed again, or the piece's own, shrinks nothing)
                if (seen.insert(dir).second)
                    for (int i = 0; i < 2; ++i) {
                        std::vector<int> both;
                        std::set_intersection(G[i]->begin(), G[i]->end(), fm[i]->begin(), fm[i]->end(),
                                              std::back_inserter(both));
                        shrinks = shrinks || both.size() < G[i]->size();
                        Gs[i] = std::move(both);
                        G[i] = &Gs[i];
                    }
                cx.claim(shrinks, w + ".same_line_normals each shrink the contact features");
            }
        }
        if (!touches) {
            cx.claim(sgn(L.at(r[0])) <= 0, w + ".contact is null only where rho2 <= 0 all along the piece");
        } else {
            cx.claim(!G[0]->empty() && !G[1]->empty(), w + ": the same-line normals share maximisers on P1 and on P2");
            const std::string label{dimension_letter(cx, sc, 0, *G[0]), dimension_letter(cx, sc, 1, *G[1])};
            cx.claim(contact_string(cx, at(p, "contact"), w + ".contact") == label,
                     w + ".contact is " + label + ", the smallest faces holding the touching set");
            cf.contacts.back() = label;
            const J& feats = at(p, "features");
            shape(cx, feats, w + ".features", {"P1", "P2"});
            std::vector<int> used[2];
            const P2 at_ = check_witness(cx, sc, at(p, "contact_witness"), w + ".contact_witness", used);
            cx.claim(sgn(at_[0]) > 0 && sgn(at_[1]) > 0 && r[0] <= at_[0] && at_[0] <= r[1] && at_[1] == L.at(at_[0]),
                     w + ".contact_witness is at a point of the piece with rho2 > 0");
            for (int i = 0; i < 2; ++i) {
                // Vertices of the feature that span it (the scene may hold more points on it).
                const std::string wf = w + ".features." + kPoly[i], ww = w + ".contact_witness." + kPoly[i];
                std::vector<int> fl = index_list(cx, at(feats, kPoly[i]), sc.count(i), wf);
                for (int v : fl) cx.claim(has(*G[i], v), wf + " lists only points of the contact feature");
                cx.claim(affine_dim(cx, sc, i, fl) == affine_dim(cx, sc, i, *G[i]), wf + " spans the contact feature");
                std::sort(used[i].begin(), used[i].end());
                for (int v : used[i]) cx.claim(has(*G[i], v), ww + " weights only vertices of the contact feature");
                cx.claim(affine_dim(cx, sc, i, used[i]) == affine_dim(cx, sc, i, *G[i]),
                         ww + " lies in the relative interior of the contact feature");
            }
        }
        // A piece whose ρ2 falls from > 0 to ≤ 0 is proved touching down to ρ2 = 0 by a witness at
        // the crossing (x0, 0): there P2(0) is the seed s2, which must lie in P1(x0). (Its other
        // end is a switch point or curve end with ρ2 > 0, witnessed below; the set of meeting
        // pairs is convex, so the piece between is touching: not only where I2 reaches.)
        const bool crosses = sgn(L.at(r[0])) > 0 && sgn(L.at(r[1])) <= 0;
        cx.claim(p.contains("zero_witness") == crosses,
                 w + ".zero_witness is given exactly when rho2 falls to 0 along the piece");
        if (crosses)
            cx.claim(check_witness(cx, sc, at(p, "zero_witness"), w + ".zero_witness") == P2{-L.b / L.a, Q(0)},
                     w + ".zero_witness is where the piece reaches rho2 = 0");
        lines.push_back(L);
        normals.push_back(n);
        maxi.push_back({f[0], f[1]});
        ranges.push_back({r[0], r[1]});
    }
    cx.claim(ranges.front()[0] == lo && ranges.back()[1] == hi,
             pre + "pieces cover " + range_name + " from end to end");
    const J& sw = at(c, "switch_points");
    cx.claim(sw.is_array() && sw.size() + 1 == pieces.size(), pre + "switch_points: one between each two pieces");
    for (size_t k = 0; k + 1 < pieces.size(); ++k) {
        std::string w = pre + "switch_points[" + std::to_string(k) + "]";
        cx.claim(ranges[k][1] == ranges[k + 1][0],
                 pre + "pieces " + std::to_string(k) + " and " + std::to_string(k + 1) + " are contiguous");
        cx.claim(lines[k].a < lines[k + 1].a, "the curve is convex: slopes increase at " + w);
        cx.claim(sw[k].is_object() && sw[k].contains("rho2") && sw[k]["rho2"].is_string(), w + ".rho2 is present");
        const bool touching = sgn(num(cx, sw[k]["rho2"], w + ".rho2")) > 0;
        if (touching)
            shape(cx, sw[k], w, {"rho1", "rho1_double", "rho2", "rho2_double", "contact", "features", "witness"},
                  {"equation"});
        else
            shape(cx, sw[k], w, {"rho1", "rho1_double", "rho2", "rho2_double", "contact"}, {"equation"});
        annotation_string(cx, sw[k], "equation", w);
        Q x = field(cx, sw[k], "rho1", w), y = field(cx, sw[k], "rho2", w);
        cx.claim(x == ranges[k][1] && y == lines[k].at(x) && y == lines[k + 1].at(x),
                 w + " is where the neighbouring lines meet");
        if (!touching) {
            // From where it reaches ρ2 = 0 the curve is one line (FORMAT.md): no switch point there.
            cx.claim(false, w + " lies at rho2 > 0: from rho2 = 0 on, the curve goes on as one line");
            cx.claim(at(sw[k], "contact").is_null(), w + ".contact is null: at rho2 <= 0 nothing touches");
            continue;
        }
        cx.claim(check_witness(cx, sc, at(sw[k], "witness"), w + ".witness") == P2{x, y},
                 w + " is touching (witness at the switch point)");
        // The contact label, recomputed from all maximisers of both neighbouring normals.
        std::vector<int> A[2], g[2];
        for (int i = 0; i < 2; ++i)
            std::set_intersection(maxi[k][i]->begin(), maxi[k][i]->end(), maxi[k + 1][i]->begin(),
                                  maxi[k + 1][i]->end(), std::back_inserter(A[i]));
        const Q rho[2] = {x, y};
        const std::string label = switch_contact(cx, sc, normals[k], normals[k + 1], rho, A, g, w);
        cx.claim(contact_string(cx, at(sw[k], "contact"), w + ".contact") == label,
                 w + ".contact is " + label + ", the features touching there");
        cf.switches.push_back({x, y, label});
        const J& feats = at(sw[k], "features");
        shape(cx, feats, w + ".features", {"P1", "P2"});
        for (int i = 0; i < 2; ++i)
            for (int v : index_list(cx, at(feats, kPoly[i]), sc.count(i), w + ".features." + kPoly[i]))
                cx.claim(has(g[i], v), w + ".features lists only vertices of the contact feature");
    }
    const J& ends = at(c, "curve_ends");
    cx.claim(ends.is_array() && ends.size() == 2, pre + "curve_ends has the two ends");
    for (int e = 0; e < 2; ++e) {
        std::string w = pre + "curve_ends[" + std::to_string(e) + "]";
        cx.claim(ends[e].is_object() && ends[e].contains("rho2") && ends[e]["rho2"].is_string(),
                 w + ".rho2 is present");
        const bool touching = sgn(num(cx, ends[e]["rho2"], w + ".rho2")) > 0;
        // A curve at or below ρ2 = 0 already at lo1 is anchored by a witness at (lo1, 0): the seed s2
        // in P1(lo1), so every pair with ρ1 >= lo1 and ρ2 > 0 meets (P1 only grows): the curve is
        // <= 0 all along I1, as claimed. (Without it any line of some normal could be claimed there.)
        const bool anchored = touching || e == 0;
        if (anchored)
            shape(cx, ends[e], w, {"rho1", "rho1_double", "rho2", "rho2_double", "witness"});
        else
            shape(cx, ends[e], w, {"rho1", "rho1_double", "rho2", "rho2_double"});
        Q x = field(cx, ends[e], "rho1", w), y = field(cx, ends[e], "rho2", w);
        const Line& L = e == 0 ? lines.front() : lines.back();
        cx.claim(x == (e == 0 ? lo : hi) && y == L.at(x), w + " is the curve at the end of " + range_name);
        cf.end_rho2[e] = y;
        if (touching)
            cx.claim(check_witness(cx, sc, at(ends[e], "witness"), w + ".witness") == P2{x, y}, w + " is touching");
        else if (anchored)
            cx.claim(check_witness(cx, sc, at(ends[e], "witness"), w + ".witness") == P2{x, Q(0)},
                     w + ".witness is at (rho1, 0): the seed of P2 lies in P1(rho1)");
    }
    return cf;
}
}  // namespace scalecert_check
