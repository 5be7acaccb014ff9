#include "certify/partition.hpp"
#include "certify/model_points.hpp"

#include <algorithm>

namespace scalecert::internal {

std::vector<Pt2> clip(const std::vector<Pt2>& poly, const Q& a, const Q& b, bool above) {
    // ρ2 >= a ρ1 + b is −a ρ1 + ρ2 >= b; ρ2 <= a ρ1 + b is a ρ1 − ρ2 >= −b.
    return above ? cut_polygon(poly, -a, Q(1), b) : cut_polygon(poly, a, Q(-1), -b);
}

static Q area2(const std::vector<Pt2>& p) {
    Q s = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        const Pt2& a = p[i];
        const Pt2& b = p[(i + 1) % p.size()];
        s += a[0] * b[1] - a[1] * b[0];
    }
    return s;
}

// I1 × I2 ∩ {ρ2 >= curve}, in time linear in the pieces. The curve c over I1 is continuous,
// convex and descending, and each piece's line supports it, so clipping the rectangle by every
// line gives that set; listing it directly avoids K clips of polygons of up to K + 4 vertices.
// Counter-clockwise: the lower chain max(c, lo2) from its left end xl (lo1, or where c meets hi2)
// to hi1 (the curve's breakpoints above lo2 and where c meets lo2), then (hi1, hi2) and (xl, hi2);
// normalize_polygon drops repeats and collinear points, so the result is the clipping's, vertex for
// vertex. A rectangle without area keeps the clipping (at most two points).
std::vector<Pt2> overlap_region(const Model& m, const TouchingCurve& c, const std::vector<Pt2>& rect) {
    const ExactScene& s = m.scene;
    auto line = [&](size_t k) -> const ContactLine& { return m.lines[c.env.pieces[c.pieces[k].env].line]; };
    if (rect.size() < 3) {
        std::vector<Pt2> over = rect;
        for (size_t k = 0; k < c.pieces.size(); ++k)
            if (!over.empty()) over = clip(over, line(k).slope, line(k).intercept, true);
        return over;
    }
    const Q &x0 = s.lo[0], &x1 = s.hi[0], &y0 = s.lo[1], &y1 = s.hi[1];
    const size_t K = c.pieces.size();
    if (line(K - 1).at(x1) > y1) return {};  // the rectangle lies below the curve
    size_t k = 0;
    Q xl = x0;
    if (line(0).at(x0) > y1) {
        while (line(k).at(c.pieces[k].to) > y1) ++k;
        xl = (y1 - line(k).intercept) / line(k).slope;
    }
    std::vector<Pt2> w;
    auto low = [&](const Q& x, const Q& y) { w.push_back({x, y > y0 ? y : y0}); };
    low(xl, line(k).at(xl));
    for (; k < K; ++k) {
        const ContactLine& L = line(k);
        const Q& to = c.pieces[k].to;
        const Q ya = L.at(std::max(c.pieces[k].from, xl)), yb = L.at(to);
        if (ya > y0 && yb < y0) w.push_back({(y0 - L.intercept) / L.slope, y0});  // c meets lo2
        if (yb >= y0 || k + 1 == K) low(to, yb);  // (breakpoints below lo2 would only be collinear)
    }
    w.push_back({x1, y1});
    w.push_back({xl, y1});
    return normalize_polygon(w);
}

CurveWitnesses curve_witnesses(const Model& m, const TouchingCurve& c, const SeedWeights& seeds) {
    CurveWitnesses W;
    const std::vector<std::pair<int, Q>>(&seed)[2] = seeds.w;
    for (const CurvePiece& p : c.pieces) {
        // A piece of no length at a switch point (I1 a single point there) has no contact of its
        // own: the touching set there is smaller than its faces, and no witness can lie in their
        // relative interiors (FORMAT.md, "The contact along a piece").
        // (The walk may know only one of the two lines there: the witness itself decides.)
        std::optional<Witness> w;
        if (const std::optional<Q> x = contact_rho1(m, c, p)) {
            try {
                w = make_witness(m, *x, m.lines[c.env.pieces[p.env].line].at(*x), p.contact.feat1, p.contact.feat2,
                                 true);
            } catch (const std::logic_error&) {
                if (p.from != p.to) throw;
                throw InputError(
                    "I1 is the single point rho1 = " + to_exact_string(p.from) +
                    ", where the curve switches pieces: a partition needs a range of rho1 there (curve, query and "
                    "certify-fp take it)");
            }
        }
        W.piece_witnesses.push_back(std::move(w));
        const ContactLine& L = m.lines[c.env.pieces[p.env].line];
        std::optional<Witness> z;
        if (sgn(L.at(p.from)) > 0 && sgn(L.at(p.to)) <= 0)
            z = make_witness(m, -L.intercept / L.slope, Q(0), c.env.pieces[p.env].line);
        W.zero_witnesses.push_back(std::move(z));
    }
    for (const CurveSwitch& sp : c.switches)
        if (sgn(sp.rho2) > 0)
            W.switch_witnesses.push_back(make_witness(m, sp.rho1, sp.rho2, c.env.pieces[c.pieces[sp.left].env].line));
    for (int e = 0; e < 2; ++e) {
        const CurvePiece& p = e == 0 ? c.pieces.front() : c.pieces.back();
        Q x = e == 0 ? p.from : p.to;
        size_t line = c.env.pieces[p.env].line;
        Q y = m.lines[line].at(x);
        if (sgn(y) > 0) {
            W.end_witness[e] = make_witness(m, x, y, line);
        } else if (e == 0) {  // s2 in P1(lo1): on the walk, from where the curve reaches 0 (x0 ≤ lo1)
            W.end_witness[e] = points_of(m).witness_off_the_curve(m, c, x, Q(0), seed);
        }
    }
    return W;
}

Partition build_partition(const Model& m, const TouchingCurve& c) {
    const ExactScene& s = m.scene;
    Partition P;
    std::vector<Pt2> rect =
        normalize_polygon({{s.lo[0], s.lo[1]}, {s.hi[0], s.lo[1]}, {s.hi[0], s.hi[1]}, {s.lo[0], s.hi[1]}});
    P.overlap = overlap_region(m, c, rect);
    const std::vector<Pt2>& over = P.overlap;
    P.seeds = seed_weights(m);
    const std::vector<std::pair<int, Q>>(&seed)[2] = P.seeds.w;
    for (const Pt2& v : over) {
        // A vertex on the curve gets the witness of its contact; one strictly above, any common
        // point: on the hull path by a program over every vertex; on the walk (no hull, up to 10^6
        // points), the witness of the curve point below it, or of where the curve reaches ρ2 = 0
        // left of it, lifted (lift_witness).
        size_t k = c.env.locate(v[0]);
        size_t line = c.env.pieces[k].line;
        const ContactLine& L = m.lines[line];
        bool on = L.at(v[0]) == v[1];
        P.overlap_witnesses.push_back(on ? make_witness(m, v[0], v[1], line)
                                         : points_of(m).witness_off_the_curve(m, c, v[0], v[1], seed));
    }
    for (size_t k = 0; k < c.pieces.size(); ++k) {
        const CurvePiece& p = c.pieces[k];
        const ContactLine& L = m.lines[c.env.pieces[p.env].line];
        std::vector<Pt2> box =
            normalize_polygon({{p.from, s.lo[1]}, {p.to, s.lo[1]}, {p.to, s.hi[1]}, {p.from, s.hi[1]}});
        if (box.size() < 3) continue;
        std::vector<Pt2> sep = clip(box, L.slope, L.intercept, false);
        if (sep.size() >= 3 && sgn(area2(sep)) > 0) P.separated.push_back({k, sep});
    }
    static_cast<CurveWitnesses&>(P) = curve_witnesses(m, c, P.seeds);
    if (sgn(c.growth.value) > 0)
        P.growth_witness = make_witness(m, c.growth.value, c.growth.value, c.env.pieces[c.growth.env].line);
    return P;
}

}  // namespace scalecert::internal
