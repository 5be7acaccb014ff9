#include "scan.hpp"

#include <algorithm>
#include <iterator>

namespace scalecert_check {
namespace {
// z as an int64 when |z| < 2^62 (and long holds it); false otherwise.
bool small_int(mpz_srcptr z, int64_t& out) {
    if (mpz_sizeinbase(z, 2) > IntPoints::kSmallBits || !mpz_fits_slong_p(z)) return false;
    out = mpz_get_si(z);
    return true;
}
mpz_class from128(__int128 v) {
    const bool neg = v < 0;
    unsigned __int128 a = neg ? -static_cast<unsigned __int128>(v) : static_cast<unsigned __int128>(v);
    mpz_class r(static_cast<unsigned long>(static_cast<uint64_t>(a >> 64)));
    r <<= 64;
    r += static_cast<unsigned long>(static_cast<uint64_t>(a));
    return neg ? mpz_class(-r) : r;
}
// r = a·x for an int64 x.
void mul64(mpz_ptr r, mpz_srcptr a, int64_t x) {
    if constexpr (sizeof(long) >= sizeof(int64_t)) {
        mpz_mul_si(r, a, static_cast<long>(x));
    } else {
        const mpz_class z = z64(x);
        mpz_mul(r, a, z.get_mpz_t());
    }
}
// All vertices, in one pass: the running maximum in a register, the list touched only when a
// vertex reaches it (rarely, once the maximum is found). Returns the maximum.
template <class T, class F>
T scan(size_t n, F value, std::vector<int>& out) {
    out.reserve(8);
    out.push_back(0);
    T best = value(0);
    for (size_t k = 1; k < n; ++k) {
        const T v = value(k);
        if (__builtin_expect(v >= best, 0)) {
            if (v > best) {
                best = v;
                out.clear();
            }
            out.push_back(static_cast<int>(k));
        }
    }
    return best;
}
// The positions of a list (ascending), in one pass.
template <class T, class F>
T scan(size_t n, const int* at, F value, std::vector<int>& out) {
    T best{};
    for (size_t j = 0; j < n; ++j) {
        const size_t k = static_cast<size_t>(at[j]);
        const T v = value(k);
        if (out.empty() || v >= best) {
            if (out.empty() || v > best) {
                best = v;
                out.clear();
            }
            out.push_back(static_cast<int>(k));
        }
    }
    return best;
}
}  // namespace

void Scan::check_limit(const std::string& what) const {
    if (mpz_sizeinbase(D_.get_mpz_t(), 2) > 16384)
        throw Unreadable{"the common denominator of " + what +
                         "'s vertex coordinates has more than 16384 bits (scalecert's own limit)"};
}

void Scan::add(Z3&& X) {
    int64_t x[3] = {0, 0, 0};
    bool small = true;
    for (int c = 0; c < 3; ++c) small = small_int(X[c].get_mpz_t(), x[c]) && small;
    if (small)
        P_.add_small(x);
    else
        P_.add_big(std::move(X));
}

Scan::Scan(Context& cx, const std::vector<V3>& v, const std::string& what) {
    for (const V3& p : v)
        for (const Q& c : p) {
            if (mpz_cmp_ui(c.get_den_mpz_t(), 1) != 0) mpz_lcm(D_.get_mpz_t(), D_.get_mpz_t(), c.get_den_mpz_t());
            check_limit(what);
        }
    cx.spend(static_cast<double>(v.size()) * (10 + 3 * limbs(D_)));
    for (auto& c : P_.x) c.reserve(v.size());
    for (const V3& p : v) {
        Z3 X;
        for (int c = 0; c < 3; ++c) {
            mpz_divexact(X[c].get_mpz_t(), D_.get_mpz_t(), p[c].get_den_mpz_t());
            X[c] *= p[c].get_num();
        }
        add(std::move(X));
    }
    index();
}

Scan::Scan(Context& cx, std::vector<Z3>&& X, mpz_class D, const std::string& what) : D_(std::move(D)) {
    check_limit(what);
    cx.spend(static_cast<double>(X.size()) * (10 + 3 * limbs(D_)));
    for (auto& c : P_.x) c.reserve(X.size());
    for (Z3& p : X) add(std::move(p));
    index();
}

// Integers: D = 1 and X_k = v_k, counted as the rational constructor counts them.
Scan::Scan(Context& cx, IntPoints&& v) : P_(std::move(v)) {
    cx.spend(static_cast<double>(P_.n) * (10 + 3 * limbs(D_)));
    index();
}

void Scan::index() {
    if (!P_.big.empty()) {
        pos_.assign(P_.n, 0);
        for (size_t p = 0; p < P_.small(); ++p) pos_[static_cast<size_t>(P_.orig[p])] = static_cast<int>(p);
        for (size_t b = 0; b < P_.big.size(); ++b) {
            pos_[static_cast<size_t>(P_.big[b])] = -1 - static_cast<int>(b);
            for (int c = 0; c < 3; ++c) big_limbs_[c] += limbs(P_.big_x[b][c]);
        }
    }
    // bits_: the bit length of the largest |X| (that of 0 taken as 1, as GMP's mpz_sizeinbase
    // gives): the highest bit set in the OR of all magnitudes. Each |X| < 2^62: no overflow.
    if (P_.small() == 0) return;
    uint64_t any = 0;
    for (const auto& xs : P_.x)
        for (const int64_t c : xs) any |= static_cast<uint64_t>(c < 0 ? -c : c);
    bits_ = any ? 64 - __builtin_clzll(any) : 1;
}

Z3 Scan::X(size_t k) const {
    if (base_) {
        const Z3 B = base_->X(k);
        Z3 y = T_;
        for (size_t r = 0; r < 3; ++r)
            for (size_t c = 0; c < 3; ++c) mpz_addmul(y[r].get_mpz_t(), M_[r][c].get_mpz_t(), B[c].get_mpz_t());
        return y;
    }
    const int p = pos_.empty() ? static_cast<int>(k) : pos_[k];
    if (p < 0) return P_.big_x[static_cast<size_t>(-1 - p)];
    const size_t q = static_cast<size_t>(p);
    return {z64(P_.x[0][q]), z64(P_.x[1][q]), z64(P_.x[2][q])};
}

double Scan::coord_limbs(size_t k, int c) const {
    const int p = pos_.empty() ? static_cast<int>(k) : pos_[k];
    if (p < 0) return limbs(P_.big_x[static_cast<size_t>(-1 - p)][c]);
    return P_.x[c][static_cast<size_t>(p)] != 0 ? 1 : 0;  // |X| < 2^62: one limb, none for 0
}

Scan::Scan(Context& cx, std::shared_ptr<const Scan> base, const Z3 (&M)[3], const Z3& T, mpz_class D,
           const std::string& what)
    : D_(std::move(D)), base_(std::move(base)), T_(T) {
    check_limit(what);
    cx.spend(100);
    for (size_t r = 0; r < 3; ++r)
        for (size_t c = 0; c < 3; ++c) M_[r][c] = M[r][c], Mt_[c][r] = M[r][c];
}

std::vector<int> Scan::argmax(Context& cx, const Z3& u, const std::vector<int>* subset) const {
    if (base_) {  // the base's maximisers along Mᵀu: nine products, counted as any
        Z3 w;
        double l = 0;
        for (size_t c = 0; c < 3; ++c) {
            for (size_t r = 0; r < 3; ++r) l += (1 + limbs(Mt_[c][r])) * (1 + limbs(u[r]));
            w[c] = Mt_[c][0] * u[0] + Mt_[c][1] * u[1] + Mt_[c][2] * u[2];
        }
        cx.spend(50 + 4 * l);
        return base_->argmax(cx, w, subset);
    }
    int ub = 0;
    for (const mpz_class& c : u) ub = std::max(ub, static_cast<int>(mpz_sizeinbase(c.get_mpz_t(), 2)));
    int64_t w[3] = {0, 0, 0};
    const bool small_u =
        small_int(u[0].get_mpz_t(), w[0]) && small_int(u[1].get_mpz_t(), w[1]) && small_int(u[2].get_mpz_t(), w[2]);
    // The machine-size vertices (at compact positions) and the others.
    std::vector<int> mlist, blist;
    const bool all = !subset;
    if (subset)
        for (int k : *subset) {
            const int p = pos_.empty() ? k : pos_[static_cast<size_t>(k)];
            (p >= 0 ? mlist.push_back(p) : blist.push_back(k));
        }
    const std::vector<int>& bl = all ? P_.big : blist;
    const size_t nm = all ? P_.small() : mlist.size();
    std::vector<int> mout, bout;
    mpz_class mbest, bbest;
    if (nm > 0) {
        const int* at = all ? nullptr : mlist.data();
        const int64_t *x = P_.x[0].data(), *y = P_.x[1].data(), *z = P_.x[2].data();
        if (small_u && bits_ + ub <= 61) {
            cx.spend(static_cast<double>(nm));
            const int64_t a = w[0], b = w[1], c = w[2];
            auto value = [=](size_t k) { return a * x[k] + b * y[k] + c * z[k]; };
            const int64_t best = at ? scan<int64_t>(nm, at, value, mout) : scan<int64_t>(nm, value, mout);
            if (all && bl.empty()) return mout;  // every vertex is at its own position
            mbest = z64(best);
        } else if (small_u) {
            cx.spend(2.0 * static_cast<double>(nm));
            const __int128 a = w[0], b = w[1], c = w[2];
            auto value = [=](size_t k) { return a * x[k] + b * y[k] + c * z[k]; };
            const __int128 best = at ? scan<__int128>(nm, at, value, mout) : scan<__int128>(nm, value, mout);
            if (all && bl.empty()) return mout;
            mbest = from128(best);
        }
        if (small_u) {
            for (int& p : mout) p = P_.point_at(static_cast<size_t>(p));
        } else {  // a normal past 2^62: GMP integers for these vertices too
            std::vector<int> list;
            list.reserve(nm);
            for (size_t j = 0; j < nm; ++j) list.push_back(P_.point_at(all ? j : static_cast<size_t>(mlist[j])));
            mout = mpz_scan(cx, u, list, mbest);
        }
    }
    if (!bl.empty()) bout = mpz_scan(cx, u, bl, bbest);
    if (bout.empty()) return mout;
    if (mout.empty()) return bout;
    const int c = cmp(mbest, bbest);
    if (c != 0) return c > 0 ? mout : bout;
    std::vector<int> both;  // equal maxima: the two ascending lists merged
    std::merge(mout.begin(), mout.end(), bout.begin(), bout.end(), std::back_inserter(both));
    return both;
}

Direction::Direction(const Z3& v) : u(v) {
    small = small_int(u[0].get_mpz_t(), w[0]) && small_int(u[1].get_mpz_t(), w[1]) && small_int(u[2].get_mpz_t(), w[2]);
    for (const mpz_class& c : u) bits = std::max(bits, static_cast<int>(mpz_sizeinbase(c.get_mpz_t(), 2)));
}

void Scan::max_dot(Context& cx, const Direction& d, mpz_class& best) const {
    if (machine() && d.small) {
        // Machine vertices and a machine normal: the bounds of argmax() (the header) in one pass.
        const size_t n = P_.small();
        const int64_t *x = P_.x[0].data(), *y = P_.x[1].data(), *z = P_.x[2].data();
        if (bits_ + d.bits <= 61) {
            cx.spend(static_cast<double>(n));
            set64(best, max_dot64(x, y, z, 0, n, d.w));
            return;
        }
        cx.spend(2.0 * static_cast<double>(n));
        const __int128 a = d.w[0], b = d.w[1], c = d.w[2];
        __int128 m = a * x[0] + b * y[0] + c * z[0];
        for (size_t k = 1; k < n; ++k) m = std::max(m, a * x[k] + b * y[k] + c * z[k]);
        best = from128(m);
        return;
    }
    const Z3 X = this->X(static_cast<size_t>(argmax(cx, d.u)[0]));
    double l = 0;
    for (int c = 0; c < 3; ++c) l += (1 + limbs(d.u[c])) * (1 + limbs(X[c]));
    cx.spend(20 + 4 * l);
    best = dotz(d.u, X);
}

// About 40 units a vertex and half a unit a limb product (measured: 45 ns a vertex of one-limb
// numbers, 250 ns for 256-limb coordinates and a one-limb normal).
std::vector<int> Scan::mpz_scan(Context& cx, const Z3& u, const std::vector<int>& list, mpz_class& best) const {
    double units = 40 * static_cast<double>(list.size());
    for (int c = 0; c < 3; ++c) {
        double lx = 0;
        if (&list == &P_.big)
            lx = big_limbs_[c];
        else
            for (int k : list) lx += coord_limbs(static_cast<size_t>(k), c);
        units += 0.5 * std::max(1.0, limbs(u[c])) * lx;
    }
    cx.spend(units);
    std::vector<int> out;
    mpz_class v, t;
    for (int k : list) {
        const int p = pos_.empty() ? k : pos_[static_cast<size_t>(k)];
        if (p >= 0) {  // a machine vertex: its int64 coordinates times u
            const size_t q = static_cast<size_t>(p);
            mul64(v.get_mpz_t(), u[0].get_mpz_t(), P_.x[0][q]);
            mul64(t.get_mpz_t(), u[1].get_mpz_t(), P_.x[1][q]);
            v += t;
            mul64(t.get_mpz_t(), u[2].get_mpz_t(), P_.x[2][q]);
            v += t;
        } else {
            const Z3& X = P_.big_x[static_cast<size_t>(-1 - p)];
            mpz_mul(v.get_mpz_t(), u[0].get_mpz_t(), X[0].get_mpz_t());
            mpz_addmul(v.get_mpz_t(), u[1].get_mpz_t(), X[1].get_mpz_t());
            mpz_addmul(v.get_mpz_t(), u[2].get_mpz_t(), X[2].get_mpz_t());
        }
        const int c = out.empty() ? 1 : cmp(v, best);
        if (c > 0) {
            mpz_swap(best.get_mpz_t(), v.get_mpz_t());
            out.clear();
        }
        if (c >= 0) out.push_back(k);
    }
    return out;
}
}  // namespace scalecert_check
