// Compounds (issue 22): each part pair's overlap polygon in I1 × I2 and their union, against
// regions derived by hand and against a brute force that shares nothing with the Gauss-map
// overlay: the separating-axis test over every face normal of both parts and the cross product
// of every pair of their edges (a superset of the facet normals of A ⊕ (−B)).
#define BOOST_TEST_MODULE compound
#include <boost/test/unit_test.hpp>

#include "compound/region.hpp"
#include "support.hpp"

#include <random>

using namespace scalecert::internal;

namespace {
Polyhedron box(int x0, int y0, int z0, int x1, int y1, int z1) {
    std::vector<Vec3q> v;
    for (int x : {x0, x1})
        for (int y : {y0, y1})
            for (int z : {z0, z1}) v.push_back({Q(x), Q(y), Q(z)});
    return build_polyhedron(v, "part");
}
const Q kLo[2] = {Q(1), Q(1)}, kHi[2] = {Q(4), Q(3)};

// Do A(ρ1) and B(ρ2) meet? No axis among the faces and edge pairs separates them.
bool meet_brute(const Polyhedron& A, const Polyhedron& B, const Vec3q& s1, const Vec3q& s2, const Q& r1, const Q& r2) {
    std::vector<Vec3q> axes;
    for (const Face& f : A.faces) axes.push_back(to_q(f.normal));
    for (const Face& f : B.faces) axes.push_back(to_q(f.normal));
    for (const Edge& e : A.edges)
        for (const Edge& g : B.edges) {
            const Vec3q c = cross(sub(A.points[static_cast<size_t>(e.b)], A.points[static_cast<size_t>(e.a)]),
                                  sub(B.points[static_cast<size_t>(g.b)], B.points[static_cast<size_t>(g.a)]));
            if (sgn(c[0]) || sgn(c[1]) || sgn(c[2])) axes.push_back(c);
        }
    auto range = [](const Polyhedron& P, const Vec3q& s, const Q& r, const Vec3q& n) {
        Q lo, hi;
        bool first = true;
        for (int v : P.vertices) {
            const Vec3q& p = P.points[static_cast<size_t>(v)];
            const Q t = dot(n, s) + r * (dot(n, p) - dot(n, s));
            if (first || t < lo) lo = t;
            if (first || t > hi) hi = t;
            first = false;
        }
        return std::pair{lo, hi};
    };
    for (const Vec3q& n : axes) {
        const auto [a0, a1] = range(A, s1, r1, n);
        const auto [b0, b1] = range(B, s2, r2, n);
        if (a1 < b0 || b1 < a0) return false;
    }
    return true;
}
bool inside_convex(const std::vector<Point2q>& p, const Point2q& x) {
    if (p.empty()) return false;
    if (p.size() == 1) return p[0] == x;
    if (p.size() == 2) {
        const Q c = (p[1][0] - p[0][0]) * (x[1] - p[0][1]) - (p[1][1] - p[0][1]) * (x[0] - p[0][0]);
        return sgn(c) == 0 && std::min(p[0][0], p[1][0]) <= x[0] && x[0] <= std::max(p[0][0], p[1][0]) &&
               std::min(p[0][1], p[1][1]) <= x[1] && x[1] <= std::max(p[0][1], p[1][1]);
    }
    for (size_t i = 0; i < p.size(); ++i) {
        const Point2q &a = p[i], &b = p[(i + 1) % p.size()];
        if (sgn((b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0])) < 0) return false;
    }
    return true;
}
}  // namespace

BOOST_AUTO_TEST_CASE(a_band_two_parts_either_side_of_the_seed) {
    // Object 1: the parts [2,3] x [-1,1]^2 and [-3,-2] x [-1,1]^2 about the seed 0, in neither.
    // Object 2: the box [4,5] x [-1,1]^2, seed (9/2, 0, 0). The right part spans
    // [2ρ1, 3ρ1] in x and [-ρ1, ρ1] in y and z; the box [9/2 − ρ2/2, 9/2 + ρ2/2] and [-ρ2, ρ2]. They
    // meet iff 3ρ1 >= 9/2 − ρ2/2 and 2ρ1 <= 9/2 + ρ2/2: a band, by hand. In I1 × I2 = [1,4] x [1,3]
    // its corners are (4/3, 1), (5/2, 1), (3, 3), (1, 3). The left part never meets the box.
    const Polyhedron right = box(2, -1, -1, 3, 1, 1), left = box(-3, -1, -1, -2, 1, 1), B = box(4, -1, -1, 5, 1, 1);
    const Vec3q s1{Q(0), Q(0), Q(0)}, s2{Q(9, 2), Q(0), Q(0)};
    const PairRegion r = pair_region(right, B, s1, s2, kLo, kHi);
    const std::vector<Point2q> band = {{Q(4, 3), Q(1)}, {Q(5, 2), Q(1)}, {Q(3), Q(3)}, {Q(1), Q(3)}};
    BOOST_TEST((r.polygon == band));
    // hA(+x) = 3, hB(+x) = 1/2, n·d = 9/2; hA(−x) = −2 (the seed outside the part).
    bool saw_plus = false, saw_minus = false;
    for (const HalfPlane& h : r.constraints) {
        if (h.normal == Vec3z{Z(1), Z(0), Z(0)}) saw_plus = h.a == 3 && h.b == Q(1, 2) && h.c == Q(9, 2);
        if (h.normal == Vec3z{Z(-1), Z(0), Z(0)}) saw_minus = h.a == -2 && h.b == Q(1, 2) && h.c == Q(-9, 2);
    }
    BOOST_TEST(saw_plus);
    BOOST_TEST(saw_minus);
    BOOST_TEST(pair_region(left, B, s1, s2, kLo, kHi).polygon.empty());
    // The union is the band: overlap, then apart again as ρ1 grows (at ρ2 = 2: from 7/6 to 11/4).
    const std::vector<RegionPiece> u = union_of({r.polygon, pair_region(left, B, s1, s2, kLo, kHi).polygon});
    BOOST_TEST_REQUIRE(u.size() == 1u);
    BOOST_TEST((u[0].outer == band));
    BOOST_TEST(u[0].holes.empty());
    BOOST_TEST(!inside_convex(band, {Q(1), Q(2)}));
    BOOST_TEST(inside_convex(band, {Q(7, 6), Q(2)}));
    BOOST_TEST(!inside_convex(band, {Q(7, 6) - Q(1, 1000), Q(2)}));
    BOOST_TEST(inside_convex(band, {Q(11, 4), Q(2)}));
    BOOST_TEST(!inside_convex(band, {Q(3), Q(2)}));
}

BOOST_AUTO_TEST_CASE(an_l_shape_against_a_box) {
    // Object 1, an L: [0,2] x [0,1] x [0,1] and [0,1] x [1,2] x [0,1], seed (1/2, 1/2, 1/2).
    // Object 2: the box [3,4] x [0,1] x [0,1], seed (7/2, 1/2, 1/2). Along x the L's first part
    // reaches 1/2 + 3ρ1/2 and the box starts at 7/2 − ρ2/2; in y and z both hold the seed's line,
    // so the pair meets iff 3ρ1 + ρ2 >= 6. The second part reaches x = 1/2 + ρ1/2: it meets iff
    // ρ1 + ρ2 >= 6 and its y-range [1/2 + ρ1/2, 1/2 + 3ρ1/2] meets the box's [1/2 − ρ2/2,
    // 1/2 + ρ2/2], i.e. ρ1 <= ρ2: in [1,4] x [1,3] only at (3, 3). The union is the first pair's.
    const Polyhedron a = box(0, 0, 0, 2, 1, 1), b = box(0, 1, 0, 1, 2, 1), B = box(3, 0, 0, 4, 1, 1);
    const Vec3q s1{Q(1, 2), Q(1, 2), Q(1, 2)}, s2{Q(7, 2), Q(1, 2), Q(1, 2)};
    const PairRegion ra = pair_region(a, B, s1, s2, kLo, kHi), rb = pair_region(b, B, s1, s2, kLo, kHi);
    const std::vector<Point2q> first = {{Q(5, 3), Q(1)}, {Q(4), Q(1)}, {Q(4), Q(3)}, {Q(1), Q(3)}};
    BOOST_TEST((ra.polygon == first));
    BOOST_TEST((rb.polygon == std::vector<Point2q>{{Q(3), Q(3)}}));
    const std::vector<RegionPiece> u = union_of({ra.polygon, rb.polygon});
    BOOST_TEST_REQUIRE(u.size() == 1u);
    BOOST_TEST((u[0].outer == first));
}

BOOST_AUTO_TEST_CASE(pair_regions_equal_the_separating_axis_brute_force) {
    // Random parts (4 to 9 points in a cube of side 8 at random offsets) about seeds anywhere,
    // at random exact pairs and at every corner of the region (on its boundary) and 2^-20 off it.
    std::mt19937 g(22);
    std::uniform_int_distribution<int> c(-4, 4), off(-6, 6), np(4, 9);
    long checked = 0, inside = 0;
    for (int t = 0; t < 40; ++t) {
        Polyhedron P[2];
        for (int i = 0; i < 2; ++i) {
            for (;;) {
                std::vector<Vec3q> v;
                const int o = off(g) + (i ? 6 : 0);
                for (int k = np(g); k > 0; --k) v.push_back({Q(c(g) + o), Q(c(g)), Q(c(g))});
                try {
                    P[i] = build_polyhedron(v, "part");
                    break;
                } catch (const InputError&) {  // flat: draw again
                }
            }
        }
        const Vec3q s1{Q(off(g)), Q(c(g)), Q(c(g))}, s2{Q(off(g) + 6), Q(c(g)), Q(c(g))};
        const Q lo[2] = {Q(1, 4), Q(1, 4)}, hi[2] = {Q(3), Q(3)};
        const PairRegion r = pair_region(P[0], P[1], s1, s2, lo, hi);
        std::vector<Point2q> probes;
        std::uniform_int_distribution<int> q(1, 120);
        for (int k = 0; k < 40; ++k) probes.push_back({Q(q(g), 40), Q(q(g), 40)});
        for (const Point2q& x : r.polygon)
            for (const Q& e : {Q(0), Q(1, 1 << 20), Q(-1, 1 << 20)}) probes.push_back({x[0] + e, x[1] - e});
        for (const Point2q& x : probes) {
            if (x[0] < lo[0] || x[0] > hi[0] || x[1] < lo[1] || x[1] > hi[1]) continue;
            const bool want = meet_brute(P[0], P[1], s1, s2, x[0], x[1]);
            BOOST_TEST(inside_convex(r.polygon, x) == want, "scene " << t << " at (" << x[0] << ", " << x[1] << ")");
            ++checked;
            inside += want;
        }
    }
    BOOST_TEST(inside > 50);
    std::cout << "compound pairs: " << checked << " pairs against the separating-axis brute force, " << inside << " meeting\n";
}

BOOST_AUTO_TEST_CASE(compound_verdicts_equal_the_brute_force_over_all_pairs) {
    // Random compounds of three parts each (seeds anywhere): the objects meet at a pair iff some
    // part pair does (separating-axis brute force), pruned pairs included; at random pairs and at
    // the corners of every pair polygon.
    std::mt19937 g(2022);
    std::uniform_int_distribution<int> c(-3, 3), off(-5, 5), np(4, 8);
    long checked = 0, meeting = 0, pruned = 0;
    for (int t = 0; t < 12; ++t) {
        ExactScene sc;
        std::vector<Polyhedron> parts[2];
        for (int i = 0; i < 2; ++i) {
            while (sc.P[i].parts.size() < 3) {
                std::vector<Vec3q> v;
                const int ox = off(g) + (i ? 7 : 0), oy = off(g);
                for (int k = np(g); k > 0; --k) v.push_back({Q(c(g) + ox), Q(c(g) + oy), Q(c(g))});
                try {
                    parts[i].push_back(build_polyhedron(v, "part"));
                } catch (const InputError&) {
                    continue;
                }
                sc.P[i].parts.push_back(v);
                sc.P[i].points.insert(sc.P[i].points.end(), v.begin(), v.end());
            }
            sc.P[i].seed = {Q(off(g) + (i ? 7 : 0)), Q(off(g)), Q(0)};
            sc.P[i].seed_given = true;
            sc.lo[i] = Q(1, 4);
            sc.hi[i] = Q(3);
        }
        const CompoundRegion r = compound_region(sc, "scene");
        pruned += r.pruned;
        std::vector<Point2q> probes;
        std::uniform_int_distribution<int> q(10, 120);
        for (int k = 0; k < 60; ++k) probes.push_back({Q(q(g), 40), Q(q(g), 40)});
        for (const auto& p : r.pairs)
            for (const Point2q& x : p.polygon) probes.push_back(x);
        for (const Point2q& x : probes) {
            bool want = false;
            for (const Polyhedron& A : parts[0])
                for (const Polyhedron& B : parts[1]) want = want || meet_brute(A, B, sc.P[0].seed, sc.P[1].seed, x[0], x[1]);
            const std::string v = compound_verdict(r, x[0], x[1]).verdict;
            BOOST_TEST((v != "separated") == want, "scene " << t << " at (" << x[0] << ", " << x[1] << "): " << v);
            ++checked;
            meeting += want;
        }
    }
    BOOST_TEST(meeting > 20);
    std::cout << "compound verdicts: " << checked << " pairs (" << meeting << " meeting), " << pruned << " part pairs pruned\n";
}
