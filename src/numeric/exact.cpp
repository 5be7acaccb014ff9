#include "numeric/exact.hpp"
#include "numeric/small_int.hpp"

#include <mpfr.h>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cerrno>
#include <cctype>
#include <cstring>
#include <algorithm>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace scalecert::internal {

Vec3z primitive(const Vec3z& v) {
    Z g = 0;
    for (const Z& c : v) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
    if (g == 0) throw std::logic_error("primitive(): zero vector");
    Vec3z r;
    for (int k = 0; k < 3; ++k) mpz_divexact(r[k].get_mpz_t(), v[k].get_mpz_t(), g.get_mpz_t());
    return r;
}

Z to_z(I128 v) {
    const bool negative = v < 0;
    unsigned __int128 u = negative ? -static_cast<unsigned __int128>(v) : static_cast<unsigned __int128>(v);
    Z r;
    mpz_set_ui(r.get_mpz_t(), static_cast<unsigned long>(u >> 64));
    mpz_mul_2exp(r.get_mpz_t(), r.get_mpz_t(), 64);
    Z lo;
    mpz_set_ui(lo.get_mpz_t(), static_cast<unsigned long>(u & ~std::uint64_t{0}));
    r += lo;
    if (negative) r = -r;
    return r;
}

bool to_i128(const Z& z, I128& out) {
    static_assert(sizeof(mp_limb_t) == 8, "64-bit limbs");
    const size_t n = mpz_size(z.get_mpz_t());
    if (n > 2) return false;
    const unsigned __int128 lo = mpz_getlimbn(z.get_mpz_t(), 0), hi = n > 1 ? mpz_getlimbn(z.get_mpz_t(), 1) : 0;
    if (hi >> 62) return false;  // 126 bits at most
    const I128 r = static_cast<I128>((hi << 64) | lo);
    out = sgn(z) < 0 ? -r : r;
    return true;
}

bool to_small_normal(const Vec3z& v, Vec3s& out) {
    for (int k = 0; k < 3; ++k) {
        if (mpz_sizeinbase(v[k].get_mpz_t(), 2) > 62) return false;
        out[k] = mpz_get_si(v[k].get_mpz_t());
    }
    return true;
}

void lcm_into(Z& acc, const Z& d) {
    if (d == 1 || acc == d) return;
    if (acc == 1) {
        acc = d;
        return;
    }
    const mpz_srcptr a = acc.get_mpz_t(), b = d.get_mpz_t();
    if (mpz_scan1(a, 0) + 1 == mpz_sizeinbase(a, 2) && mpz_scan1(b, 0) + 1 == mpz_sizeinbase(b, 2)) {
        if (mpz_sizeinbase(b, 2) > mpz_sizeinbase(a, 2)) acc = d;
        return;
    }
    mpz_lcm(acc.get_mpz_t(), a, b);
}

Z over(const Q& q, const Z& den) {
    Z z;
    mpz_divexact(z.get_mpz_t(), den.get_mpz_t(), q.get_den_mpz_t());
    z *= q.get_num();
    return z;
}

Vec3z over_common_denominator(const Vec3q& v, Z& den) {
    den = 1;
    for (const Q& c : v) lcm_into(den, c.get_den());
    return {over(v[0], den), over(v[1], den), over(v[2], den)};
}

Vec3z primitive(const Vec3q& v) {
    Z den;
    return primitive(over_common_denominator(v, den));
}

namespace {
bool all_digits(const std::string& s, size_t b, size_t e) {
    if (b >= e) return false;
    for (size_t i = b; i < e; ++i)
        if (s[i] < '0' || s[i] > '9') return false;
    return true;
}
// [+-]digits into z; false for anything else.
bool parse_integer(const std::string& s, Z& z) {
    size_t b = (!s.empty() && (s[0] == '-' || s[0] == '+')) ? 1 : 0;
    if (!all_digits(s, b, s.size())) return false;
    z = Z(s[0] == '+' ? s.substr(1) : s, 10);
    return true;
}
}  // namespace

bool hex_float_syntax(const std::string& t, HexFloat* out) {
    size_t i = 0;
    const bool negative = !t.empty() && t[0] == '-';
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    if (t.size() < i + 2 || t[i] != '0' || (t[i + 1] != 'x' && t[i + 1] != 'X')) return false;
    i += 2;
    std::string digits;
    long frac = 0;
    bool point = false;
    for (; i < t.size() && (std::isxdigit(static_cast<unsigned char>(t[i])) || (t[i] == '.' && !point)); ++i) {
        if (t[i] == '.') {
            point = true;
            continue;
        }
        digits += t[i];
        frac += point;
    }
    if (digits.empty()) return false;
    // Trailing zeros of the fraction say nothing (0x1.000p0 is 1).
    while (frac > 0 && digits.back() == '0') digits.pop_back(), --frac;
    if (digits.empty()) digits = "0";
    long exponent = 0;
    if (i < t.size() && (t[i] == 'p' || t[i] == 'P')) {
        ++i;
        const bool minus = i < t.size() && t[i] == '-';
        if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
        if (i == t.size() || !all_digits(t, i, t.size())) return false;
        while (i + 1 < t.size() && t[i] == '0') ++i;  // leading zeros
        // An exponent of more than 9 digits passes every limit (2^(10^9)): taken as 10^10, which
        // the exact reading refuses as too large and strtod reads as an overflow or 0.
        exponent = t.size() - i > 9 ? 10000000000L : std::stol(t.substr(i));
        if (minus) exponent = -exponent;
        i = t.size();
    }
    if (i != t.size()) return false;
    if (out) {
        out->negative = negative;
        out->mant = Z(digits, 16);
        out->exp2 = exponent - 4 * frac;
    }
    return true;
}

std::string in_quotes(const std::string& text) {
    constexpr size_t kShown = 40;
    std::string out = "'";
    for (size_t i = 0; i < text.size() && i < kShown; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '\\')
            out += "\\\\";
        else if (c == '\'')
            out += "\\'";
        else if (c < 0x20 || c == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", c);
            out += buf;
        } else
            out += static_cast<char>(c);
    }
    out += "'";
    if (text.size() > kShown) out += " (" + std::to_string(text.size()) + " characters, cut)";
    return out;
}

Q parse_exact(const std::string& text) {
    // Plain integers of up to 18 digits (most coordinates): no detour through strings.
    if (!text.empty() && text.size() <= 19) {
        size_t b = text[0] == '-' || text[0] == '+' ? 1 : 0;
        if (text.size() - b >= 1 && text.size() - b <= 18 && all_digits(text, b, text.size())) {
            long v = 0;
            for (size_t i = b; i < text.size(); ++i) v = v * 10 + (text[i] - '0');
            Q r;
            mpq_set_si(r.get_mpq_t(), text[0] == '-' ? -v : v, 1);
            return r;
        }
    }
    auto bad = [&text] {
        return InputError(in_quotes(text) +
                          " is not an exact number (a decimal such as -1.5e-3, a hex float such as 0x1.8p-3, or a "
                          "fraction p/q)");
    };
    auto sized = [&text](Q r) {
        if (mpz_sizeinbase(r.get_num_mpz_t(), 2) > kMaxNumberBits ||
            mpz_sizeinbase(r.get_den_mpz_t(), 2) > kMaxNumberBits)
            throw InputError(in_quotes(text) + " has more than " + std::to_string(kMaxNumberBits) +
                             " bits in its numerator or denominator (the limit for one number)");
        return r;
    };
    if (text.size() > kMaxNumberChars)
        throw InputError(in_quotes(text) + " is longer than " + std::to_string(kMaxNumberChars) +
                         " characters, the limit for one number");
    if (text.empty()) throw bad();
    size_t slash = text.find('/');
    if (slash != std::string::npos) {
        Z p, q;
        if (!parse_integer(text.substr(0, slash), p)) throw bad();
        std::string ds = text.substr(slash + 1);
        if (ds.empty() || ds[0] == '-' || ds[0] == '+') throw bad();
        if (!parse_integer(ds, q)) throw bad();
        if (q == 0) throw InputError(in_quotes(text) + " has a zero denominator");
        Q r(p, q);
        r.canonicalize();
        return sized(std::move(r));
    }
    if (HexFloat h; hex_float_syntax(text, &h)) {
        // mant·2^exp2: the exponent is refused where its power alone passes the limit of bits.
        if (h.exp2 > static_cast<long>(kMaxNumberBits) + 64 || h.exp2 < -static_cast<long>(kMaxNumberBits) - 64)
            throw InputError(in_quotes(text) + " has an exponent too large to read exactly");
        Q r(h.mant);
        if (h.exp2 >= 0)
            mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(h.exp2));
        else
            mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(-h.exp2));
        return sized(h.negative ? Q(-r) : r);
    }
    size_t i = 0;
    bool negative = false;
    if (text[i] == '+' || text[i] == '-') negative = text[i++] == '-';
    size_t int_b = i;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
    std::string digits = text.substr(int_b, i - int_b);
    long frac_len = 0;
    if (i < text.size() && text[i] == '.') {
        size_t fb = ++i;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
        digits += text.substr(fb, i - fb);
        frac_len = static_cast<long>(i - fb);
    }
    if (digits.empty()) throw bad();
    long exponent = 0;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        size_t eb = i;
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
        if (!all_digits(text, i, text.size())) throw bad();
        if (text.size() - i > 6) throw InputError(in_quotes(text) + " has an exponent too large to read exactly");
        exponent = std::stol(text.substr(eb));
        i = text.size();
    }
    if (i != text.size()) throw bad();
    long e = exponent - frac_len;
    if (e > 100000 || e < -100000) throw InputError(in_quotes(text) + " has an exponent too large to read exactly");
    Z m(digits, 10);
    Z p10;
    mpz_ui_pow_ui(p10.get_mpz_t(), 10, static_cast<unsigned long>(e < 0 ? -e : e));
    Q r = e >= 0 ? Q(m * p10) : Q(m, p10);
    r.canonicalize();
    return sized(negative ? Q(-r) : r);
}

Q exact_from_double(double d) {
    if (!std::isfinite(d))
        throw InputError(
            "value is not finite as a double (beyond the double range: written as a string, \"1e400\", it is read "
            "exactly)");
    Q r;
    mpq_set_d(r.get_mpq_t(), d);
    return r;
}

namespace {
// Whether text is a decimal as parse_exact reads one: [+-] digits [. digits] [e|E [+-] digits],
// with at least one digit before the exponent. strtod reads more ("inf", "nan", leading spaces);
// a program's number is read one way only, so those are refused. Hex floats are hex_float_syntax's.
bool decimal_syntax(const std::string& t) {
    size_t i = 0, digits = 0;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    for (; i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])); ++i) ++digits;
    if (i < t.size() && t[i] == '.')
        for (++i; i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])); ++i) ++digits;
    if (digits == 0) return false;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
        ++i;
        if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
        const size_t b = i;
        while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i;
        if (i == b) return false;
    }
    return i == t.size();
}
}  // namespace

Q parse_number(const std::string& text, Numbers numbers) {
    if (numbers == Numbers::Exact || text.find('/') != std::string::npos) return parse_exact(text);
    if (text.size() > kMaxNumberChars)
        throw InputError(in_quotes(text) + " is longer than " + std::to_string(kMaxNumberChars) +
                         " characters, the limit for one number");
    HexFloat hex;
    const bool is_hex = hex_float_syntax(text, &hex);
    if (!is_hex && !decimal_syntax(text))
        throw InputError(in_quotes(text) +
                         " is not a number (a decimal such as -1.5e-3, a hex float such as 0x1.8p-3, or a fraction "
                         "p/q)");
    const bool single = numbers == Numbers::Float32;
    const char* what = single ? "float32" : "double";
    // strtof rounds the decimal (or the hex float) once, as a float32 program's parser does (not
    // through a double); a hex float with more bits than the format holds is rounded likewise.
    const double d =
        single ? static_cast<double>(std::strtof(text.c_str(), nullptr)) : std::strtod(text.c_str(), nullptr);
    if (!std::isfinite(d))
        throw InputError(in_quotes(text) + " is beyond the " + what + " range (as a " + what +
                         " it overflows): give its exact value as a fraction, or a JSON string");
    // A nonzero decimal that is 0 in binary was never a number a program held.
    if (d == 0 && (is_hex ? sgn(hex.mant) != 0 : text.find_first_of("123456789") < text.find_first_of("eE")))
        throw InputError(in_quotes(text) + " is 0 as a " + what +
                         " (it underflows): give its exact value as a fraction, or a JSON string");
    return exact_from_double(d);
}

const char* numbers_name(Numbers n) {
    return n == Numbers::Double ? "double" : n == Numbers::Float32 ? "float32" : "exact";
}

Q parse_number(const std::string& text, Numbers numbers, long* inexact) {
    Q q = parse_number(text, numbers);
    // Fractions, and integers of at most 7 characters (below 2^24: floats and doubles exactly), are
    // read as written; the rest are compared with the text's exact value.
    if (inexact && numbers != Numbers::Exact && text.find('/') == std::string::npos &&
        !(text.size() <= 7 && text.find_first_of(".eE") == std::string::npos) && q != parse_exact(text))
        ++*inexact;
    return q;
}

bool binary_is_exact(const std::string& text, Numbers numbers) {
    long inexact = 0;
    parse_number(text, numbers, &inexact);
    return inexact == 0;
}

std::string to_shortest(double d) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, d);
    return std::string(buf, r.ptr);
}

std::string to_exact_string(const Q& q) {
    Q c = q;
    c.canonicalize();
    return c.get_str(10);  // GMP prints "p" when q = 1 and "p/q" otherwise, q > 0
}

double to_double_rn(const Q& q) {
    mpfr_t x;
    mpfr_init2(x, 53);
    mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
    mpfr_set_emin(-1073);  // IEEE binary64 range, so subnormals round as in hardware
    mpfr_set_emax(1024);
    int t = mpfr_set_q(x, q.get_mpq_t(), MPFR_RNDN);
    t = mpfr_check_range(x, t, MPFR_RNDN);
    mpfr_subnormalize(x, t, MPFR_RNDN);
    double d = mpfr_get_d(x, MPFR_RNDN);
    mpfr_clear(x);
    mpfr_set_emin(emin);
    mpfr_set_emax(emax);
    return d;
}

}  // namespace scalecert::internal
