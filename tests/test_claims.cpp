// The claim rules of certificates/CLAIMS.md (certify/claims.cpp reading, certify/rules.cpp
// judging), each against values derived by hand: verdict and curve lines, curve claims,
// separating planes, distances and depths, malformed claims.
#include <boost/test/unit_test.hpp>

#include "certify/claims.hpp"
#include "io/scene.hpp"
#include "session/session.hpp"
#include "curve/envelope.hpp"
#include "geometry/measures.hpp"

#include <nlohmann/json.hpp>

#include <random>
#include <string>
#include <vector>

using namespace scalecert::internal;

BOOST_AUTO_TEST_CASE(certify_fp_marks_hand_derived_claims) {
    // Stacked cubes: the touching line is ρ1 + ρ2 = 3 and ρ* = 3/2 (test_hand_curves).
    HullModel m =
        build_model(load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json"));
    TouchingCurve c = build_curve(m);
    long wrong = -1;
    std::string r = certify_fp(m, c,
                               "1 2 touching\n1 1.99 separated\n1 2.01 separated\n1 2.01 intersecting\n"
                               "curve 1 2\ncurve 1 2.000001\ngrowth 3/2\ngrowth 1.5000001\n",
                               "claims", Numbers::Double, false, &wrong);
    BOOST_TEST(wrong == 3);  // (1, 2.01) is overlapping; the curve is at 2; ρ* is 3/2 exactly
    BOOST_TEST(r.find("claims: 8, right: 5, wrong: 3") != std::string::npos);
    BOOST_CHECK_THROW(certify_fp(m, c, "1 2 maybe\n", "claims", Numbers::Double, false, &wrong), InputError);
    BOOST_CHECK_THROW(certify_fp(m, c, "-1 2 touching\n", "claims", Numbers::Double, false, &wrong), InputError);
}

// ---- JSON claims: every kind, against values worked out by hand -------------------------------
namespace {

struct Claims {
    HullModel m;
    TouchingCurve c;
    explicit Claims(const ExactScene& s) : m(build_model(s)), c(build_curve(m)) {}
    explicit Claims(const std::string& bundled)
        : Claims(load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/" + bundled + ".json")) {}
    // The report of one claim (JSON), and whether it was right. These cases read decimals exactly
    // (Numbers::Exact) unless binary_doubles.
    nlohmann::json one(const std::string& claim, const std::string& tolerance = "0", bool binary_doubles = false) {
        long wrong = -1;
        const std::string r = certify_fp(
            m, c, "{\"format\": \"scalecert-claims-1\", \"claims\": [" + claim + "]}", "c.json",
            ClaimOptions{binary_doubles ? Numbers::Double : Numbers::Exact, parse_exact(tolerance), true}, &wrong);
        auto j = nlohmann::json::parse(r)["claims"][0];
        BOOST_TEST(wrong == (j["right"].get<bool>() ? 0 : 1));
        return j;
    }
    bool right(const std::string& claim, const std::string& tolerance = "0", bool binary_doubles = false) {
        return one(claim, tolerance, binary_doubles)["right"].get<bool>();
    }
};

std::vector<Vec3q> cube(long x0, long y0, long z0, long side) {
    std::vector<Vec3q> v;
    for (long x : {x0, x0 + side})
        for (long y : {y0, y0 + side})
            for (long z : {z0, z0 + side}) v.push_back({Q(x), Q(y), Q(z)});
    return v;
}

}  // namespace

BOOST_AUTO_TEST_CASE(curve_claim_rules) {
    // CLAIMS.md, "Curve claims", rule by rule. The tetrahedron on the box (test_hand_curves) with
    // I1 narrowed to [1/2, 3/4]: the exact curve is (V,F) ρ2 = 9/2 − 5ρ1/2 for 0 < ρ1 ≤ 1 and (E,E)
    // ρ2 = (18 − 4ρ1)/7 on [1, 27/13], so its switch point (1, 2) now lies outside I1.
    ExactScene sc = load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/tetra_box_switch.json");
    sc.hi[0] = Q(3, 4);
    Claims k(sc);
    auto refused = [&](const std::string& claim) {
        try {
            k.one(claim);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    // Rule 2 outside I1: the chord from (1/2, 13/4) to (3/2, 12/7) is exact at both ends, but at the
    // switch point it gives 13/4 + (12/7 − 13/4)/2 = 139/56 where f(1) = 2: off by 27/56.
    auto j = k.one(R"({"kind": "curve", "vertices": [["1/2", "13/4"], ["3/2", "12/7"]], "switch_points": []})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["max_vertical_error"] == "27/56");
    BOOST_TEST(j["max_vertical_error_at_rho1"] == "1");
    BOOST_TEST(j["switch_points_missed"] == nlohmann::json::parse(R"([["1", "2"]])"));
    // The exact curve outside I1, with its labels, is right (its switch point is no longer "extra").
    BOOST_TEST(k.right(R"({"kind": "curve", "pieces": [
        {"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2", "contact": "VF"},
        {"rho1": [1, "3/2"], "slope": "-4/7", "intercept": "18/7", "contact": "EE"}]})"));
    BOOST_TEST(k.right(R"({"kind": "switch_point", "rho1": 1, "rho2": 2, "contact": "VE"})"));
    // Curve points: f(1/2) = 9/2 − 5/4 = 13/4, f(3/2) = (18 − 6)/7 = 12/7; the double nearest
    // 12/7 is right within 1e-15 but not exactly.
    BOOST_TEST(k.right(R"({"kind": "curve_point", "rho1": "1/2", "rho2": "13/4"})"));
    BOOST_TEST(k.right(R"({"kind": "curve_point", "rho1": "3/2", "rho2": "12/7"})"));
    BOOST_TEST(!k.right(R"({"kind": "curve_point", "rho1": "3/2", "rho2": 1.7142857142857142})"));
    BOOST_TEST(k.right(R"({"kind": "curve_point", "rho1": "3/2", "rho2": 1.7142857142857142})", "1e-15"));
    BOOST_TEST(!k.right(R"({"kind": "curve_point", "rho1": 1, "rho2": "2.001"})", "1e-4"));
    // Rule 3 at the ends: a range ending at the switch point may list it or not; listed with the
    // wrong ρ2 it is misplaced. Starting there, likewise.
    const std::string first =
        R"({"kind": "curve", "pieces": [{"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2"}])";
    BOOST_TEST(k.right(first + "}"));
    BOOST_TEST(k.right(first + R"(, "switch_points": [[1, 2]]})"));
    j = k.one(first + R"(, "switch_points": [[1, 999]]})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["switch_points_misplaced"].size() == 1u);
    BOOST_TEST(j["switch_points_misplaced"][0]["claimed_rho2"] == "999");
    BOOST_TEST(k.right(R"({"kind": "curve", "vertices": [[1, 2], ["3/2", "12/7"]], "switch_points": [[1, 2]]})"));
    // Rule 3 inside: the switch point's ρ2 is compared too, between pieces and as a claim.
    j = k.one(R"({"kind": "curve", "pieces": [
        {"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2"},
        {"rho1": [1, "3/2"], "slope": "-4/7", "intercept": "18/7"}], "switch_points": [[1, 999]]})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["switch_points_misplaced"].size() == 1u);
    BOOST_TEST(!k.right(R"({"kind": "switch_point", "rho1": 1, "rho2": 999})"));
    BOOST_TEST(k.right(R"({"kind": "switch_point", "rho1": 1, "rho2": "2.0000001"})", "1e-7"));
    BOOST_TEST(!k.right(R"({"kind": "switch_point", "rho1": 1, "rho2": "2.0000003"})", "1e-7"));
    // Scalings <= 0 are refused in every form, and so are switch points outside the range and
    // pieces with gaps between them.
    BOOST_TEST(refused(R"({"kind": "curve", "vertices": [[0, "9/2"], [1, 2]]})").find("scalings must be > 0") !=
               std::string::npos);
    BOOST_TEST(refused(R"({"kind": "curve", "vertices": [[1, 2], [2, 0]]})").find("scalings must be > 0") !=
               std::string::npos);
    // The message names the scaling at fault, with its value.
    BOOST_TEST(refused(R"({"kind": "verdict", "rho1": 1, "rho2": -1, "verdict": "separated"})")
                   .find("rho2: scalings must be > 0 (got -1)") != std::string::npos);
    BOOST_TEST(refused(R"({"kind": "distance", "rho1": 0, "rho2": 1, "value": 1})")
                   .find("rho1: scalings must be > 0 (got 0)") != std::string::npos);
    BOOST_TEST(refused(R"({"kind": "curve", "pieces": [{"rho1": [1, 5], "slope": "-4/7", "intercept": "18/7"}]})")
                   .find("rho2 <= 0") != std::string::npos);  // (18 − 20)/7 < 0 at ρ1 = 5
    BOOST_TEST(refused(R"({"kind": "curve", "vertices": [[1, 2], ["3/2", "12/7"]], "switch_points": [[-1, 2]]})") !=
               "accepted");
    BOOST_TEST(refused(R"({"kind": "curve", "vertices": [[1, 2], ["3/2", "12/7"]], "switch_points": [[2, "10/7"]]})")
                   .find("outside the claimed range") != std::string::npos);
    BOOST_TEST(refused(R"({"kind": "curve", "pieces": [
        {"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2"},
        {"rho1": ["11/10", "3/2"], "slope": "-4/7", "intercept": "18/7"}]})")
                   .find("start where") != std::string::npos);
    BOOST_TEST(refused(R"({"kind": "switch_point", "rho1": 1, "rho2": -2})") != "accepted");
    BOOST_TEST(refused(R"({"kind": "growth_distance", "value": "-18/11"})").find(">= 0") != std::string::npos);
    long wrong = -1;
    for (const char* line : {"curve 1 0\n", "curve 0 9/2\n", "curve 1 -2\n", "growth -1\n"})
        BOOST_CHECK_THROW(certify_fp(k.m, k.c, line, "c.txt", ClaimOptions{Numbers::Exact, Q(0), false}, &wrong),
                          InputError);
    BOOST_TEST(
        certify_fp(k.m, k.c, "curve 1 2\ncurve 3/2 12/7\n", "c.txt", ClaimOptions{Numbers::Exact, Q(0), false}, &wrong)
            .find("wrong: 0") != std::string::npos);
    // Rule 4 at a switch point: the chord over [1/2, 3/2] (within a tolerance of 1/2 of the curve)
    // has its midpoint at the switch point (1, 2), whose contact is VE (EE, the next
    // piece's, is wrong there).
    const std::string chord =
        R"({"kind": "curve", "pieces": [{"rho1": ["1/2", "3/2"], "slope": "-43/28", "intercept": "225/56", )"
        R"("contact": ")";
    BOOST_TEST(k.right(chord + R"(VE"}], "switch_points": [[1, 2]]})", "1/2"));
    j = k.one(chord + R"(EE"}], "switch_points": [[1, 2]]})", "1/2");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["wrong_contacts"][0]["exact"] == "VE");
    // Rule 1: the stacked cubes' curve ρ2 = 3 − ρ1 (one (F,F) line for every ρ1 > 0) reaches 0 at
    // ρ1 = 3. A claim that stays above 0 up to ρ1 = 4 is wrong, however large the tolerance.
    Claims cubes("stacked_cubes");
    j = cubes.one(R"({"kind": "curve", "vertices": [[1, 2], [4, "1/1000"]]})", "1000");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(!j["exact_rho2_positive_over_range"].get<bool>());
    BOOST_TEST(cubes.right(R"({"kind": "curve", "vertices": [[1, 2], ["5/2", "1/2"]], "switch_points": []})"));
}

BOOST_AUTO_TEST_CASE(claimed_planes_must_separate_exactly) {
    // Stacked cubes at (1, 1): P1 = [0,2]^3 reaches z = 2, P2 = [0,2]^2 x [3,5] starts at z = 3.
    Claims k("stacked_cubes");
    BOOST_TEST(k.right(R"({"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0, 0, 1], "offset": 2.5})"));
    // The plane z = 2 − 10^-17 leaves P1's top vertices on the wrong side by 10^-17.
    auto j = k.one(
        R"({"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0, 0, 1], "offset": "1.99999999999999999"})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["offset_minus_P1"] == "-1/100000000000000000");
    // A correct plane with rounded coefficients (the doubles nearest 0.1, 1e-3 and 2.6): still
    // strictly between P1 (max 0.1·2 + 0.002 + 2 ≈ 2.202) and P2 (min 3).
    BOOST_TEST(k.right(
        R"({"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0.1, 0.001, 1], "offset": 2.6})", "0", true));
    // At a touching pair no plane separates strictly, and the normal's direction matters.
    BOOST_TEST(!k.right(R"({"kind": "separating_plane", "rho1": 1.5, "rho2": 1.5, "normal": [0, 0, 1]})"));
    BOOST_TEST(!k.right(R"({"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0, 0, -1]})"));
    // A witness point: (1, 1, 5/2) is in both at (3/2, 3/2); 2.5 + 10^-17 is above P1(3/2).
    BOOST_TEST(k.right(R"({"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [1, 1, 2.5]})"));
    j = k.one(R"({"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [1, 1, "2.50000000000000001"]})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(!j["in_P1"].get<bool>());
    BOOST_TEST(j["in_P2"].get<bool>());
}

BOOST_AUTO_TEST_CASE(distances_and_depths_by_hand) {
    // Unit-side... side-2 cubes [0,2]^3 and [3,5] x [0,2] x [3,5], seeds at their centres: at (1, 1)
    // they are 1 apart in x and 1 apart in z, and overlap in y: the closest features are two edges,
    // the squared distance 1 + 1 = 2, attained from (2, y, 2) to (3, y, 3).
    ExactScene s;
    s.P[0].points = cube(0, 0, 0, 2);
    s.P[1].points = cube(3, 0, 3, 2);
    s.lo[0] = s.lo[1] = Q(1, 2);
    s.hi[0] = s.hi[1] = Q(3);
    finish_scene(s, "diagonal cubes");
    Claims k(s);
    const ExactDistance d = exact_distance(k.m, Q(1), Q(1));
    BOOST_TEST(d.squared == Q(2));
    BOOST_TEST(d.p1[0] == Q(2));
    BOOST_TEST(d.p1[2] == Q(2));
    BOOST_TEST(d.p2[0] == Q(3));
    BOOST_TEST(d.p2[2] == Q(3));
    // At (1, 1/2): P2(1/2) = [3.5, 4.5] x [0.5, 1.5] x [3.5, 4.5]: gaps 1.5 and 1.5, squared 9/2.
    BOOST_TEST(exact_distance(k.m, Q(1), Q(1, 2)).squared == Q(9, 2));
    // sqrt(2) as a double is not the distance; within 10^-15 it is.
    auto j = k.one(R"({"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.4142135623730951})", "0", true);
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["exact_squared"] == "2");
    const double err = j["abs_error_double"].get<double>();
    BOOST_TEST((err > 0 && err < 2.3e-16));  // |fl(√2) − √2| < ulp(√2)/2 = 1.1e-16
    BOOST_TEST(k.right(R"({"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.4142135623730951})", "1e-15", true));
    BOOST_TEST(k.right(R"({"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.4142135623730951,
                           "closest": [[2, 1, 2], [3, 1, 3]]})",
                       "1e-15", true));
    BOOST_TEST(!k.right(R"({"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.4142135623730951,
                            "closest": [[2, 1, 2], [3, 1, 4]]})",
                        "1e-15", true));  // |(1,0,2)|² = 5
    // Meeting bodies have distance 0: at (2, 2) P1(2) = [-1,3]^3 and P2(2) = [2,6] x [-1,3] x [2,6].
    BOOST_TEST(exact_distance(k.m, Q(2), Q(2)).squared == Q(0));

    // Penetration depth, stacked cubes at (2, 5/2): P1(2) = [-1,3]^3, P2(5/2) = [-1.5,3.5]^2 x
    // [1.5, 6.5]. Separating along z needs 3 − 1.5 = 3/2; along x, 3 + 1.5 = 9/2; so the depth is
    // 3/2 (squared 9/4) along (0,0,1), and 9/2 along (1,0,0).
    Claims st("stacked_cubes");
    const ExactDepth e = exact_penetration_depth(st.m, all_facet_normals(st.m), Q(2), Q(5, 2));
    BOOST_TEST(e.squared == Q(9, 4));
    BOOST_TEST((e.direction == Vec3z{Z(0), Z(0), Z(1)}));
    BOOST_TEST(directional_depth_squared(st.m, {Q(1), Q(0), Q(0)}, Q(2), Q(5, 2)) == Q(81, 4));
    BOOST_TEST(
        st.right(R"({"kind": "penetration_depth", "rho1": 2, "rho2": 2.5, "value": 1.5, "direction": [0, 0, 1]})"));
    j = st.one(R"({"kind": "penetration_depth", "rho1": 2, "rho2": 2.5, "value": 1.5, "direction": [1, 0, 0]})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(!j["direction_right"].get<bool>());
    BOOST_TEST(!st.right(R"({"kind": "penetration_depth", "rho1": 2, "rho2": 2.5, "value": 1.4})"));
    BOOST_TEST(!st.right(R"({"kind": "penetration_depth", "rho1": 1, "rho2": 1, "value": 0})"));  // separated
    // Touching: depth 0.
    BOOST_TEST(st.right(R"({"kind": "penetration_depth", "rho1": 1.5, "rho2": 1.5, "value": 0})"));
}

BOOST_AUTO_TEST_CASE(claimed_curves_switches_and_labels) {
    // The tetrahedron on the box (test_hand_curves): (V,F) ρ2 = 9/2 − 5ρ1/2 on [1/2, 1], then
    // (E,E) ρ2 = (18 − 4ρ1)/7, switching at (1, 2) with a (V,E) contact; ρ* = 18/11.
    Claims k("tetra_box_switch");
    const std::string exact_pieces = R"({"kind": "curve", "pieces": [
        {"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2", "contact": "VF"},
        {"rho1": [1, 2], "slope": "-4/7", "intercept": "18/7", "contact": "EE"}]})";
    BOOST_TEST(k.right(exact_pieces));
    // A wrong label on the second piece.
    auto j = k.one(R"({"kind": "curve", "pieces": [
        {"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2", "contact": "VF"},
        {"rho1": [1, 2], "slope": "-4/7", "intercept": "18/7", "contact": "FE"}]})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["wrong_contacts"].size() == 1u);
    BOOST_TEST(j["wrong_contacts"][0]["exact"] == "EE");
    // The switch moved to ρ1 = 101/100: misplaced, and the curve is off there.
    j = k.one(R"({"kind": "curve", "pieces": [
        {"rho1": ["1/2", "101/100"], "slope": "-5/2", "intercept": "9/2"},
        {"rho1": ["101/100", 2], "slope": "-4/7", "intercept": "18/7"}]})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["switch_points_misplaced"].size() == 1u);
    BOOST_TEST(j["switch_points_misplaced"][0]["claimed_rho1"] == "101/100");
    // At 101/100 the claimed first piece gives 9/2 − 5/2 · 101/100 = 79/40, and the exact (E,E)
    // line (18 − 404/100)/7 = 349/175: error 79/40 − 349/175 = (2765 − 2792)/1400 = −27/1400.
    BOOST_TEST(j["max_vertical_error"] == "27/1400");
    BOOST_TEST(j["max_vertical_error_at_rho1"] == "101/100");
    // A polyline that skips the switch: from (1/2, 13/4) to (2, 10/7), at ρ1 = 1 it gives
    // 13/4 + (10/7 − 13/4)/3 = 37/14 where the curve is 2: error 9/14, and the switch is missed.
    j = k.one(R"({"kind": "curve", "vertices": [["1/2", "13/4"], [2, "10/7"]]})");
    BOOST_TEST(j["max_vertical_error"] == "9/14");
    BOOST_TEST(j["max_vertical_error_at_rho1"] == "1");
    BOOST_TEST(j["switch_points_missed"].size() == 1u);
    BOOST_TEST(
        k.right(R"({"kind": "curve", "vertices": [["1/2", "13/4"], [1, 2], [2, "10/7"]], "switch_points": [[1, 2]]})"));
    BOOST_TEST(
        k.right(R"({"kind": "curve", "vertices": [["1/2", "13/4"], [1, 2], [2, "10/7"]]})"));  // its bend is the switch
    // A sampled curve that claims no switch point: 13 samples at ρ1 = 1/2, 5/8, ..., 2, each 1/1000
    // above the exact curve (by hand, as above). The (V,E) switch at ρ1 = 1 is reported missing,
    // and the vertical error is the samples' 1/1000 (the curve is linear between samples, with
    // its break at the sample ρ1 = 1).
    {
        std::string vs;
        for (int i = 0; i <= 12; ++i) {
            const Q x = Q(1, 2) + Q(i, 8);
            const Q f = x <= 1 ? Q(Q(9, 2) - Q(5, 2) * x) : Q((18 - 4 * x) / 7);
            vs += std::string(i ? ", " : "") + "[\"" + to_exact_string(x) + "\", \"" +
                  to_exact_string(Q(f + Q(1, 1000))) + "\"]";
        }
        j = k.one(R"({"kind": "curve", "vertices": [)" + vs + R"(], "switch_points": []})");
        BOOST_TEST(!j["right"].get<bool>());
        BOOST_TEST(j["switch_points_missed"] == nlohmann::json::parse(R"([["1", "2"]])"));
        BOOST_TEST(j["max_vertical_error"] == "1/1000");
    }
    // An extra switch point.
    j = k.one(
        R"({"kind": "curve", "vertices": [["1/2", "13/4"], [1, 2], [2, "10/7"]], "switch_points": [[1, 2], ["3/2", )"
        R"("12/7"]]})");
    BOOST_TEST(j["switch_points_extra"].size() == 1u);
    // Switch points and the growth distance, exact or within a tolerance.
    BOOST_TEST(k.right(R"({"kind": "switch_point", "rho1": 1, "rho2": 2, "contact": "VE"})"));
    // Curve points: f(1/2) = 9/2 − 5/4 = 13/4, f(3/2) = (18 − 6)/7 = 12/7; the double nearest
    // 12/7 is right within 1e-15 but not exactly.
    BOOST_TEST(k.right(R"({"kind": "curve_point", "rho1": "1/2", "rho2": "13/4"})"));
    BOOST_TEST(k.right(R"({"kind": "curve_point", "rho1": "3/2", "rho2": "12/7"})"));
    BOOST_TEST(!k.right(R"({"kind": "curve_point", "rho1": "3/2", "rho2": 1.7142857142857142})"));
    BOOST_TEST(k.right(R"({"kind": "curve_point", "rho1": "3/2", "rho2": 1.7142857142857142})", "1e-15"));
    BOOST_TEST(!k.right(R"({"kind": "curve_point", "rho1": 1, "rho2": "2.001"})", "1e-4"));
    BOOST_TEST(!k.right(R"({"kind": "switch_point", "rho1": 1, "rho2": 2, "contact": "VV"})"));
    BOOST_TEST(!k.right(R"({"kind": "switch_point", "rho1": "1.0000001", "rho2": 2})"));
    BOOST_TEST(k.right(R"({"kind": "switch_point", "rho1": "1.0000001", "rho2": 2})", "1e-6"));
    BOOST_TEST(k.right(R"({"kind": "growth_distance", "value": "18/11"})"));
    j = k.one(R"({"kind": "growth_distance", "value": 1.6363636363636365})", "0", true);
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["exact"] == "18/11");
    BOOST_TEST(k.right(R"({"kind": "growth_distance", "value": 1.6363636363636365})", "1e-15", true));
}

BOOST_AUTO_TEST_CASE(malformed_claims_get_one_line) {
    Claims k("stacked_cubes");
    auto err = [&](const std::string& text) {
        long wrong = 0;
        try {
            certify_fp(k.m, k.c, text, "c.json", ClaimOptions{Numbers::Exact, Q(0), false}, &wrong);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    BOOST_TEST(err(R"({"format": "scalecert-claims-1", "claims": [{"kind": "area"}]})")
                   .find("claims[0].kind: unknown kind 'area'") != std::string::npos);
    BOOST_TEST(err(R"({"format": "scalecert-claims-1", "claims": [{"kind": "distance", "rho1": 1, "rho2": 1}]})") ==
               "c.json: claims[0].value: missing");
    BOOST_TEST(
        err(R"({"format": "scalecert-claims-1", "claims": [{"kind": "growth_distance", "value": 1, "valu": 2}]})") ==
        "c.json: claims[0].valu: unknown field");
    BOOST_TEST(err(R"({"format": "scalecert-claims-2", "claims": []})").find("format") != std::string::npos);
    BOOST_TEST(err(R"({"format": "scalecert-claims-1", "claims": [], "claims": []})").find("duplicate") !=
               std::string::npos);
    // A zero normal is a wrong claim, not a malformed one (outputs_that_are_no_answer).
    BOOST_TEST(err(R"({"format": "scalecert-claims-1", "claims": [{"kind": "separating_plane", "rho1": 1, "rho2": 1, )"
                   R"("normal": [0, 0, 0]}]})")
                   .empty());
    BOOST_TEST(err(R"({"format": "scalecert-claims-1", "claims": [{"kind": "verdict", "rho1": 0, "rho2": 1, )"
                   R"("verdict": "separated"}]})")
                   .find("> 0") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(signed_distances_and_not_overlapping_by_hand) {
    // CLAIMS.md, "signed_distance", on the stacked cubes: P1(ρ1) = [1 − ρ1, 1 + ρ1]^3 reaches z =
    // 1 + ρ1, P2(ρ2) = [1 − ρ2, 1 + ρ2]^2 x [4 − ρ2, 4 + ρ2] starts at 4 − ρ2. At (1, 1/2) they are
    // 3/2 apart; at (1, 2) they touch; at (2, 2) they overlap by 1 along z (along x and y by 4).
    Claims k("stacked_cubes");
    auto sd = [&](const std::string& at, const std::string& rest, const std::string& tol = "0") {
        return k.right(R"({"kind": "signed_distance", )" + at + ", " + rest + "}", tol);
    };
    const std::string apart = R"("rho1": 1, "rho2": "1/2")", touch = R"("rho1": 1, "rho2": 2)",
                      deep = R"("rho1": 2, "rho2": 2)";
    BOOST_TEST(sd(apart, R"("value": 1.5)"));
    BOOST_TEST(!sd(apart, R"("value": -1.5)"));  // the sign is the state
    BOOST_TEST(sd(deep, R"("value": -1)"));
    BOOST_TEST(!sd(deep, R"("value": 1)"));
    BOOST_TEST(sd(touch, R"("value": 0)"));
    BOOST_TEST(!sd(touch, R"("value": "1/1000")"));
    // Within a relative tolerance of 1/10: −1.1 is right at (2, 2), −1.11 is not.
    BOOST_TEST(sd(deep, R"("value": -1.1)", "1/10"));
    BOOST_TEST(!sd(deep, R"("value": -1.11)", "1/10"));
    // Bounds: at least 3/2 (right: equal), at least 1.6 (wrong); below 3/2 (wrong: not strictly),
    // below 1.6 (right); overlapping by 1: at least −1 right, below −1 wrong, below 0 right.
    BOOST_TEST(sd(apart, R"("at_least": 1.5)"));
    BOOST_TEST(!sd(apart, R"("at_least": 1.6)"));
    BOOST_TEST(!sd(apart, R"("below": 1.5)"));
    BOOST_TEST(sd(apart, R"("below": 1.6)"));
    BOOST_TEST(sd(deep, R"("at_least": -1)"));
    BOOST_TEST(!sd(deep, R"("below": -1)"));
    BOOST_TEST(sd(deep, R"("below": 0)"));
    BOOST_TEST(sd(touch, R"("at_least": 0)"));
    BOOST_TEST(!sd(touch, R"("below": 0)"));
    // At a pose lifting P2 by 1 the pair at (1, 1/2) is 5/2 apart.
    BOOST_TEST(sd(apart, R"("value": 2.5, "pose2": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 1]])"));
    // The report: the state and the exact square, signed display.
    const nlohmann::json r = k.one(R"({"kind": "signed_distance", "rho1": 2, "rho2": 2, "below": 0})");
    BOOST_TEST(r["exact_verdict"] == "overlapping");
    BOOST_TEST(r["exact_squared"] == "1");
    BOOST_TEST(r["exact_double"].get<double>() == -1.0);
    BOOST_TEST(r["bound"] == "below");
    // One of value, at_least and below; not on objects made of parts.
    BOOST_CHECK_THROW(k.one(R"({"kind": "signed_distance", "rho1": 1, "rho2": 1, "value": 1, "below": 2})"),
                      InputError);
    BOOST_CHECK_THROW(k.one(R"({"kind": "signed_distance", "rho1": 1, "rho2": 1})"), InputError);
    // not_overlapping (separated or touching): right at (1, 1/2) and (1, 2), wrong at (2, 2).
    auto no = [&](const std::string& at) {
        return k.right(R"({"kind": "verdict", )" + at + R"(, "verdict": "not_overlapping"})");
    };
    BOOST_TEST(no(apart));
    BOOST_TEST(no(touch));
    BOOST_TEST(!no(deep));
}

BOOST_AUTO_TEST_CASE(outputs_that_are_no_answer) {
    // CLAIMS.md, "Outputs that are no answer", by hand on the stacked cubes: P1(1) = [0, 2]^3 and
    // P2(1/2) = [0, 2]^2 x [7/2, 9/2] are 3/2 apart; at (2, 2) they overlap by 1 along z.
    Claims k("stacked_cubes");
    long wrong = -1, count = -1;
    const std::string batch = R"({"format": "scalecert-claims-1", "claims": [
        {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5},
        {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": NaN},
        {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": 1, "direction": [0, 0, 0]},
        {"kind": "separating_plane", "rho1": 1, "rho2": 0.5, "normal": [0, null, 1]},
        {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5, "closest": [[1, 1, 2], [1, 1, -Infinity]]},
        {"kind": "curve_point", "rho1": 1, "rho2": Infinity},
        {"kind": "growth_distance", "value": null}]})";
    const nlohmann::json r =
        nlohmann::json::parse(certify_fp(k.m, k.c, batch, "c.json", ClaimOptions{Numbers::Double, Q(0), true}, &wrong));
    BOOST_TEST(wrong == 6);
    const auto& cl = r["claims"];
    BOOST_TEST(cl[0]["right"].get<bool>());
    const char* field[] = {"", "value", "direction", "normal", "closest", "rho2", "value"};
    const char* reason[] = {
        "", "not a number", "the zero vector", "not a number", "not a number", "not a number", "not a number"};
    for (int i = 1; i < 7; ++i) {
        BOOST_TEST(!cl[i]["right"].get<bool>(), i);
        BOOST_TEST(cl[i]["no_answer"] == field[i], i);
        BOOST_TEST(cl[i]["reason"] == reason[i], i);
    }
    // The line format: printf's nan and inf where the program answers; a non-number scaling is
    // bad input, as is a non-number in a curve claim.
    const std::string lines = certify_fp(HullClaimModels(k.m, k.c), "growth nan\ncurve 1 -INF\ngrowth 3/2\n", "c.txt",
                                         ClaimOptions{Numbers::Double, Q(0), false}, &wrong, &count);
    BOOST_TEST(wrong == 2);
    BOOST_TEST(count == 3);
    BOOST_TEST(lines.find("WRONG  growth distance nan: value is not a number: no answer") != std::string::npos, lines);
    BOOST_CHECK_THROW(certify_fp(k.m, k.c, "nan 1 separated\n", "c.txt", ClaimOptions{}, &wrong), InputError);
    BOOST_CHECK_THROW(k.one(R"({"kind": "verdict", "rho1": NaN, "rho2": 1, "verdict": "separated"})"), InputError);
    BOOST_CHECK_THROW(k.one(R"({"kind": "curve", "vertices": [[1, 2], [2, NaN]]})"), InputError);
    // An empty batch is judged: 0 claims, none wrong.
    for (const std::string& empty :
         {std::string(R"({"format": "scalecert-claims-1", "claims": []})"), std::string("# nothing\n\n")}) {
        wrong = count = -1;
        certify_fp(HullClaimModels(k.m, k.c), empty, "c", ClaimOptions{}, &wrong, &count);
        BOOST_TEST(wrong == 0);
        BOOST_TEST(count == 0);
    }
}

BOOST_AUTO_TEST_CASE(absolute_tolerance_on_points_values_and_planes) {
    // CLAIMS.md, "Tolerances", by hand on the stacked cubes: P1(1) = [0, 2]^3 and
    // P2(1/2) = [0, 2]^2 x [7/2, 9/2] are 3/2 apart; P1(3/2) = [-1/2, 5/2]^3 and
    // P2(3/2) = [-1/2, 5/2]^2 x [5/2, 11/2] touch on z = 5/2; at (2, 2) the depth is 1 along z.
    // The double 2.000000000001 is 2 + 4503599627/2^52 (about 1.00009e-12 above 2), so the first
    // closest point lies that far outside P1(1): wrong exactly, right within 1e-9; the pair is then
    // 3/2 − 1.00009e-12 apart, within 2·(1e-9) of 3/2.
    Claims k("stacked_cubes");
    const std::string batch = R"({"format": "scalecert-claims-1", "claims": [
        {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5, "closest": [[1, 1, 2.000000000001], [1, 1, 3.5]]},
        {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": "1500000001/1000000000"},
        {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": "1500000002/1000000000"},
        {"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [1, 1, "2500000001/1000000000"]},
        {"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [1, 1, "2500000002/1000000000"]},
        {"kind": "separating_plane", "rho1": 1.5, "rho2": 1.5, "normal": [0, 0, 1], "offset": 2.5},
        {"kind": "separating_plane", "rho1": 1.5, "rho2": 1.5, "normal": [0, 0, 2], "offset": "5000000001/1000000000"},
        {"kind": "separating_plane", "rho1": 1.5, "rho2": 1.5, "normal": [0, 0, 1], "offset": "2500000002/1000000000"},
        {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": "999999999/1000000000", "direction": [0, 0, 1]},
        {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5,
      "closest": [[1, 1, "2000000001/1000000000"], [1, 1, "3499999999/1000000000"]]},
        {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5,
      "closest": [[1, 1, "1999999999/1000000000"], [1, 1, "3500000002/1000000000"]]}]})";
    // Exact (tolerance 0) every one is wrong: each point or value is off, and at the touching pair
    // no plane separates strictly. Within 1e-9 (nothing relative):
    //  0 right (point 1.00009e-12 out, pair within 2e-9);
    //  1 right (|1.500000001 − 3/2| = 1e-9); 2 wrong (2e-9);
    //  3 right (1e-9 above P1(3/2)'s top 5/2, and in P2(3/2)); 4 wrong (2e-9 above);
    //  5 right (each body reaches the plane z = 5/2, 0 past it); 6 right (normal (0, 0, 2): the
    //    plane z = 2.5000000005, P1 5e-10 short of it, P2 5e-10 past it); 7 wrong (P2 starts at
    //    5/2, 2e-9 below the plane z = 2.500000002: past it by more than 1e-9);
    //  8 right (depth 1 − 1e-9); 9 right (both points 1e-9 out of their bodies, 1.5 − 2e-9 apart);
    // 10 wrong (the points lie in the bodies, 1.5 + 3e-9 apart: more than 3/2 + 2e-9).
    const std::vector<bool> within = {true, true, false, true, false, true, true, false, true, true, false};
    long wrong = -1;
    ClaimOptions exact{Numbers::Double, Q(0), true};
    const nlohmann::json e = nlohmann::json::parse(certify_fp(k.m, k.c, batch, "c.json", exact, &wrong));
    for (size_t i = 0; i < within.size(); ++i) BOOST_TEST(!e["claims"][i]["right"].get<bool>(), i);
    ClaimOptions tol = exact;
    tol.abs_tolerance = Q(1, 1000000000);
    const nlohmann::json r = nlohmann::json::parse(certify_fp(k.m, k.c, batch, "c.json", tol, &wrong));
    for (size_t i = 0; i < within.size(); ++i) BOOST_TEST(r["claims"][i]["right"].get<bool>() == within[i], i);
    BOOST_TEST(r["abs_tolerance"] == "1/1000000000");
    // The report says which points were outside, within the tolerance: claim 0's first closest
    // point, claim 3's witness point in P1 (not in P2, which holds it), claim 9's two points.
    BOOST_TEST(r["claims"][0]["closest_near_P1"] == true);
    BOOST_TEST(!r["claims"][0].contains("closest_near_P2"));
    BOOST_TEST(r["claims"][3]["near_P1"] == true);
    BOOST_TEST(!r["claims"][3].contains("near_P2"));
    BOOST_TEST(r["claims"][9]["closest_near_P1"] == true);
    BOOST_TEST(r["claims"][9]["closest_near_P2"] == true);
    BOOST_TEST(!e.contains("abs_tolerance"));
    // With a relative tolerance beside it, a value within LEN + REL·|exact|: 1.500000002 is within
    // 1e-9 + (1e-9)·(3/2) of 3/2, and 1.500000003 is not.
    tol.tolerance = Q(1, 1000000000);
    const nlohmann::json b = nlohmann::json::parse(certify_fp(k.m, k.c,
                                                              R"({"format": "scalecert-claims-1", "claims": [
        {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": "1500000002/1000000000"},
        {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": "1500000003/1000000000"}]})",
                                                              "c.json", tol, &wrong));
    BOOST_TEST(b["claims"][0]["right"].get<bool>());
    BOOST_TEST(!b["claims"][1]["right"].get<bool>());
    // A negative tolerance, or one on lines, is bad input.
    tol.abs_tolerance = -1;
    BOOST_CHECK_THROW(certify_fp(k.m, k.c, batch, "c.json", tol, &wrong), InputError);
    ClaimOptions lines{Numbers::Double, Q(0), false};
    lines.abs_tolerance = 1;
    BOOST_CHECK_THROW(certify_fp(HullClaimModels(k.m, k.c), "1 1 separated\n", "c.txt", lines, &wrong), InputError);
}

// A claim that needs the hull model is refused past the edge-pair limit wherever the hull model
// comes from: the command's session builds it, the library's asks its scene for the one it holds
// (Session::set_hull_source), and both refuse before building. Two copies of one 3,000-point
// near-sphere, about 9,000 edges each: 8*10^7 edge pairs, past 2*10^7; the hull engine (no walk),
// so the curve at ρ1 = 1 needs the hull model. The source is never asked.
BOOST_AUTO_TEST_CASE(a_claim_past_the_edge_pair_limit_is_refused_whatever_holds_the_hull_model) {
    std::mt19937 g(7);
    std::normal_distribution<double> N(0, 1);
    ExactScene s;
    for (int i = 0; i < 3000; ++i) {
        const double x = N(g), y = N(g), z = N(g), l = std::sqrt(x * x + y * y + z * z);
        s.P[0].points.push_back(
            {Q(std::lround(1e6 * x / l)), Q(std::lround(1e6 * y / l)), Q(std::lround(1e6 * z / l))});
    }
    s.P[1].points = s.P[0].points;
    s.lo[0] = s.lo[1] = Q(1, 2);
    s.hi[0] = s.hi[1] = Q(2);
    finish_scene(s, "spheres");
    for (const bool library : {false, true}) {
        Session session(s, "spheres", Engine::Hull);
        bool asked = false;
        if (library)
            session.set_hull_source([&asked]() -> std::shared_ptr<const HullModel> {
                asked = true;
                throw std::logic_error("the hull source was asked");
            });
        const ClaimModels& models = session.claim_models();
        BOOST_CHECK_EXCEPTION(models.curve_value(Q(1)), InputError, [](const InputError& e) {
            return std::string(e.what()).find("needs the hull model (every contact line)") != std::string::npos;
        });
        BOOST_TEST(!asked);
    }
}
