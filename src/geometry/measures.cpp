#include "geometry/measures.hpp"
#include "geometry/gjk.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include <mpfr.h>

namespace scalecert::internal {

Vec3q scaled_point(const Bodies& m, int i, const Q& rho, const Vec3q& x) {
    const Vec3q& s = m.s[i];
    return {s[0] + rho * (x[0] - s[0]), s[1] + rho * (x[1] - s[1]), s[2] + rho * (x[2] - s[2])};
}

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
    const Vec3q p1 = S.point(0, S.argmax(0, p)), p2 = S.point(1, S.argmax(1, neg(p)));
    const Q ns1 = dot(n, S.seed(0)), ns2 = dot(n, S.seed(1));
    const Q max1 = dot(n, p1), min2 = dot(n, p2);
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
    Q r1, r2;
    Z D;
    std::vector<MPoint> pts;
    struct Tri {
        std::array<int, 3> v;
        Vec3z N;  // (b − a) × (c − a), outward
        Z off;    // N·a
        Z NN;     // N·N
        bool alive = true;
    };
    std::vector<Tri> tris;
    std::map<std::pair<int, int>, size_t> edge;  // directed edge -> its live triangle

    Epa(const PointSets& sets, const Q& rho1, const Q& rho2) : S(sets), r1(rho1), r2(rho2) {
        Z d[2];
        const Q* r[2] = {&r1, &r2};
        for (int i = 0; i < 2; ++i) {
            Z l = S.scale(i);
            for (const Q& c : S.seed(i)) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
            d[i] = l * r[i]->get_den();
        }
        mpz_lcm(D.get_mpz_t(), d[0].get_mpz_t(), d[1].get_mpz_t());
    }
    Vec3z integral(const Vec3q& x) const {
        Vec3z z;
        for (int c = 0; c < 3; ++c) {
            const Q q = x[c] * D;
            if (q.get_den() != 1) throw std::logic_error("EPA: a point off the common denominator");
            z[c] = q.get_num();
        }
        return z;
    }
    Vec3q scaled(int i, const Q& rho, int k) const {
        const Vec3q x = S.point(i, k), &s = S.seed(i);
        return {s[0] + rho * (x[0] - s[0]), s[1] + rho * (x[1] - s[1]), s[2] + rho * (x[2] - s[2])};
    }
    MPoint support_M(const Vec3z& n) const {
        const int i = S.argmax(0, n);
        const int j = S.argmax(1, Vec3z{-n[0], -n[1], -n[2]});
        return {i, j, integral(sub(scaled(0, r1, i), scaled(1, r2, j)))};
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
        edge[{a, b}] = k;
        edge[{b, c}] = k;
        edge[{c, a}] = k;
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
        // Faces of the tetrahedron, each turned to face away from the fourth point.
        const int f[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
        for (const auto& q : f) {
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
            // Remove every face the point sees — a connected patch around the best one, as K is
            // convex — and close the hole with a fan from its boundary (the horizon).
            std::vector<size_t> seen{best};
            tris[best].alive = false;
            for (size_t q = 0; q < seen.size(); ++q)
                for (int e = 0; e < 3; ++e) {
                    const Tri& t = tris[seen[q]];
                    const auto other = edge.find({t.v[static_cast<size_t>((e + 1) % 3)], t.v[static_cast<size_t>(e)]});
                    if (other == edge.end()) continue;
                    Tri& u = tris[other->second];
                    if (u.alive && visible(u, p.z)) {
                        u.alive = false;
                        seen.push_back(other->second);
                    }
                }
            std::vector<std::pair<int, int>> horizon;
            for (size_t t : seen)
                for (int e = 0; e < 3; ++e) {
                    const int a = tris[t].v[static_cast<size_t>(e)], b = tris[t].v[static_cast<size_t>((e + 1) % 3)];
                    const auto other = edge.find({b, a});
                    if (other != edge.end() && tris[other->second].alive) horizon.push_back({a, b});
                }
            for (size_t t : seen)
                for (int e = 0; e < 3; ++e) {
                    const auto it =
                        edge.find({tris[t].v[static_cast<size_t>(e)], tris[t].v[static_cast<size_t>((e + 1) % 3)]});
                    if (it != edge.end() && it->second == t) edge.erase(it);
                }
            for (const auto& [a, b] : horizon) {
                add_tri(a, b, k);
                heap.push_back(tris.size() - 1);
                std::push_heap(heap.begin(), heap.end(), farther);
            }
        }
    }
};

}  // namespace

namespace {
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
    d.squared = Q(t.off * t.off, t.NN * epa.D * epa.D);
    d.squared.canonicalize();
    d.direction = primitive(t.N);
    for (const MPoint& p : epa.pts) d.points.push_back({p.i, p.j});
    for (const auto& u : epa.tris)
        if (u.alive) d.triangles.push_back(u.v);
    d.iterations = static_cast<int>(epa.pts.size()) - 4;
    return d;
}
}  // namespace

std::optional<ProvedDepth> proved_depth(const PointSets& S, const Q& rho1, const Q& rho2) {
    return epa_depth(S, rho1, rho2);
}
std::optional<ProvedDepth> proved_depth(const Bodies& m, const Q& rho1, const Q& rho2) {
    return proved_depth(HullPoints(m), rho1, rho2);
}

std::optional<MeasuredDepth> measured_depth(const PointSets& S, const Q& rho1, const Q& rho2, int max_rounds) {
    // Apart by the doubles' guess: the proved distance decides (its slab separates, or it finds
    // them meeting after all).
    if (gjk_guess(S, to_double_rn(rho1), to_double_rn(rho2)).distance > 0) {
        const std::optional<ProvedDistance> pd = proved_distance(S, rho1, rho2, max_rounds);
        if (!pd) return std::nullopt;
        return depth_from_distance(S, pd->d, rho1, rho2);
    }
    // Meeting by the guess: the EPA decides alone. Its final plane supports M: beyond the origin,
    // the depth; with the origin strictly beyond it, it separates; through the origin, touching,
    // and the proved distance (0) names a common point.
    MeasuredDepth r;
    Vec3z supporting;
    Q off;
    r.depth = epa_depth(S, rho1, rho2, &supporting, &off);
    r.normal = r.depth ? r.depth->direction : supporting;
    if (r.depth) {
        r.state = MeasuredDepth::Overlapping;
        return r;
    }
    if (sgn(off) < 0) {
        r.state = MeasuredDepth::Separated;
        return r;
    }
    const std::optional<ProvedDistance> pd = proved_distance(S, rho1, rho2, max_rounds);
    if (!pd) return std::nullopt;
    if (sgn(pd->d.squared) != 0)
        throw std::logic_error("measured_depth: a supporting plane through the origin, and the bodies apart");
    r.state = MeasuredDepth::Touching;
    r.distance = pd->d;
    return r;
}

MeasuredDepth depth_from_distance(const PointSets& S, const ExactDistance& dist, const Q& rho1, const Q& rho2) {
    MeasuredDepth r;
    r.distance = dist;
    if (sgn(dist.squared) > 0) {  // apart: the slab's direction separates
        r.state = MeasuredDepth::Separated;
        r.normal = primitive(sub(dist.p2, dist.p1));
        return r;
    }
    Vec3z supporting;
    r.depth = epa_depth(S, rho1, rho2, &supporting);
    r.state = r.depth ? MeasuredDepth::Overlapping : MeasuredDepth::Touching;
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
