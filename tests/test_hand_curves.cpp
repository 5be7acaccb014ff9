// Curves derived by hand (the derivations are in the comments), compared with the engine.
#define BOOST_TEST_MODULE hand_curves
#include <boost/test/unit_test.hpp>

#include "support.hpp"

using namespace scalecert::internal;

static std::string scene_path(const char* name) { return std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/" + name; }

BOOST_AUTO_TEST_CASE(stacked_cubes_single_ff_line) {
    // Cube [0,2]^3 seed (1,1,1) below cube [0,2]^2 x [3,5] seed (1,1,4). The top face of P1 at
    // scale ρ1 is z = 1 + ρ1, the bottom face of P2 at scale ρ2 is z = 4 − ρ2: they touch along
    // the whole face when 1 + ρ1 = 4 − ρ2, i.e. ρ2 = 3 − ρ1 (F,F) — and the cubes are aligned,
    // so no other contact ever occurs. Growth distance: ρ = 3 − ρ, ρ* = 3/2.
    Model m = build_model(load_scene(scene_path("stacked_cubes.json")));
    Curve c = build_curve(m);
    BOOST_TEST_REQUIRE(c.pieces.size() == 1u);
    const ContactLine& L = m.lines[c.env.pieces[c.pieces[0].env].line];
    BOOST_TEST(L.slope == -1);
    BOOST_TEST(L.intercept == 3);
    BOOST_TEST(L.contact == "FF");
    BOOST_TEST(c.pieces[0].from == Q(1, 2));
    BOOST_TEST(c.pieces[0].to == Q(5, 2));
    BOOST_TEST(c.switches.empty());
    BOOST_TEST(c.growth.value == Q(3, 2));
    BOOST_TEST(c.growth.in_rectangle);
    BOOST_TEST(query(m, c, Q(1), Q(2)).verdict == Verdict::Touching);
    BOOST_TEST(query(m, c, Q(1), Q(199, 100)).verdict == Verdict::Separated);
    BOOST_TEST(query(m, c, Q(1), Q(201, 100)).verdict == Verdict::Overlapping);
}

BOOST_AUTO_TEST_CASE(tetrahedron_box_vf_to_ee_switch) {
    // P1: tetrahedron c=(2,0,2), a=(−2,2,5), b=(−1,−2,6), t=(2,0,7), seed s1=(0,0,9/2).
    // P2: box [−1,1]^3, seed 0. d = (0,0,−9/2).
    // (V,F): c on the box top. Normal (0,0,−1): h1 = 9/2 − 2 = 5/2, h2 = 1, n·d = 9/2, so
    //   ρ2 = 9/2 − (5/2)ρ1. c' = (2ρ1, 0, 9/2 − 5ρ1/2) stays on the top face while 2ρ1 ≤ ρ2, i.e. ρ1 ≤ 1.
    // (E,E): edge c–a against the box edge x = z = 1. Normal −(3,0,4): h2 = max(3x+4z) = 7,
    //   h1 = 18 − min(3x+4z) = 18 − 14 = 4 (c and a), n·d = 18, so ρ2 = (18 − 4ρ1)/7;
    //   the edges meet while 1 ≤ ρ1 ≤ 27/13.
    // Switch: 9/2 − 5ρ1/2 = (18 − 4ρ1)/7 at ρ1 = 1, ρ2 = 2: vertex c on the box edge, (V,E).
    // Growth distance: ρ = (18 − 4ρ)/7, ρ* = 18/11 (the (V,F) line would give 9/7 > 1, off its piece).
    Model m = build_model(load_scene(scene_path("tetra_box_switch.json")));
    Curve c = build_curve(m);
    BOOST_TEST_REQUIRE(c.pieces.size() == 2u);
    const ContactLine& A = m.lines[c.env.pieces[c.pieces[0].env].line];
    const ContactLine& B = m.lines[c.env.pieces[c.pieces[1].env].line];
    BOOST_TEST(A.contact == "VF");
    BOOST_TEST(A.slope == Q(-5, 2));
    BOOST_TEST(A.intercept == Q(9, 2));
    BOOST_TEST(B.contact == "EE");
    BOOST_TEST(B.slope == Q(-4, 7));
    BOOST_TEST(B.intercept == Q(18, 7));
    BOOST_TEST(A.feat1 == std::vector<int>{0});         // vertex c
    BOOST_TEST(B.feat1 == (std::vector<int>{0, 1}));    // edge c–a
    BOOST_TEST(B.feat2 == (std::vector<int>{5, 7}));    // box edge x = z = 1
    BOOST_TEST_REQUIRE(c.switches.size() == 1u);
    BOOST_TEST(c.switches[0].rho1 == 1);
    BOOST_TEST(c.switches[0].rho2 == 2);
    BOOST_TEST(c.switches[0].contact.label == "VE");
    BOOST_TEST(c.growth.value == Q(18, 11));
    // Off the curve by hand: at ρ1 = 1/2 the curve is at 13/4.
    BOOST_TEST(query(m, c, Q(1, 2), Q(13, 4)).verdict == Verdict::Touching);
    BOOST_TEST(query(m, c, Q(1, 2), Q(3)).verdict == Verdict::Separated);
    BOOST_TEST(query(m, c, Q(1, 2), Q(7, 2)).verdict == Verdict::Overlapping);
}

BOOST_AUTO_TEST_CASE(coincident_seeds_overlap_everywhere) {
    // Two cubes around the same seed: every positive scaling pair overlaps; the curve lies below
    // zero, the growth distance is 0, and nothing divides by zero.
    Scene sc;
    for (int i = 0; i < 2; ++i) {
        for (int x : {-1, 1}) for (int y : {-1, 1}) for (int z : {-i - 1, i + 1}) sc.P[i].points.push_back({Q(x), Q(y), Q(z)});
        sc.P[i].seed = {Q(0), Q(0), Q(0)};
        sc.lo[i] = Q(1, 10);
        sc.hi[i] = Q(10);
    }
    Model m = build_model(sc);
    Curve c = build_curve(m);
    BOOST_TEST(c.growth.value == 0);
    BOOST_TEST(query(m, c, Q(1, 10), Q(1, 10)).verdict == Verdict::Overlapping);
    BOOST_TEST(query_direct(m, Q(1, 1000), Q(1, 1000)) == Verdict::Overlapping);
    Partition p = build_partition(m, c);
    BOOST_TEST(p.separated.empty());
    BOOST_TEST(p.overlap.size() == 4u);
}

BOOST_AUTO_TEST_CASE(scenes_built_in_code_get_the_readers_checks) {
    // The stacked cubes of the first case, assembled in code. With lo > hi, build_curve used to
    // return a piece [3, 1/2]; now build_model refuses the scene as the reader would.
    Scene sc;
    for (int k = 0; k < 8; ++k) {
        sc.P[0].points.push_back({Q(2 * (k & 1)), Q((k & 2)), Q((k & 4) / 2)});
        sc.P[1].points.push_back({Q(2 * (k & 1)), Q((k & 2)), Q(3 + (k & 4) / 2)});
    }
    sc.lo[0] = Q(3);
    sc.hi[0] = Q(1, 2);
    sc.lo[1] = Q(1, 2);
    sc.hi[1] = Q(5, 2);
    auto message = [](const Scene& s) {
        try {
            build_model(s);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    BOOST_TEST(message(sc) == "scene: I1: lo > hi");
    sc.lo[0] = Q(1, 2);
    sc.hi[0] = Q(5, 2);
    sc.lo[1] = Q(0);
    BOOST_TEST(message(sc) == "scene: I2: lo must be > 0 (got '0')");
    sc.lo[1] = Q(1, 2);
    Scene three = sc;
    three.P[1].points.resize(3);
    BOOST_TEST(message(three) == "scene: P2: fewer than 4 vertices (3)");
    // finish_scene gives the default seeds, the means: (1, 1, 1) and (1, 1, 4) by hand.
    finish_scene(sc, "scene");
    BOOST_TEST((sc.P[0].seed == Vec3q{Q(1), Q(1), Q(1)}));
    BOOST_TEST((sc.P[1].seed == Vec3q{Q(1), Q(1), Q(4)}));
    Curve c = build_curve(build_model(sc));
    BOOST_TEST(c.growth.value == Q(3, 2));  // ρ1 + ρ2 = 3 meets ρ1 = ρ2 at 3/2
}
