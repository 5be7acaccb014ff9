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
    for (const char* bad : {"", "abc", "1/0", "1e", "--1", "1.2.3", "nan", "inf", "1/-2", "0x", "0x.p1", " 1",
                            "1e9999999", "0x1p", "0x1p+", "0x1.8.1p0", "0xg", "x1p0", "0x1p1e3"})
        BOOST_CHECK_THROW(parse_exact(bad), InputError);
}

BOOST_AUTO_TEST_CASE(hex_floats_are_read_exactly_and_as_strtod_reads_them) {
    using scalecert::Numbers;
    // As written: 0x1.8p-3 = (1 + 8/16)·2^-3 = 3/16; 0X.Cp+1 = 12/16·2 = 3/2; 0x10 = 16 (the
    // binary exponent is optional, as strtod takes it); 0xA.8 = 10 + 8/16 = 21/2.
    BOOST_TEST(parse_exact("0x1.8p-3") == Q(3, 16));
    BOOST_TEST(parse_exact("-0X.Cp+1") == Q(-3, 2));
    BOOST_TEST(parse_exact("0x10") == Q(16));
    BOOST_TEST(parse_exact("+0xA.8") == Q(21, 2));
    BOOST_TEST(parse_exact("0x1p-1074") == Q(1, Z(1) << 1074));
    // Read as a program holds it: 0x1.000003p0 = 1 + 3·2^-24 lies halfway between the floats
    // 1 + 2^-23 and 1 + 2^-22; ties to even give 1 + 2^-22 (and 0x1.000001p0 = 1 + 2^-24, halfway
    // between 1 and 1 + 2^-23, gives 1). Every double holds both as written.
    BOOST_TEST(parse_number("0x1.000003p0", Numbers::Float32) == Q(1) + Q(1, Z(1) << 22));
    BOOST_TEST(parse_number("0x1.000001p0", Numbers::Float32) == Q(1));
    BOOST_TEST(parse_number("0x1.000003p0", Numbers::Double) == Q(1) + Q(3, Z(1) << 24));
    BOOST_TEST(binary_is_exact("0x1.000003p0", Numbers::Double));
    BOOST_TEST(!binary_is_exact("0x1.000003p0", Numbers::Float32));
    // 0x1.80000000000008p0 = 3/2 + 2^-53, halfway between the doubles 3/2 and 3/2 + 2^-52: 3/2.
    BOOST_TEST(parse_number("0x1.80000000000008p0", Numbers::Double) == Q(3, 2));
    BOOST_TEST(parse_number("0x1.80000000000008p0", Numbers::Exact) == Q(3, 2) + Q(1, Z(1) << 53));
    // The least float is 2^-149; 2^-150 is halfway to 0 and rounds to it (even): no float a program
    // held. Past the double range likewise: 0x1p1024 overflows.
    BOOST_TEST(parse_number("0x1p-149", Numbers::Float32) == Q(1, Z(1) << 149));
    BOOST_CHECK_THROW(parse_number("0x1p-150", Numbers::Float32), InputError);
    BOOST_CHECK_THROW(parse_number("0x1p1024", Numbers::Double), InputError);
    BOOST_TEST(parse_number("0x0p0", Numbers::Double) == Q(0));
    // Past the limit of bits for one number, as a decimal's exponent is; a 10-digit exponent too.
    BOOST_CHECK_THROW(parse_exact("0x1p20000"), InputError);
    BOOST_CHECK_THROW(parse_exact("0x1p1234567890"), InputError);
    BOOST_CHECK_THROW(parse_number("0x1p1234567890", Numbers::Double), InputError);  // overflows
    // Zeros that say nothing: trailing ones of the fraction, leading ones of the exponent.
    BOOST_TEST(parse_exact("0x1." + std::string(5000, '0') + "p0") == Q(1));
    BOOST_TEST(parse_exact("0x1p0000000001") == Q(2));
    BOOST_TEST(parse_number("0x1p0000000001", Numbers::Double) == Q(2));
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
