#include "judging.hpp"

#include "numbers.hpp"

#include <algorithm>
#include <cstdio>

namespace scalecert_check {
bool Rules::close(Context& cx, const Q& c, const Q& e) const {
    cx.spend_ops(3, qsize(c) + qsize(e) + qsize(tol));
    return abs(c - e) <= tol * abs(e);
}
bool Rules::close_sq(Context& cx, const Q& c, const Q& E) const {
    cx.spend_ops(8, 2 * qsize(c) + qsize(E) + 2 * qsize(tol));
    if (sgn(c) < 0) return false;
    const Q lo = 1 - tol, hi = 1 + tol;
    return (sgn(lo) <= 0 || lo * lo * E <= c * c) && c * c <= hi * hi * E;
}
bool Rules::within_above(Context& cx, const Q& x, const Q& E) const {
    cx.spend_ops(5, qsize(x) + qsize(E) + 2 * qsize(tol));
    return E <= x && x <= (1 + tol) * (1 + tol) * E;
}

std::string tolerance_shown(const Q& tol) {
    const std::string t = tol.get_str();
    if (t.size() <= 40) return t;
    char b[64];
    std::snprintf(b, sizeof b, "%.6g", nearest(tol));
    return std::string("~") + b + " (an exact fraction of " + std::to_string(t.size()) + " characters)";
}

double vsize(const V3& v) { return std::max({qsize(v[0]), qsize(v[1]), qsize(v[2])}); }

V3 integral(const V3& n, mpz_class* scale) {
    mpz_class L = 1;
    for (const Q& c : n) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), c.get_den_mpz_t());
    *scale = L;
    return {n[0] * L, n[1] * L, n[2] * L};
}

Q positive(Context& cx, const J& o, const char* key, const std::string& where) {
    const Q q = num(cx, at(o, key), where + "." + key);
    cx.claim(sgn(q) > 0, where + "." + key + " is > 0");
    return q;
}

V3 nonzero_vector(Context& cx, const J& j, const std::string& where) {
    const V3 n = point(cx, j, where);
    cx.claim(nonzero(n), where + " is nonzero");
    return n;
}
}  // namespace scalecert_check
