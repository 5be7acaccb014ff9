// The fast measures against the exact path: proved_distance (a double GJK's guess, proved by the
// slab over all vertices) against CGAL's QP over all vertices, and proved_depth (the exact EPA)
// against the minimum over every facet normal of the Minkowski sum, at random pairs and at pairs
// 2^-k off the touching curve (rounded to doubles, as a floating-point program would claim them).
// Equal exact values give equal judgements: every rule of CLAIMS.md for a distance or a depth is
// a function of the claim and the exact square. Hand-derived values on cubes and a tetrahedron
// first.
#define BOOST_TEST_MODULE measures
#include <boost/test/unit_test.hpp>

#include "certify/query.hpp"
#include "geometry/measures.hpp"
#include "support.hpp"

#include <cstdlib>
#include <iostream>
#include <random>

using namespace scalecert::internal;

namespace {
std::vector<Vec3q> box(int x0, int y0, int z0, int x1, int y1, int z1) {
    std::vector<Vec3q> v;
    for (int x : {x0, x1})
        for (int y : {y0, y1})
            for (int z : {z0, z1}) v.push_back({Q(x), Q(y), Q(z)});
    return v;
}
HullModel stacked() {  // [0,2]^3 below [0,2]^2 x [3,5]: they touch on ρ1 + ρ2 = 3
    ExactScene s;
    s.P[0].points = box(0, 0, 0, 2, 2, 2);
    s.P[1].points = box(0, 0, 3, 2, 2, 5);
    s.lo[0] = s.lo[1] = Q(1, 2);
    s.hi[0] = s.hi[1] = Q(5, 2);
    finish_scene(s, "scene");
    return build_model(s);
}
}  // namespace

BOOST_AUTO_TEST_CASE(cubes_by_hand) {
    const HullModel m = stacked();
    // P1(ρ1) reaches z = 1 + ρ1 and P2(ρ2) starts at z = 4 − ρ2: at (1, 1/2) the gap is 3/2.
    const ProvedDistance d = proved_distance(m, Q(1), Q(1, 2));
    BOOST_TEST(d.d.squared == Q(9, 4));
    BOOST_TEST(!d.fallback);
    BOOST_TEST(d.d.p2[2] - d.d.p1[2] == Q(3, 2));
    // At (2, 2) they overlap by 1 in z (and by 4 in x and y): depth 1 along +z.
    const std::optional<ProvedDepth> e = proved_depth(m, Q(2), Q(2));
    BOOST_TEST_REQUIRE(e.has_value());
    BOOST_TEST(e->squared == Q(1));
    BOOST_TEST((e->direction == Vec3z{Z(0), Z(0), Z(1)}));
    // Touching at (3/2, 3/2) and separated at (1, 1): no origin strictly inside the difference.
    BOOST_TEST(!proved_depth(m, Q(3, 2), Q(3, 2)).has_value());
    BOOST_TEST(!proved_depth(m, Q(1), Q(1)).has_value());
    BOOST_TEST(proved_distance(m, Q(3, 2), Q(3, 2)).d.squared == Q(0));
    // At (1, 1/2) shifted sideways: P2 = [3,5] x [0,2] x [3,5] beside and above P1 = [0,2]^3.
    ExactScene s;
    s.P[0].points = box(0, 0, 0, 2, 2, 2);
    s.P[1].points = box(3, 0, 3, 5, 2, 5);
    s.lo[0] = s.lo[1] = Q(1, 2);
    s.hi[0] = s.hi[1] = Q(5, 2);
    finish_scene(s, "scene");
    const HullModel k = build_model(s);
    // P1(1) = [0,2]^3, P2(1) = [3,5]x[0,2]x[3,5]: the nearest corners (2, y, 2) and (3, y, 3): √2.
    BOOST_TEST(proved_distance(k, Q(1), Q(1)).d.squared == Q(2));
}

BOOST_AUTO_TEST_CASE(fast_measures_equal_the_exact_path) {
    // SCALECERT_DIFFERENTIAL_PAIRS sets the number of pairs (docs/testing.md runs 100,000).
    long want = 6000;
    if (const char* e = std::getenv("SCALECERT_DIFFERENTIAL_PAIRS")) want = std::atol(e);
    std::mt19937 g(2026);
    long pairs = 0, distances = 0, depths = 0, touching = 0, fallbacks = 0, near = 0;
    for (int t = 0; pairs < want; ++t) {
        const ExactScene sc = test::random_scene(g, 4 + t % 13, 4 + (t / 13) % 11);
        const HullModel m = build_model(sc);
        const TouchingCurve c = build_curve(m);
        const std::vector<Vec3z> normals = all_facet_normals(m);
        std::uniform_real_distribution<double> u(0.25, 4);
        std::uniform_int_distribution<int> kd(1, 52);
        for (int i = 0; i < 100 && pairs < want; ++i, ++pairs) {
            double a = u(g), b = u(g);
            if (i % 2) {  // 2^-k above or below the curve, rounded to doubles
                const Q y = c.env.value(m.lines, exact_from_double(a));
                if (sgn(y) > 0) {
                    const int k = kd(g);
                    b = to_double_rn(y + (i % 4 == 1 ? 1 : -1) * y / Q(Z(1) << k));
                    ++near;
                }
                if (!(b > 0)) b = u(g);
            }
            const Q r1 = exact_from_double(a), r2 = exact_from_double(b);
            const Verdict v = query(m, c, r1, r2, false).verdict;
            const ProvedDistance pd = proved_distance(m, r1, r2);
            fallbacks += pd.fallback;
            const ExactDistance ed = exact_distance(m, r1, r2);
            BOOST_TEST(pd.d.squared == ed.squared, "distance at (" << a << ", " << b << ") in scene " << t);
            BOOST_TEST((sgn(pd.d.squared) == 0) == (v != Verdict::Separated));
            ++distances;
            const ExactDepth ee = exact_penetration_depth(m, normals, r1, r2);
            const std::optional<ProvedDepth> pe = proved_depth(m, r1, r2);
            if (v == Verdict::Overlapping) {
                BOOST_TEST_REQUIRE(pe.has_value());
                BOOST_TEST(pe->squared == ee.squared, "depth at (" << a << ", " << b << ") in scene " << t);
                ++depths;
            } else {
                BOOST_TEST(!pe.has_value());
                BOOST_TEST((v == Verdict::Touching ? ee.squared == 0 : sgn(ee.squared) < 0));
                touching += v == Verdict::Touching;
            }
        }
    }
    std::cout << "differential: " << pairs << " pairs (" << near << " within 2^-k of the curve), " << distances << " distances ("
              << fallbacks << " exact fallbacks), " << depths << " depths of overlapping pairs, " << touching << " touching\n";
    BOOST_TEST(depths > pairs / 10);
}
