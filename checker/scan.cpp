#include "scan.hpp"

#include <algorithm>
#include <iterator>

namespace scalecert_check {
namespace {
// z as an int64 when |z| < 2^62 (and long holds it); false otherwise.
bool small_int(mpz_srcptr z, int64_t& out) {
    if (mpz_sizeinbase(z, 2) > 62 || !mpz_fits_slong_p(z)) return false;
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

Scan::Scan(Context& cx, const std::vector<V3>& v, const std::string& what) : n_(v.size()) {
    for (const V3& p : v)
        for (const Q& c : p) {
            if (mpz_cmp_ui(c.get_den_mpz_t(), 1) != 0) mpz_lcm(D_.get_mpz_t(), D_.get_mpz_t(), c.get_den_mpz_t());
            if (mpz_sizeinbase(D_.get_mpz_t(), 2) > 16384)
                throw Unreadable{"the common denominator of " + what +
                                 "'s vertex coordinates has more than 16384 bits (scalecert's own limit)"};
        }
    cx.spend(static_cast<double>(n_) * (10 + 3 * limbs(D_)));
    Z_.resize(n_);
    pos_.assign(n_, -1);
    for (size_t k = 0; k < n_; ++k) {
        bool machine = sizeof(long) >= 8;  // mpz_get_si gives the int64 values as long
        int64_t x[3];
        for (int c = 0; c < 3; ++c) {
            mpz_divexact(Z_[k][c].get_mpz_t(), D_.get_mpz_t(), v[k][c].get_den_mpz_t());
            Z_[k][c] *= v[k][c].get_num();
            machine = machine && small_int(Z_[k][c].get_mpz_t(), x[c]);
        }
        if (!machine) {
            big_.push_back(static_cast<int>(k));
            for (int c = 0; c < 3; ++c) big_limbs_[c] += limbs(Z_[k][c]);
            continue;
        }
        pos_[k] = static_cast<int>(X_[0].size());
        orig_.push_back(static_cast<int>(k));
        for (int c = 0; c < 3; ++c) {
            X_[c].push_back(x[c]);
            bits_ = std::max(bits_, static_cast<int>(mpz_sizeinbase(Z_[k][c].get_mpz_t(), 2)));
        }
    }
}

std::vector<int> Scan::argmax(Context& cx, const Z3& u, const std::vector<int>* subset) const {
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
            const int p = pos_[static_cast<size_t>(k)];
            (p >= 0 ? mlist.push_back(p) : blist.push_back(k));
        }
    const std::vector<int>& bl = all ? big_ : blist;
    const size_t nm = all ? X_[0].size() : mlist.size();
    std::vector<int> mout, bout;
    mpz_class mbest, bbest;
    if (nm > 0) {
        const int* at = all ? nullptr : mlist.data();
        const int64_t *x = X_[0].data(), *y = X_[1].data(), *z = X_[2].data();
        if (small_u && bits_ + ub <= 61) {
            cx.spend(static_cast<double>(nm));
            const int64_t a = w[0], b = w[1], c = w[2];
            auto value = [=](size_t k) { return a * x[k] + b * y[k] + c * z[k]; };
            const int64_t best = at ? scan<int64_t>(nm, at, value, mout) : scan<int64_t>(nm, value, mout);
            if (all && bl.empty()) return mout;  // every vertex is at its own position
            mbest = static_cast<long>(best);
        } else if (small_u) {
            cx.spend(2.0 * static_cast<double>(nm));
            const __int128 a = w[0], b = w[1], c = w[2];
            auto value = [=](size_t k) { return a * x[k] + b * y[k] + c * z[k]; };
            const __int128 best = at ? scan<__int128>(nm, at, value, mout) : scan<__int128>(nm, value, mout);
            if (all && bl.empty()) return mout;
            mbest = from128(best);
        }
        if (small_u) {
            for (int& p : mout) p = orig_[static_cast<size_t>(p)];
        } else {  // a normal past 2^62: GMP integers for these vertices too
            std::vector<int> list;
            if (all)
                list = orig_;
            else
                for (int p : mlist) list.push_back(orig_[static_cast<size_t>(p)]);
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

// About 40 units a vertex and half a unit a limb product (measured: 45 ns a vertex of one-limb
// numbers, 250 ns for 256-limb coordinates and a one-limb normal).
std::vector<int> Scan::mpz_scan(Context& cx, const Z3& u, const std::vector<int>& list, mpz_class& best) const {
    double units = 40 * static_cast<double>(list.size());
    for (int c = 0; c < 3; ++c) {
        double lx = 0;
        if (&list == &big_)
            lx = big_limbs_[c];
        else
            for (int k : list) lx += limbs(Z_[static_cast<size_t>(k)][c]);
        units += 0.5 * std::max(1.0, limbs(u[c])) * lx;
    }
    cx.spend(units);
    std::vector<int> out;
    mpz_class v;
    for (int k : list) {
        const auto& X = Z_[static_cast<size_t>(k)];
        mpz_mul(v.get_mpz_t(), u[0].get_mpz_t(), X[0].get_mpz_t());
        mpz_addmul(v.get_mpz_t(), u[1].get_mpz_t(), X[1].get_mpz_t());
        mpz_addmul(v.get_mpz_t(), u[2].get_mpz_t(), X[2].get_mpz_t());
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
