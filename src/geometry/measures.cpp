#include "geometry/measures.hpp"
#include "geometry/difference.hpp"
#include "geometry/gjk.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>
#include <mpfr.h>

namespace scalecert::internal {

Vec3q scaled_point(const Bodies& m, int i, const Q& rho, const Vec3q& x) { return scaled_about(m.s[i], rho, x); }

bool contains(const Bodies& m, int i, const Q& rho, const Vec3q& x) {
    const Vec3q& s = m.s[i];
    const Vec3q y{s[0] + (x[0] - s[0]) / rho, s[1] + (x[1] - s[1]) / rho,
                  s[2] + (x[2] - s[2]) / rho};  // x = s + ρ(y − s)
    return m.P[i].place(y).side <= 0;
}

std::pair<Q, Q> plane_extents(const PointSets& S, const Vec3q& n, const Q& rho1, const Q& rho2) {
    // n = k·p with p primitive and k > 0: max over P1 of n·x is k·max p·x, min over P2 is
    // k·min p·x; scaling about the seed maps a value t to n·s + ρ(t − n·s).
    const Vec3z p = primitive(n);
    Q k;
    for (int i = 0; i < 3; ++i)
        if (sgn(p[i]) != 0) {
            k = n[i] / Q(p[i]);
            break;
        }
    // n·x for the maximiser x = z/scale: k·(p·z)/scale, one fraction from integers.
    auto along = [&](int i, const Vec3z& dir) {
        Q v(dotz(p, S.zpoint(i, S.argmax(i, dir))), S.scale(i));
        v.canonicalize();
        return Q(k * v);
    };
    const Q ns1 = dot(n, S.seed(0)), ns2 = dot(n, S.seed(1));
    const Q max1 = along(0, p), min2 = along(1, neg(p));
    return {ns1 + rho1 * (max1 - ns1), ns2 + rho2 * (min2 - ns2)};
}
std::pair<Q, Q> plane_extents(const Bodies& m, const Vec3q& n, const Q& rho1, const Q& rho2) {
    return plane_extents(HullPoints(m), n, rho1, rho2);
}

Q directional_depth_squared(const PointSets& S, const Vec3q& n, const Q& rho1, const Q& rho2) {
    const auto [c1, c2] = plane_extents(S, n, rho1, rho2);
    const Q h = c1 - c2;  // max over P1(ρ1) − P2(ρ2) of n·x
    const Q sq = h * h / dot(n, n);
    return sgn(h) < 0 ? Q(-sq) : sq;
}
Q directional_depth_squared(const Bodies& m, const Vec3q& n, const Q& rho1, const Q& rho2) {
    return directional_depth_squared(HullPoints(m), n, rho1, rho2);
}

ExactDepth exact_penetration_depth(const Bodies& m, const std::vector<Vec3z>& normals, const Q& rho1, const Q& rho2) {
    ExactDepth best{Q(-1), {}};
    for (const Vec3z& n : normals) {
        const Q h1 = m.P[0].support(n) - dot(n, m.s[0]);
        const Q h2 = m.P[1].support(neg(n)) + dot(n, m.s[1]);
        const Q h = rho1 * h1 + rho2 * h2 - dot(n, m.d);
        if (sgn(h) < 0) return {Q(-1), n};  // this plane separates: no depth
        const Q sq = h * h / Q(dotz(n, n));
        if (sgn(best.squared) < 0 || sq < best.squared) best = {sq, n};
    }
    return best;
}

namespace {
Z integral(const Q& q, const char* what) {
    if (q.get_den() != 1) throw std::logic_error(what);
    return q.get_num();
}
}  // namespace

DifferenceGrid::DifferenceGrid(const PointSets& S, const Q& rho1, const Q& rho2) : S_(S), rho_{rho1, rho2} {
    Z d[2];
    for (int i = 0; i < 2; ++i) {
        Z l = S.scale(i);
        for (const Q& c : S.seed(i)) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
        d[i] = l * rho_[i].get_den();
    }
    mpz_lcm(D_.get_mpz_t(), d[0].get_mpz_t(), d[1].get_mpz_t());
    for (int i = 0; i < 2; ++i) {
        const Q f = Q(D_) * (1 - rho_[i]);
        for (int c = 0; c < 3; ++c)
            shift_[i][c] = integral(f * S.seed(i)[c], "difference grid: D(1 - rho)s not integral");
        factor_[i] = integral(Q(D_) * rho_[i] / S.scale(i), "difference grid: D rho / scale not integral");
    }
}

Vec3z DifferenceGrid::body(int i, int k) const {
    const Vec3z x = S_.zpoint(i, k);
    return {Z(shift_[i][0] + factor_[i] * x[0]), Z(shift_[i][1] + factor_[i] * x[1]),
            Z(shift_[i][2] + factor_[i] * x[2])};
}

Vec3q DifferenceGrid::scaled(int i, int k) const { return scaled_about(S_.seed(i), rho_[i], S_.point(i, k)); }

namespace {
// The faces of a tetrahedron of points 0..3, each three corners and the point off it: both EPAs
// start from it, each face turned to face away from its fourth point.
constexpr int kTetrahedronFaces[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};

// The directed edges of a closed triangulated surface (both EPAs' polytope): edge (a, b) -> the
// live triangle that holds it.
struct EdgeIndex {
    std::unordered_map<std::uint64_t, size_t> at;
    static std::uint64_t key(int a, int b) {
        return static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32 | static_cast<std::uint32_t>(b);
    }
    // Triangle t's three edges; false when one is held already (the surface would not be a surface).
    bool add(const std::array<int, 3>& v, size_t t) {
        bool fresh = true;
        for (int e = 0; e < 3; ++e)
            fresh =
                at.insert_or_assign(key(v[static_cast<size_t>(e)], v[static_cast<size_t>((e + 1) % 3)]), t).second &&
                fresh;
        return fresh;
    }
    const size_t* find(int a, int b) const {
        const auto it = at.find(key(a, b));
        return it == at.end() ? nullptr : &it->second;
    }
};

// One step of an EPA: the live triangles that `sees` marks, grown from `best` across edges (a
// connected patch, as the polytope is convex), die; their edges leave the index; and the hole's
// boundary is returned (the horizon, each edge as its dead triangle had it, to be fanned to the
// new point). None when an edge lacks its reverse (no closed surface).
template <class Tri, class Sees>
std::optional<std::vector<std::pair<int, int>>> carve(std::vector<Tri>& tris, EdgeIndex& edges, size_t best,
                                                      Sees sees) {
    std::vector<size_t> seen{best};
    tris[best].alive = false;
    for (size_t q = 0; q < seen.size(); ++q)
        for (int e = 0; e < 3; ++e) {
            const std::array<int, 3>& v = tris[seen[q]].v;
            const size_t* other = edges.find(v[static_cast<size_t>((e + 1) % 3)], v[static_cast<size_t>(e)]);
            if (!other) return std::nullopt;
            Tri& u = tris[*other];
            if (u.alive && sees(u)) {
                u.alive = false;
                seen.push_back(*other);
            }
        }
    std::vector<std::pair<int, int>> horizon;
    for (size_t t : seen)
        for (int e = 0; e < 3; ++e) {
            const int a = tris[t].v[static_cast<size_t>(e)], b = tris[t].v[static_cast<size_t>((e + 1) % 3)];
            if (tris[*edges.find(b, a)].alive) horizon.push_back({a, b});
        }
    for (size_t t : seen)
        for (int e = 0; e < 3; ++e) {
            const auto it = edges.at.find(
                EdgeIndex::key(tris[t].v[static_cast<size_t>(e)], tris[t].v[static_cast<size_t>((e + 1) % 3)]));
            if (it != edges.at.end() && it->second == t) edges.at.erase(it);
        }
    return horizon;
}

// A support point of M = P1(ρ1) − P2(ρ2) in the integer direction n: vertex i of P1 maximising
// n·v, vertex j of P2 minimising n·w (the smallest index of each), and i(ρ1) − j(ρ2) times the
// run's common denominator D (an integer point).
struct MPoint {
    int i, j;
    Vec3z z;
};

// The exact EPA: a convex polytope K ⊆ M, grown from a tetrahedron by support points, until its
// face nearest the origin lies on a face of M. Then every face of K is at least that far from
// the origin, and that distance is M's: the depth. In integers: every point of M is an integer
// point over one denominator D = lcm(den ρ1 · lcm(scale1, den s1), den ρ2 · lcm(scale2, den s2)).
struct Epa {
    const PointSets& S;
    DifferenceGrid grid;
    std::vector<MPoint> pts;
    struct Tri {
        std::array<int, 3> v;
        Vec3z N;  // (b − a) × (c − a), outward
        Z off;    // N·a
        Z NN;     // N·N
        bool alive = true;
    };
    std::vector<Tri> tris;
    EdgeIndex edges;

    Epa(const PointSets& sets, const Q& rho1, const Q& rho2) : S(sets), grid(sets, rho1, rho2) {}
    MPoint support_M(const Vec3z& n) const {
        const int i = S.argmax(0, n);
        const int j = S.argmax(1, Vec3z{-n[0], -n[1], -n[2]});
        return {i, j, grid.point(i, j)};
    }
    // a nearer the origin than b (signed: a plane with the origin beyond it is nearer than any)
    static bool nearer(const Tri& a, const Tri& b) {
        const int sa = sgn(a.off), sb = sgn(b.off);
        if (sa != sb) return sa < sb;
        const Z l = a.off * a.off * b.NN, r = b.off * b.off * a.NN;
        return sa >= 0 ? l < r : l > r;
    }
    int add_point(const MPoint& p) {
        pts.push_back(p);
        return static_cast<int>(pts.size()) - 1;
    }
    void add_tri(int a, int b, int c) {
        Tri t;
        t.v = {a, b, c};
        const Vec3z& A = pts[static_cast<size_t>(a)].z;
        t.N = cross(sub(pts[static_cast<size_t>(b)].z, A), sub(pts[static_cast<size_t>(c)].z, A));
        t.off = dotz(t.N, A);
        t.NN = dotz(t.N, t.N);
        const size_t k = tris.size();
        tris.push_back(std::move(t));
        edges.add(tris.back().v, k);
    }
    bool visible(const Tri& t, const Vec3z& z) const { return dotz(t.N, z) > t.off; }

    // Four affinely independent support points, from fixed directions and then from directions
    // off the span found so far (M has an interior when the pair overlaps).
    void start() {
        std::vector<Vec3z> dirs;
        for (int a = 0; a < 3; ++a)
            for (int s : {1, -1}) {
                Vec3z d{Z(0), Z(0), Z(0)};
                d[static_cast<size_t>(a)] = s;
                dirs.push_back(d);
            }
        for (int x : {1, -1})
            for (int y : {1, -1})
                for (int z : {1, -1}) dirs.push_back({Z(x), Z(y), Z(z)});
        std::vector<MPoint> base;
        auto nonzero = [](const Vec3z& v) { return sgn(v[0]) || sgn(v[1]) || sgn(v[2]); };
        auto independent = [&](const Vec3z& z) {
            if (base.empty()) return true;
            const Vec3z e1 = sub(z, base[0].z);
            if (base.size() == 1) return nonzero(e1);
            const Vec3z c = cross(sub(base[1].z, base[0].z), e1);
            if (base.size() == 2) return nonzero(c);
            return sgn(dotz(cross(sub(base[1].z, base[0].z), sub(base[2].z, base[0].z)), e1)) != 0;
        };
        for (size_t k = 0; base.size() < 4; ++k) {
            if (k >= dirs.size()) {
                // A direction off the span: the plane's normal, or one across the line (both
                // signs, so that a support point leaves the span).
                if (k > 30) throw std::logic_error("EPA: the Minkowski difference is flat");
                Vec3z d;
                if (base.size() == 3)
                    d = cross(sub(base[1].z, base[0].z), sub(base[2].z, base[0].z));
                else if (base.size() == 2) {
                    const Vec3z e = sub(base[1].z, base[0].z);
                    d = cross(e, Vec3z{Z(1), Z(0), Z(0)});
                    if (!nonzero(d)) d = cross(e, Vec3z{Z(0), Z(1), Z(0)});
                } else
                    throw std::logic_error("EPA: no support points");
                const Vec3z p = primitive(d);
                dirs.push_back(p);
                dirs.push_back(neg(p));
            }
            const MPoint p = support_M(dirs[k]);
            if (independent(p.z)) base.push_back(p);
        }
        for (const MPoint& p : base) add_point(p);
        for (const auto& q : kTetrahedronFaces) {
            const Vec3z& A = pts[static_cast<size_t>(q[0])].z;
            const Vec3z N = cross(sub(pts[static_cast<size_t>(q[1])].z, A), sub(pts[static_cast<size_t>(q[2])].z, A));
            if (sgn(dotz(N, sub(pts[static_cast<size_t>(q[3])].z, A))) > 0)
                add_tri(q[0], q[2], q[1]);
            else
                add_tri(q[0], q[1], q[2]);
        }
    }

    // Runs to the end; the index of the nearest triangle.
    size_t run() {
        start();
        // The live triangles in a heap, nearest on top (dead ones dropped when they surface).
        auto farther = [this](size_t a, size_t b) { return nearer(tris[b], tris[a]); };
        std::vector<size_t> heap;
        for (size_t t = 0; t < tris.size(); ++t) heap.push_back(t);
        std::make_heap(heap.begin(), heap.end(), farther);
        for (;;) {
            while (!tris[heap.front()].alive) {
                std::pop_heap(heap.begin(), heap.end(), farther);
                heap.pop_back();
            }
            const size_t best = heap.front();
            const MPoint p = support_M(primitive(tris[best].N));
            if (!visible(tris[best], p.z)) return best;  // the plane supports M: a face of M
            const int k = add_point(p);
            // Remove every face the point sees and close the hole with a fan from its horizon.
            const auto horizon = carve(tris, edges, best, [&](const Tri& u) { return visible(u, p.z); });
            if (!horizon) throw std::logic_error("EPA: the polytope's surface is not closed");
            for (const auto& [a, b] : *horizon) {
                add_tri(a, b, k);
                heap.push_back(tris.size() - 1);
                std::push_heap(heap.begin(), heap.end(), farther);
            }
        }
    }
};

}  // namespace

namespace {
// The EPA in doubles, from the double GJK's tetrahedron around the origin: a guess of the final
// surface (its points as vertex pairs, its triangles outward), checked exactly by
// checked_surface. None when the doubles degenerate.
struct GuessedSurface {
    std::vector<std::pair<int, int>> points;
    std::vector<std::array<int, 3>> triangles;
};
std::optional<GuessedSurface> double_epa(const PointSets& S, double rho1, double rho2,
                                         const std::vector<std::pair<int, int>>& tetrahedron) {
    if (tetrahedron.size() != 4) return std::nullopt;
    const double rho[2] = {rho1, rho2};
    D3 seed[2];
    for (int i = 0; i < 2; ++i)
        for (int c = 0; c < 3; ++c) seed[i][c] = to_double_rn(S.seed(i)[c]);
    auto scaled = [&](int i, int k) {
        const D3 x = S.dpoint(i, k);
        return D3{seed[i][0] + rho[i] * (x[0] - seed[i][0]), seed[i][1] + rho[i] * (x[1] - seed[i][1]),
                  seed[i][2] + rho[i] * (x[2] - seed[i][2])};
    };
    GuessedSurface out;
    std::vector<D3> z;
    double size = 0;  // the largest coordinate seen, for the tolerances
    auto add_point = [&](int i, int j) {
        out.points.push_back({i, j});
        z.push_back(subd(scaled(0, i), scaled(1, j)));
        for (double c : z.back()) size = std::max(size, std::fabs(c));
        return static_cast<int>(z.size()) - 1;
    };
    struct Tri {
        std::array<int, 3> v;
        D3 n;        // unit outward normal
        double off;  // n·a: the plane's distance from the origin
        bool alive = true;
    };
    std::vector<Tri> tris;
    EdgeIndex edges;
    auto add_tri = [&](int a, int b, int c) {
        const D3 N = crossd(subd(z[static_cast<size_t>(b)], z[static_cast<size_t>(a)]),
                            subd(z[static_cast<size_t>(c)], z[static_cast<size_t>(a)]));
        const double l = normd(N);
        if (!(l > 0) || !std::isfinite(l)) return false;
        const D3 n{N[0] / l, N[1] / l, N[2] / l};
        const size_t k = tris.size();
        tris.push_back({{a, b, c}, n, dotd(n, z[static_cast<size_t>(a)])});
        return edges.add(tris.back().v, k);
    };
    for (const auto& [i, j] : tetrahedron) add_point(i, j);
    for (const auto& q : kTetrahedronFaces) {
        const D3 N = crossd(subd(z[static_cast<size_t>(q[1])], z[static_cast<size_t>(q[0])]),
                            subd(z[static_cast<size_t>(q[2])], z[static_cast<size_t>(q[0])]));
        const bool flip = dotd(N, subd(z[static_cast<size_t>(q[3])], z[static_cast<size_t>(q[0])])) > 0;
        if (!(flip ? add_tri(q[0], q[2], q[1]) : add_tri(q[0], q[1], q[2]))) return std::nullopt;
    }
    for (int it = 0; it < 200; ++it) {
        size_t best = tris.size();
        for (size_t t = 0; t < tris.size(); ++t)
            if (tris[t].alive && (best == tris.size() || tris[t].off < tris[best].off)) best = t;
        if (best == tris.size()) return std::nullopt;
        const D3& n = tris[best].n;
        const int i = S.dargmax(0, n), j = S.dargmax(1, negd(n));
        const D3 p = subd(scaled(0, i), scaled(1, j));
        // No support point beyond the plane by more than rounding: the guess is made.
        if (dotd(n, p) - tris[best].off <= 1e-13 * size) break;
        for (const auto& q : out.points)
            if (q.first == i && q.second == j) return std::nullopt;  // no progress in doubles
        const int k = add_point(i, j);
        const auto horizon = carve(tris, edges, best, [&](const Tri& u) { return dotd(u.n, z.back()) > u.off; });
        if (!horizon) return std::nullopt;
        for (const auto& [a, b] : *horizon)
            if (!add_tri(a, b, k)) return std::nullopt;
    }
    for (const Tri& t : tris)
        if (t.alive) out.triangles.push_back(t.v);
    return out;
}

// An enclosure of the integer z: mpz_get_d truncates towards zero. False when z is beyond the
// doubles.
bool enclose(const Z& z, CGAL::Interval_nt<false>& out) {
    const double d = z.get_d();
    if (!std::isfinite(d) || !std::isfinite(std::nextafter(d, sgn(z) > 0 ? INFINITY : -INFINITY))) return false;
    out = sgn(z) == 0  ? CGAL::Interval_nt<false>(0)
          : sgn(z) > 0 ? CGAL::Interval_nt<false>(d, std::nextafter(d, INFINITY))
                       : CGAL::Interval_nt<false>(std::nextafter(d, -INFINITY), d);
    return true;
}

// The guessed surface as a proof, checked exactly on the difference grid, or none: a closed
// oriented surface (every directed edge once, its reverse once) whose every triangle has the
// origin strictly on its inner side, and whose nearest plane supports M (FORMAT.md, "A depth
// proof": these make its distance the depth). Each triangle's plane is first enclosed in
// intervals (predicates.hpp, 10): a triangle whose offset is surely positive and whose squared
// distance surely exceeds the nearest one's needs no integers.
std::optional<ProvedDepth> checked_surface(const PointSets& S, const Q& rho1, const Q& rho2, const GuessedSurface& g) {
    using I = CGAL::Interval_nt<false>;
    if (g.triangles.empty()) return std::nullopt;
    const DifferenceGrid grid(S, rho1, rho2);
    std::vector<std::pair<int, int>> edges;
    for (const auto& t : g.triangles)
        for (int e = 0; e < 3; ++e) edges.push_back({t[static_cast<size_t>(e)], t[static_cast<size_t>((e + 1) % 3)]});
    std::sort(edges.begin(), edges.end());
    for (size_t k = 0; k < edges.size(); ++k) {
        if (k > 0 && edges[k] == edges[k - 1]) return std::nullopt;
        if (!std::binary_search(edges.begin(), edges.end(), std::pair{edges[k].second, edges[k].first}))
            return std::nullopt;
    }
    std::vector<Vec3z> z;
    std::vector<std::array<I, 3>> zi;
    bool finite = true;  // else every triangle is checked in integers
    for (const auto& [i, j] : g.points) {
        z.push_back(grid.point(i, j));
        zi.emplace_back();
        for (int c = 0; c < 3; ++c) finite = finite && enclose(z.back()[c], zi.back()[c]);
    }
    // Each triangle's offset N·a and squared distance (N·a)² / N·N, enclosed.
    const size_t T = g.triangles.size();
    std::vector<I> off(T), dist(T);
    if (finite) {
        CGAL::Protect_FPU_rounding<true> upward;
        for (size_t t = 0; t < T; ++t) {
            const auto &A = zi[static_cast<size_t>(g.triangles[t][0])], &B = zi[static_cast<size_t>(g.triangles[t][1])],
                       &C = zi[static_cast<size_t>(g.triangles[t][2])];
            const I e[3] = {B[0] - A[0], B[1] - A[1], B[2] - A[2]}, f[3] = {C[0] - A[0], C[1] - A[1], C[2] - A[2]};
            const I N[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
            off[t] = N[0] * A[0] + N[1] * A[1] + N[2] * A[2];
            dist[t] = CGAL::square(off[t]) / (CGAL::square(N[0]) + CGAL::square(N[1]) + CGAL::square(N[2]));
        }
    }
    struct Plane {
        Vec3z N;
        Z off, NN;
    };
    auto exact = [&](size_t t) {
        const Vec3z& A = z[static_cast<size_t>(g.triangles[t][0])];
        Plane p;
        p.N =
            cross(sub(z[static_cast<size_t>(g.triangles[t][1])], A), sub(z[static_cast<size_t>(g.triangles[t][2])], A));
        p.off = dotz(p.N, A);
        p.NN = dotz(p.N, p.N);
        return p;
    };
    // The nearest by the enclosures, exactly; then every other plane at least as far.
    size_t best = 0;
    for (size_t t = 1; t < T && finite; ++t)
        if (dist[t].inf() < dist[best].inf()) best = t;
    Plane bp = exact(best);
    if (sgn(bp.off) <= 0) return std::nullopt;
    for (size_t t = 0; t < T; ++t) {
        if (t == best) continue;
        if (finite && off[t].inf() > 0 && dist[t].inf() >= dist[best].sup()) continue;
        Plane p = exact(t);
        if (sgn(p.off) <= 0) return std::nullopt;
        if (p.off * p.off * bp.NN < bp.off * bp.off * p.NN) best = t, bp = std::move(p);  // nearer still
    }
    const Vec3z n = primitive(bp.N);
    if (dotz(bp.N, grid.point(S.argmax(0, n), S.argmax(1, neg(n)))) > bp.off) return std::nullopt;
    ProvedDepth d;
    d.squared = Q(bp.off * bp.off, bp.NN * grid.D() * grid.D());
    d.squared.canonicalize();
    d.direction = n;
    d.points = g.points;
    d.triangles = g.triangles;
    d.iterations = static_cast<int>(g.points.size()) - 4;
    d.from_doubles = true;
    return d;
}

// The EPA's result: its nearest triangle's plane, and the proof when it lies strictly beyond the
// origin.
std::optional<ProvedDepth> epa_depth(const PointSets& S, const Q& rho1, const Q& rho2, Vec3z* supporting = nullptr,
                                     Q* offset = nullptr) {
    Epa epa(S, rho1, rho2);
    const size_t best = epa.run();
    const auto& t = epa.tris[best];
    if (supporting) *supporting = primitive(t.N);
    if (offset) *offset = Q(t.off);
    if (sgn(t.off) <= 0) return std::nullopt;  // the origin is not strictly inside M
    ProvedDepth d;
    // off and N are D³ and D² times the true ones: the squared distance off²/|N|² over D².
    d.squared = Q(t.off * t.off, t.NN * epa.grid.D() * epa.grid.D());
    d.squared.canonicalize();
    d.direction = primitive(t.N);
    for (const MPoint& p : epa.pts) d.points.push_back({p.i, p.j});
    for (const auto& u : epa.tris)
        if (u.alive) d.triangles.push_back(u.v);
    d.iterations = static_cast<int>(epa.pts.size()) - 4;
    return d;
}
}  // namespace

namespace {
// The doubles' surface from the GJK's tetrahedron, checked exactly; none when the guess is not
// a proof (the exact EPA decides then).
std::optional<ProvedDepth> guessed_depth(const PointSets& S, const Q& rho1, const Q& rho2, const GjkGuess& g) {
    if (g.distance > 0) return std::nullopt;
    const std::optional<GuessedSurface> s = double_epa(S, to_double_rn(rho1), to_double_rn(rho2), g.simplex);
    return s ? checked_surface(S, rho1, rho2, *s) : std::nullopt;
}
}  // namespace

std::optional<ProvedDepth> proved_depth(const PointSets& S, const Q& rho1, const Q& rho2) {
    if (std::optional<ProvedDepth> d =
            guessed_depth(S, rho1, rho2, gjk_guess(S, to_double_rn(rho1), to_double_rn(rho2))))
        return d;
    return epa_depth(S, rho1, rho2);
}
std::optional<ProvedDepth> exact_epa(const PointSets& S, const Q& rho1, const Q& rho2) {
    return epa_depth(S, rho1, rho2);
}
std::optional<ProvedDepth> proved_depth(const Bodies& m, const Q& rho1, const Q& rho2) {
    return proved_depth(HullPoints(m), rho1, rho2);
}

std::optional<Verdict> proved_verdict(const PointSets& S, const Q& rho1, const Q& rho2) {
    const GjkGuess g = gjk_guess(S, to_double_rn(rho1), to_double_rn(rho2));
    if (g.distance > 0) {
        if (!std::isfinite(g.closest[0]) || !std::isfinite(g.closest[1]) || !std::isfinite(g.closest[2]))
            return std::nullopt;
        Z den;
        const Vec3z n = over_common_denominator(
            Vec3q{-exact_from_double(g.closest[0]), -exact_from_double(g.closest[1]), -exact_from_double(g.closest[2])},
            den);
        if (is_zero(n)) return std::nullopt;
        const DifferenceGrid grid(S, rho1, rho2);
        // h_M(n) = n·(v_i − w_j) with v_i maximising n over P1(ρ1), w_j minimising it over P2(ρ2).
        if (sgn(dotz(n, grid.point(S.argmax(0, n), S.argmax(1, neg(n))))) < 0) return Verdict::Separated;
        return std::nullopt;
    }
    if (g.simplex.size() != 4) return std::nullopt;
    const DifferenceGrid grid(S, rho1, rho2);
    Vec3z z[4];
    for (size_t k = 0; k < 4; ++k) z[k] = grid.point(g.simplex[k].first, g.simplex[k].second);
    // The origin strictly inside: on the same side as the fourth point of each face's plane.
    auto orient = [](const Vec3z& a, const Vec3z& b, const Vec3z& c, const Vec3z& d) {
        const Vec3z u{Z(b[0] - a[0]), Z(b[1] - a[1]), Z(b[2] - a[2])},
            v{Z(c[0] - a[0]), Z(c[1] - a[1]), Z(c[2] - a[2])}, w{Z(d[0] - a[0]), Z(d[1] - a[1]), Z(d[2] - a[2])};
        return sgn(Z(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                     u[2] * (v[0] * w[1] - v[1] * w[0])));
    };
    const Vec3z o{Z(0), Z(0), Z(0)};
    static const int face[4][4] = {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}};
    for (const auto& f : face) {
        const int side = orient(z[f[0]], z[f[1]], z[f[2]], z[f[3]]);
        if (side == 0 || orient(z[f[0]], z[f[1]], z[f[2]], o) != side) return std::nullopt;
    }
    return Verdict::Overlapping;
}

std::optional<MeasuredDepth> measured_depth(const PointSets& S, const Q& rho1, const Q& rho2, int max_rounds) {
    // Apart by the doubles' guess: the proved distance decides (its slab separates, or it finds
    // them meeting after all).
    const GjkGuess g = gjk_guess(S, to_double_rn(rho1), to_double_rn(rho2));
    if (g.distance > 0) {
        const std::optional<ProvedDistance> pd = proved_distance(S, rho1, rho2, max_rounds);
        if (!pd) return std::nullopt;
        return depth_from_distance(S, pd->d, rho1, rho2);
    }
    // Meeting by the guess: the EPA decides alone. Its final plane supports M: beyond the origin,
    // the depth; with the origin strictly beyond it, it separates; through the origin, touching,
    // and the proved distance (0) names a common point.
    MeasuredDepth r;
    if ((r.depth = guessed_depth(S, rho1, rho2, g))) {
        r.state = Verdict::Overlapping;
        r.normal = r.depth->direction;
        return r;
    }
    Vec3z supporting;
    Q off;
    r.depth = epa_depth(S, rho1, rho2, &supporting, &off);
    r.normal = r.depth ? r.depth->direction : supporting;
    if (r.depth) {
        r.state = Verdict::Overlapping;
        return r;
    }
    if (sgn(off) < 0) {
        r.state = Verdict::Separated;
        return r;
    }
    const std::optional<ProvedDistance> pd = proved_distance(S, rho1, rho2, max_rounds);
    if (!pd) return std::nullopt;
    if (sgn(pd->d.squared) != 0)
        throw std::logic_error("measured_depth: a supporting plane through the origin, and the bodies apart");
    r.state = Verdict::Touching;
    r.distance = pd->d;
    return r;
}

MeasuredDepth depth_from_distance(const PointSets& S, const ExactDistance& dist, const Q& rho1, const Q& rho2) {
    MeasuredDepth r;
    r.distance = dist;
    if (sgn(dist.squared) > 0) {  // apart: the slab's direction separates
        r.state = Verdict::Separated;
        r.normal = primitive(sub(dist.p2, dist.p1));
        return r;
    }
    Vec3z supporting;
    r.depth = epa_depth(S, rho1, rho2, &supporting);
    r.state = r.depth ? Verdict::Overlapping : Verdict::Touching;
    r.normal = r.depth ? r.depth->direction : supporting;
    return r;
}

double sqrt_minus_rn(const Q& square, const Q& c) {
    mpfr_t a, b;
    mpfr_init2(a, 256);
    mpfr_init2(b, 256);
    mpfr_set_q(a, square.get_mpq_t(), MPFR_RNDN);
    mpfr_sqrt(a, a, MPFR_RNDN);
    mpfr_set_q(b, c.get_mpq_t(), MPFR_RNDN);
    mpfr_sub(a, a, b, MPFR_RNDN);
    const double d = mpfr_get_d(a, MPFR_RNDN);
    mpfr_clear(a);
    mpfr_clear(b);
    return d;
}

double relative_sqrt_error_rn(const Q& square, const Q& c) {
    mpfr_t a, b;
    mpfr_init2(a, 256);
    mpfr_init2(b, 256);
    mpfr_set_q(a, square.get_mpq_t(), MPFR_RNDN);
    mpfr_sqrt(a, a, MPFR_RNDN);
    mpfr_set_q(b, c.get_mpq_t(), MPFR_RNDN);
    mpfr_sub(b, b, a, MPFR_RNDN);
    mpfr_abs(b, b, MPFR_RNDN);
    mpfr_div(b, b, a, MPFR_RNDN);
    const double d = mpfr_get_d(b, MPFR_RNDN);
    mpfr_clear(a);
    mpfr_clear(b);
    return d;
}

}  // namespace scalecert::internal
