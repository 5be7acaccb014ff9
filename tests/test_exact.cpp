#include <boost/test/unit_test.hpp>

#include "numeric/exact.hpp"
#include "numeric/small_int.hpp"

#include <random>

using namespace scalecert::internal;

BOOST_AUTO_TEST_CASE(decimal_and_fraction_text_is_read_exactly) {
    BOOST_TEST(parse_exact("0.1") == Q(1, 10));
    BOOST_TEST(parse_exact("3/7") == Q(3, 7));
    BOOST_TEST(parse_exact("6/14") == Q(3, 7));
    BOOST_TEST(parse_exact("-6/14") == Q(-3, 7));
    BOOST_TEST(parse_exact("1e-3") == Q(1, 1000));
    BOOST_TEST(parse_exact("-2.5E+2") == Q(-250));
    BOOST_TEST(parse_exact("+.5") == Q(1, 2));
    BOOST_TEST(parse_exact("12.") == Q(12));
    BOOST_TEST(parse_exact("123456789012345678901234567890") == Q(Z("123456789012345678901234567890")));
    for (const char* bad : {"", "abc", "1/0", "1e", "--1", "1.2.3", "nan", "inf", "1/-2", "0x10", " 1", "1e9999999"})
        BOOST_CHECK_THROW(parse_exact(bad), InputError);
}

BOOST_AUTO_TEST_CASE(exact_strings_are_lowest_terms) {
    BOOST_TEST(to_exact_string(Q(6, 4)) == "3/2");
    BOOST_TEST(to_exact_string(Q(-6, 4)) == "-3/2");
    BOOST_TEST(to_exact_string(Q(8, 4)) == "2");
    BOOST_TEST(to_exact_string(Q(0, 5)) == "0");
}

BOOST_AUTO_TEST_CASE(binary_doubles_are_dyadic) {
    // 0.1 as a double is 3602879701896397 / 2^55.
    BOOST_TEST(exact_from_double(0.1) == Q(Z(3602879701896397), Z(1) << 55));
    BOOST_CHECK_THROW(exact_from_double(std::nan("")), InputError);
    // Read as a double, a token is the whole text: strtod stops at a NUL, the token does not (the
    // claims fuzzer read "1<NUL>02" as 1), nor at trailing junk.
    BOOST_TEST(parse_number("0.1", scalecert::Numbers::Double) == exact_from_double(0.1));
    BOOST_CHECK_THROW(parse_number(std::string("1\0"
                                               "02",
                                               4),
                                   scalecert::Numbers::Double),
                      InputError);
    BOOST_CHECK_THROW(parse_number("1x", scalecert::Numbers::Double), InputError);
    BOOST_CHECK_THROW(parse_number(" 1", scalecert::Numbers::Double), InputError);
    BOOST_CHECK_THROW(parse_number("", scalecert::Numbers::Double), InputError);
}

BOOST_AUTO_TEST_CASE(numbers_are_read_as_the_program_holds_them) {
    using scalecert::Numbers;
    // 0.1 as a float: 0.1 = 1.6·2^-4, 24 bits, so the step is 2^-27 and 0.1·2^27 = 13421772.8
    // rounds to 13421773. As a double, 3602879701896397/2^55 (above); as written, 1/10.
    BOOST_TEST(parse_number("0.1", Numbers::Float32) == Q(13421773, Z(1) << 27));
    BOOST_TEST(parse_number("0.1", Numbers::Exact) == Q(1, 10));
    // A fraction is exact under every reading.
    BOOST_TEST(parse_number("1/10", Numbers::Float32) == Q(1, 10));
    BOOST_TEST(parse_number("1/10", Numbers::Double) == Q(1, 10));
    // 2^24 + 1 = 16777217 is no float: ties to even give 16777216. Every double holds it.
    BOOST_TEST(parse_number("16777217", Numbers::Float32) == Q(16777216));
    BOOST_TEST(parse_number("16777217", Numbers::Double) == Q(16777217));
    // Beyond the float range (3.4e38), and a nonzero decimal that underflows to 0 (below 1.4e-45).
    BOOST_CHECK_THROW(parse_number("1e39", Numbers::Float32), InputError);
    BOOST_CHECK_THROW(parse_number("1e-50", Numbers::Float32), InputError);
    BOOST_TEST(parse_number("1e39", Numbers::Double) == Q(exact_from_double(1e39)));
    // Which decimals a reading keeps as written: dyadic ones with few enough bits.
    BOOST_TEST(binary_is_exact("0.375", Numbers::Double));
    BOOST_TEST(binary_is_exact("0.375", Numbers::Float32));
    BOOST_TEST(!binary_is_exact("0.1", Numbers::Double));
    BOOST_TEST(binary_is_exact("0.1", Numbers::Exact));
    BOOST_TEST(!binary_is_exact("16777217", Numbers::Float32));
    BOOST_TEST(binary_is_exact("16777217", Numbers::Double));
    BOOST_TEST(binary_is_exact("3/7", Numbers::Double));
    // Counting what was not read as written: 0.1 and 0.3, not 0.5, 2 or 1/3.
    long n = 0;
    for (const char* t : {"0.1", "0.5", "2", "0.3", "1/3"}) parse_number(t, Numbers::Double, &n);
    BOOST_TEST(n == 2);
    // What a program reading the double 0.1 holds, each way; the shortest decimal of a double.
    BOOST_TEST(scalecert::held(0.1, Numbers::Double) == exact_from_double(0.1));
    BOOST_TEST(scalecert::held(0.1, Numbers::Float32) == Q(13421773, Z(1) << 27));
    BOOST_TEST(scalecert::held(0.1, Numbers::Exact) == Q(1, 10));
    BOOST_TEST(scalecert::held(1e300, Numbers::Exact) == parse_exact("1e300"));
    BOOST_CHECK_THROW(scalecert::held(1e300, Numbers::Float32), InputError);
    BOOST_CHECK_THROW(scalecert::held(std::nan(""), Numbers::Double), InputError);
    BOOST_TEST(to_shortest(0.1) == "0.1");
    BOOST_TEST(std::string(scalecert::name(Numbers::Float32)) == "float32");
}

BOOST_AUTO_TEST_CASE(display_doubles_are_correctly_rounded) {
    // IEEE division of exactly representable integers is correctly rounded: an independent oracle.
    std::mt19937 g(7);
    std::uniform_int_distribution<long> u(-(1L << 40), 1L << 40);
    for (int i = 0; i < 2000; ++i) {
        long p = u(g), q = u(g);
        if (q == 0) continue;
        Q r(p, q);
        r.canonicalize();
        BOOST_TEST(to_double_rn(r) == static_cast<double>(p) / static_cast<double>(q));
    }
    // Ties round to even: 2^53 + 1 lies halfway between 2^53 and 2^53 + 2.
    BOOST_TEST(to_double_rn(Q((Z(1) << 53) + 1)) == 9007199254740992.0);
    BOOST_TEST(to_double_rn(Q((Z(1) << 53) + 3)) == 9007199254740996.0);
}

BOOST_AUTO_TEST_CASE(primitive_normals) {
    Vec3q v{Q(1, 2), Q(-3, 4), Q(0)};
    Vec3z p = primitive(v);
    BOOST_TEST(p[0] == 2);
    BOOST_TEST(p[1] == -3);
    BOOST_TEST(p[2] == 0);
}

// 128-bit conversions against GMP's own decimal reading.
BOOST_AUTO_TEST_CASE(int128_conversions) {
    const Z two100("1267650600228229401496703205376", 10);  // 2^100
    I128 v = 0;
    BOOST_TEST(to_i128(Z(two100 + 7), v));
    BOOST_TEST((v == (I128(1) << 100) + 7));
    BOOST_TEST(to_i128(Z(-two100), v));
    BOOST_TEST((v == -(I128(1) << 100)));
    BOOST_TEST((to_z(-(I128(1) << 100)) == -two100));
    BOOST_TEST((to_z((I128(1) << 100) + 7) == two100 + 7));
    const Z two126 = two100 * Z(1 << 26);
    BOOST_TEST(!to_i128(two126, v));
    BOOST_TEST(to_i128(Z(two126 - 1), v));
    BOOST_TEST((to_z(v) == two126 - 1));
    BOOST_TEST(to_i128(Z(0), v));
    BOOST_TEST((v == 0));
    Vec3s s;
    BOOST_TEST(to_small_normal({Z(-3), Z(0), Z("4611686018427387903", 10)}, s));  // 2^62 − 1 fits
    BOOST_TEST((s == Vec3s{-3, 0, 4611686018427387903LL}));
    BOOST_TEST(!to_small_normal({Z(1), Z("4611686018427387904", 10), Z(0)}, s));  // 2^62 does not
    BOOST_TEST((primitive(Vec3s{6, -9, 12}) == Vec3s{2, -3, 4}));
    BOOST_TEST((to_z(primitive(Vec3s{6, -9, 12})) == primitive(Vec3z{Z(6), Z(-9), Z(12)})));
}
