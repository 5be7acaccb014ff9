// Exact number layer: rationals (GMP), integer vectors, exact parsing and display rounding.
#pragma once
#include "scalecert/limits.hpp"
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
inline bool is_zero(const Vec3z& v) { return sgn(v[0]) == 0 && sgn(v[1]) == 0 && sgn(v[2]) == 0; }
inline Vec3q to_q(const Vec3z& v) { return {Q(v[0]), Q(v[1]), Q(v[2])}; }
inline Vec3z neg(const Vec3z& v) { return {Z(-v[0]), Z(-v[1]), Z(-v[2])}; }

// The primitive integer vector with the direction of v (v != 0): common denominators cleared,
// common factor removed. Two normals are the same direction iff their primitive forms are equal.
Vec3z primitive(const Vec3q& v);
Vec3z primitive(const Vec3z& v);
// v over its common denominator: v = z / den, den > 0 the lcm of the coordinates' denominators.
Vec3z over_common_denominator(const Vec3q& v, Z& den);

// User text for an error message: quoted, control characters escaped (so the message stays one
// line), and cut after 40 characters.
std::string quoted(const std::string& text);

// Every file scalecert reads is opened here. open_regular_file opens `path` with O_RDONLY |
// O_NONBLOCK | O_CLOEXEC (and O_NOFOLLOW when no_follow): the open never blocks (a FIFO with no
// writer, a terminal) and the descriptor is not inherited. Anything but a regular file (a FIFO,
// socket, device or directory; with no_follow, a symbolic link) is refused, before it is opened
// when its name already says so. Throws InputError "PATH: problem" (one line; `what` names the
// file's role, "scene file"). Returns the descriptor, blocking again, and its size in *size.
int open_regular_file(const std::string& path, const std::string& what, bool no_follow = false, size_t* size = nullptr);
// The whole of a regular file (open_regular_file), at most max_bytes, else InputError naming the limit.
std::string read_regular_file(const std::string& path, const std::string& what, size_t max_bytes, bool no_follow = false);
// read_regular_file, or standard input for "-" (where a command documents it).
std::string read_input(const std::string& path, const std::string& what, size_t max_bytes);

// While an InputObserver lives, every file read_input and read_regular_file read on this thread
// is passed to it, with the path as given: campaigns hash the bytes an audit actually read.
class InputObserver {
public:
    using Fn = std::function<void(const std::string& path, const std::string& bytes)>;
    explicit InputObserver(Fn f);
    ~InputObserver();
    InputObserver(const InputObserver&) = delete;
    InputObserver& operator=(const InputObserver&) = delete;

private:
    Fn f_;
    const Fn* prev_;
};

// Reads a number exactly as written: "-12", "0.1" (= 1/10), "1e-3", "2.5E+7", "3/7".
// Throws InputError (without location; callers add it) when the text is not such a number.
Q parse_exact(const std::string& text);
// The double's exact value (every finite double is a dyadic rational).
Q exact_from_double(double d);
// Number text read exactly (parse_exact), or with binary_doubles as the double strtod gives (its
// exact value). Throws InputError (without location) for text that is neither.
Q parse_number(const std::string& text, bool binary_doubles);

// "p/q" in lowest terms with q > 0, or "p" when q = 1.
std::string to_exact_string(const Q& q);
// The double nearest to q (round-to-nearest-even), computed with MPFR.
double to_double_rn(const Q& q);

}  // namespace scalecert::internal
