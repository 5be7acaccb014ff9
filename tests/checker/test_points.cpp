// Integer points held compactly (checker/points.hpp, the IntPoints the reader fills): integers at
// and past the limits of int64 held exactly, and long lists grown by remapping.
#include "checker_tests.hpp"

#include "../../checker/json.hpp"
#include "../../checker/points.hpp"
#include "../../checker/scan.hpp"

#include <algorithm>
#include <array>

BOOST_AUTO_TEST_SUITE(checker_points)

BOOST_AUTO_TEST_CASE(integers_at_the_limits_of_int64_are_read_exactly) {
    // Below 2^62 in magnitude a coordinate is held as int64; from 2^62 on (INT64_MAX and INT64_MIN
    // among them, and 2^63 and 20 digits past them) its vertex is held in GMP integers. The
    // maximum along each axis, by hand, and ties between a small vertex and big ones merged.
    const std::string text = R"({"scene": {"P1": {"vertices": [
        ["4611686018427387903", "-4611686018427387903", "0"],
        ["4611686018427387904", "0", "0"],
        ["-4611686018427387904", "0", "0"],
        ["9223372036854775807", "0", "0"],
        ["-9223372036854775808", "0", "0"],
        ["9223372036854775808", "1", "2"],
        ["99999999999999999999", "0", "0"],
        ["1", "2", "3"],
        ["0", "2", "-1"],
        ["4611686018427387904", "2", "-1"]]}}})";
    sc_::Parsed parsed = sc_::parse_certificate(text);
    BOOST_TEST_REQUIRE(parsed.points.size() == 1u);
    sc_::Context cx;
    cx.points = &parsed.points;
    sc_::IntPoints* ip = sc_::captured(cx, parsed.root["scene"]["P1"]["vertices"]);
    BOOST_TEST_REQUIRE(ip == &parsed.points[0]);
    BOOST_TEST(ip->n == 10u);
    BOOST_TEST(ip->small() == 3u);  // vertices 0, 7 and 8
    BOOST_TEST((ip->orig == std::vector<int>{0, 7, 8}));
    BOOST_TEST((ip->big == std::vector<int>{1, 2, 3, 4, 5, 6, 9}));
    const std::vector<std::array<const char*, 3>> want = {{"4611686018427387903", "-4611686018427387903", "0"},
                                                          {"4611686018427387904", "0", "0"},
                                                          {"-4611686018427387904", "0", "0"},
                                                          {"9223372036854775807", "0", "0"},
                                                          {"-9223372036854775808", "0", "0"},
                                                          {"9223372036854775808", "1", "2"},
                                                          {"99999999999999999999", "0", "0"},
                                                          {"1", "2", "3"},
                                                          {"0", "2", "-1"},
                                                          {"4611686018427387904", "2", "-1"}};
    std::vector<CV> rational;
    for (const auto& w : want) rational.push_back({CQ(w[0]), CQ(w[1]), CQ(w[2])});
    const sc_::Scan from_text(cx, std::move(*ip)), from_rationals(cx, rational, "P1");
    for (size_t k = 0; k < want.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            BOOST_TEST(from_text.X(k)[c] == mpz_class(want[k][c]), k << "," << c);
            BOOST_TEST(from_rationals.X(k)[c] == mpz_class(want[k][c]), k << "," << c);
        }
    auto argmax = [&](long a, long b, long c) {
        const sc_::Z3 u{mpz_class(a), mpz_class(b), mpz_class(c)};
        const std::vector<int> m = from_text.argmax(cx, u);
        BOOST_TEST((m == from_rationals.argmax(cx, u)));
        return m;
    };
    BOOST_TEST((argmax(1, 0, 0) == std::vector<int>{6}));        // 10^20 - 1
    BOOST_TEST((argmax(-1, 0, 0) == std::vector<int>{4}));       // -2^63
    BOOST_TEST((argmax(0, 1, 0) == std::vector<int>{7, 8, 9}));  // y = 2: small 7, 8 and big 9 tie
    BOOST_TEST((argmax(0, -1, 0) == std::vector<int>{0}));       // y = -(2^62 - 1)
    BOOST_TEST((argmax(0, 0, 1) == std::vector<int>{7}));        // z = 3
    BOOST_TEST((argmax(0, 0, -1) == std::vector<int>{8, 9}));    // z = -1: a small and a big vertex
    // (2^62 - 1) x − y over vertex 0 is 2^62 (2^62 − 1) + ... : past int64 products, exact
    const sc_::Z3 u{mpz_class("4611686018427387903"), mpz_class(-1), mpz_class(0)};
    BOOST_TEST((from_text.argmax(cx, u) == std::vector<int>{6}));
    BOOST_TEST((from_text.argmax(cx, u) == from_rationals.argmax(cx, u)));
    // A subset holding only small vertices, and one holding both.
    const std::vector<int> small_only{0, 7, 8}, both{3, 8};
    BOOST_TEST((from_text.argmax(cx, {mpz_class(1), mpz_class(0), mpz_class(0)}, &small_only) == std::vector<int>{0}));
    BOOST_TEST((from_text.argmax(cx, {mpz_class(1), mpz_class(0), mpz_class(0)}, &both) == std::vector<int>{3}));
}

BOOST_AUTO_TEST_CASE(large_integer_lists_grow_exactly) {
    // A list long enough that each coordinate array is a mapping of its own (from 1 MiB: 2^17
    // coordinates), grown by remapping, with big points among the small ones: every point where
    // it was put.
    auto coord = [](size_t k, int c) { return static_cast<int64_t>(k * 7919 % 1000003) * (c + 1) - 1000000; };
    const mpz_class two70 = mpz_class(1) << 70;
    sc_::IntPoints all;
    const size_t n = 603003;
    std::vector<size_t> bigs;
    for (size_t k = 0; k < n; ++k)
        if (k % 50021 == 17) {  // a big point: x past int64
            all.add_big({mpz_class(two70 + k), mpz_class(coord(k, 1)), mpz_class(coord(k, 2))});
            bigs.push_back(k);
        } else {
            const int64_t x[3] = {coord(k, 0), coord(k, 1), coord(k, 2)};
            all.add_small(x);
        }
    BOOST_TEST(all.n == n);
    BOOST_TEST(all.big.size() == bigs.size());
    BOOST_TEST(all.small() + all.big.size() == n);
    sc_::Context cx;
    const sc_::Scan s(cx, std::move(all));
    BOOST_TEST(s.size() == n);
    size_t wrong = 0;
    for (size_t k = 0; k < n; ++k) {
        const bool big = std::binary_search(bigs.begin(), bigs.end(), k);
        const sc_::Z3 X = s.X(k);
        wrong += X[0] != (big ? mpz_class(two70 + k) : mpz_class(static_cast<long>(coord(k, 0)))) ||
                 X[1] != mpz_class(static_cast<long>(coord(k, 1))) || X[2] != mpz_class(static_cast<long>(coord(k, 2)));
    }
    BOOST_TEST(wrong == 0u);
    // the largest x: the last big point
    BOOST_TEST(
        (s.argmax(cx, {mpz_class(1), mpz_class(0), mpz_class(0)}) == std::vector<int>{static_cast<int>(bigs.back())}));
}

BOOST_AUTO_TEST_SUITE_END()
