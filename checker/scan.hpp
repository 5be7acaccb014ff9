// Support scans (certificates/FORMAT.md, "What the checker costs": support values and
// maximisers). Every support value h_i(n) and every list of maximisers is a scan of all the
// vertices of a polytope, once per normal direction: with the lists of normals a file may hold,
// the checker's largest cost. The scan compares u·X_k, X_k = D v_k, over the vertices v_k, where
// D > 0 is the lcm of the denominators of the polytope's vertex coordinates (at most 2^16384, the
// engine's own limit): this orders the vertices as u·(v_k − s_i) does. Exact in every case, in the
// cheapest arithmetic the numbers allow. The vertices whose X coordinates are all below 2^62 in
// magnitude are held as int64 only (points.hpp); with every such |X| < 2^b and an integer u with
// every |u_c| < 2^c they are scanned
//   - b + c <= 61: in int64. Each product u_c X_c is below 2^61 in magnitude, each partial sum
//     below 3·2^61 < 2^63: no overflow;
//   - b <= 62 and c <= 62: in __int128. Each product is below 2^124 in magnitude, each partial
//     sum below 3·2^124 < 2^126 < 2^127;
//   - otherwise (a normal past 2^62): in mpz.
// The other vertices (a few large numbers among many small ones cost the small ones nothing) in
// mpz, and the two maxima compared in mpz. The maximisers found are exactly those of the
// rational comparison, in ascending order (tests/checker/test_scan.cpp compares both on random scenes
// of every number kind, mixed sizes among them).
#pragma once
#include "context.hpp"
#include "points.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <memory>
#include <vector>

namespace scalecert_check {
// An integer direction u for many scans, with its int64 form (when every |u_c| < 2^62) and the
// bit length of its largest coordinate found once.
struct Direction {
    explicit Direction(const Z3& u);
    const Z3& u;
    int64_t w[3] = {0, 0, 0};
    bool small = false;
    int bits = 0;
};

// max over the vertices j in [begin, end) of w·(x_j, y_j, z_j), in int64: callers ensure the
// bounds of argmax()'s first case (the header: b + c <= 61), so nothing overflows.
inline int64_t max_dot64(const int64_t* x, const int64_t* y, const int64_t* z, size_t begin, size_t end,
                         const int64_t (&w)[3]) {
    int64_t m = w[0] * x[begin] + w[1] * y[begin] + w[2] * z[begin];
    for (size_t j = begin + 1; j < end; ++j) m = std::max(m, w[0] * x[j] + w[1] * y[j] + w[2] * z[j]);
    return m;
}
// r = v, without a temporary where long holds an int64.
inline void set64(mpz_class& r, int64_t v) {
    if constexpr (sizeof(long) >= sizeof(int64_t))
        mpz_set_si(r.get_mpz_t(), static_cast<long>(v));
    else
        r = z64(v);
}

class Scan {
  public:
    // The vertices v of one polytope (`what` names it in messages); refused as unreadable when
    // their common denominator passes 16,384 bits.
    Scan(Context& cx, const std::vector<V3>& v, const std::string& what);
    // The vertices of one polytope of integer coordinates, as the reader holds them (D = 1).
    Scan(Context& cx, IntPoints&& v);
    // Vertices v_k = X_k / D given over their least common denominator D > 0 (posed vertices);
    // refused as unreadable past 16,384 bits.
    Scan(Context& cx, std::vector<Z3>&& X, mpz_class D, const std::string& what);
    // The vertices k (of `subset`, ascending, or of all) at which u·v_k is largest, ascending.
    // u has integer coordinates.
    std::vector<int> argmax(Context& cx, const Z3& u, const std::vector<int>* subset = nullptr) const;
    // The largest u·X_k over all the vertices, in `best` (the value argmax() maximises; a
    // compound's block compares its parts' by it).
    void max_dot(Context& cx, const Direction& d, mpz_class& best) const;
    // Another polytope `base` moved by a pose, held as the base and the pose (scene.cpp,
    // posed_view): X_k = M·B_k + T over D, for B_k base's X (M = L·R, T = D·L·t, D = base's D
    // times L, L the lcm of the pose's denominators). Nothing is moved until asked: X(k) moves
    // vertex k, and argmax() asks the base along Mᵀu (u·X_k is largest where (Mᵀu)·B_k is), over
    // the base's own numbers. Refused as unreadable when D passes 16,384 bits.
    Scan(Context& cx, std::shared_ptr<const Scan> base, const Z3 (&M)[3], const Z3& T, mpz_class D,
         const std::string& what);
    const mpz_class& D() const { return D_; }
    Z3 X(size_t k) const;  // D v_k
    size_t size() const { return base_ ? base_->size() : P_.n; }
    // Whether every X coordinate is below 2^62 in magnitude; then coords(c) holds coordinate c of
    // every vertex in order, each below 2^bits(). (A moved polytope is not: its vertices are not held.)
    bool machine() const { return !base_ && P_.big.empty(); }
    const int64_t* coords(int c) const { return P_.x[c].data(); }
    int bits() const { return bits_; }

  private:
    mpz_class D_ = 1;
    std::shared_ptr<const Scan> base_;  // a moved polytope's base, M, Mᵀ and T
    Z3 M_[3], Mt_[3], T_;
    // X_k = D v_k: the vertices whose X coordinates are all below 2^62 in magnitude as int64 at
    // compact positions (P_.point_at: position -> vertex), the others (P_.big) in mpz; pos_:
    // vertex -> its position, or -1 - its place in P_.big (empty while no vertex is big: the
    // identity).
    IntPoints P_;
    std::vector<int> pos_;
    int bits_ = 0;                     // every machine |X| < 2^bits_
    double big_limbs_[3] = {0, 0, 0};  // the limbs of the others' X, by coordinate

    // pos_, bits_ and big_limbs_, once P_ holds every vertex.
    void index();
    // Appends a vertex's X, as int64 when every coordinate fits (IntPoints::kSmallBits).
    void add(Z3&& X);
    // Refuses D_ past 16,384 bits (`what` names the vertices).
    void check_limit(const std::string& what) const;
    // The limbs of X_k's coordinate c (as GMP would hold it).
    double coord_limbs(size_t k, int c) const;
    // u·X_k over the vertices of `list` (ascending) in GMP integers: the maximisers, ascending,
    // and the maximum in `best`.
    std::vector<int> mpz_scan(Context& cx, const Z3& u, const std::vector<int>& list, mpz_class& best) const;
};
}  // namespace scalecert_check
