// Machine integers for scenes whose integer-scaled coordinates are small: the same exact
// arithmetic as the GMP layer, without allocation. Every function here states the bound that
// keeps it exact; callers take this path only when their data satisfy it (Polyhedron::small()),
// and the GMP path otherwise. Both give identical results (tests/test_geometry.cpp checks it).
#pragma once
#include "numeric/exact.hpp"

#include <cstdint>
#include <cstdlib>
#include <numeric>

namespace scalecert::internal {

using I128 = __int128;
using Vec3s = std::array<std::int64_t, 3>;

// Coordinates with |x| ≤ kSmallCoord: differences < 2^30, cross products of differences < 2^61
// in each component, and dot products of such normals with points < 2^92.
constexpr std::int64_t kSmallCoord = std::int64_t{1} << 29;

inline bool fits_small(const Z& z) { return mpz_sizeinbase(z.get_mpz_t(), 2) <= 29; }
inline Z to_z(std::int64_t v) {
    Z r;
    mpz_set_si(r.get_mpz_t(), static_cast<long>(v));
    return r;
}
inline Vec3z to_z(const Vec3s& v) { return {to_z(v[0]), to_z(v[1]), to_z(v[2])}; }
Z to_z(I128 v);
// v as an int64 triple if every component fits in 62 bits (so that dot products with small
// points stay below 2^93).
bool to_small_normal(const Vec3z& v, Vec3s& out);

inline Vec3s sub_s(const Vec3s& a, const Vec3s& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
// Exact for |a|, |b| < 2^31 per component.
inline Vec3s cross_s(const Vec3s& a, const Vec3s& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// Exact for |a|, |b| < 2^62 per component.
inline I128 dot_s(const Vec3s& a, const Vec3s& b) { return I128(a[0]) * b[0] + I128(a[1]) * b[1] + I128(a[2]) * b[2]; }
// Component k of a × b, exact for |a|, |b| < 2^62.
inline I128 cross_k(const Vec3s& a, const Vec3s& b, int k) {
    int i = (k + 1) % 3, j = (k + 2) % 3;
    return I128(a[i]) * b[j] - I128(a[j]) * b[i];
}
inline Vec3s neg_s(const Vec3s& v) { return {-v[0], -v[1], -v[2]}; }
inline bool is_zero(const Vec3s& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }
inline int sgn128(I128 v) { return (v > 0) - (v < 0); }
// The primitive vector of v != 0 (|v| < 2^63).
inline Vec3s primitive(const Vec3s& v) {
    std::int64_t g = std::gcd(std::gcd(std::llabs(v[0]), std::llabs(v[1])), std::llabs(v[2]));
    if (g == 0) throw std::logic_error("primitive(): zero vector");
    return {v[0] / g, v[1] / g, v[2] / g};
}

// a·b + c·d style expressions on 128 bits with overflow detection: false on overflow.
inline bool mul_ok(I128 a, I128 b, I128& r) { return !__builtin_mul_overflow(a, b, &r); }
inline bool add_ok(I128 a, I128 b, I128& r) { return !__builtin_add_overflow(a, b, &r); }
inline bool sub_ok(I128 a, I128 b, I128& r) { return !__builtin_sub_overflow(a, b, &r); }
// z as a 128-bit integer if it fits in 126 bits.
bool to_i128(const Z& z, I128& out);

// The same operations on either kind of integer vector, for code written once for both (the
// machine-integer overloads keep the bounds stated above).
inline Vec3s vsub(const Vec3s& a, const Vec3s& b) { return sub_s(a, b); }
inline Vec3z vsub(const Vec3z& a, const Vec3z& b) { return sub(a, b); }
inline Vec3s vcross(const Vec3s& a, const Vec3s& b) { return cross_s(a, b); }
inline Vec3z vcross(const Vec3z& a, const Vec3z& b) { return cross(a, b); }
inline I128 vdot(const Vec3s& a, const Vec3s& b) { return dot_s(a, b); }
inline Z vdot(const Vec3z& a, const Vec3z& b) { return dotz(a, b); }
inline Vec3s vneg(const Vec3s& v) { return neg_s(v); }
inline Vec3z vneg(const Vec3z& v) { return neg(v); }
inline int sign_of(I128 v) { return sgn128(v); }
inline int sign_of(const Z& v) { return sgn(v); }
inline int sign_of(std::int64_t v) { return (v > 0) - (v < 0); }
inline std::int64_t mag(std::int64_t v) { return v < 0 ? -v : v; }
inline Z mag(const Z& v) { return abs(v); }
inline Vec3z as_z(const Vec3s& v) { return to_z(v); }
inline const Vec3z& as_z(const Vec3z& v) { return v; }
// ... and on rational vectors (exact, any size).
inline Vec3q vsub(const Vec3q& a, const Vec3q& b) { return sub(a, b); }
inline Vec3q vcross(const Vec3q& a, const Vec3q& b) { return cross(a, b); }
inline Q vdot(const Vec3q& a, const Vec3q& b) { return dot(a, b); }
inline bool is_zero(const Vec3q& v) { return sgn(v[0]) == 0 && sgn(v[1]) == 0 && sgn(v[2]) == 0; }
inline int sign_of(const Q& v) { return sgn(v); }

// Whether the points span 3 dimensions (four of them affinely independent), exactly.
template <class V>
bool affinely_3d(const std::vector<V>& pts) {
    size_t i1 = 0, i2 = 0;
    for (i1 = 1; i1 < pts.size() && pts[i1] == pts[0]; ++i1) {}
    if (i1 >= pts.size()) return false;
    const V e1 = vsub(pts[i1], pts[0]);
    V c;
    for (i2 = i1 + 1; i2 < pts.size(); ++i2) {
        c = vcross(e1, vsub(pts[i2], pts[0]));
        if (!is_zero(c)) break;
    }
    if (i2 >= pts.size()) return false;
    for (size_t i3 = i2 + 1; i3 < pts.size(); ++i3)
        if (sign_of(vdot(c, vsub(pts[i3], pts[0])))) return true;
    return false;
}

}  // namespace scalecert::internal
