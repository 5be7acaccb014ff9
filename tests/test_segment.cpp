// The t1–t2 decision curve along a segment (the paper's Section III).
#include <boost/test/unit_test.hpp>

#include "segment/segment.hpp"
#include "support.hpp"

#include <cmath>

using namespace scalecert::internal;

static HullModel hand_model() {
    return build_model(load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/tetra_box_switch.json"));
}

BOOST_AUTO_TEST_CASE(seed_segment_by_hand) {
    // Tetrahedron seed s1 = (0,0,9/2), box seed s2 = 0: the segment runs straight down the z axis.
    // It leaves the tetrahedron through face c,a,b at (0,0,4) (barycentric 2/7, 2/7, 3/7 of c, a, b,
    // worked out in test_hand_curves' scene notes), i.e. t_s1 = (9/2 − 4)/(9/2) = 1/9; it leaves the
    // box through its top z = 1, t_s2 = 1/(9/2) = 2/9. The Remark: t1 = ρ1/9, t2 = 2ρ2/9.
    HullModel m = hand_model();
    TouchingCurve c = build_curve(m);
    Segment s = make_segment(m, m.s[0], m.s[1]);
    BOOST_TEST_REQUIRE(s.t[0].size() == 1u);
    BOOST_TEST_REQUIRE(s.t[1].size() == 1u);
    BOOST_TEST(s.t[0][0].slope == Q(1, 9));
    BOOST_TEST(s.t[0][0].intercept == 0);
    BOOST_TEST(s.t[1][0].slope == Q(2, 9));
    BOOST_TEST(s.t[1][0].intercept == 0);
    // gap along the segment: 1 − ρ1/9 − 2ρ2/9; at (1, 1): 2/3.
    BOOST_TEST(directional_gap(s, Q(1), Q(1)) == Q(2, 3));
    // The t-curve: (V,F) ρ2 = 9/2 − 5ρ1/2 maps to t2 = 2/9(9/2 − 5·(9 t1)/2) = 1 − 5 t1, so the
    // switch (1, 2) maps to (1/9, 4/9).
    auto tc = t_curve(m, c, s);
    bool found = false;
    for (const auto& p : tc) found |= (p[0] == Q(1, 9) && p[1] == Q(4, 9));
    BOOST_TEST(found);
}

BOOST_AUTO_TEST_CASE(t_plane_query_agrees_with_rho_plane) {
    std::mt19937 g(3);
    int touching = 0;
    for (int t = 0; t < 10; ++t) {
        ExactScene sc = test::random_scene(g, 5 + t % 4, 5);
        HullModel m = build_model(sc);
        TouchingCurve c = build_curve(m);
        Segment s = make_segment(m, m.s[0], m.s[1]);
        std::uniform_int_distribution<int> u(25, 400);
        for (int k = 0; k < 30; ++k) {
            Q r1 = test::qc(u(g), 100), r2 = test::qc(u(g), 100);
            auto b1 = rho_from_t(s, 0, eval(s.t[0], r1)), b2 = rho_from_t(s, 1, eval(s.t[1], r2));
            BOOST_TEST_REQUIRE((b1 && b2));
            BOOST_TEST(*b1 == r1);
            BOOST_TEST(*b2 == r2);
        }
        // every vertex of the t-curve is the image of a touching pair
        for (const auto& p : t_curve(m, c, s)) {
            auto r1 = rho_from_t(s, 0, p[0]), r2 = rho_from_t(s, 1, p[1]);
            BOOST_TEST_REQUIRE((r1 && r2));
            BOOST_TEST(test::Brute(sc).classify(sc, *r1, *r2) == 0);
            ++touching;
        }
    }
    BOOST_TEST(touching > 0);
}

BOOST_AUTO_TEST_CASE(segment_ends_must_be_inside) {
    HullModel m = hand_model();
    BOOST_CHECK_THROW(make_segment(m, {Q(0), Q(0), Q(100)}, m.s[1]), InputError);
    BOOST_CHECK_THROW(make_segment(m, m.s[0], {Q(1), Q(1), Q(1)}),
                      InputError);  // a box corner: on P2(lo2)'s... outside
}

BOOST_AUTO_TEST_CASE(inner_ellipsoid_path_of_stacked_cubes) {
    // Stacked cubes (test_hand_curves): P1(1/2) = [1/2, 3/2]^3 and P2(1/2) = [1/2, 3/2]^2 × [7/2, 9/2].
    // By symmetry each maximum-volume inscribed ellipsoid is the inscribed ball of radius 1/2, at
    // (1,1,1) and (1,1,4); the shortest path between them runs from (1,1,3/2) to (1,1,7/2).
    HullModel m =
        build_model(load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json"));
    Segment s = segment_by_kind(m, "ellipsoids");
    BOOST_TEST(s.kind == "ellipsoids");
    BOOST_TEST_REQUIRE(s.path.has_value());
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) BOOST_TEST(std::fabs(s.path->E[0].matrix[i][k] - (i == k ? 0.5 : 0.0)) < 2e-3);
    BOOST_TEST(std::fabs(s.path->E[1].center[2] - 4.0) < 1e-3);
    BOOST_TEST(std::fabs(s.path->distance - 2.0) < 2e-3);
    BOOST_TEST(std::fabs(s.v1[2].get_d() - 1.5) < 2e-3);
    BOOST_TEST(std::fabs(s.v2[2].get_d() - 3.5) < 2e-3);
    // The exit point p = v1 + t1·(v2 − v1) lies on the boundary of P1(ρ1), the cube of half-width
    // ρ1 about (1,1,1): max_k |p_k − 1| = ρ1, exactly.
    for (Q r : {Q(1, 2), Q(1), Q(2)}) {
        Q t = eval(s.t[0], r), far = 0;
        for (int k = 0; k < 3; ++k) far = std::max(far, Q(abs(s.v1[k] + t * (s.v2[k] - s.v1[k]) - 1)));
        BOOST_TEST(far == r);
    }
}

BOOST_AUTO_TEST_CASE(ellipsoids_fall_back_to_the_seeds_when_floating_point_fails) {
    // A needle 10^29 long next to a point 10^31 away: the inner ellipsoid cannot be computed in
    // doubles (this once crashed); the segment falls back to the seeds and says so.
    ExactScene sc;
    sc.P[0].points = {{Q(Z("123456789012345678901234567890")), Q(0), Q(0)},
                      {Q(0), Q(1), Q(0)},
                      {Q(0), Q(0), Q(1)},
                      {Q(-1), Q(-1), Q(-1)}};
    Z far("10000000000000000000000000000000");
    sc.P[1].points = {{Q(far), Q(0), Q(0)}, {Q(far + 1), Q(0), Q(0)}, {Q(far), Q(1), Q(0)}, {Q(far), Q(0), Q(1)}};
    for (int i = 0; i < 2; ++i) {
        Vec3q c{Q(0), Q(0), Q(0)};
        for (const auto& v : sc.P[i].points)
            for (int k = 0; k < 3; ++k) c[k] += v[k] / 4;
        sc.P[i].seed = c;
        sc.lo[i] = Q(1, 2);
        sc.hi[i] = Q(2);
    }
    HullModel m = build_model(sc);
    Segment s = segment_by_kind(m, "ellipsoids");
    BOOST_TEST(s.kind == "seeds");
    BOOST_TEST(!s.note.empty());
    BOOST_TEST((s.v1 == m.s[0] && s.v2 == m.s[1]));
}
