// The overlap region of two compounds (region.hpp). One of the few translation units that
// include CGAL: its 2D Boolean set operations, on exact rationals (gmpxx), for the union.
#include "compound/region.hpp"

#include "curve/contact_lines.hpp"

#include <algorithm>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/gmpxx.h>

namespace scalecert::internal {

namespace {
using K = CGAL::Simple_cartesian<mpq_class>;
using Polygon = CGAL::Polygon_2<K>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<K>;
using PolygonSet = CGAL::Polygon_set_2<K>;

bool lower(const Point2q& a, const Point2q& b) { return a[1] != b[1] ? a[1] < b[1] : a[0] < b[0]; }

std::vector<Point2q> ring(const Polygon& p) {
    std::vector<Point2q> v;
    for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it) v.push_back({it->x(), it->y()});
    return normalize_polygon(std::move(v));
}
}  // namespace

std::vector<Vec3z> minkowski_facet_normals(const Polyhedron& A, const Polyhedron& B) {
    HullModel m;  // the overlay reads the two polyhedra only
    m.P[0] = A;
    m.P[1] = B;
    return all_facet_normals(m);
}

PairRegion pair_region(const Polyhedron& A, const Polyhedron& B, const Vec3q& s1, const Vec3q& s2, const Q lo[2], const Q hi[2]) {
    PairRegion r;
    r.polygon = normalize_polygon({{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}});
    const Vec3q d = sub(s2, s1);
    for (const Vec3z& n : minkowski_facet_normals(A, B)) {
        const Vec3q nq = to_q(n);
        HalfPlane h;
        h.a = A.support(n) - dot(nq, s1);
        h.b = B.support(neg(n)) + dot(nq, s2);
        h.c = dot(nq, d);
        h.normal = n;
        if (!r.polygon.empty()) {
            std::vector<Point2q> cut = cut_polygon(r.polygon, h.a, h.b, h.c);
            if (cut != r.polygon) {
                r.fence.push_back(r.constraints.size());
                r.polygon = std::move(cut);
            }
        }
        r.constraints.push_back(std::move(h));
    }
    // Fence cuts that a later one made redundant: dropped while the rest still give the polygon
    // (from the last, so the survivors are the earliest that suffice; each test a few cuts).
    const std::vector<Point2q> rect = normalize_polygon({{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}});
    for (size_t k = r.fence.size(); k-- > 0 && r.fence.size() > 1;) {
        std::vector<Point2q> p = rect;
        for (size_t j = 0; j < r.fence.size() && !p.empty(); ++j)
            if (j != k) p = cut_polygon(p, r.constraints[r.fence[j]].a, r.constraints[r.fence[j]].b, r.constraints[r.fence[j]].c);
        if (p == r.polygon) r.fence.erase(r.fence.begin() + static_cast<long>(k));
    }
    return r;
}

std::vector<RegionPiece> union_of(const std::vector<std::vector<Point2q>>& convex) {
    PolygonSet set;
    for (const std::vector<Point2q>& c : convex) {
        if (c.size() < 3) continue;  // no area: not part of a union of regions
        Polygon p;
        for (const Point2q& v : c) p.push_back(K::Point_2(v[0], v[1]));
        if (p.orientation() == CGAL::CLOCKWISE) p.reverse_orientation();
        set.join(p);
    }
    std::vector<PolygonWithHoles> pieces;
    set.polygons_with_holes(std::back_inserter(pieces));
    std::vector<RegionPiece> out;
    for (const PolygonWithHoles& ph : pieces) {
        RegionPiece r;
        r.outer = ring(ph.outer_boundary());
        for (auto h = ph.holes_begin(); h != ph.holes_end(); ++h) r.holes.push_back(ring(*h));
        std::sort(r.holes.begin(), r.holes.end(), [](const auto& x, const auto& y) { return lower(x.front(), y.front()); });
        out.push_back(std::move(r));
    }
    std::sort(out.begin(), out.end(), [](const RegionPiece& x, const RegionPiece& y) { return lower(x.outer.front(), y.outer.front()); });
    return out;
}

namespace {
// The box holding P(ρ) = s + ρ(P − s) for every ρ in [lo, hi] (ρ > 0 keeps the order along an
// axis, and each coordinate is linear in ρ: the ends decide).
std::array<std::array<Q, 2>, 3> swept_box(const Polyhedron& P, const Vec3q& s, const Q& lo, const Q& hi) {
    std::array<std::array<Q, 2>, 3> b;
    for (int c = 0; c < 3; ++c) {
        Q m = P.points[static_cast<size_t>(P.vertices.front())][c], M = m;
        for (int v : P.vertices) {
            const Q& x = P.points[static_cast<size_t>(v)][c];
            if (x < m) m = x;
            if (x > M) M = x;
        }
        const Q a = s[c] + lo * (m - s[c]), bb = s[c] + hi * (m - s[c]), e = s[c] + lo * (M - s[c]), f = s[c] + hi * (M - s[c]);
        b[c] = {std::min(a, bb), std::max(e, f)};
    }
    return b;
}
}  // namespace

CompoundRegion compound_region(const ExactScene& sc, const std::string& name) {
    CompoundRegion r;
    std::vector<Polyhedron>(&parts)[2] = r.parts;
    std::vector<std::array<std::array<Q, 2>, 3>> boxes[2];
    const char* pname[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        const PolyInput& in = sc.P[i];
        const std::vector<std::vector<Vec3q>> one{in.points};
        const std::vector<std::vector<Vec3q>>& list = in.parts.empty() ? one : in.parts;
        for (size_t k = 0; k < list.size(); ++k) {
            const std::string part = in.parts.empty() ? std::string(pname[i]) : std::string(pname[i]) + ".parts[" + std::to_string(k) + "]";
            parts[i].push_back(build_polyhedron(list[k], name + ": " + part));
            boxes[i].push_back(swept_box(parts[i].back(), in.seed, sc.lo[i], sc.hi[i]));
        }
    }
    std::vector<std::vector<Point2q>> polys;
    const Vec3q &s1 = sc.P[0].seed, &s2 = sc.P[1].seed;
    for (size_t a = 0; a < parts[0].size(); ++a)
        for (size_t b = 0; b < parts[1].size(); ++b) {
            CompoundRegion::Pair p{static_cast<int>(a), static_cast<int>(b), false, {}, {}, {}};
            for (int c = 0; c < 3 && !p.pruned; ++c) {
                const int side = boxes[0][a][c][1] < boxes[1][b][c][0] ? 1 : boxes[1][b][c][1] < boxes[0][a][c][0] ? -1 : 0;
                if (side) p.pruned = true, p.prune_axis = c, p.prune_side = side;
            }
            if (p.pruned) {
                ++r.pruned;
            } else {
                ++r.built;
                PairRegion pr = pair_region(parts[0][a], parts[1][b], s1, s2, sc.lo, sc.hi);
                p.polygon = std::move(pr.polygon);
                p.constraints = std::move(pr.constraints);
                p.fence = std::move(pr.fence);
                polys.push_back(p.polygon);
                // Where it meets ρ1 = ρ2: the polygon cut to the diagonal (a point or a segment).
                const std::vector<Point2q> diag = cut_polygon(cut_polygon(p.polygon, Q(1), Q(-1), Q(0)), Q(-1), Q(1), Q(0));
                if (!diag.empty()) {
                    Q t0 = diag.front()[0], t1 = t0;
                    for (const Point2q& x : diag) t0 = std::min(t0, x[0]), t1 = std::max(t1, x[0]);
                    r.growth.push_back({t0, t1, p.part1, p.part2});
                }
            }
            r.pairs.push_back(std::move(p));
        }
    r.region = union_of(polys);
    // The intervals merged: sorted by start (ties: the first pair), each joined with those that
    // start within it.
    std::stable_sort(r.growth.begin(), r.growth.end(), [](const auto& x, const auto& y) { return x.from < y.from; });
    std::vector<CompoundRegion::Interval> merged;
    for (const auto& iv : r.growth) {
        if (!merged.empty() && iv.from <= merged.back().to) {
            if (iv.to > merged.back().to) merged.back().to = iv.to;
        } else {
            merged.push_back(iv);
        }
    }
    r.growth = std::move(merged);
    return r;
}

CompoundVerdict compound_verdict(const CompoundRegion& r, const Q& rho1, const Q& rho2) {
    CompoundVerdict v{"separated"};
    for (const CompoundRegion::Pair& p : r.pairs) {
        if (p.pruned) continue;
        int least = 1;  // the smallest sign of a ρ1 + b ρ2 − c over the pair's half-planes
        for (const HalfPlane& h : p.constraints) least = std::min(least, sgn(Q(h.a * rho1 + h.b * rho2 - h.c)));
        if (least > 0) return {"overlapping", p.part1, p.part2};
        if (least == 0 && v.part1 < 0) v = {"touching", p.part1, p.part2};
    }
    return v;
}

}  // namespace scalecert::internal
