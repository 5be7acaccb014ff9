// The fast measures against the exact path: proved_distance (a double GJK's guess, proved by the
// slab over all vertices: by the exact GJK, and by the QP's rounds) against CGAL's QP over all
// vertices, and proved_depth (an EPA in doubles checked exactly, and the exact EPA) against the
// minimum over every facet normal of the Minkowski sum, at random pairs and at pairs
// 2^-k off the touching curve (rounded to doubles, as a floating-point program would claim them).
// Equal exact values give equal judgements: every rule of CLAIMS.md for a distance or a depth is
// a function of the claim and the exact square. Hand-derived values on cubes and a tetrahedron
// first.
#include <boost/test/unit_test.hpp>

#include "certify/query.hpp"
#include "curve/scan.hpp"
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
    // measured_depth (what certify-fp runs): touching at (3/2, 3/2), where P1 reaches z = 5/2 and
    // P2 starts there: the supporting plane is z's, and the common point lies on both faces.
    const std::optional<MeasuredDepth> t = measured_depth(HullPoints(m), Q(3, 2), Q(3, 2));
    BOOST_TEST_REQUIRE(t.has_value());
    BOOST_TEST(t->state == Verdict::Touching);
    BOOST_TEST((t->normal == Vec3z{Z(0), Z(0), Z(1)}));
    BOOST_TEST(t->distance.p1[2] == Q(5, 2));
    BOOST_TEST(!t->distance.w1.empty());
    // Separated at (1, 1) (gap 1 in z): the slab's normal is +z; overlapping at (2, 2): depth 1.
    const std::optional<MeasuredDepth> sep = measured_depth(HullPoints(m), Q(1), Q(1));
    BOOST_TEST((sep && sep->state == Verdict::Separated && sep->normal == Vec3z{Z(0), Z(0), Z(1)}));
    const std::optional<MeasuredDepth> ov = measured_depth(HullPoints(m), Q(2), Q(2));
    BOOST_TEST((ov && ov->state == Verdict::Overlapping && ov->depth->squared == Q(1)));
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
    long pairs = 0, distances = 0, depths = 0, touching = 0, fallbacks = 0, near = 0, by_qp = 0, from_doubles = 0;
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
            by_qp += pd.by_qp;
            const ExactDistance ed = exact_distance(m, r1, r2);
            BOOST_TEST(pd.d.squared == ed.squared, "distance at (" << a << ", " << b << ") in scene " << t);
            // Its second stage alone, and the closest points each names (convex weights on the
            // vertices they name, as the certificate states them).
            const std::optional<ProvedDistance> qp = proved_distance_by_qp(HullPoints(m), r1, r2, 1 << 20);
            BOOST_TEST_REQUIRE(qp.has_value());
            BOOST_TEST(qp->d.squared == ed.squared);
            for (const ProvedDistance* x : {&pd, &*qp}) {
                const Vec3q u = sub(x->d.p2, x->d.p1);
                BOOST_TEST(dot(u, u) == ed.squared);
                for (int k = 0; k < 2; ++k) {
                    Vec3q y{Q(0), Q(0), Q(0)};
                    Q total(0);
                    for (const auto& [v, w] : k ? x->d.w2 : x->d.w1) {
                        BOOST_TEST(sgn(w) > 0);
                        total += w;
                        const Vec3q p = scaled_point(m, k, k ? r2 : r1, m.P[k].points[static_cast<size_t>(v)]);
                        for (int c = 0; c < 3; ++c) y[c] += w * p[c];
                    }
                    BOOST_TEST(total == Q(1));
                    BOOST_TEST((y == (k ? x->d.p2 : x->d.p1)));
                }
            }
            BOOST_TEST((sgn(pd.d.squared) == 0) == (v != Verdict::Separated));
            ++distances;
            const ExactDepth ee = exact_penetration_depth(m, normals, r1, r2);
            const std::optional<ProvedDepth> pe = proved_depth(m, r1, r2);
            const std::optional<ProvedDepth> xe = exact_epa(HullPoints(m), r1, r2);
            if (v == Verdict::Overlapping) {
                BOOST_TEST_REQUIRE(pe.has_value());
                BOOST_TEST(pe->squared == ee.squared, "depth at (" << a << ", " << b << ") in scene " << t);
                BOOST_TEST_REQUIRE(xe.has_value());
                BOOST_TEST(xe->squared == ee.squared);
                from_doubles += pe->from_doubles;
                ++depths;
            } else {
                BOOST_TEST(!pe.has_value());
                BOOST_TEST(!xe.has_value());
                BOOST_TEST((v == Verdict::Touching ? ee.squared == 0 : sgn(ee.squared) < 0));
                touching += v == Verdict::Touching;
            }
            // What certify-fp runs: the depth from support queries alone, with its state.
            const std::optional<MeasuredDepth> md = measured_depth(HullPoints(m), r1, r2);
            BOOST_TEST_REQUIRE(md.has_value());
            BOOST_TEST(md->state == v, "measured depth's state at (" << a << ", " << b << ") in scene " << t);
            if (md->state == Verdict::Overlapping && v == Verdict::Overlapping)
                BOOST_TEST(md->depth->squared == ee.squared);
        }
    }
    std::cout << "differential: " << pairs << " pairs (" << near << " within 2^-k of the curve), " << distances
              << " distances (" << by_qp << " by the QP's rounds, " << fallbacks << " exact fallbacks), " << depths
              << " depths of overlapping pairs (" << from_doubles << " from the doubles' surface), " << touching
              << " touching\n";
    BOOST_TEST(depths > pairs / 10);
    // Both first stages carry most of the load (each second stage is checked on every pair above).
    BOOST_TEST(by_qp < distances / 10);
    BOOST_TEST(from_doubles > depths / 2);
}

BOOST_AUTO_TEST_CASE(cloud_points_equal_the_hull) {
    // The measures on the scan path's point trees (no hull) against the same on the hull model's
    // vertices and CGAL's QP over all of them: random integer clouds in and on balls, with points
    // inside the hulls (which the trees hold and the hull drops), at random pairs.
    std::mt19937 g(77);
    long pairs = 0;
    for (int t = 0; t < 24; ++t) {
        std::normal_distribution<double> N(0, 1);
        std::uniform_real_distribution<double> U(0, 1);
        ExactScene sc;
        for (int i = 0; i < 2; ++i) {
            const int n = 50 + 150 * (t % 5);
            for (int k = 0; k < n; ++k) {
                double x = N(g), y = N(g), z = N(g);
                const double l = std::sqrt(x * x + y * y + z * z), r = (k % 3 ? 1000 : 1000 * U(g)) / l;
                sc.P[i].points.push_back({Q(std::lround(x * r) + (i ? 2500 : 0)),
                                          Q(std::lround(y * r) + (i ? 300 * (t % 4) : 0)), Q(std::lround(z * r))});
            }
        }
        sc.lo[0] = sc.lo[1] = Q(1, 2);
        sc.hi[0] = sc.hi[1] = Q(2);
        finish_scene(sc, "scene");
        const HullModel m = build_model(sc);
        const TouchingCurve c = build_curve(m);
        auto cs = std::make_shared<const CompactScene>(*compact_scene(sc));
        const CloudPoints cloud(cs);
        const HullPoints hull(m);
        std::uniform_real_distribution<double> u(0.5, 2.5);
        for (int i = 0; i < 25; ++i, ++pairs) {
            const Q r1 = exact_from_double(u(g)), r2 = exact_from_double(u(g));
            const Verdict v = query(m, c, r1, r2, false).verdict;
            const std::optional<ProvedDistance> dc = proved_distance(cloud, r1, r2);
            BOOST_TEST_REQUIRE(dc.has_value());
            BOOST_TEST(dc->d.squared == exact_distance(m, r1, r2).squared);
            const std::optional<MeasuredDepth> mc = measured_depth(cloud, r1, r2), mh = measured_depth(hull, r1, r2);
            BOOST_TEST_REQUIRE((mc && mh));
            BOOST_TEST(mc->state == mh->state);
            BOOST_TEST((mc->state == Verdict::Separated) == (v == Verdict::Separated));
            if (mc->state == Verdict::Overlapping) BOOST_TEST(mc->depth->squared == mh->depth->squared);
            const Vec3q n{Q(1), Q(i, 7), Q(-2)};
            BOOST_TEST((plane_extents(cloud, n, r1, r2) == plane_extents(m, n, r1, r2)));
            // Directions past the double range (their doubles scaled by a power of two for the
            // trees' filter): the same support value as the hull's exact climb.
            const Vec3z huge{Z((Z(3) << (1000 + 10 * i)) + i), Z(-(Z(1) << (999 + 10 * i)) + 7 * i),
                             Z(Z(i % 5 - 2) << (990 + 9 * i))};
            for (int b = 0; b < 2; ++b) {
                const Vec3z d = b ? neg(huge) : huge;
                BOOST_TEST(dot(to_q(d), cloud.point(b, cloud.argmax(b, d))) ==
                           dot(to_q(d), hull.point(b, hull.argmax(b, d))));
            }
        }
    }
    std::cout << "cloud points: " << pairs << " pairs, the same distances, depths and extents as the hull\n";
}
