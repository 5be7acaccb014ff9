// Exact number layer: rationals (GMP), integer vectors, exact parsing and display rounding.
#pragma once
#include "numeric/limits.hpp"
#include "scalecert/scalecert.hpp"

#include <gmpxx.h>
#include <array>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace scalecert::internal {

using Q = mpq_class;
using Z = mpz_class;
using Vec3q = std::array<Q, 3>;
using Vec3z = std::array<Z, 3>;

// Any problem with the user's input (the public scalecert::InputError): one line, exit status 2.
using scalecert::InputError;
using scalecert::Numbers;

template <class A, class B>
inline auto dot(const std::array<A, 3>& a, const std::array<B, 3>& b) {
    return Q(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}
inline Z dotz(const Vec3z& a, const Vec3z& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
template <class T>
inline std::array<T, 3> sub(const std::array<T, 3>& a, const std::array<T, 3>& b) {
    return {T(a[0] - b[0]), T(a[1] - b[1]), T(a[2] - b[2])};
}
template <class T>
inline std::array<T, 3> cross(const std::array<T, 3>& a, const std::array<T, 3>& b) {
    return {T(a[1] * b[2] - a[2] * b[1]), T(a[2] * b[0] - a[0] * b[2]), T(a[0] * b[1] - a[1] * b[0])};
}
// s + ρ(x − s): the point x scaled by ρ about s.
inline Vec3q scaled_about(const Vec3q& s, const Q& rho, const Vec3q& x) {
    return {s[0] + rho * (x[0] - s[0]), s[1] + rho * (x[1] - s[1]), s[2] + rho * (x[2] - s[2])};
}
inline bool is_zero(const Vec3z& v) { return sgn(v[0]) == 0 && sgn(v[1]) == 0 && sgn(v[2]) == 0; }
inline Vec3q to_q(const Vec3z& v) { return {Q(v[0]), Q(v[1]), Q(v[2])}; }
inline Vec3z neg(const Vec3z& v) { return {Z(-v[0]), Z(-v[1]), Z(-v[2])}; }

// The primitive integer vector with the direction of v (v != 0): common denominators cleared,
// common factor removed. Two normals are the same direction iff their primitive forms are equal.
Vec3z primitive(const Vec3q& v);
Vec3z primitive(const Vec3z& v);
// v over its common denominator: v = z / den, den > 0 the lcm of the coordinates' denominators.
Vec3z over_common_denominator(const Vec3q& v, Z& den);
// acc = lcm(acc, d) for d > 0, without a gcd where d is 1, acc is 1 or d, or both are powers of
// two (the denominators of doubles).
void lcm_into(Z& acc, const Z& d);
// The numerator of q over a multiple den of its denominator: q·den, an integer, by exact division.
Z over(const Q& q, const Z& den);

// User text for an error message: quoted, control characters escaped (so the message stays one
// line), and cut after 40 characters.
std::string in_quotes(const std::string& text);

// A C99 hexadecimal float as strtod reads it and printf's %a writes it: [+-] 0x|0X, hex digits
// with at most one point (at least one digit), an optional binary exponent p|P [+-] digits. Its
// value is ±mant·2^exp2, filled in *out when given (an exponent past 9 digits as ±10^10).
struct HexFloat {
    bool negative = false;
    Z mant;
    long exp2 = 0;
};
bool hex_float_syntax(const std::string& text, HexFloat* out = nullptr);

// Reads a number exactly as written: "-12", "0.1" (= 1/10), "1e-3", "2.5E+7", "3/7", "0x1.8p-3"
// (= 3/16).
// Throws InputError (without location; callers add it) when the text is not such a number.
Q parse_exact(const std::string& text);
// The double's exact value (every finite double is a dyadic rational).
Q exact_from_double(double d);
// Number text as `numbers` reads it (the public Numbers): exactly (parse_exact), or as the double
// strtod or the float strtof gives (its exact value); a fraction p/q is exact always. Throws
// InputError (without location) for text that is no number, and for a nonzero decimal that
// overflows or underflows to 0 in that binary format.
Q parse_number(const std::string& text, Numbers numbers);
// "double", "float32", "exact" (the --numbers words).
const char* numbers_name(Numbers numbers);
// Whether parse_number(text, numbers) is the number as written (text a number parse_number reads).
bool binary_is_exact(const std::string& text, Numbers numbers);
// parse_number, counting in *inexact (when given) a number that is not the number as written.
Q parse_number(const std::string& text, Numbers numbers, long* inexact);

// The shortest decimal that strtod reads back as d (d finite): "0.1", "1e+300".
std::string to_shortest(double d);
// "p/q" in lowest terms with q > 0, or "p" when q = 1.
std::string to_exact_string(const Q& q);
// The double nearest to q (round-to-nearest-even), computed with MPFR.
double to_double_rn(const Q& q);

}  // namespace scalecert::internal
