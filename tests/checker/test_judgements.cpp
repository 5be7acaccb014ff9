// Judgements files (checker/judgements.cpp): certify-fp's judgements of claims of every kind,
// derived by hand, at poses too, pass, and every mutation is rejected or judged alike by the engine;
// a switch-point claim is right when any exact switch point matches it.
#include "checker_tests.hpp"

#include <algorithm>

BOOST_AUTO_TEST_SUITE(checker_judgements)

// certify-fp --certificate: claims of every certified kind, right and wrong, derived by hand.
// Stacked cubes ([0,2]^3 below [0,2]^2 x [3,5], seeds the centres): P1(r1) reaches z = 1 + r1,
// P2(r2) starts at z = 4 − r2; they touch on r1 + r2 = 3, growth distance 3/2; at (1, 1/2) the
// gap is 3.5 − 2 = 3/2; at (2, 2) they overlap by 1 in z (depth 1 along z). The tetrahedron and
// box (tetra_box_switch): (1, 1) separated, (3/2, 12/7) touching, (2, 2) overlapping
// (test_hand_curves).
const char* kCubeClaims = R"({"format": "scalecert-claims-1", "claims": [
  {"kind": "verdict", "rho1": 1, "rho2": "1.5", "verdict": "separated"},
  {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "separated"},
  {"kind": "verdict", "rho1": "3/2", "rho2": "3/2", "verdict": "touching"},
  {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "intersecting"},
  {"kind": "curve", "vertices": [[1, 2], [2, 1]]},
  {"kind": "growth_distance", "value": 1.5},
  {"kind": "growth_distance", "value": 1.25},
  {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0.1, 0, 1], "offset": 2.6},
  {"kind": "separating_plane", "rho1": 2, "rho2": 1, "normal": [0, 0, 1]},
  {"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [1, 1, 2.5]},
  {"kind": "witness_point", "rho1": 1, "rho2": 1.5, "point": [1, 1, 2.5]},
  {"kind": "witness_point", "rho1": 3, "rho2": 3, "point": [0, 0, 2]},
  {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5, "closest": [[1, 1, 2], [1, 1, 3.5]]},
  {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5, "closest": [[1, 1, 2], [1, 1.5, 3.5]]},
  {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.25},
  {"kind": "distance", "rho1": 2, "rho2": 2, "value": 0},
  {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": 1, "direction": [0, 0, 1]},
  {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": 1, "direction": [0, 1, 1]},
  {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": 0.5},
  {"kind": "penetration_depth", "rho1": 1.5, "rho2": 1.5, "value": 0},
  {"kind": "penetration_depth", "rho1": 1, "rho2": 1, "value": 0}]})";
// right or wrong, claim by claim, by hand: the closest points (1, 1.5, 3.5) are not both at the
// distance (|(0, 1/2, 3/2)|² = 5/2 > 9/4); the depth along (0, 1, 1) is h_M/√2 = (6 − 1)/√2 > 1,
// as P1(2) = [−1, 3]^3 reaches y + z = 6 and P2(2) = [−1, 3]^2 x [2, 6] starts at y + z = 1;
// (0, 0, 2) is in P1(3) = [−2, 4]^3 and P2(3) = [−2, 4]^2 x [1, 7].
const std::vector<bool> kCubeRight = {true,  false, true,  true,  /* the curve ρ1 + ρ2 = 3 */ true,
                                      true,  false, true,  false, true,
                                      false, true,  true,  false, false,
                                      true,  true,  false, false, true,
                                      false};

BOOST_AUTO_TEST_CASE(judgements_certificates_are_valid_and_tampering_is_rejected) {
    const fs::path claims = tmpdir() / "cube_claims.json", cert = tmpdir() / "judgements.json",
                   rep = tmpdir() / "report.json";
    { std::ofstream(claims) << kCubeClaims; }
    const std::string cubes = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json";
    BOOST_TEST_REQUIRE(engine("certify-fp " + cubes + " " + claims.string() + " --json --out " + rep.string() +
                              " --certificate " + cert.string()) == 1);
    BOOST_TEST_REQUIRE(check_file(cert) == 0);
    const OJ j = load(cert), r = load(rep);
    BOOST_TEST(j["kind"] == "judgements");
    BOOST_TEST(j["judgements"].size() == 21u);
    std::vector<bool> rights;
    for (const OJ& e : j["judgements"]) {
        rights.push_back(e["right"].get<bool>());
        BOOST_TEST(r["claims"][e["index"].get<size_t>()]["right"] == e["right"]);  // the report says the same
    }
    BOOST_TEST(rights == kCubeRight, [&] {
        std::string t;
        for (bool b : rights) t += b ? '1' : '0';
        return t;
    }());
    // The depth at (2, 2) is 1: its proof's direction is +z and its surface closes around the origin.
    BOOST_TEST(j["judgements"][16]["proof"]["squared"] == "1");
    BOOST_TEST(j["judgements"][16]["proof"]["direction"] == OJ::parse(R"(["0", "0", "1"])"));
    // The curve ρ1 + ρ2 = 3 (one piece, no switch point): proved over a window around [1, 2].
    BOOST_TEST(j["judgements"][4]["proof"]["pieces"].size() == 1u);
    BOOST_TEST(j["judgements"][4]["proof"]["pieces"][0]["slope"] == "-1");
    mutate_and_report(j, "judgements (stacked cubes)", false, true);

    // The tetrahedron and the box: verdicts of all three kinds, and a depth and a distance whose
    // proofs come from facets that are not axis-aligned.
    const fs::path tclaims = tmpdir() / "tetra_claims.json", tcert = tmpdir() / "tetra_judgements.json";
    {
        std::ofstream(tclaims) << R"({"format": "scalecert-claims-1", "claims": [
      {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated"},
      {"kind": "verdict", "rho1": "3/2", "rho2": "12/7", "verdict": "touching"},
      {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "overlapping"},
      {"kind": "distance", "rho1": 1, "rho2": 1, "value": 0.1},
      {"kind": "penetration_depth", "rho1": 2.5, "rho2": 2.5, "value": 0.1},
      {"kind": "growth_distance", "value": 1.6},
      {"kind": "switch_point", "rho1": 1, "rho2": 2, "contact": "VE"},
      {"kind": "switch_point", "rho1": 1, "rho2": 2, "contact": "EE"},
      {"kind": "switch_point", "rho1": "1/2", "rho2": 2},
      {"kind": "curve", "pieces": [
        {"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2", "contact": "VF"},
        {"rho1": [1, "3/2"], "slope": "-4/7", "intercept": "18/7", "contact": "EE"}]},
      {"kind": "curve", "vertices": [["1/2", "13/4"], ["3/2", "12/7"]], "switch_points": []},
      {"kind": "curve", "vertices": [[1, 2], ["3/2", "12/7"]]}]})";
    }
    const std::string tetra = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/tetra_box_switch.json";
    BOOST_TEST_REQUIRE(engine("certify-fp " + tetra + " " + tclaims.string() + " --certificate " + tcert.string()) ==
                       1);
    BOOST_TEST_REQUIRE(check_file(tcert) == 0);
    const OJ t = load(tcert);
    BOOST_TEST(t["judgements"][0]["right"] == true);
    BOOST_TEST(t["judgements"][1]["right"] == true);
    BOOST_TEST(t["judgements"][2]["right"] == true);
    // Its curve (test_claims.cpp, curve_claim_rules): (V,F) ρ2 = 9/2 − 5ρ1/2 up to the switch point
    // (1, 2), of contact VE, then (E,E) ρ2 = (18 − 4ρ1)/7. The chord from ρ1 = 1/2 to 3/2 is off at
    // ρ1 = 1 and misses the switch point; a switch point claimed at ρ1 = 1/2 has the wrong ρ1.
    const std::vector<bool> tetra_right = {true, false, false, true, false, true};  // claims 6 to 11
    for (size_t k = 0; k < tetra_right.size(); ++k)
        BOOST_TEST(t["judgements"][6 + k]["right"] == tetra_right[k], 6 + k);
    BOOST_TEST(t["judgements"][6]["proof"]["switch_points"].size() == 1u);
    BOOST_TEST(t["judgements"][6]["proof"]["switch_points"][0]["rho1"] == "1");
    mutate_and_report(t, "judgements (tetrahedron and box)", false, true);
}

BOOST_AUTO_TEST_CASE(signed_distances_are_checked_and_tampering_is_rejected) {
    // By hand (the stacked cubes above): 3/2 apart at (1, 1/2), touching at (1, 2), overlapping by
    // 1 at (2, 2); with P2 lifted by 1, 5/2 apart at (1, 1/2). The tetrahedron and box:
    // separated at (1, 1), touching at (3/2, 12/7), overlapping at (2, 2).
    const fs::path claims = tmpdir() / "sd_claims.json", cert = tmpdir() / "sd.json";
    {
        std::ofstream(claims) << R"({"format": "scalecert-claims-1", "claims": [
      {"kind": "signed_distance", "rho1": 1, "rho2": 0.5, "value": 1.5},
      {"kind": "signed_distance", "rho1": 2, "rho2": 2, "value": -1},
      {"kind": "signed_distance", "rho1": 2, "rho2": 2, "value": 1},
      {"kind": "signed_distance", "rho1": 1, "rho2": 2, "value": 0},
      {"kind": "signed_distance", "rho1": 1, "rho2": 0.5, "at_least": 1.5},
      {"kind": "signed_distance", "rho1": 1, "rho2": 0.5, "below": 1.5},
      {"kind": "signed_distance", "rho1": 2, "rho2": 2, "below": 0},
      {"kind": "signed_distance", "rho1": 1, "rho2": 0.5, "value": 2.5, "pose2": [[1,0,0,0],[0,1,0,0],[0,0,1,1]]},
      {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "not_overlapping"},
      {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "not_overlapping"}]})";
    }
    const std::string cubes = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json";
    BOOST_TEST_REQUIRE(engine("certify-fp " + cubes + " " + claims.string() + " --certificate " + cert.string()) == 1);
    BOOST_TEST_REQUIRE(check_file(cert) == 0);
    const OJ j = load(cert);
    const std::vector<bool> right = {true, true, false, true, true, false, true, true, true, false};
    BOOST_TEST_REQUIRE(j["judgements"].size() == right.size());
    for (size_t k = 0; k < right.size(); ++k) BOOST_TEST(j["judgements"][k]["right"] == right[k], k);
    // Apart: a distance proof of squared distance 9/4; overlapping: a depth proof of squared depth 1.
    BOOST_TEST(j["judgements"][0]["proof"]["distance"]["squared"] == "9/4");
    BOOST_TEST(j["judgements"][1]["proof"]["depth"]["squared"] == "1");
    mutate_and_report(j, "signed distances (stacked cubes)", false, true);

    const fs::path tclaims = tmpdir() / "sd_tetra.json", tcert = tmpdir() / "sd_tetra_cert.json";
    {
        std::ofstream(tclaims) << R"({"format": "scalecert-claims-1", "claims": [
      {"kind": "signed_distance", "rho1": 1, "rho2": 1, "below": 0},
      {"kind": "signed_distance", "rho1": "3/2", "rho2": "12/7", "value": 0},
      {"kind": "signed_distance", "rho1": 2, "rho2": 2, "at_least": 0}]})";
    }
    const std::string tetra = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/tetra_box_switch.json";
    BOOST_TEST_REQUIRE(engine("certify-fp " + tetra + " " + tclaims.string() + " --certificate " + tcert.string()) ==
                       1);
    BOOST_TEST_REQUIRE(check_file(tcert) == 0);
    const OJ t = load(tcert);
    BOOST_TEST(t["judgements"][0]["right"] == false);
    BOOST_TEST(t["judgements"][1]["right"] == true);
    BOOST_TEST(t["judgements"][2]["right"] == false);
    mutate_and_report(t, "signed distances (tetrahedron and box)", false, true);
}

BOOST_AUTO_TEST_CASE(a_switch_point_claim_is_right_when_any_exact_one_matches) {
    // The Fig. 5 scene's switch points (README): (23/19, 45/19) VE and (29/13, 18/13) EV. The
    // claim (7/4, 45/19, VE) is nearer in rho1 to the second (|7/4 − 29/13| = 11/52 against
    // |7/4 − 23/19| = 41/76), but matches the first within 0.45: |7/4 − 23/19|/(23/19) = 41/92 ≈
    // 0.4457 and rho2 exactly. Right at tolerance 0.45 (judged against the nearest in both
    // coordinates, not in rho1 alone), wrong at 0.44; and with contact EV wrong at 0.45 (the
    // second's rho2 18/13 is off by 0.71).
    const std::string fig5 = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/fig5_vf_ve_ee.json";
    const fs::path claims = tmpdir() / "switch_any.json", cert = tmpdir() / "switch_any.cert.json";
    {
        std::ofstream(claims) << R"({"format": "scalecert-claims-1", "claims": [
      {"kind": "switch_point", "rho1": "7/4", "rho2": "45/19", "contact": "VE"},
      {"kind": "switch_point", "rho1": "7/4", "rho2": "45/19", "contact": "EV"},
      {"kind": "switch_point", "rho1": "7/4", "rho2": "45/19"}]})";
    }
    for (const auto& [tol, rights] : std::vector<std::pair<std::string, std::vector<bool>>>{
             {"0.45", {true, false, true}}, {"0.44", {false, false, false}}, {"2", {true, true, true}}}) {
        // (tolerance 2: the second matches too, 18/13 within 2 x 18/13 of 45/19, so EV is right)
        const int st = engine("certify-fp " + fig5 + " " + claims.string() + " --tolerance " + tol + " --certificate " +
                              cert.string());
        BOOST_TEST(st == (std::count(rights.begin(), rights.end(), false) ? 1 : 0), tol);
        BOOST_TEST_REQUIRE(check_file(cert) == 0);
        const OJ j = load(cert);
        for (size_t k = 0; k < rights.size(); ++k)
            BOOST_TEST(j["judgements"][k]["right"] == rights[k], tol << " claim " << k);
        // Flipping a judgement is rejected.
        OJ f = j;
        f["judgements"][0]["right"] = !rights[0];
        BOOST_TEST(check_json(f) == 1);
    }
}

BOOST_AUTO_TEST_CASE(judgements_at_poses_are_valid_and_tampering_is_rejected) {
    // The stacked cubes ([0,2]^3 about (1,1,1) below [0,2]^2 x [3,5] about (1,1,4)) with P2 turned a
    // quarter about the vertical line through (1, 1) (A: onto itself) or also lifted by 1 (B):
    // under A every claim is judged as on the unposed cubes (touching on rho1 + rho2 = 3, the gap
    // 1 at (1, 1), depth 1 at (2, 2)); under B, P2(1) starts at z = 4: 2 apart at (1, 1), and at
    // (1, 2) P2 starts at z = 3 > 2 = P1's top, separated.
    const std::string A = "[[0,-1,0,2],[1,0,0,0],[0,0,1,0]]", B = "[[0,-1,0,2],[1,0,0,0],[0,0,1,1]]";
    const fs::path claims = tmpdir() / "posed_claims.json", cert = tmpdir() / "posed.cert.json";
    std::ofstream(claims) << R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "touching", "pose2": )" +
                                 A + R"(},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1, "pose2": )" +
                                 A + R"(},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 2, "pose2": )" +
                                 B + R"(, "closest": [[1, 1, 2], [1, 1, 4]]},
     {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "overlapping", "pose2": )" +
                                 A + R"(},
     {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": 1, "direction": [0, 0, 1], "pose2": )" +
                                 A + R"(},
     {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0, 0, 1], "offset": 2.5, "pose2": )" +
                                 A + R"(},
     {"kind": "witness_point", "rho1": 2, "rho2": 2, "point": [1, 1, 2.5], "pose1": )" +
                                 A + R"(, "pose2": )" + A + R"(},
     {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "touching", "pose2": )" +
                                 B + R"(}
    ]})";
    const std::string cubes = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json";
    BOOST_REQUIRE(engine("certify-fp " + cubes + " " + claims.string() + " --certificate " + cert.string()) == 1);
    const OJ j = load(cert);
    const std::vector<bool> right = {true, true, true, true, true, true, true, false};
    BOOST_TEST_REQUIRE(j["judgements"].size() == right.size());
    for (size_t k = 0; k < right.size(); ++k) BOOST_TEST(j["judgements"][k]["right"] == right[k], k);
    BOOST_TEST(check_file(cert) == 0);
    mutate_and_report(j, "judgements at poses", false, true);
    // A claim with no answer is still a claim of its kind: its pose too (exact, R nonsingular).
    for (const char* pose : {R"(["0","-1","0","2"])", R"("garbage")", "[[0,0,0,0],[0,0,0,0],[0,0,0,0]]",
                             R"([["0","-1","0","2"],["1","0","0","0"],["0","0","1","0"]])"}) {
        OJ f = j;
        f["judgements"][1]["claim"]["value"] = nullptr;
        f["judgements"][1]["claim"]["pose2"] = OJ::parse(pose);
        f["judgements"][1]["proof"] = OJ::parse(R"({"no_answer": "value"})");
        f["judgements"][1]["right"] = false;
        // (the last, the claim's own pose as exact strings, is valid: the control)
        BOOST_TEST(check_json(f) == (std::string(pose).rfind("[[\"", 0) == 0 ? 0 : 1), pose);
    }
}

BOOST_AUTO_TEST_SUITE_END()
