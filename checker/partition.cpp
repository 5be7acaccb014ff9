// A partition file (kind "partition"; certificates/FORMAT.md, "Fields of a partition file" and
// "Why a file that passes proves the partition"): the scene and its seeds' interior weights, the
// curve over I1 (curve.cpp), the growth distance and its certificate, and the two regions, which
// are recomputed from the verified pieces and compared vertex by vertex; the engine's `model`
// statistics are an annotation of a fixed shape.
#include "curve.hpp"
#include "formats.hpp"
#include "json.hpp"
#include "numbers.hpp"
#include "polygon.hpp"
#include "scene.hpp"

namespace scalecert_check {
// From the pieces once they are verified: contiguous over I1, each nonempty, neighbouring lines
// equal at their common end (the switch points), slopes increasing. So the curve c is continuous
// and convex on I1, and each piece's line, which agrees with c on an interval, supports it:
// L_k <= c on all of I1, and max_k L_k = c there. Clipping the rectangle by every line (O(K)
// clips of polygons of up to K + 4 vertices) therefore gives the set
// {(ρ1, ρ2) in the rectangle : ρ2 >= c(ρ1)}, which this walk lists directly, counter-clockwise:
// the lower chain max(c, lo2) from its left end to hi1 (the curve's breakpoints above lo2, where c
// meets lo2, the corner (hi1, lo2)), then (hi1, hi2) and the top edge back. Its corners are those
// of that same convex set, so normalize() writes it exactly as the clipping does
// (tests/checker/test_partition.cpp compares both on random convex curves). Slopes are −h1/h2 < 0:
// c decreases. A rectangle without area (lo = hi in I1 or I2) keeps the clipping, which is linear
// for a polygon of at most two points.
std::vector<P2> overlap_region(const Scene& sc, const std::vector<P2>& rect, const std::vector<Line>& lines,
                               const std::vector<std::array<Q, 2>>& ranges) {
    const Q &x0 = sc.lo[0], &x1 = sc.hi[0], &y0 = sc.lo[1], &y1 = sc.hi[1];
    if (rect.size() < 3) {
        std::vector<P2> over = rect;
        for (const Line& L : lines)
            if (!over.empty()) over = clip(over, L, true);
        return over;
    }
    if (lines.back().at(x1) > y1) return {};  // the rectangle lies below the curve
    // The left end: lo1 when c(lo1) <= hi2, else where c meets hi2 (in the first piece whose right
    // end is on or below hi2).
    size_t k = 0;
    Q xl = x0;
    if (lines[0].at(x0) > y1) {
        while (lines[k].at(ranges[k][1]) > y1) ++k;
        xl = (y1 - lines[k].b) / lines[k].a;
    }
    std::vector<P2> w;
    Q y = lines[k].at(xl);
    if (y <= y0)
        w.push_back({xl, y0});  // the curve is at or below lo2 from xl on
    else {
        w.push_back({xl, y});
        for (;; ++k) {
            const Q& xr = ranges[k][1];
            y = lines[k].at(xr);
            if (y <= y0) {  // c meets lo2 in this piece
                w.push_back({(y0 - lines[k].b) / lines[k].a, y0});
                break;
            }
            w.push_back({xr, y});
            if (k + 1 == lines.size()) break;
        }
    }
    w.push_back({x1, y0 > y ? y0 : y});
    w.push_back({x1, y1});
    w.push_back({xl, y1});
    return normalize(w);
}

namespace {
// Engine statistics: an annotation, but of a fixed shape (non-negative integers): the hull
// path's, or the walk's (`engine: "scan"`).
void check_model(Context& cx, const J& m) {
    auto count = [&cx](const J& j, const std::string& w) { cx.claim(natural(j), w + " is a count"); };
    if (m.is_object() && m.contains("engine")) {  // the walk's statistics (no hull)
        cx.claim(at(m, "engine") == J("scan"), "model.engine is \"scan\"");
        shape(cx, m, "model",
              {"engine", "P1", "P2", "contact_lines", "support_queries", "gift_wrap_steps", "start_lp",
               "decided_by_filter", "decided_exactly"});
        for (const char* p : kPoly) {
            shape(cx, at(m, p), std::string("model.") + p, {"points"});
            count(at(at(m, p), "points"), std::string("model.") + p + ".points");
        }
        for (const char* k : {"contact_lines", "support_queries", "gift_wrap_steps"})
            count(at(m, k), std::string("model.") + k);
        shape(cx, at(m, "start_lp"), "model.start_lp", {"solves", "rows"});
        for (const char* k : {"solves", "rows"}) count(at(at(m, "start_lp"), k), std::string("model.start_lp.") + k);
        for (const char* k : {"decided_by_filter", "decided_exactly"}) {
            shape(cx, at(m, k), std::string("model.") + k, {"support_comparisons"});
            count(at(at(m, k), "support_comparisons"), std::string("model.") + k + ".support_comparisons");
        }
        return;
    }
    shape(cx, m, "model",
          {"P1", "P2", "facet_normals", "contact_lines", "edge_pairs_tested", "gauss_arc_crossings",
           "decided_by_filter", "decided_exactly"});
    for (const char* p : kPoly) {
        shape(cx, at(m, p), std::string("model.") + p, {"vertices", "edges", "faces"});
        for (const char* k : {"vertices", "edges", "faces"})
            count(at(at(m, p), k), std::string("model.") + p + "." + k);
    }
    for (const char* k : {"facet_normals", "contact_lines", "edge_pairs_tested", "gauss_arc_crossings"})
        count(at(m, k), std::string("model.") + k);
    for (const char* k : {"decided_by_filter", "decided_exactly"}) {
        shape(cx, at(m, k), std::string("model.") + k, {"arc_signs", "support_comparisons"});
        for (const char* s : {"arc_signs", "support_comparisons"})
            count(at(at(m, k), s), std::string("model.") + k + "." + s);
    }
}
}  // namespace

void check_partition(Context& cx, const J& c) {
    shape(cx, c, "",
          {"format", "kind", "pieces", "switch_points", "growth_distance", "growth_distance_double",
           "growth_distance_in_rectangle", "curve_ends", "growth_distance_certificate", "regions", "seed_interior",
           "scene"},
          {"model", "growth_distance_note"});
    const Scene sc = read_scene(cx, at(c, "scene"));
    check_seed_interior(cx, sc, at(c, "seed_interior"));
    if (c.contains("model")) check_model(cx, at(c, "model"));
    const CurveFacts cf = check_curve(cx, sc, c, sc.lo[0], sc.hi[0], "", "I1");
    const std::vector<Line>& lines = cf.lines;
    const std::vector<std::array<Q, 2>>& ranges = cf.ranges;
    // Growth distance: (ρ*, ρ*) touches — the plane of n has n.d = ρ*(h1 + h2) and a witness — or
    // the seeds coincide and ρ* = 0.
    Q g = field(cx, c, "growth_distance", "");
    const J& gc = at(c, "growth_distance_certificate");
    cx.claim(gc.is_object(), "growth_distance_certificate is an object");
    if (gc.contains("seeds_coincide")) {
        shape(cx, gc, "growth_distance_certificate", {"seeds_coincide"});
        cx.claim(at(gc, "seeds_coincide") == J(true), "growth_distance_certificate.seeds_coincide is true");
        cx.claim(!sgn(sc.Delta[0]) && !sgn(sc.Delta[1]) && !sgn(sc.Delta[2]) && sgn(g) == 0,
                 "growth distance 0: the seeds coincide");
    } else {
        const std::string w = "growth_distance_certificate";
        shape(cx, gc, w, {"normal", "h1", "h1_double", "h2", "h2_double", "witness"});
        V3 n = normal(cx, at(gc, "normal"), w + ".normal");
        mpz_class H[2];  // D* h1, D* h2
        sc.support(cx, n, H);
        cx.claim(sc.over(field(cx, gc, "h1", w), H[0]) && sc.over(field(cx, gc, "h2", w), H[1]),
                 w + " support values recomputed");
        cx.claim(sgn(H[0]) > 0 && sgn(H[1]) > 0 && dotz(ints(n), sc.Delta) * g.get_den() == g.get_num() * (H[0] + H[1]),
                 "the growth distance's plane touches at (rho*, rho*)");
        cx.claim(check_witness(cx, sc, at(gc, "witness"), w + ".witness") == P2{g, g},
                 "growth distance witness is at (rho*, rho*)");
    }
    if (c.contains("growth_distance_note"))
        cx.claim(at(c, "growth_distance_note").is_string() && sgn(g) == 0,
                 "growth_distance_note is a string, written only when the growth distance is 0");
    bool inside = g >= sc.lo[0] && g <= sc.hi[0] && g >= sc.lo[1] && g <= sc.hi[1];
    const J& in_rect = at(c, "growth_distance_in_rectangle");
    cx.claim(in_rect.is_boolean() && in_rect.get<bool>() == inside, "growth_distance_in_rectangle is right");
    for (size_t k = 0; k < lines.size(); ++k)
        if (g >= ranges[k][0] && g <= ranges[k][1])
            cx.claim(lines[k].at(g) == g, "the growth distance lies on piece " + std::to_string(k));
    // Regions: the rectangle cut along the curve, recomputed here and compared vertex by vertex.
    const J& reg = at(c, "regions");
    shape(cx, reg, "regions", {"overlap", "separated"});
    std::vector<P2> rect = rectangle(sc.lo, sc.hi);
    const std::vector<P2> over = overlap_region(sc, rect, lines, ranges);
    const J& ov = at(reg, "overlap");
    shape(cx, ov, "regions.overlap", {"vertices", "vertices_double", "witnesses"});
    cx.claim(polygon(cx, ov, "regions.overlap") == over, "regions.overlap is the rectangle on and above the curve");
    const J& wit = at(ov, "witnesses");
    cx.claim(wit.is_array() && wit.size() == over.size(), "every vertex of the overlap polygon has a witness");
    for (size_t k = 0; k < over.size(); ++k)
        cx.claim(check_witness(cx, sc, wit[k], "regions.overlap.witnesses[" + std::to_string(k) + "]") == over[k],
                 "overlap witness " + std::to_string(k) + " is at its vertex");
    std::vector<std::vector<P2>> seps;
    std::vector<size_t> owners;
    for (size_t k = 0; k < lines.size(); ++k) {
        const Q &x0 = ranges[k][0], &x1 = ranges[k][1];
        std::vector<P2> box = normalize({{x0, sc.lo[1]}, {x1, sc.lo[1]}, {x1, sc.hi[1]}, {x0, sc.hi[1]}});
        if (box.size() < 3) continue;
        std::vector<P2> s = clip(box, lines[k], false);
        Q area = 0;
        for (size_t i = 0; i < s.size(); ++i)
            area += s[i][0] * s[(i + 1) % s.size()][1] - s[i][1] * s[(i + 1) % s.size()][0];
        if (s.size() >= 3 && sgn(area) > 0) {
            seps.push_back(s);
            owners.push_back(k);
        }
    }
    const J& sr = at(reg, "separated");
    cx.claim(sr.is_array() && sr.size() == seps.size(),
             "regions.separated has one polygon per piece with area below the curve");
    for (size_t k = 0; k < seps.size(); ++k) {
        std::string w = "regions.separated[" + std::to_string(k) + "]";
        shape(cx, sr[k], w, {"piece", "vertices", "vertices_double"});
        cx.claim(index(cx, at(sr[k], "piece"), lines.size(), w + ".piece") == owners[k], w + ".piece names its piece");
        cx.claim(polygon(cx, sr[k], w) == seps[k], w + " is the rectangle strictly below its piece");
    }
}
}  // namespace scalecert_check
