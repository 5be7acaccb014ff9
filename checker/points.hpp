// Integer points held compactly: the store of a polytope's scaled vertices X_k = D v_k that the
// support scans read (scan.hpp), and the form in which the reader keeps a scene's vertex list of
// integers straight from the text (json.hpp), never as a tree of strings or as rationals.
#pragma once
#include "context.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace scalecert_check {
// Advice that the pages of [p, p + bytes) be the kernel's 2 MiB pages where it can (Linux:
// madvise MADV_HUGEPAGE; elsewhere nothing). The first touch of each 4 KiB page of a fresh
// allocation is a page fault, and on a virtual machine a fault costs tens of microseconds: reading
// a 141 MB certificate into 4 KiB pages took 0.7 s of CPU time, into 2 MiB pages 0.05 s. Advice
// only: it changes nothing that is stored.
void advise_huge_pages(void* p, size_t bytes);

// A growable array of int64, for the coordinates of up to millions of points. A large one (from
// 1 MiB) is its own mapping of memory, advised into huge pages and grown by remapping its pages
// (Linux: mremap), never copied; a small one, and any elsewhere, is grown by realloc.
class Int64s {
  public:
    Int64s() = default;
    Int64s(const Int64s&) = delete;
    Int64s& operator=(const Int64s&) = delete;
    Int64s(Int64s&& o) noexcept : p_(o.p_), n_(o.n_), cap_(o.cap_), mapped_(o.mapped_) { o.forget(); }
    Int64s& operator=(Int64s&& o) noexcept {
        if (this != &o) {
            release();
            p_ = o.p_, n_ = o.n_, cap_ = o.cap_, mapped_ = o.mapped_;
            o.forget();
        }
        return *this;
    }
    ~Int64s() { release(); }

    void push_back(int64_t v) {
        if (n_ == cap_) grow(n_ + 1);
        p_[n_++] = v;
    }
    void reserve(size_t n) {
        if (n > cap_) grow(n);
    }
    size_t size() const { return n_; }
    const int64_t* data() const { return p_; }
    int64_t operator[](size_t k) const { return p_[k]; }
    const int64_t* begin() const { return p_; }
    const int64_t* end() const { return p_ + n_; }

  private:
    int64_t* p_ = nullptr;
    size_t n_ = 0, cap_ = 0;
    bool mapped_ = false;  // p_ is a mapping of its own (else from malloc)
    void forget() { p_ = nullptr, n_ = cap_ = 0, mapped_ = false; }
    void grow(size_t need);  // to room for at least `need`, and at least twice the room before
    void release();
};

// v as an mpz.
inline mpz_class z64(int64_t v) {
    if constexpr (sizeof(long) >= sizeof(int64_t)) {
        return mpz_class(static_cast<long>(v));
    } else {
        const uint64_t a = v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
        mpz_class r;
        mpz_import(r.get_mpz_t(), 1, 1, sizeof a, 0, 0, &a);
        if (v < 0) mpz_neg(r.get_mpz_t(), r.get_mpz_t());
        return r;
    }
}

// A point is small when each of its coordinates is below 2^62 in magnitude: held as int64, at the
// next position of x (positions follow the points' order). The others are big: held as mpz.
struct IntPoints {
    static constexpr int kSmallBits = 62;  // a small coordinate: |c| < 2^62
    size_t n = 0;                          // points in all
    Int64s x[3];                           // the small points' coordinates, by position
    std::vector<int> orig;                 // position -> point, once some point is big (before: the identity)
    std::vector<int> big;                  // the big points, ascending
    std::vector<Z3> big_x;                 // their coordinates, in that order

    size_t small() const { return x[0].size(); }
    // Appends a small point (every |c[j]| < 2^62).
    void add_small(const int64_t c[3]) {
        if (!big.empty()) orig.push_back(static_cast<int>(n));
        for (int j = 0; j < 3; ++j) x[j].push_back(c[j]);
        ++n;
    }
    // Appends a big point.
    void add_big(Z3 c) {
        positions_written();
        big.push_back(static_cast<int>(n));
        big_x.push_back(std::move(c));
        ++n;
    }
    // The point at each position: orig[p], or p while no point is big.
    int point_at(size_t p) const { return big.empty() ? static_cast<int>(p) : orig[p]; }

  private:
    // Before the first big point every point is small and its position is its index: written out
    // in orig, which from then on maps every position.
    void positions_written() {
        if (big.empty() && orig.empty())
            for (size_t p = 0; p < small(); ++p) orig.push_back(static_cast<int>(p));
    }
};
}  // namespace scalecert_check
