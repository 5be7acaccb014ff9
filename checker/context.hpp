// What every part of the checker shares: the number types, the two ways a check ends (an invalid
// claim, exit 1; an unreadable file, exit 2), and the Context of one file's check: the claims
// counted and the work limit (certificates/FORMAT.md, "What the checker rejects" and "What the
// checker costs").
#pragma once
#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace scalecert_check {
using J = nlohmann::json;
using Q = mpq_class;
using V3 = std::array<Q, 3>;
using P2 = std::array<Q, 2>;
using Z3 = std::array<mpz_class, 3>;
struct IntPoints;  // points.hpp

// Limits on what is read at all (FORMAT.md): beyond them the file is unreadable (exit 2).
constexpr size_t kMaxFileBytes = size_t(1) << 30;  // 1 GiB
constexpr size_t kMaxDepth = 32;                   // certificates nest 7 levels deep

struct Invalid {
    std::string what;
};  // a claim that fails: exit 1
struct Unreadable {
    std::string what;
};  // not a readable file: exit 2

inline double limbs(const mpz_class& z) { return static_cast<double>(mpz_size(z.get_mpz_t())); }
inline double qsize(const Q& q) { return limbs(q.get_num()) + limbs(q.get_den()); }

// One file's check, passed by reference to every step that states a claim or counts work.
//
// The work limit. The support scans cost (distinct normals) × (vertices), and a vertex named in
// a list costs its own digits wherever it is named: products of sizes the file does not pay for
// one by one. Each such step is counted with spend(), in units of about a nanosecond, before it
// runs; past work_per_byte units a byte of the file (at least min_work) the file is refused as
// unreadable (exit 2), at a point that depends on the file only. Certificates the engine writes
// use a few units a byte (FORMAT.md, "What the checker costs"). The two rates are fields, not
// constants, for the tests.
struct Context {
    double work_per_byte = 600, min_work = 6e8;  // the limit's rate and floor
    double work = 0, budget = 6e8;               // the units counted so far, and this file's limit
    long claims = 0;                             // the claims checked so far
    std::string summary;                         // appended to the line printed for a valid file
    // The scene's vertex lists of integers, which the reader takes straight from the text
    // (json.hpp, parse_certificate); with direct_points false (for the tests, which compare the
    // two) every list is read as a tree of strings instead.
    std::vector<IntPoints>* points = nullptr;
    bool direct_points = true;

    // A new file of `bytes` bytes: nothing counted yet, its budget from its size.
    void start(size_t bytes) {
        claims = 0;
        summary.clear();
        work = 0;
        budget = std::max(min_work, work_per_byte * static_cast<double>(bytes));
    }

    void claim(bool ok, const std::string& what) {
        ++claims;
        if (!ok) throw Invalid{what};
    }
    // n claims that hold, established in bulk (each vertex of a list the reader took as integers).
    void held(long n) { claims += n; }
    // The same as claim(), with the message built only when the claim fails (one that prints a number: a
    // conversion to decimal costs more than the comparison).
    template <class F>
    void claim_lazy(bool ok, F what) {
        ++claims;
        if (!ok) throw Invalid{what()};
    }

    void spend(double units) {
        work += units;
        if (work > budget) over_budget();
    }
    // Rational arithmetic on numbers of the file and the scene, counted before it runs: `ops`
    // operations (each a product and the gcd that keeps it in lowest terms) whose operands total
    // m limbs, at 30 + m²/16 units each: above the measured cost (GMP's products and gcds are
    // quadratic at the sizes certificates hold, and cost less than counted beyond). A number
    // stored once but used by every judgement — a tolerance, a seed — is counted at each use.
    // (Measured: seeds of 100 and 1,000 limbs cost 36 µs and 1 ms a plane judgement, counted
    // 120,000 and 1.2·10^7 units; a tolerance of 100 limbs 25 µs a distance judgement, counted
    // 88,000.)
    void spend_ops(double ops, double m) { spend(ops * (30 + m * m / 16)); }

  private:
    [[noreturn]] void over_budget() const;
};
}  // namespace scalecert_check
