// What both judgement formats share (checker/judging.*): the tolerance and the seeds counted at
// each use, the tolerance shown by its size, and the absolute tolerance's near and out proofs.
#include "checker_tests.hpp"

#include <chrono>

BOOST_AUTO_TEST_SUITE(checker_judging)

BOOST_AUTO_TEST_CASE(numbers_every_judgement_uses_are_counted_at_each_use) {
    // A tolerance of 10^6 digits with 1,000 distance judgements (1.2 MB), and seeds of 2·10^5
    // digits with plane judgements: the arithmetic on a number stored once is counted per use
    // (uncounted, 29 s and 19 ms a judgement). Both are refused at the work limit, at once.
    const fs::path claims = tmpdir() / "one_distance.json", cert = tmpdir() / "one_distance.cert.json";
    std::ofstream(claims)
        << R"({"format": "scalecert-claims-1", "claims": [{"kind": "distance", "rho1": 1, "rho2": "1/2", )"
           R"("value": 1.5}]})";
    const std::string cubes = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json";
    BOOST_TEST_REQUIRE(engine("certify-fp " + cubes + " " + claims.string() + " --certificate " + cert.string()) == 0);
    OJ j = load(cert);
    BOOST_TEST_REQUIRE(check_file(cert) == 0);
    const OJ one = j["judgements"][0];
    j["judgements"] = OJ::array();
    for (int k = 0; k < 1000; ++k) {
        OJ e = one;
        e["index"] = k;
        j["judgements"].push_back(e);
    }
    j["tolerance"] = "1/1" + std::string(1000000, '0') + "1";
    std::string msg;
    const auto t0 = std::chrono::steady_clock::now();
    BOOST_TEST(scalecert_check::check_text(j.dump(), msg) == 2);
    BOOST_TEST(msg.find("work limit") != std::string::npos, msg);
    BOOST_TEST(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < 5.0);
}

BOOST_AUTO_TEST_CASE(a_long_tolerance_is_shown_by_its_size) {
    // The summary writes the tolerance whole: cut to its first 40 characters, 1.2e-9 and 1.2e52
    // written with the same leading digits would look alike. A verdict's judgement does not
    // depend on the tolerance, so both files are valid; their summaries must differ.
    const std::string cubes = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json";
    const fs::path claims = tmpdir() / "tol_claims.json", cert = tmpdir() / "tol.cert.json";
    {
        std::ofstream(claims)
            << R"({"format": "scalecert-claims-1", "claims": [{"kind": "verdict", "rho1": 1, "rho2": 1, )"
               R"("verdict": "separated"}]})";
    }
    BOOST_REQUIRE(engine("certify-fp " + cubes + " " + claims.string() + " --certificate " + cert.string()) == 0);
    OJ j = load(cert);
    const std::string digits = "12345678901234567890123456789012345678901";
    std::string small_msg, big_msg;
    j["tolerance"] = digits + "/" + "1" + std::string(49, '0');
    BOOST_TEST(scalecert_check::check_text(j.dump(1), small_msg) == 0);
    j["tolerance"] = digits + std::string(12, '0');
    BOOST_TEST(scalecert_check::check_text(j.dump(1), big_msg) == 0);
    BOOST_TEST(small_msg.find("tolerance ~1.23457e-09") != std::string::npos, small_msg);
    BOOST_TEST(big_msg.find("tolerance ~1.23457e+52") != std::string::npos, big_msg);
}

BOOST_AUTO_TEST_CASE(absolute_tolerance_judgements_are_valid_and_tampering_is_rejected) {
    // Points 1e-9 off their bodies, values 1e-9 off, planes the bodies reach (test_claims.cpp,
    // absolute_tolerance_on_points_values_and_planes, derives each by hand): right within 1e-9 by
    // {"near"} memberships, wrong ones by {"out"} normals showing more than 1e-9, on the stacked
    // cubes and on the band of parts. Every mutation is rejected or judged the same by the engine.
    const std::string cubes_claims = R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5,
      "closest": [[1, 1, "2000000001/1000000000"], [1, 1, "3499999999/1000000000"]]},
     {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5,
      "closest": [[1, 1, "1999999999/1000000000"], [1, 1, "3500000002/1000000000"]]},
     {"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [1, 1, "2500000001/1000000000"]},
     {"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [1, 1, "2500000002/1000000000"]},
     {"kind": "separating_plane", "rho1": 1.5, "rho2": 1.5, "normal": [0, 0, 2], "offset": "5000000001/1000000000"},
     {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": "999999999/1000000000", "direction": [0, 0, 1]}]})";
    const OJ cubes = compound_judgements(fs::path(SCALECERT_SOURCE_DIR) / "certificates/scenes/stacked_cubes.json",
                                         cubes_claims, "abs_cubes", " --abs-tolerance 1e-9");
    BOOST_TEST(cubes["abs_tolerance"] == "1/1000000000");
    const std::vector<bool> right = {true, false, true, false, true, true};
    BOOST_TEST_REQUIRE(cubes["judgements"].size() == right.size());
    for (size_t k = 0; k < right.size(); ++k) BOOST_TEST(cubes["judgements"][k]["right"] == right[k], k);
    BOOST_TEST(cubes["judgements"][2]["proof"]["P1"].contains("near"));
    BOOST_TEST(cubes["judgements"][3]["proof"]["P1"].contains("out"));
    mutate_and_report(cubes, "judgements at an absolute tolerance (stacked cubes)", false, true);
    // A "near" point farther than the tolerance: the checker says so. (The engine's own file is
    // made to lie: claim 3's point, 2e-9 out, given the weights of claim 2's near point.)
    OJ forged = cubes;
    forged["judgements"][3]["right"] = true;
    forged["judgements"][3]["proof"]["P1"] = cubes["judgements"][2]["proof"]["P1"];
    std::string msg;
    BOOST_TEST(scalecert_check::check_text(forged.dump(1), msg) == 1);
    BOOST_TEST(msg.find("within abs_tolerance") != std::string::npos, msg);
    // Without the tolerance, a "near" proof is no membership proof at all.
    OJ exact = cubes;
    exact.erase("abs_tolerance");
    BOOST_TEST(scalecert_check::check_text(exact.dump(1), msg) == 1);

    // The band of parts: P1's right box [2, 3] x [-1, 1]^2 scaled about the origin, P2 [4, 5] x
    // [-1, 1]^2 about (9/2, 0, 0); at (4/3, 1) they touch at x = 4.
    const std::string band_claims = R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1, "closest": [["3000000001/1000000000", 0, 0], [4, 0, 0]]},
     {"kind": "witness_point", "rho1": "4/3", "rho2": 1, "point": ["4000000001/1000000000", 0, 0]},
     {"kind": "witness_point", "rho1": "4/3", "rho2": 1, "point": ["4000000002/1000000000", 0, 0]},
     {"kind": "separating_plane", "rho1": "4/3", "rho2": 1, "normal": [1, 0, 0], "offset": 4},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": "999999999/1000000000"}]})";
    const OJ band = compound_judgements(data("compound_band.json"), band_claims, "abs_band", " --abs-tolerance 1e-9");
    const std::vector<bool> band_right = {true, true, false, true, true};
    BOOST_TEST_REQUIRE(band["judgements"].size() == band_right.size());
    for (size_t k = 0; k < band_right.size(); ++k) BOOST_TEST(band["judgements"][k]["right"] == band_right[k], k);
    BOOST_TEST(band["judgements"][1]["proof"]["P1"]["near"].is_array());
    mutate_and_report(band, "compound judgements at an absolute tolerance (band)", false, true);
}

BOOST_AUTO_TEST_SUITE_END()
