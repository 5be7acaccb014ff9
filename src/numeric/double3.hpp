// Three doubles, for the filters and proposals that precede exact decisions (never a decision by
// themselves).
#pragma once
#include <array>
#include <cmath>

namespace scalecert::internal {

using D3 = std::array<double, 3>;
inline D3 subd(const D3& a, const D3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline D3 negd(const D3& a) { return {-a[0], -a[1], -a[2]}; }
inline D3 crossd(const D3& a, const D3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double dotd(const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double normd(const D3& a) { return std::sqrt(dotd(a, a)); }

}  // namespace scalecert::internal
