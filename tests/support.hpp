// Test helpers: random exact scenes, and a brute-force classifier that shares nothing with the
// engine (no hull, no Gauss map, no envelope): every cross product of two vertex differences is a
// candidate normal, and the largest gap min_B n·x − max_A n·x over them decides.
#pragma once
#include "certify/certificate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>

namespace scalecert {
inline std::ostream& operator<<(std::ostream& o, Verdict v) { return o << name(v); }
}  // namespace scalecert

namespace test {
using namespace scalecert::internal;

// The message of the InputError f throws, or "" when it throws none.
template <class F>
std::string input_error(F&& f) {
    try {
        f();
    } catch (const scalecert::InputError& e) {
        return e.what();
    }
    return "";
}

// p/q in lowest terms (GMP's rational arithmetic requires canonical operands).
inline Q qc(long p, long q) {
    Q r(p, q);
    r.canonicalize();
    return r;
}

inline Vec3q scaled(const Vec3q& v, const Vec3q& s, const Q& rho) {
    return {s[0] + rho * (v[0] - s[0]), s[1] + rho * (v[1] - s[1]), s[2] + rho * (v[2] - s[2])};
}

struct Brute {
    // Per candidate direction n: n·s1, max over P1 of n·v, n·s2, min over P2 of n·w. For ρ > 0 the
    // scaled extremes are n·s + ρ(extreme − n·s).
    struct Dir {
        Q ns1, max1, ns2, min2;
    };
    std::vector<Dir> dirs;
    std::vector<Vec3z> normals;  // dirs[k]'s direction
    explicit Brute(const ExactScene& sc) {
        std::vector<Vec3q> diffs;
        for (int i = 0; i < 2; ++i) {
            const auto& p = sc.P[i].points;
            for (size_t a = 0; a < p.size(); ++a)
                for (size_t b = a + 1; b < p.size(); ++b)
                    if (p[a] != p[b]) diffs.push_back(sub(p[b], p[a]));
        }
        std::set<Vec3z> seen;
        for (size_t a = 0; a < diffs.size(); ++a)
            for (size_t b = a + 1; b < diffs.size(); ++b) {
                Vec3q c = cross(diffs[a], diffs[b]);
                if (sgn(c[0]) == 0 && sgn(c[1]) == 0 && sgn(c[2]) == 0) continue;
                Vec3z n = primitive(c);
                for (const Vec3z& m : {n, neg(n)})
                    if (seen.insert(m).second) {
                        dirs.push_back(extremes(sc, to_q(m)));
                        normals.push_back(m);
                    }
            }
    }
    static Dir extremes(const ExactScene& sc, const Vec3q& n) {
        Dir d{dot(n, sc.P[0].seed), dot(n, sc.P[0].points[0]), dot(n, sc.P[1].seed), dot(n, sc.P[1].points[0])};
        for (const Vec3q& v : sc.P[0].points) d.max1 = std::max(d.max1, dot(n, v));
        for (const Vec3q& w : sc.P[1].points) d.min2 = std::min(d.min2, dot(n, w));
        return d;
    }
    // +1 separated, 0 touching, −1 overlapping.
    int classify(const ExactScene&, const Q& r1, const Q& r2) const {
        int best = -1;
        for (const Dir& d : dirs) {
            int s = cmp(d.ns2 + r2 * (d.min2 - d.ns2), d.ns1 + r1 * (d.max1 - d.ns1));
            if (s > 0) return 1;
            best = std::max(best, s);
        }
        return best;
    }
};

// The contact at a point (ρ1, ρ2) of the touching curve, by brute force: the vertices (indices
// into the points, duplicates and points inside faces included) of the smallest face of each
// polytope that holds the touching set. Every candidate direction whose planes touch there
// (max over P1(ρ1) = min over P2(ρ2)) holds the touching set in its maximisers; intersecting them
// over all candidates (every facet normal of the Minkowski sum is one) gives the smallest faces.
// Empty when no candidate touches (the pair is not touching there).
inline std::pair<std::vector<int>, std::vector<int>> brute_contact(const ExactScene& sc, const Q& r1, const Q& r2) {
    // Candidate normals: cross products of two distinct directions between points (of either
    // polytope), each direction taken once up to sign.
    std::set<Vec3z> dirs;
    for (int i = 0; i < 2; ++i) {
        const auto& p = sc.P[i].points;
        for (size_t a = 0; a < p.size(); ++a)
            for (size_t c = a + 1; c < p.size(); ++c)
                if (p[a] != p[c]) {
                    const Vec3z d = primitive(sub(p[c], p[a]));
                    dirs.insert(std::max(d, neg(d)));
                }
    }
    const std::vector<Vec3z> D(dirs.begin(), dirs.end());
    std::vector<int> g[2];
    bool any = false;
    std::set<Vec3z> seen;
    for (size_t a = 0; a < D.size(); ++a)
        for (size_t b = a + 1; b < D.size(); ++b) {
            const Vec3q n = cross(to_q(D[a]), to_q(D[b]));
            if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0) continue;
            for (const Vec3z& m : {primitive(n), neg(primitive(n))}) {
                if (!seen.insert(m).second) continue;
                const Vec3q mq = to_q(m);
                const Brute::Dir d = Brute::extremes(sc, mq);
                if (d.ns1 + r1 * (d.max1 - d.ns1) != d.ns2 + r2 * (d.min2 - d.ns2)) continue;
                const Q ext[2] = {d.max1, d.min2};
                for (int k = 0; k < 2; ++k) {
                    std::vector<int> att;
                    for (size_t v = 0; v < sc.P[k].points.size(); ++v)
                        if (dot(mq, sc.P[k].points[v]) == ext[k] &&
                            (!any || std::binary_search(g[k].begin(), g[k].end(), int(v))))
                            att.push_back(static_cast<int>(v));
                    g[k] = att;
                }
                any = true;
            }
        }
    return {g[0], g[1]};
}

// The affine dimension of some of the points (0 for a point, 3 for a solid).
inline int affine_dimension(const std::vector<Vec3q>& pts, const std::vector<int>& idx) {
    int dim = 0;
    Vec3q e1, c;
    for (int k : idx) {
        const Vec3q v = sub(pts[k], pts[idx[0]]);
        if (dim == 0 && (sgn(v[0]) || sgn(v[1]) || sgn(v[2])))
            e1 = v, dim = 1;
        else if (dim == 1) {
            const Vec3q x = cross(e1, v);
            if (sgn(x[0]) || sgn(x[1]) || sgn(x[2])) c = x, dim = 2;
        } else if (dim == 2 && sgn(dot(c, v)))
            return 3;
    }
    return dim;
}

inline int verdict_sign(Verdict v) { return v == Verdict::Separated ? 1 : v == Verdict::Touching ? 0 : -1; }

// A random non-flat polytope of n points with coordinates k/den, k in [-range, range], offset by o.
inline std::vector<Vec3q> random_points(std::mt19937& g, int n, int range, int den, const Vec3q& o) {
    std::uniform_int_distribution<int> u(-range, range);
    for (;;) {
        std::vector<Vec3q> p;
        for (int i = 0; i < n; ++i) p.push_back({o[0] + qc(u(g), den), o[1] + qc(u(g), den), o[2] + qc(u(g), den)});
        // non-flat: some 4 points with nonzero volume
        for (size_t a = 1; a < p.size(); ++a)
            for (size_t b = a + 1; b < p.size(); ++b)
                for (size_t c = b + 1; c < p.size(); ++c)
                    if (sgn(dot(sub(p[a], p[0]), cross(sub(p[b], p[0]), sub(p[c], p[0]))))) {
                        return p;
                    }
    }
}

inline ExactScene random_scene(std::mt19937& g, int n1, int n2) {
    ExactScene sc;
    std::uniform_int_distribution<int> off(-6, 6);
    sc.P[0].points = random_points(g, n1, 4, 1, {Q(0), Q(0), Q(0)});
    sc.P[1].points = random_points(g, n2, 4, 2, {Q(off(g)), Q(off(g)), Q(off(g))});
    for (int i = 0; i < 2; ++i) {
        Vec3q c{Q(0), Q(0), Q(0)};
        for (const auto& v : sc.P[i].points)
            for (int k = 0; k < 3; ++k) c[k] += v[k];
        for (int k = 0; k < 3; ++k) c[k] /= Q(static_cast<long>(sc.P[i].points.size()));
        sc.P[i].seed = c;
        sc.lo[i] = Q(1, 4);
        sc.hi[i] = Q(4);
    }
    return sc;
}

// Crossed prisms (scalecert-bench's family): a regular n-gon rounded to integers on a circle of
// radius 10^6, extruded along z for P1 and along x for P2 above it. The Minkowski sum has O(n^2)
// facet normals; the curve reaches ρ2 = 0 after a piece or two.
inline std::array<std::vector<std::array<long, 3>>, 2> crossed_prisms(int n) {
    std::array<std::vector<std::array<long, 3>>, 2> P;
    const long R = 1000000;
    const double pi = std::acos(-1.0);
    for (int k = 0; k < n; ++k) {
        const long x = std::lround(R * std::cos(2 * pi * k / n + 0.1)),
                   y = std::lround(R * std::sin(2 * pi * k / n + 0.1));
        for (long z : {-3 * R, 3 * R}) {
            P[0].push_back({x, y, z});
            P[1].push_back({z + 12345, y + R / 5, x + 3 * R});
        }
    }
    return P;
}
// The same as a scene, with mean seeds and I1 = I2 = [1/2, 2].
inline ExactScene crossed_prism_scene(int n) {
    ExactScene sc;
    const auto P = crossed_prisms(n);
    for (int i = 0; i < 2; ++i) {
        for (const auto& v : P[i]) sc.P[i].points.push_back({Q(v[0]), Q(v[1]), Q(v[2])});
        sc.lo[i] = Q(1, 2);
        sc.hi[i] = Q(2);
    }
    finish_scene(sc, "crossed prisms");
    return sc;
}

}  // namespace test
