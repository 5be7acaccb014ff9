// Exact numbers and their nearest doubles (checker/numbers.*): null exactly where the nearest double
// would be infinite.
#include "checker_tests.hpp"

#include "../../checker/numbers.hpp"

#include <cmath>

BOOST_AUTO_TEST_SUITE(checker_numbers)

BOOST_AUTO_TEST_CASE(doubles_beyond_the_double_range_are_null) {
    // A vertex at 10^400: its nearest double would be infinite; the engine writes null there and
    // the checker accepts null exactly then (FORMAT.md "Numbers").
    fs::path sp = tmpdir() / "far.json", cp = tmpdir() / "far.cert.json", qp = tmpdir() / "far.q.json";
    std::ofstream(sp) << R"({"P1": {"vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,"1e400"]]},
        "P2": {"vertices": [[5,0,0],[6,0,0],[5,1,0],[5,0,1]]}, "I1": [1,2], "I2": [1,2]})";
    BOOST_TEST_REQUIRE(engine("partition " + sp.string() + " --out " + cp.string()) == 0);
    BOOST_TEST(check_file(cp) == 0);
    std::string text = test::slurp(cp);
    BOOST_TEST(text.find("null") != std::string::npos);
    BOOST_TEST_REQUIRE(engine("query --json " + sp.string() + " 1e4000 2 --numbers exact --out " + qp.string()) == 0);
    BOOST_TEST(check_file(qp) == 0);
    OJ q = load(qp);
    BOOST_TEST(q["rho1_double"].is_null());
    q["rho1_double"] = 1.7976931348623157e308;  // the largest double is not the nearest: refused
    BOOST_TEST(verdict_of(q) == 1);
    OJ r = load(qp);
    r["rho2_double"] = nullptr;  // null for a value in range: refused
    BOOST_TEST(verdict_of(r) == 1);
    // Hand-derived neighbours of the overflow threshold 2^1024 - 2^970 (halfway between the
    // largest double and 2^1024, which rounds to even: infinity).
    using scalecert_check::nearest;
    using scalecert_check::Q;
    const mpz_class two1024 = mpz_class(1) << 1024, half = mpz_class(1) << 970;
    BOOST_TEST(std::isinf(nearest(Q(two1024 - half))));
    BOOST_TEST(nearest(Q(two1024 - half - 1)) == 1.7976931348623157e308);
    BOOST_TEST(std::isinf(nearest(Q(-two1024))));
}

BOOST_AUTO_TEST_SUITE_END()
