// Curves derived by hand (the derivations are in the comments), compared with the engine.
#include <boost/test/unit_test.hpp>

#include "curve/scan.hpp"
#include "support.hpp"

using namespace scalecert::internal;

static std::string scene_path(const char* name) {
    return std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/" + name;
}

BOOST_AUTO_TEST_CASE(stacked_cubes_single_ff_line) {
    // Cube [0,2]^3 seed (1,1,1) below cube [0,2]^2 x [3,5] seed (1,1,4). The top face of P1 at
    // scale ρ1 is z = 1 + ρ1, the bottom face of P2 at scale ρ2 is z = 4 − ρ2: they touch along
    // the whole face when 1 + ρ1 = 4 − ρ2, i.e. ρ2 = 3 − ρ1 (F,F) — and the cubes are aligned,
    // so no other contact ever occurs. Growth distance: ρ = 3 − ρ, ρ* = 3/2.
    HullModel m = build_model(load_scene(scene_path("stacked_cubes.json")));
    TouchingCurve c = build_curve(m);
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
    HullModel m = build_model(load_scene(scene_path("tetra_box_switch.json")));
    TouchingCurve c = build_curve(m);
    BOOST_TEST_REQUIRE(c.pieces.size() == 2u);
    const ContactLine& A = m.lines[c.env.pieces[c.pieces[0].env].line];
    const ContactLine& B = m.lines[c.env.pieces[c.pieces[1].env].line];
    BOOST_TEST(A.contact == "VF");
    BOOST_TEST(A.slope == Q(-5, 2));
    BOOST_TEST(A.intercept == Q(9, 2));
    BOOST_TEST(B.contact == "EE");
    BOOST_TEST(B.slope == Q(-4, 7));
    BOOST_TEST(B.intercept == Q(18, 7));
    BOOST_TEST(A.feat1 == std::vector<int>{0});       // vertex c
    BOOST_TEST(B.feat1 == (std::vector<int>{0, 1}));  // edge c–a
    BOOST_TEST(B.feat2 == (std::vector<int>{5, 7}));  // box edge x = z = 1
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
    ExactScene sc;
    for (int i = 0; i < 2; ++i) {
        for (int x : {-1, 1})
            for (int y : {-1, 1})
                for (int z : {-i - 1, i + 1}) sc.P[i].points.push_back({Q(x), Q(y), Q(z)});
        sc.P[i].seed = {Q(0), Q(0), Q(0)};
        sc.lo[i] = Q(1, 10);
        sc.hi[i] = Q(10);
    }
    HullModel m = build_model(sc);
    TouchingCurve c = build_curve(m);
    BOOST_TEST(c.growth.value == 0);
    BOOST_TEST(query(m, c, Q(1, 10), Q(1, 10)).verdict == Verdict::Overlapping);
    BOOST_TEST(query_direct(m, Q(1, 1000), Q(1, 1000)) == Verdict::Overlapping);
    Partition p = build_partition(m, c);
    BOOST_TEST(p.separated.empty());
    BOOST_TEST(p.overlap.size() == 4u);
}

BOOST_AUTO_TEST_CASE(below_rho2_zero_the_curve_goes_on_as_one_line) {
    // P1 = [−1,1]^3, seed 0; P2 = [2,4] × [−1,3] × [−2,2], seed (3,1,0): d = (3,1,0). Both are
    // axis-aligned boxes, so Q1 ⊕ (−Q2) is a box: its facet normals are ±e_k only.
    //   n = (1,0,0):  h1 = 1, h2 = 1, n·d = 3   →  ρ2 = 3 − ρ1   (face x = ρ1 on face x = 3 − ρ2: FF)
    //   n = (0,1,0):  h1 = 1, h2 = 2, n·d = 1   →  ρ2 = (1 − ρ1)/2
    //   the others have n·d ≤ 0 and lie lower for ρ1 > 0.
    // The lines' envelope is 3 − ρ1 up to their meeting at (5, −2), then (1 − ρ1)/2. The curve
    // reaches ρ2 = 0 at ρ1 = 3 (the seed s2 on P1(3)'s face x = 3) and goes on as 3 − ρ1: with
    // I1 = [1, 6], one piece and no switch point at (5, −2), on both engines.
    ExactScene sc;
    for (long x : {-1, 1})
        for (long y : {-1, 1})
            for (long z : {-1, 1}) sc.P[0].points.push_back({Q(x), Q(y), Q(z)});
    for (long x : {2, 4})
        for (long y : {-1, 3})
            for (long z : {-2, 2}) sc.P[1].points.push_back({Q(x), Q(y), Q(z)});
    sc.lo[0] = Q(1), sc.hi[0] = Q(6), sc.lo[1] = Q(1), sc.hi[1] = Q(2);
    finish_scene(sc, "scene");
    BOOST_TEST_REQUIRE((sc.P[1].seed == Vec3q{Q(3), Q(1), Q(0)}));
    const HullModel hm = build_model(sc);
    const ContactLine side = line_for_normal(hm, {Z(0), Z(1), Z(0)});
    BOOST_TEST(side.slope == Q(-1, 2));
    BOOST_TEST(side.intercept == Q(1, 2));
    BOOST_TEST(side.at(Q(6)) > Q(-3));  // above 3 − ρ1 at hi1: a curve must not switch to it
    auto cs = compact_scene(sc);
    BOOST_TEST_REQUIRE(cs.has_value());
    const WalkResult walked = scan_model(std::make_shared<CompactScene>(std::move(*cs)));
    BOOST_TEST_REQUIRE(walked.model.has_value());
    const Model& sm = *walked.model;
    BOOST_TEST(!sm.walk_hi.has_value());  // the walk stops where the curve reaches 0, proved beyond
    for (const Model* m : {static_cast<const Model*>(&hm), &sm}) {
        const TouchingCurve c = build_curve(*m);
        BOOST_TEST_REQUIRE(c.pieces.size() == 1u);
        const ContactLine& L = m->lines[c.env.pieces[c.pieces[0].env].line];
        BOOST_TEST(L.slope == -1);
        BOOST_TEST(L.intercept == 3);
        BOOST_TEST(c.pieces[0].from == 1);
        BOOST_TEST(c.pieces[0].to == 6);
        BOOST_TEST(c.pieces[0].contact.label == "FF");
        BOOST_TEST(c.switches.empty());
        BOOST_TEST(c.env.value(m->lines, Q(6)) == -3);
        BOOST_TEST(c.growth.value == Q(3, 2));
    }
    const TouchingCurve c = build_curve(hm);
    const Partition p = build_partition(hm, c);
    BOOST_TEST_REQUIRE(p.zero_witnesses.size() == 1u);
    BOOST_TEST_REQUIRE(p.zero_witnesses[0].has_value());
    BOOST_TEST(p.zero_witnesses[0]->rho1 == 3);
    BOOST_TEST((p.zero_witnesses[0]->point == Vec3q{Q(3), Q(1), Q(0)}));  // s2 on P1(3)
}

BOOST_AUTO_TEST_CASE(scenes_built_in_code_get_the_readers_checks) {
    // The stacked cubes of the first case, assembled in code. With lo > hi, build_curve used to
    // return a piece [3, 1/2]; now build_model refuses the scene as the reader would.
    ExactScene sc;
    for (int k = 0; k < 8; ++k) {
        sc.P[0].points.push_back({Q(2 * (k & 1)), Q((k & 2)), Q((k & 4) / 2)});
        sc.P[1].points.push_back({Q(2 * (k & 1)), Q((k & 2)), Q(3 + (k & 4) / 2)});
    }
    sc.lo[0] = Q(3);
    sc.hi[0] = Q(1, 2);
    sc.lo[1] = Q(1, 2);
    sc.hi[1] = Q(5, 2);
    auto message = [](const ExactScene& s) {
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
    ExactScene three = sc;
    three.P[1].points.resize(3);
    BOOST_TEST(message(three) == "scene: P2: fewer than 4 vertices (3)");
    // finish_scene gives the default seeds, the means: (1, 1, 1) and (1, 1, 4) by hand.
    finish_scene(sc, "scene");
    BOOST_TEST((sc.P[0].seed == Vec3q{Q(1), Q(1), Q(1)}));
    BOOST_TEST((sc.P[1].seed == Vec3q{Q(1), Q(1), Q(4)}));
    TouchingCurve c = build_curve(build_model(sc));
    BOOST_TEST(c.growth.value == Q(3, 2));  // ρ1 + ρ2 = 3 meets ρ1 = ρ2 at 3/2
}

namespace {
// Eight corners of the cube [x, x+2] × [y, y+2] × [z, z+2], in the order (a, b, c) ∈ {0,2}^3 with c
// fastest: index 4a/2 + 2b/2 + c/2.
std::vector<Vec3q> cube(long x, long y, long z) {
    std::vector<Vec3q> v;
    for (long a : {0, 2})
        for (long b : {0, 2})
            for (long c : {0, 2}) v.push_back({Q(x + a), Q(y + b), Q(z + c)});
    return v;
}
std::vector<Vec3q> pts(std::initializer_list<std::array<long, 3>> l) {
    std::vector<Vec3q> v;
    for (const auto& p : l) v.push_back({Q(p[0]), Q(p[1]), Q(p[2])});
    return v;
}
ExactScene two(std::vector<Vec3q> a, std::vector<Vec3q> b) {
    ExactScene sc;
    sc.P[0].points = std::move(a);
    sc.P[1].points = std::move(b);
    for (int i = 0; i < 2; ++i) sc.lo[i] = Q(1, 2), sc.hi[i] = Q(3, 2);
    finish_scene(sc, "scene");
    return sc;
}
struct HandContact {
    const char* name;
    ExactScene sc;
    Q slope, intercept;
    std::string label;
    std::vector<int> f1, f2;
};
}  // namespace

BOOST_AUTO_TEST_CASE(contact_labels_are_the_smallest_faces_holding_the_touching_set) {
    // P1 is the cube [0,2]^3 (seed (1,1,1)) in every case but the last. Each P2 is placed so that
    // at ρ1 = ρ2 = 1 the bodies touch as named, and its seed (the mean of its points) lies on the
    // line through P1's seed and the contact, so the contact keeps its kind along the whole line.
    //  - edge:    P2 = [2,4]×[2,4]×[0,2], seed (3,3,1). The faces x = 1+ρ1 and x = 3−ρ2 (normal
    //             (1,0,0)) and y (normal (0,1,0)) give the same line ρ2 = 2 − ρ1; the touching set
    //             is the common part of the edges {x = y = 2} of both: EE, vertices 6, 7 of P1
    //             ((2,2,0), (2,2,2)) and 0, 1 of P2.
    //  - corner:  P2 = [2,4]^3: three normals, one line ρ2 = 2 − ρ1, touching at the corner
    //             (2,2,2) = P1's vertex 7, P2's vertex 0: VV.
    //  - face:    P2 = [2,4]×[0,2]×[0,2]: only (1,0,0) touches; the faces x = 2 are concentric
    //             squares, and the smaller one is the touching set: FF, P1's 4..7, P2's 0..3.
    //  - ridge:   P2 = prism with ridge (2,1,0)–(2,1,2) and back face x = 4, seed (10/3, 1, 1).
    //             (1,0,0): h1 = 1, h2 = 10/3 − 2 = 4/3, n·d = 7/3, so ρ2 = 7/4 − (3/4)ρ1. The
    //             ridge stays at y = 1, z ∈ [1 − ρ2, 1 + ρ2], inside P1's face: FE.
    //  - tipface: P2 = square pyramid with tip (2,1,1), base x = 4, seed (18/5, 1, 1): h2 = 8/5,
    //             n·d = 13/5, ρ2 = 13/8 − (5/8)ρ1; the tip stays at the centre of P1's face: FV.
    //  - tips:    two square pyramids tip to tip at (0,0,2): P1 tip up over the base z = 0, seed
    //             (0,0,2/5); P2 tip down under z = 4, seed (0,0,18/5). The tips sit on the z axis,
    //             at 2/5 + (8/5)ρ1 and 18/5 − (8/5)ρ2: they meet when ρ2 = 2 − ρ1, and then the
    //             touching set is the single tip (each pyramid lies on its side of z = tip). The
    //             four slanted faces of each and their edge pairs all give that line: VV.
    const std::vector<HandContact> cases = {
        {"edge", two(cube(0, 0, 0), cube(2, 2, 0)), Q(-1), Q(2), "EE", {6, 7}, {0, 1}},
        {"corner", two(cube(0, 0, 0), cube(2, 2, 2)), Q(-1), Q(2), "VV", {7}, {0}},
        {"face", two(cube(0, 0, 0), cube(2, 0, 0)), Q(-1), Q(2), "FF", {4, 5, 6, 7}, {0, 1, 2, 3}},
        {"ridge",
         two(cube(0, 0, 0), pts({{2, 1, 0}, {2, 1, 2}, {4, 0, 0}, {4, 2, 0}, {4, 0, 2}, {4, 2, 2}})),
         Q(-3, 4),
         Q(7, 4),
         "FE",
         {4, 5, 6, 7},
         {0, 1}},
        {"tipface",
         two(cube(0, 0, 0), pts({{2, 1, 1}, {4, 0, 0}, {4, 2, 0}, {4, 0, 2}, {4, 2, 2}})),
         Q(-5, 8),
         Q(13, 8),
         "FV",
         {4, 5, 6, 7},
         {0}},
        {"tips",
         two(pts({{0, 0, 2}, {-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 1, 0}}),
             pts({{0, 0, 2}, {-1, -1, 4}, {1, -1, 4}, {-1, 1, 4}, {1, 1, 4}})),
         Q(-1),
         Q(2),
         "VV",
         {0},
         {0}},
    };
    for (const HandContact& h : cases) {
        BOOST_TEST_CONTEXT(h.name) {
            const HullModel m = build_model(h.sc);
            const TouchingCurve c = build_curve(m);
            BOOST_TEST_REQUIRE(c.pieces.size() == 1u);
            const ContactLine& L = m.lines[c.env.pieces[c.pieces[0].env].line];
            BOOST_TEST(L.slope == h.slope);
            BOOST_TEST(L.intercept == h.intercept);
            BOOST_TEST(c.pieces[0].contact.label == h.label);
            BOOST_TEST(c.pieces[0].contact.feat1 == h.f1);
            BOOST_TEST(c.pieces[0].contact.feat2 == h.f2);
            // The brute force (support.hpp) agrees at ρ1 = ρ2 = 1 and at ρ1 = 3/4.
            for (const Q& x : {Q(1), Q(3, 4)}) {
                const auto [g1, g2] = test::brute_contact(h.sc, x, h.slope * x + h.intercept);
                BOOST_TEST(g1 == h.f1);
                BOOST_TEST(g2 == h.f2);
            }
            // The certificate carries a witness in both features' relative interiors, and the
            // checker accepts it.
            const Partition p = build_partition(m, c);
            BOOST_TEST_REQUIRE(p.piece_witnesses.size() == 1u);
            BOOST_TEST_REQUIRE(p.piece_witnesses[0].has_value());
            BOOST_TEST(p.piece_witnesses[0]->w1.size() == h.f1.size());
            BOOST_TEST(p.piece_witnesses[0]->w2.size() == h.f2.size());
        }
    }
}

BOOST_AUTO_TEST_CASE(contact_labels_match_the_brute_force_on_lattice_boxes_and_polytopes) {
    // Axis-aligned boxes and small lattice polytopes meet edge to edge, corner to face and so on
    // far more often than random ones: many facet normals share one line. At the middle of every
    // piece (where ρ2 > 0), the engine's features are the hull vertices of the brute force's
    // smallest faces, and its label their dimensions.
    std::mt19937 g(20261123);
    std::uniform_int_distribution<int> u(0, 3), off(-2, 2);
    int compared = 0, shared_lines = 0;
    for (int t = 0; t < 300; ++t) {
        ExactScene sc;
        for (int i = 0; i < 2; ++i) {
            const long ox = i ? off(g) : 0, oy = i ? off(g) : 0, oz = i ? off(g) : 0;
            if (t % 2 == 0) {  // a box
                const long a = 1 + u(g) % 3, b = t % 4 == 0 ? a : 1 + u(g) % 3,
                           c = t % 4 == 0 ? a : 1 + u(g) % 3;  // cubes often
                for (long x : {0L, a})
                    for (long y : {0L, b})
                        for (long z : {0L, c}) sc.P[i].points.push_back({Q(ox + x), Q(oy + y), Q(oz + z)});
            } else {
                sc.P[i].points = test::random_points(g, 6, 2, 1, {Q(ox), Q(oy), Q(oz)});
            }
        }
        for (int i = 0; i < 2; ++i) sc.lo[i] = Q(1, 2), sc.hi[i] = Q(2);
        finish_scene(sc, "scene");
        Model m;
        try {
            m = build_model(sc);
        } catch (const InputError&) {
            continue;  // a seed on the boundary (flat lattice hulls are skipped by random_points)
        }
        const TouchingCurve c = build_curve(m);
        for (const CurvePiece& p : c.pieces) {
            const std::optional<Q> x = contact_rho1(m, c, p);
            if (!x) continue;
            const Q y = m.lines[c.env.pieces[p.env].line].at(*x);
            const auto [g1, g2] = test::brute_contact(sc, *x, y);
            BOOST_TEST_REQUIRE(!g1.empty());
            for (int k : p.contact.feat1) BOOST_TEST(std::binary_search(g1.begin(), g1.end(), k));
            for (int k : p.contact.feat2) BOOST_TEST(std::binary_search(g2.begin(), g2.end(), k));
            const std::string brute{"VEF"[test::affine_dimension(sc.P[0].points, g1)],
                                    "VEF"[test::affine_dimension(sc.P[1].points, g2)]};
            BOOST_TEST(p.contact.label == brute);
            shared_lines += c.env.pieces[p.env].same.size() > 1;
            ++compared;
        }
    }
    BOOST_TEST(compared > 300);
    BOOST_TEST_MESSAGE(compared << " pieces compared, " << shared_lines << " with several normals on one line");
    BOOST_TEST(shared_lines > 10);  // the case this test is for
}
