// Exact numbers as the file writes them (certificates/FORMAT.md, "Numbers"): a string "p" or
// "p/q" in lowest terms, with q > 0, and beside it a `_double` that must be the nearest double
// (null exactly when that rounding overflows); points and normals of three; the vector
// arithmetic on them.
#pragma once
#include "context.hpp"
#include "json.hpp"

#include <string>
#include <vector>

namespace scalecert_check {
// An exact number: "p" or "p/q", in lowest terms, q > 0.
Q num(Context& cx, const J& j, const std::string& where);
// The same, with where() naming it only in a message (when a claim fails).
template <class Where>
Q num_at(Context& cx, const J& j, Where where);
// The double nearest to q, ties to even (GMP only); ±infinity when that rounding overflows.
double nearest(const Q& q);
// The `_double` of q: the nearest double, bit for bit (so -0 is not 0), or null exactly when the
// nearest double would be infinite (the value is beyond the double range).
bool is_nearest(const J& d, const Q& q);
// An exact field `key` of o, with its neighbour `key_double` (shape() has required both).
Q field(Context& cx, const J& o, const std::string& key, const std::string& where);
// A list `key` of n exact numbers, with its list `key_double` of their nearest doubles.
std::vector<Q> fields(Context& cx, const J& o, const std::string& key, size_t n, const std::string& where);

// A point: three exact numbers.
V3 point(Context& cx, const J& j, const std::string& where);
// A normal: three exact integers, not all 0.
V3 normal(Context& cx, const J& j, const std::string& where);

inline Q dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline V3 cross(const V3& a, const V3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline bool nonzero(const V3& v) { return sgn(v[0]) || sgn(v[1]) || sgn(v[2]); }

template <class Where>
Q num_at(Context& cx, const J& j, Where where) {
    cx.claim_lazy(j.is_string(), [&] { return where() + " is an exact number string"; });
    const std::string& s = j.get_ref<const std::string&>();
    const size_t slash = s.find('/');
    auto is_int = [&](size_t from, size_t to, bool sign) {  // s[from, to)
        const size_t b = from + ((sign && to > from && s[from] == '-') ? 1 : 0);
        if (to <= b) return false;
        for (size_t k = b; k < to; ++k)
            if (s[k] < '0' || s[k] > '9') return false;
        return to == b + 1 || s[b] != '0';
    };
    const bool ok = slash == std::string::npos ? is_int(0, s.size(), true)
                                               : is_int(0, slash, true) && is_int(slash + 1, s.size(), false);
    cx.claim_lazy(ok, [&] { return where() + " = '" + printable(s) + "' is an integer or p/q"; });
    Q q(s, 10);
    cx.claim_lazy(sgn(q.get_den()) > 0, [&] { return where() + " has a nonzero denominator"; });
    Q c = q;
    c.canonicalize();
    // The text is the canonical one: the digits are (no sign but a numerator's '-', no leading
    // zero), so it is when q was in lowest terms, a denominator is written only when it is not 1,
    // and 0 carries no sign.
    const bool lowest = c.get_num() == q.get_num() && c.get_den() == q.get_den() &&
                        (slash == std::string::npos || c.get_den() != 1) && !(sgn(c) == 0 && s[0] == '-');
    cx.claim_lazy(lowest, [&] { return where() + " = '" + printable(s) + "' is in lowest terms"; });
    return c;
}

// Integer vectors: the dot product, and a vector of integers as one.
inline mpz_class dotz(const Z3& a, const Z3& b) {
    mpz_class r;
    mpz_mul(r.get_mpz_t(), a[0].get_mpz_t(), b[0].get_mpz_t());
    mpz_addmul(r.get_mpz_t(), a[1].get_mpz_t(), b[1].get_mpz_t());
    mpz_addmul(r.get_mpz_t(), a[2].get_mpz_t(), b[2].get_mpz_t());
    return r;
}
inline Z3 ints(const V3& n) { return {n[0].get_num(), n[1].get_num(), n[2].get_num()}; }  // an integer vector
}  // namespace scalecert_check
