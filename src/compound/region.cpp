// The overlap region of two compounds (region.hpp). One of the few translation units that
// include CGAL: its 2D Boolean set operations for the union, on its lazy exact kernel (Epeck:
// interval arithmetic first, exact rationals where the intervals cannot decide), with the
// rational corners read in and the union's corners read out exactly.
#include "compound/region.hpp"

#include "curve/contact_lines.hpp"
#include "numeric/parallel.hpp"
#include "numeric/timing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/gmpxx.h>

#include <type_traits>

namespace scalecert::internal {

namespace {
using K = CGAL::Epeck;
using Polygon = CGAL::Polygon_2<K>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<K>;
using PolygonSet = CGAL::Polygon_set_2<K>;
using ET = K::FT::ET;  // the kernel's exact rationals (GMP's, under one of three wrappers)

// (templates, so that only the branch of the kernel's own type is compiled)
template <class E>
E exact_of(const Q& q) {
    if constexpr (std::is_same_v<E, Q>)
        return q;
    else
        return E(q.get_mpq_t());  // boost's gmp_rational and CGAL's Gmpq take an mpq_t
}
template <class E>
Q rational_of(const E& e) {
    if constexpr (std::is_same_v<E, Q>)
        return e;
    else if constexpr (std::is_same_v<E, CGAL::Gmpq>)
        return Q(e.mpq());
    else
        return Q(e.backend().data());  // boost::multiprecision::mpq_rational
}
K::FT to_kernel(const Q& q) { return K::FT(exact_of<ET>(q)); }
Q from_kernel(const K::FT& x) { return rational_of<ET>(CGAL::exact(x)); }

bool lower(const Point2q& a, const Point2q& b) { return a[1] != b[1] ? a[1] < b[1] : a[0] < b[0]; }

std::vector<Point2q> ring(const Polygon& p) {
    std::vector<Point2q> v;
    for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it)
        v.push_back({from_kernel(it->x()), from_kernel(it->y())});
    return normalize_polygon(std::move(v));
}
}  // namespace

std::vector<Vec3z> minkowski_facet_normals(const Polyhedron& A, const Polyhedron& B) { return all_facet_normals(A, B); }

std::vector<HalfPlane> pair_constraints(const Polyhedron& A, const Polyhedron& B, const Vec3q& s1, const Vec3q& s2) {
    // In integers: s_i = S_i / D_i, and the supports times each part's scale; one rational each.
    Z D1, D2;
    const Vec3z S1 = over_common_denominator(s1, D1), S2 = over_common_denominator(s2, D2);
    const std::vector<Vec3z> normals = minkowski_facet_normals(A, B);
    std::vector<HalfPlane> hs;
    hs.reserve(normals.size());  // (mpq's move may throw: a reallocation would copy)
    Z ha, hb;
    for (const Vec3z& n : normals) {
        A.argmax(n, nullptr, &ha);       // max over A of n·v, times A.scale
        B.argmax(neg(n), nullptr, &hb);  // max over B of −n·w, times B.scale
        const Z n1 = dotz(n, S1), n2 = dotz(n, S2);
        HalfPlane h;
        h.a = Q(Z(ha * D1 - A.scale * n1), Z(A.scale * D1));  // hA(n) = max n·v − n·s1
        h.b = Q(Z(hb * D2 + B.scale * n2), Z(B.scale * D2));  // hB(n) = max −n·w + n·s2
        h.c = Q(Z(n2 * D1 - n1 * D2), Z(D1 * D2));            // n·d = n·s2 − n·s1
        h.a.canonicalize(), h.b.canonicalize(), h.c.canonicalize();
        h.normal = n;
        h.ad = filter::region_double(h.a), h.bd = filter::region_double(h.b), h.cd = filter::region_double(h.c);
        hs.push_back(std::move(h));
    }
    return hs;
}

namespace {
using filter::region_double;

struct PointD {
    double x, y;
};
std::vector<PointD> doubles(const std::vector<Point2q>& p) {
    std::vector<PointD> d;
    for (const Point2q& v : p) d.push_back({region_double(v[0]), region_double(v[1])});
    return d;
}

// The convex polygon p (corners counter-clockwise) cut to a ρ1 + b ρ2 >= c in doubles: a guess
// of whether the constraint cuts the polygon at all (it picks the candidates; exact cuts decide).
// `label` names the constraint each edge lies on (edge i from corner i to i + 1; −1: the
// rectangle), and the cut's own edge gets `k`.
std::vector<PointD> cut_d(const std::vector<PointD>& p, std::vector<long>& label, const HalfPlane& h, long k,
                          bool& cut) {
    std::vector<PointD> out;
    std::vector<long> out_label;
    cut = false;
    const double scale = std::fabs(h.ad) + std::fabs(h.bd) + std::fabs(h.cd);
    for (size_t i = 0; i < p.size(); ++i) {
        const PointD &x = p[i], &y = p[(i + 1) % p.size()];
        const double fx = h.ad * x.x + h.bd * x.y - h.cd, fy = h.ad * y.x + h.bd * y.y - h.cd;
        if (fx >= 0) out.push_back(x), out_label.push_back(fx == 0 && fy < 0 ? k : label[i]);
        if (fx < -1e-12 * scale) cut = true;
        if ((fx > 0 && fy < 0) || (fx < 0 && fy > 0)) {
            const double t = fx / (fx - fy);
            out.push_back({x.x + t * (y.x - x.x), x.y + t * (y.y - x.y)});
            out_label.push_back(fx > 0 ? k : label[i]);
        }
    }
    label = std::move(out_label);
    return out;
}
}  // namespace

// Output-sensitive: the constraints on the edges of the polygon cut in doubles are the candidates
// (when that polygon has area; when it is empty, as few of the constraints that cut it as still
// empty it; else every constraint that cut it), cut exactly; every other
// constraint is then checked exactly (filter 8) at the polygon's corners, and cuts in turn if it
// fails anywhere. The polygon only shrinks, so a constraint that held stays held: the result is
// the rectangle cut by every constraint. The fence: for a polygon with area, for each edge not
// on the rectangle, the first candidate whose line holds both its ends (the polygon is the
// rectangle cut by its edges' half-planes); otherwise the candidates, each dropped (from the last)
// while the others still give the polygon.
PairRegion pair_region(const Polyhedron& A, const Polyhedron& B, const Vec3q& s1, const Vec3q& s2, const Q lo[2],
                       const Q hi[2], filter::PredicateStats* stats) {
    filter::PredicateStats local;
    filter::PredicateStats& st = stats ? *stats : local;
    PairRegion r;
    const std::vector<Point2q> rect =
        normalize_polygon({{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}});
    r.constraints = pair_constraints(A, B, s1, s2);
    const std::vector<HalfPlane>& hs = r.constraints;
    std::vector<size_t> cand;
    {
        std::vector<PointD> pd = doubles(rect);
        std::vector<long> label(pd.size(), -1);
        for (size_t k = 0; k < hs.size() && !pd.empty(); ++k) {
            bool cut = false;
            std::vector<long> l = label;
            std::vector<PointD> q = cut_d(pd, l, hs[k], static_cast<long>(k), cut);
            if (cut) cand.push_back(k), pd = std::move(q), label = std::move(l);
        }
        if (pd.size() >= 3) {  // the constraints on its edges
            std::vector<size_t> on;
            for (long k : label)
                if (k >= 0) on.push_back(static_cast<size_t>(k));
            std::sort(on.begin(), on.end());
            on.erase(std::unique(on.begin(), on.end()), on.end());
            cand = std::move(on);
        } else if (pd.empty()) {  // empty in doubles: each cut dropped (from the last) while the rest empty it
            auto empties = [&](const std::vector<size_t>& ks) {
                std::vector<PointD> q = doubles(rect);
                for (size_t k : ks) {
                    if (q.empty()) break;
                    bool cut = false;
                    std::vector<long> scratch(q.size(), -1);
                    std::vector<PointD> c = cut_d(q, scratch, hs[k], static_cast<long>(k), cut);
                    if (cut) q = std::move(c);
                }
                return q.empty();
            };
            for (size_t i = cand.size(); i-- > 0 && cand.size() > 1;) {
                std::vector<size_t> without = cand;
                without.erase(without.begin() + static_cast<long>(i));
                if (empties(without)) cand = std::move(without);
            }
        }
    }
    std::vector<Point2q> p = rect;
    for (size_t k : cand)
        if (!p.empty()) p = cut_polygon(p, hs[k].a, hs[k].b, hs[k].c);
    std::vector<bool> in_cand(hs.size(), false);
    for (size_t k : cand) in_cand[k] = true;
    std::vector<PointD> pd = doubles(p);
    for (size_t k = 0; k < hs.size() && !p.empty(); ++k) {
        if (in_cand[k]) continue;
        bool holds = true;
        for (size_t i = 0; i < p.size() && holds; ++i) holds = hs[k].side(p[i][0], p[i][1], pd[i].x, pd[i].y, st) >= 0;
        if (holds) continue;
        p = cut_polygon(p, hs[k].a, hs[k].b, hs[k].c);
        pd = doubles(p);
        cand.push_back(k);
        in_cand[k] = true;
    }
    r.polygon = p;
    if (p.size() >= 3) {
        auto on_rect_side = [&](const Point2q& u, const Point2q& v) {
            return (u[0] == v[0] && (u[0] == lo[0] || u[0] == hi[0])) ||
                   (u[1] == v[1] && (u[1] == lo[1] || u[1] == hi[1]));
        };
        for (size_t i = 0; i < p.size(); ++i) {
            const Point2q &u = p[i], &v = p[(i + 1) % p.size()];
            if (on_rect_side(u, v)) continue;
            size_t found = hs.size();
            for (size_t k : cand)
                if (hs[k].side(u[0], u[1], pd[i].x, pd[i].y, st) == 0 &&
                    hs[k].side(v[0], v[1], pd[(i + 1) % p.size()].x, pd[(i + 1) % p.size()].y, st) == 0) {
                    found = k;
                    break;
                }
            if (found == hs.size()) throw std::logic_error("a pair polygon's edge lies on no constraint");
            r.fence.push_back(found);
        }
    } else {
        r.fence = cand;
        for (size_t k = r.fence.size(); k-- > 0 && r.fence.size() > 1;) {
            std::vector<Point2q> q = rect;
            for (size_t j = 0; j < r.fence.size() && !q.empty(); ++j)
                if (j != k) q = cut_polygon(q, hs[r.fence[j]].a, hs[r.fence[j]].b, hs[r.fence[j]].c);
            if (q == p) r.fence.erase(r.fence.begin() + static_cast<long>(k));
        }
    }
    std::sort(r.fence.begin(), r.fence.end());
    r.fence.erase(std::unique(r.fence.begin(), r.fence.end()), r.fence.end());
    return r;
}

std::vector<RegionPiece> union_of(const std::vector<std::vector<Point2q>>& convex) {
    std::vector<Polygon> polys;
    for (const std::vector<Point2q>& c : convex) {
        if (c.size() < 3) continue;  // no area: not part of a union of regions
        Polygon p;
        for (const Point2q& v : c) p.push_back(K::Point_2(to_kernel(v[0]), to_kernel(v[1])));
        if (p.orientation() == CGAL::CLOCKWISE) p.reverse_orientation();
        polys.push_back(std::move(p));
    }
    // All at once: CGAL merges them divide-and-conquer (one at a time, the union of n polygons
    // cost n sweeps of a growing arrangement: 5.6 s for 906 pair polygons).
    PolygonSet set;
    if (!polys.empty()) set.join(polys.begin(), polys.end());
    std::vector<PolygonWithHoles> pieces;
    set.polygons_with_holes(std::back_inserter(pieces));
    std::vector<RegionPiece> out;
    for (const PolygonWithHoles& ph : pieces) {
        RegionPiece r;
        r.outer = ring(ph.outer_boundary());
        for (auto h = ph.holes_begin(); h != ph.holes_end(); ++h) r.holes.push_back(ring(*h));
        std::sort(r.holes.begin(), r.holes.end(),
                  [](const auto& x, const auto& y) { return lower(x.front(), y.front()); });
        out.push_back(std::move(r));
    }
    std::sort(out.begin(), out.end(),
              [](const RegionPiece& x, const RegionPiece& y) { return lower(x.outer.front(), y.outer.front()); });
    return out;
}

std::array<std::array<Q, 2>, 3> bounding_box(const Polyhedron& P) {
    std::array<std::array<Q, 2>, 3> b;
    for (size_t c = 0; c < 3; ++c) {
        Q m = P.points[static_cast<size_t>(P.vertices.front())][c], M = m;
        for (int v : P.vertices) {
            const Q& x = P.points[static_cast<size_t>(v)][c];
            if (x < m) m = x;
            if (x > M) M = x;
        }
        b[c] = {m, M};
    }
    return b;
}

void build_parts(const ExactScene& sc, const std::string& name, std::vector<Polyhedron> (&parts)[2]) {
    const size_t m = std::max<size_t>(1, sc.P[0].parts.size()), n = std::max<size_t>(1, sc.P[1].parts.size());
    if (m * n > kMaxPartPairs)
        throw InputError(name + ": " + std::to_string(m) + " x " + std::to_string(n) + " part pairs, more than " +
                         std::to_string(kMaxPartPairs) + " (the limit)");
    const char* pname[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        const PolyInput& in = sc.P[i];
        const std::vector<std::vector<Vec3q>> one{in.points};
        const std::vector<std::vector<Vec3q>>& list = in.parts.empty() ? one : in.parts;
        for (size_t k = 0; k < list.size(); ++k) {
            const std::string part = in.parts.empty() ? std::string(pname[i]) : part_label(i, in, k);
            parts[i].push_back(build_polyhedron(list[k], name + ": " + part));
        }
    }
}

namespace {
// The box holding P(ρ) = s + ρ(P − s) for every ρ in [lo, hi] (ρ > 0 keeps the order along an
// axis, and each coordinate is linear in ρ: the ends decide).
std::array<std::array<Q, 2>, 3> swept_box(const Polyhedron& P, const Vec3q& s, const Q& lo, const Q& hi) {
    std::array<std::array<Q, 2>, 3> b = bounding_box(P);
    for (size_t c = 0; c < 3; ++c) {
        const Q m = b[c][0], M = b[c][1];
        const Q a = s[c] + lo * (m - s[c]), bb = s[c] + hi * (m - s[c]), e = s[c] + lo * (M - s[c]),
                f = s[c] + hi * (M - s[c]);
        b[c] = {std::min(a, bb), std::max(e, f)};
    }
    return b;
}
}  // namespace

CompoundRegion compound_region(const ExactScene& sc, const std::string& name, bool with_union) {
    StageClock clock;
    for (int i = 0; i < 2; ++i)
        if (sc.lo[i] == sc.hi[i])
            throw InputError(name + ": I" + std::to_string(i + 1) +
                             " has no width (lo = hi): the region is a set in the plane of (rho1, rho2), "
                             "so region needs I1 and I2 with lo < hi");
    const size_t m = std::max<size_t>(1, sc.P[0].parts.size()), n = std::max<size_t>(1, sc.P[1].parts.size());
    CompoundRegion r;
    std::vector<Polyhedron>(&parts)[2] = r.parts;
    build_parts(sc, name, parts);
    std::vector<std::array<std::array<Q, 2>, 3>> boxes[2];
    for (int i = 0; i < 2; ++i)
        for (const Polyhedron& P : parts[i]) boxes[i].push_back(swept_box(P, sc.P[i].seed, sc.lo[i], sc.hi[i]));
    clock.lap("parts (hulls)");
    // Prune first (a byte a pair), and count the exact work the rest would take.
    r.prune.assign(m * n, 0);
    double work = 0;
    std::vector<std::pair<int, int>> todo;  // the pairs to build, part1-major
    for (size_t a = 0; a < m; ++a)
        for (size_t b = 0; b < n; ++b) {
            for (int c = 0; c < 3; ++c) {
                const int side = boxes[0][a][c][1] < boxes[1][b][c][0]   ? 1
                                 : boxes[1][b][c][1] < boxes[0][a][c][0] ? -1
                                                                         : 0;
                if (side) {
                    r.prune[a * n + b] = static_cast<std::uint8_t>(1 + 2 * c + (side > 0));
                    break;
                }
            }
            if (r.prune[a * n + b]) {
                ++r.pruned;
                continue;
            }
            ++r.built;
            todo.push_back({static_cast<int>(a), static_cast<int>(b)});
            work += static_cast<double>(parts[0][a].edges.size()) * static_cast<double>(parts[1][b].edges.size());
        }
    if (static_cast<size_t>(r.built) > kMaxBuiltPairs)
        throw InputError(name + ": " + std::to_string(r.built) +
                         " part pairs can meet in I1 x I2 (their swept boxes meet), more than " +
                         std::to_string(kMaxBuiltPairs) + " (the limit)");
    if (work > kMaxEdgePairWork)
        throw InputError(
            name + ": the part pairs that can meet have " + std::to_string(static_cast<long long>(work)) +
            " edge pairs in all, more than 2*10^7 (the limit: each pair's facet normals grow with its edge pairs)");
    // The built pairs, on every core: each thread with its own copies of the parts (a part's
    // predicate statistics are written by its support queries), each pair's result in its slot.
    const Vec3q &s1 = sc.P[0].seed, &s2 = sc.P[1].seed;
    const unsigned threads =
        static_cast<unsigned>(std::min<size_t>(default_threads(), std::max<size_t>(1, todo.size() / 8)));
    std::vector<std::vector<Polyhedron>> copies[2];
    for (int i = 0; i < 2; ++i) copies[i].assign(threads > 1 ? threads : 0, parts[i]);
    std::vector<filter::PredicateStats> stats(threads);
    r.pairs.resize(todo.size());
    parallel_tasks(todo.size(), threads, [&](unsigned t, size_t k) {
        const auto [a, b] = todo[k];
        const Polyhedron& A = threads > 1 ? copies[0][t][static_cast<size_t>(a)] : parts[0][static_cast<size_t>(a)];
        const Polyhedron& B = threads > 1 ? copies[1][t][static_cast<size_t>(b)] : parts[1][static_cast<size_t>(b)];
        PairRegion pr = pair_region(A, B, s1, s2, sc.lo, sc.hi, &stats[t]);
        r.pairs[k] = CompoundRegion::Pair{a, b, std::move(pr.polygon), std::move(pr.constraints), std::move(pr.fence)};
    });
    for (const auto& st : stats) r.predicates += st;
    std::vector<std::vector<Point2q>> polys;
    for (const CompoundRegion::Pair& p : r.pairs) {
        polys.push_back(p.polygon);
        // Where it meets ρ1 = ρ2: the polygon cut to the diagonal (a point or a segment).
        const std::vector<Point2q> diag = cut_polygon(cut_polygon(p.polygon, Q(1), Q(-1), Q(0)), Q(-1), Q(1), Q(0));
        if (!diag.empty()) {
            Q t0 = diag.front()[0], t1 = t0;
            for (const Point2q& x : diag) t0 = std::min(t0, x[0]), t1 = std::max(t1, x[0]);
            r.growth.push_back({t0, t1, p.part1, p.part2});
        }
    }
    clock.lap("pair polygons");
    if (with_union) {
        const size_t with_area =
            static_cast<size_t>(std::count_if(polys.begin(), polys.end(), [](const auto& p) { return p.size() >= 3; }));
        if (with_area <= kMaxUnionPolygons)
            r.region = union_of(polys);
        else
            r.union_skipped = true;
        clock.lap("union (CGAL)");
    }
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
    CompoundVerdict v;
    for (const CompoundRegion::Pair& p : r.pairs) {
        int least = 1;  // the smallest sign of a ρ1 + b ρ2 − c over the pair's half-planes
        for (const HalfPlane& h : p.constraints) least = std::min(least, sgn(Q(h.a * rho1 + h.b * rho2 - h.c)));
        if (least > 0) return {Verdict::Overlapping, p.part1, p.part2};
        if (least == 0 && v.part1 < 0) v = {Verdict::Touching, p.part1, p.part2};
    }
    return v;
}

}  // namespace scalecert::internal
