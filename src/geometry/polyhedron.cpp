#include "geometry/polyhedron.hpp"

#include "numeric/predicates.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <type_traits>

namespace scalecert::internal {

namespace {
using D3 = std::array<double, 3>;
// The cube-map cell of a direction.
int cube_cell(const D3& v, int kG) {
    int ax = 0;
    for (int k = 1; k < 3; ++k)
        if (std::fabs(v[k]) > std::fabs(v[ax])) ax = k;
    double m = std::fabs(v[ax]);
    if (!(m > 0) || !std::isfinite(m)) return 0;
    int face = 2 * ax + (v[ax] < 0 ? 1 : 0);
    double a = v[(ax + 1) % 3] / m, b = v[(ax + 2) % 3] / m;  // in [-1, 1]
    int i = std::clamp(static_cast<int>((a + 1) * 0.5 * kG), 0, kG - 1);
    int j = std::clamp(static_cast<int>((b + 1) * 0.5 * kG), 0, kG - 1);
    return (face * kG + i) * kG + j;
}
}  // namespace

int Polyhedron::start_vertex(const std::array<double, 3>& n) const {
    if (start_table.empty()) return vertices.front();
    return start_table[cube_cell(n, start_g)];
}

namespace {
// n·x compared through a double filter (predicates.hpp, bound 1). Only comparisons the
// filter cannot decide (or non-finite ones) are made exactly: in 128-bit integers for a small
// normal on a small polyhedron, in GMP otherwise.
template <class N>
struct FilteredDot {
    const Polyhedron& P;
    const N& n;
    D3 nd;
    FilteredDot(const Polyhedron& p, const N& normal) : P(p), n(normal) {
        for (int k = 0; k < 3; ++k) nd[k] = static_cast<double>(to_double(normal[k]));
    }
    static double to_double(const Z& z) { return z.get_d(); }
    static double to_double(std::int64_t v) { return static_cast<double>(v); }
    filter::SupportApprox approx(int v) const { return filter::support_approx(nd.data(), P.dpts[v].data()); }
    int exact_cmp(int w, int v) const {
        if constexpr (std::is_same_v<N, Vec3s>) {
            I128 a = dot_s(n, P.ipts_s[w]), b = dot_s(n, P.ipts_s[v]);
            return (a > b) - (a < b);
        } else {
            return cmp(dotz(n, P.ipts[w]), dotz(n, P.ipts[v]));
        }
    }
    // sign of n·x_w − n·x_v, exactly (predicate 1)
    int compare(int w, const filter::SupportApprox& wa, int v, const filter::SupportApprox& va) const {
        return filter::support_cmp(
            wa, va, [&] { return exact_cmp(w, v); }, P.predicates);
    }
};

template <class N>
int climb_with(const FilteredDot<N>& f) {
    int cur = f.P.start_vertex(f.nd);
    filter::SupportApprox ca = f.approx(cur);
    for (bool moved = true; moved;) {
        moved = false;
        for (int w : f.P.adj[cur]) {
            const filter::SupportApprox wa = f.approx(w);
            if (f.compare(w, wa, cur, ca) > 0) {
                cur = w;
                ca = wa;
                moved = true;
                break;
            }
        }
    }
    return cur;
}

// The vertices tied with `top` for the maximum of n·x: the face of maximisers is connected in
// the vertex graph.
template <class N>
std::vector<int> tied_with(const FilteredDot<N>& f, int top) {
    const filter::SupportApprox ta = f.approx(top);
    std::vector<int> out{top}, stack{top};
    while (!stack.empty()) {
        int v = stack.back();
        stack.pop_back();
        for (int w : f.P.adj[v]) {
            if (std::find(out.begin(), out.end(), w) != out.end()) continue;
            if (f.compare(w, f.approx(w), top, ta) == 0) {
                out.push_back(w);
                stack.push_back(w);
            }
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}
}  // namespace

int Polyhedron::climb(const Vec3s& n) const {
    if (!small()) return climb(to_z(n));
    return climb_with(FilteredDot<Vec3s>(*this, n));
}

int Polyhedron::climb(const Vec3z& n) const {
    Vec3s ns;
    if (small() && to_small_normal(n, ns)) return climb_with(FilteredDot<Vec3s>(*this, ns));
    return climb_with(FilteredDot<Vec3z>(*this, n));
}

std::vector<int> Polyhedron::argmax(const Vec3z& n, Q* value, Z* scaled_value) const {
    // One filter (machine integers when the normal fits) serves the climb and the ties.
    auto climb_and_ties = [](const auto& f) { return tied_with(f, climb_with(f)); };
    Vec3s ns;
    std::vector<int> out = small() && to_small_normal(n, ns) ? climb_and_ties(FilteredDot<Vec3s>(*this, ns))
                                                             : climb_and_ties(FilteredDot<Vec3z>(*this, n));
    const int top = out.front();  // every vertex in out attains the maximum
    if (value || scaled_value) {
        Z best = dotz(n, ipts[top]);  // = max n·x times scale
        if (value) *value = Q(best, scale), value->canonicalize();
        if (scaled_value) *scaled_value = std::move(best);
    }
    return out;
}

Q Polyhedron::support(const Vec3z& n) const {
    Q v;
    argmax(n, &v);
    return v;
}

PointPlace Polyhedron::place(const Vec3q& p) const {
    // In the integer frame: p·scale = z/den, so n·p < n·v  iff  n·z < den·(n·ipts[v]).
    Z den;
    const Vec3z z = over_common_denominator({p[0] * scale, p[1] * scale, p[2] * scale}, den);
    I128 z128[3], den128;
    bool fits = small() && to_i128(den, den128);
    for (int k = 0; k < 3 && fits; ++k) fits = to_i128(z[k], z128[k]);
    // The side of every face: n·z − den·(n·v), in 128 bits while it fits, else GMP.
    PointPlace r;
    for (const Face& f : faces) {
        auto gmp = [&] { return sgn(dotz(f.normal, z) - den * dotz(f.normal, ipts[f.verts[0]])); };
        const int side = !fits ? gmp()
                               : filter::exact_sign(
                                     [&](filter::Acc128& acc) {
                                         for (int k = 0; k < 3; ++k) acc.add(f.normal_s[k], z128[k]);
                                         acc.sub(den128, dot_s(f.normal_s, ipts_s[f.verts[0]]));
                                     },
                                     gmp);
        if (side > 0) return {1, &f};
        if (side == 0 && !r.face) r = {0, &f};
    }
    return r;
}

bool Polyhedron::strictly_inside(const Vec3q& p) const { return place(p).side < 0; }

std::vector<std::pair<int, Q>> Polyhedron::interior_weights(const Vec3q& p) const {
    // Four affinely independent vertices (they exist: the polyhedron spans 3 dimensions).
    std::vector<int> tet{vertices[0]};
    for (int v : vertices) {
        if (tet.size() == 4) break;
        const Vec3z e = sub(ipts[v], ipts[tet[0]]);
        if (tet.size() == 1 && !is_zero(e))
            tet.push_back(v);
        else if (tet.size() == 2 && !is_zero(cross(sub(ipts[tet[1]], ipts[tet[0]]), e)))
            tet.push_back(v);
        else if (tet.size() == 3 &&
                 sgn(dotz(cross(sub(ipts[tet[1]], ipts[tet[0]]), sub(ipts[tet[2]], ipts[tet[0]])), e)))
            tet.push_back(v);
    }
    if (tet.size() != 4) throw std::logic_error("interior_weights: no four independent vertices");
    Vec3q c{Q(0), Q(0), Q(0)};
    for (int v : tet)
        for (int k = 0; k < 3; ++k) c[k] += points[v][k] / 4;
    std::map<int, Q> w;
    const Vec3q u = sub(p, c);
    Q t = 0;  // p = (1 − t)·c + t·q
    if (sgn(u[0]) || sgn(u[1]) || sgn(u[2])) {
        // The exit of the ray c + λu: the smallest λ over the faces it heads towards.
        std::optional<Q> best;
        size_t bf = 0;
        for (size_t f = 0; f < faces.size(); ++f) {
            const Vec3q n = to_q(faces[f].normal);
            const Q nu = dot(n, u);
            if (sgn(nu) <= 0) continue;
            Q lam = (dot(n, points[faces[f].verts[0]]) - dot(n, c)) / nu;
            if (!best || lam < *best) best = lam, bf = f;
        }
        if (!best || *best <= 1) throw std::logic_error("interior_weights: point not strictly inside");
        t = 1 / *best;
        Vec3q q;
        for (int k = 0; k < 3; ++k) q[k] = c[k] + *best * u[k];
        // q in a fan triangle (v0, v_i, v_i+1) of the face: barycentric coordinates in the plane
        // projected along the normal's largest component, all ≥ 0 for the triangle holding q.
        const Face& F = faces[bf];
        int drop = 0;
        for (int k = 1; k < 3; ++k)
            if (abs(F.normal[k]) > abs(F.normal[drop])) drop = k;
        const int a = (drop + 1) % 3, b = (drop + 2) % 3;
        auto area = [&](const Vec3q& x, const Vec3q& y, const Vec3q& z) {
            return Q((y[a] - x[a]) * (z[b] - x[b]) - (y[b] - x[b]) * (z[a] - x[a]));
        };
        bool found = false;
        for (size_t i = 1; i + 1 < F.verts.size() && !found; ++i) {
            const Vec3q &A = points[F.verts[0]], &B = points[F.verts[i]], &C = points[F.verts[i + 1]];
            const Q whole = area(A, B, C), la = area(q, B, C) / whole, lb = area(A, q, C) / whole,
                    lc = area(A, B, q) / whole;
            if (sgn(la) < 0 || sgn(lb) < 0 || sgn(lc) < 0) continue;
            found = true;
            const int idx[3] = {F.verts[0], F.verts[i], F.verts[i + 1]};
            const Q bary[3] = {la, lb, lc};
            for (int k = 0; k < 3; ++k)
                if (sgn(bary[k]) > 0) w[idx[k]] += t * bary[k];
        }
        if (!found) throw std::logic_error("interior_weights: exit point outside its face");
    }
    for (int v : tet) w[v] += (1 - t) / 4;
    return {w.begin(), w.end()};
}

namespace {

// Integer vectors of either kind: machine integers (within the bounds of small_int.hpp, with
// 128-bit products) or GMP.
template <class V>
struct Wide;
template <>
struct Wide<Vec3s> {
    using type = I128;
};
template <>
struct Wide<Vec3z> {
    using type = Z;
};

// Sorts the vertices of a convex polygon with outward normal n counter-clockwise (seen from
// outside), exactly: angular order around an interior point, in the plane projected along the
// dominant axis of n.
template <class V>
void order_ccw(std::vector<int>& vs, const std::vector<V>& pts, const V& n) {
    using W = typename Wide<V>::type;
    int drop = 0;
    for (int k = 1; k < 3; ++k)
        if (mag(n[k]) > mag(n[drop])) drop = k;
    int u = (drop + 1) % 3, w = (drop + 2) % 3;
    // Centre (times the vertex count, to stay in integers).
    const W cnt = static_cast<long>(vs.size());
    W cu = 0, cw = 0;
    for (int v : vs) {
        cu += pts[v][u];
        cw += pts[v][w];
    }
    auto du = [&](int v) { return W(W(pts[v][u]) * cnt - cu); };
    auto dw = [&](int v) { return W(W(pts[v][w]) * cnt - cw); };
    // In the (u, w) projection, counter-clockwise around +drop axis means ccw seen from outside
    // when n[drop] > 0; reverse otherwise.
    auto half = [&](int v) {
        W a = du(v), b = dw(v);
        return (sign_of(b) > 0 || (sign_of(b) == 0 && sign_of(a) > 0)) ? 0 : 1;
    };
    std::sort(vs.begin(), vs.end(), [&](int a, int b) {
        int ha = half(a), hb = half(b);
        if (ha != hb) return ha < hb;
        return sign_of(W(du(a) * dw(b) - dw(a) * du(b))) > 0;
    });
    if (sign_of(W(n[drop])) < 0) std::reverse(vs.begin(), vs.end());
}

// A supporting plane of the hull, as found: its outward primitive normal, the hull points on it,
// and (from CGAL's triangles) the number of triangles and one of them, counter-clockwise.
template <class V>
struct Plane {
    V normal;
    std::vector<int> on;
    int ntris = 0;
    std::array<int, 3> tri{};
};

// Groups CGAL's hull triangles by their supporting plane (on a convex polytope one plane, one
// face), in the order of the normals.
template <class V>
std::vector<Plane<V>> planes_from_triangles(const std::vector<std::array<int, 3>>& tris, const std::vector<V>& ip) {
    std::vector<V> tn(tris.size());
    for (size_t t = 0; t < tris.size(); ++t)
        tn[t] = primitive(vcross(vsub(ip[tris[t][1]], ip[tris[t][0]]), vsub(ip[tris[t][2]], ip[tris[t][0]])));
    std::vector<size_t> order(tris.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return tn[a] < tn[b] || (tn[a] == tn[b] && a < b); });
    std::vector<Plane<V>> planes;
    for (size_t k = 0; k < order.size(); ++k) {
        size_t t = order[k];
        if (k == 0 || !(tn[t] == tn[order[k - 1]])) planes.push_back({tn[t], {}, 0, tris[t]});
        Plane<V>& p = planes.back();
        ++p.ntris;
        p.on.insert(p.on.end(), tris[t].begin(), tris[t].end());
    }
    for (auto& p : planes) {
        std::sort(p.on.begin(), p.on.end());
        p.on.erase(std::unique(p.on.begin(), p.on.end()), p.on.end());
    }
    return planes;
}

// Faces, vertices, edges and adjacency from the supporting planes (sorted by normal).
template <class V>
void assemble(Polyhedron& P, const std::vector<Plane<V>>& planes, const std::vector<V>& ip) {
    const size_t np = ip.size();
    // True vertices lie on at least three faces; points inside a face or an edge are dropped.
    std::vector<int> nfaces(np, 0);
    for (const auto& p : planes)
        for (int v : p.on) ++nfaces[v];
    std::vector<char> is_vertex(np, 0);
    for (size_t v = 0; v < np; ++v)
        if (nfaces[v] >= 3) is_vertex[v] = 1, P.vertices.push_back(static_cast<int>(v));
    P.faces.resize(planes.size());
    for (size_t fi = 0; fi < planes.size(); ++fi) {
        const Plane<V>& pl = planes[fi];
        Face& f = P.faces[fi];
        f.normal = as_z(pl.normal);
        if constexpr (std::is_same_v<V, Vec3s>) f.normal_s = pl.normal;
        const auto& t = pl.tri;
        if (pl.ntris == 1 && is_vertex[t[0]] && is_vertex[t[1]] && is_vertex[t[2]]) {
            // a triangular face: CGAL's triangle is already counter-clockwise from outside
            int r = static_cast<int>(std::min_element(t.begin(), t.end()) - t.begin());
            f.verts = {t[r], t[(r + 1) % 3], t[(r + 2) % 3]};
            continue;
        }
        for (int v : pl.on)
            if (is_vertex[v]) f.verts.push_back(v);
        order_ccw(f.verts, ip, pl.normal);
        std::rotate(f.verts.begin(), std::min_element(f.verts.begin(), f.verts.end()),
                    f.verts.end());  // smallest first
    }
    // Edges: (a, b, face) for every side of every face, sorted; each edge appears twice.
    std::vector<std::array<int, 3>> sides;
    for (size_t fi = 0; fi < P.faces.size(); ++fi) {
        const auto& vs = P.faces[fi].verts;
        for (size_t k = 0; k < vs.size(); ++k) {
            int a = vs[k], b = vs[(k + 1) % vs.size()];
            sides.push_back({std::min(a, b), std::max(a, b), static_cast<int>(fi)});
        }
    }
    std::sort(sides.begin(), sides.end());
    P.adj.assign(np, {});
    for (int v : P.vertices) P.adj[v].reserve(static_cast<size_t>(nfaces[v]));  // degree = faces at v
    for (size_t k = 0; k < sides.size(); k += 2) {
        if (k + 1 >= sides.size() || sides[k][0] != sides[k + 1][0] || sides[k][1] != sides[k + 1][1] ||
            (k + 2 < sides.size() && sides[k + 2][0] == sides[k][0] && sides[k + 2][1] == sides[k][1]))
            throw std::logic_error("hull edge not shared by exactly two faces");
        const int a = sides[k][0], b = sides[k][1];
        P.edges.push_back({a, b, sides[k][2], sides[k + 1][2]});
        P.adj[a].push_back(b);
        P.adj[b].push_back(a);
    }
    if (P.vertices.size() + P.faces.size() != P.edges.size() + 2) throw std::logic_error("hull fails Euler's formula");
}

}  // namespace

std::vector<HullPlane> hull_planes_brute(const std::vector<Vec3s>& pts) {
    std::vector<int> uniq;  // first copies of distinct points
    for (size_t i = 0; i < pts.size(); ++i) {
        bool seen = false;
        for (int u : uniq) seen = seen || pts[u] == pts[i];
        if (!seen) uniq.push_back(static_cast<int>(i));
    }
    if (uniq.size() > 32) throw std::logic_error("hull_planes_brute: too many points");
    std::vector<HullPlane> out;
    std::vector<std::uint32_t> masks;  // per plane, the positions in uniq of the points on it
    const size_t m = uniq.size();
    for (size_t a = 0; a < m; ++a)
        for (size_t b = a + 1; b < m; ++b)
            for (size_t c = b + 1; c < m; ++c) {
                const Vec3s& p = pts[uniq[a]];
                Vec3s n = cross_s(sub_s(pts[uniq[b]], p), sub_s(pts[uniq[c]], p));
                if (is_zero(n)) continue;
                // Three points not on a line lie on one plane: known if a plane found holds them.
                const std::uint32_t tri = (1u << a) | (1u << b) | (1u << c);
                bool known = false;
                for (std::uint32_t mask : masks) known = known || (mask & tri) == tri;
                if (known) continue;
                const I128 at = dot_s(n, p);
                bool above = false, below = false;
                for (size_t q = 0; q < m && !(above && below); ++q) {
                    I128 v = dot_s(n, pts[uniq[q]]);
                    above = above || v > at;
                    below = below || v < at;
                }
                if (above && below) continue;
                n = primitive(above ? neg_s(n) : n);
                HullPlane h{n, {}};
                const I128 top = dot_s(n, p);
                std::uint32_t mask = 0;
                for (size_t q = 0; q < m; ++q)
                    if (dot_s(n, pts[uniq[q]]) == top) h.on.push_back(uniq[q]), mask |= 1u << q;
                out.push_back(std::move(h));
                masks.push_back(mask);
            }
    std::sort(out.begin(), out.end(), [](const HullPlane& x, const HullPlane& y) { return x.normal < y.normal; });
    return out;
}

Polyhedron build_polyhedron(const std::vector<Vec3q>& pts, const std::string& name) {
    Polyhedron P;
    P.points = pts;
    // Integer coordinates: every point times the lcm of all denominators (same planes, same order).
    P.scale = 1;
    for (const Vec3q& v : pts) {
        for (const Q& c : v) mpz_lcm(P.scale.get_mpz_t(), P.scale.get_mpz_t(), c.get_den_mpz_t());
        if (mpz_sizeinbase(P.scale.get_mpz_t(), 2) > kMaxDenominatorBits)
            throw InputError(name + ": the common denominator of the coordinates has more than " +
                             std::to_string(kMaxDenominatorBits) + " bits (the limit; README \"Limits\")");
    }
    P.ipts.resize(pts.size());
    bool small = true;
    for (size_t i = 0; i < pts.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            mpz_divexact(P.ipts[i][k].get_mpz_t(), P.scale.get_mpz_t(), pts[i][k].get_den_mpz_t());
            P.ipts[i][k] *= pts[i][k].get_num();
            small = small && fits_small(P.ipts[i][k]);
        }
    const std::vector<Vec3z>& ip = P.ipts;
    P.dpts.resize(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) P.dpts[i] = {ip[i][0].get_d(), ip[i][1].get_d(), ip[i][2].get_d()};
    if (small) {
        P.ipts_s.resize(pts.size());
        for (size_t i = 0; i < pts.size(); ++i)
            for (int k = 0; k < 3; ++k) P.ipts_s[i][k] = mpz_get_si(ip[i][k].get_mpz_t());
    }
    if (small ? !affinely_3d(P.ipts_s) : !affinely_3d(ip))
        throw InputError(name + ": fewer than 4 affinely independent vertices (the points are flat)");
    // The hull of the integer-scaled points (a uniform scaling: same faces). A few small points:
    // every triple tested in machine integers. Otherwise CGAL, with Epick's exact filtered
    // predicates whenever these integers are exact doubles.
    if (small && pts.size() <= kBrutePoints) {
        std::vector<Plane<Vec3s>> planes;
        for (auto& h : hull_planes_brute(P.ipts_s)) planes.push_back({h.normal, std::move(h.on), 0, {}});
        assemble(P, planes, P.ipts_s);
    } else if (small) {
        assemble(P, planes_from_triangles(hull_triangles(ip, pts), P.ipts_s), P.ipts_s);
    } else {
        assemble(P, planes_from_triangles(hull_triangles(ip, pts), ip), ip);
    }
    // Start table: for each cube-map cell centre, the argmax found by climbing in doubles from the
    // previous cell's answer. Only a hint: argmax always finishes the climb exactly.
    const std::vector<D3>& dp = P.dpts;     // scaled coordinates: the same maximisers
    if (P.vertices.size() <= 64) return P;  // small: climbing from any vertex is already short
    // About four vertices per cell, so that a climb from the cell's vertex is a few steps.
    const int kG = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(P.vertices.size()) / 24.0)), 16, 256);
    P.start_g = kG;
    P.start_table.assign(6 * kG * kG, P.vertices.front());
    int cur = P.vertices.front();
    for (int face = 0; face < 6; ++face)
        for (int i = 0; i < kG; ++i)
            for (int j = 0; j < kG; ++j) {
                int ax = face / 2;
                D3 dir{};
                dir[ax] = face % 2 ? -1.0 : 1.0;
                dir[(ax + 1) % 3] = (i + 0.5) / kG * 2 - 1;
                dir[(ax + 2) % 3] = (j + 0.5) / kG * 2 - 1;
                auto f = [&](int v) { return dir[0] * dp[v][0] + dir[1] * dp[v][1] + dir[2] * dp[v][2]; };
                for (int steps = 0, moved = 1; moved && steps < 100000; ++steps) {
                    moved = 0;
                    for (int w : P.adj[cur])
                        if (f(w) > f(cur)) {
                            cur = w;
                            moved = 1;
                            break;
                        }
                }
                P.start_table[(face * kG + i) * kG + j] = cur;
            }
    return P;
}

}  // namespace scalecert::internal
