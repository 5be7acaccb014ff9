// The work limit (checker/context.hpp, Context): a file past its work is refused with exit status 2
// at a point that depends on the file only; and the denominator limit.
#include "checker_tests.hpp"

BOOST_AUTO_TEST_SUITE(checker_context)

BOOST_AUTO_TEST_CASE(the_work_limit_and_the_denominator_limit_refuse_with_exit_2) {
    // Two square pyramids tip to tip: one piece. With 2,000 more vertices (copies of the seeds)
    // the file is valid; under a work limit lowered for the test it is refused with exit status 2,
    // at a point that depends on the file only (the same message every time). (Same-line normals,
    // which this test once multiplied, are at most four now, each one shrinking the features.)
    const fs::path scene = tmpdir() / "pyramids.json", cert = tmpdir() / "pyramids.partition.json";
    std::ofstream(scene)
        << R"({"P1": {"vertices": [[0,0,10],[10,10,-10],[10,-10,-10],[-10,10,-10],[-10,-10,-10]], "seed": [0,0,0]},
 "P2": {"vertices": [[0,0,20],[10,10,40],[10,-10,40],[-10,10,40],[-10,-10,40]], "seed": [0,0,30]}, "I1": ["1/2",
 2], "I2": ["1/2", 2]})";
    BOOST_TEST_REQUIRE(engine("partition " + scene.string() + " --out " + cert.string()) == 0);
    OJ j = load(cert);
    BOOST_TEST_REQUIRE(j["pieces"].size() == 1u);
    for (int k = 0; k < 1000; ++k) {
        j["scene"]["P1"]["vertices"].push_back(j["scene"]["P1"]["seed"]);
        j["scene"]["P2"]["vertices"].push_back(j["scene"]["P2"]["seed"]);
    }
    const std::string text = j.dump(1);
    std::string msg;
    scalecert_check::Context cx;
    BOOST_TEST(scalecert_check::check_text(text, msg, cx) == 0, msg);
    const double work = cx.work;
    BOOST_TEST(work > 2.0 * 1005);  // at least one normal scanned both polytopes
    scalecert_check::Context tight;
    tight.work_per_byte = 0.5 * work / static_cast<double>(text.size());
    tight.min_work = 0;
    std::string first, again;
    BOOST_TEST(scalecert_check::check_text(text, first, tight) == 2);
    BOOST_TEST(first.find("work limit") != std::string::npos, first);
    BOOST_TEST(scalecert_check::check_text(text, again, tight) == 2);
    BOOST_TEST(first == again);
    BOOST_TEST(scalecert_check::check_text(text, msg) == 0, msg);
    // A vertex whose denominator takes the polytope's common denominator past 2^16384 (the
    // engine's own limit): refused with exit status 2, before any scan.
    OJ big = bundled("tetra_box_switch");
    big["scene"]["P2"]["vertices"].push_back(OJ::array({"1/" + mpz_class(mpz_class(1) << 16384).get_str(), "0", "0"}));
    BOOST_TEST(verdict_of(big) == 2);
    OJ fits = bundled("tetra_box_switch");
    fits["scene"]["P2"]["vertices"].push_back(OJ::array({"1/" + mpz_class(mpz_class(1) << 16383).get_str(), "0", "0"}));
    BOOST_TEST(verdict_of(fits) == 0);  // a point inside the cube: every claim still holds
}

BOOST_AUTO_TEST_SUITE_END()
