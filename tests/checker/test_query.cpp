// Query answers (checker/query.cpp): every mutation of the engine's answers, separated, touching and
// overlapping, is rejected or still true.
#include "checker_tests.hpp"

BOOST_AUTO_TEST_SUITE(checker_query)

BOOST_AUTO_TEST_CASE(tampered_query_answers_are_rejected) {
    fs::path scene = fs::path(SCALECERT_SOURCE_DIR) / "certificates/scenes/tetra_box_switch.json";
    // separated, touching (on the (E,E) piece, derived by hand in test_hand_curves) and overlapping
    for (const char* q : {"1 1", "3/2 12/7", "2 2"}) {
        fs::path out = tmpdir() / "q.json";
        BOOST_TEST_REQUIRE(engine("query " + scene.string() + " " + q + " --json --out " + out.string()) == 0);
        BOOST_TEST_REQUIRE(check_file(out) == 0);
        const OJ j = load(out);
        mutate_and_report(j, std::string("query ") + q + " (" + j["verdict"].get<std::string>() + ")", true);
    }
}

BOOST_AUTO_TEST_SUITE_END()
