#include "numbers.hpp"

#include "json.hpp"

#include <cmath>

namespace scalecert_check {
Q num(Context& cx, const J& j, const std::string& where) {
    return num_at(cx, j, [&] { return where; });
}

double nearest(const Q& q) {
    if (sgn(q) == 0) return 0.0;
    mpz_class n = abs(q.get_num()), d = q.get_den(), m, r, D;
    long e =
        static_cast<long>(mpz_sizeinbase(n.get_mpz_t(), 2)) - static_cast<long>(mpz_sizeinbase(d.get_mpz_t(), 2)) - 53;
    for (int it = 0; it < 4; ++it) {
        mpz_class N = n;
        D = d;
        if (e < -1074) e = -1074;
        if (e > 2000) break;  // far beyond the double range: infinity below
        if (e < 0)
            N <<= static_cast<unsigned long>(-e);
        else
            D <<= static_cast<unsigned long>(e);
        mpz_fdiv_qr(m.get_mpz_t(), r.get_mpz_t(), N.get_mpz_t(), D.get_mpz_t());
        if (m >= (mpz_class(1) << 53)) {
            ++e;
            continue;
        }
        if (m < (mpz_class(1) << 52) && e > -1074) {
            --e;
            continue;
        }
        break;
    }
    if (e > 2000) return sgn(q) < 0 ? -HUGE_VAL : HUGE_VAL;
    int c = cmp(mpz_class(2 * r), D);
    if (c > 0 || (c == 0 && mpz_odd_p(m.get_mpz_t()))) ++m;
    double v = std::ldexp(m.get_d(), static_cast<int>(e));  // overflows to infinity past the range
    return sgn(q) < 0 ? -v : v;
}

bool is_nearest(const J& d, const Q& q) {
    const double x = nearest(q);
    if (std::isinf(x)) return d.is_null();
    if (!d.is_number()) return false;
    const double y = d.get<double>();
    return y == x && std::signbit(y) == std::signbit(x);
}

Q field(Context& cx, const J& o, const std::string& key, const std::string& where) {
    auto w = [&] { return where.empty() ? key : where + "." + key; };
    Q q = num_at(cx, o.at(key), w);
    cx.claim_lazy(is_nearest(o.at(key + "_double"), q),
                  [&] { return w() + "_double is the nearest double to " + printable(q.get_str()); });
    return q;
}

std::vector<Q> fields(Context& cx, const J& o, const std::string& key, size_t n, const std::string& where) {
    cx.claim_lazy(o.at(key).is_array() && o.at(key).size() == n,
                  [&] { return where + "." + key + " has " + std::to_string(n) + " entries"; });
    const J& dd = o.at(key + "_double");
    cx.claim_lazy(dd.is_array() && dd.size() == n,
                  [&] { return where + "." + key + "_double has " + std::to_string(n) + " entries"; });
    std::vector<Q> out;
    for (size_t i = 0; i < n; ++i) {
        auto w = [&] { return where + "." + key + "[" + std::to_string(i) + "]"; };
        out.push_back(num_at(cx, o.at(key)[i], w));
        cx.claim_lazy(is_nearest(dd[i], out.back()), [&] { return w() + "_double is the nearest double"; });
    }
    return out;
}

V3 point(Context& cx, const J& j, const std::string& where) {
    cx.claim(j.is_array() && j.size() == 3, where + " is a point of 3 coordinates");
    return {num(cx, j[0], where + "[0]"), num(cx, j[1], where + "[1]"), num(cx, j[2], where + "[2]")};
}

V3 normal(Context& cx, const J& j, const std::string& where) {
    cx.claim(j.is_array() && j.size() == 3, where + " is a normal of 3 integers");
    V3 n = point(cx, j, where);
    for (const Q& c : n) cx.claim(c.get_den() == 1, where + " has integer components");
    cx.claim(nonzero(n), where + " is nonzero");
    return n;
}
}  // namespace scalecert_check
