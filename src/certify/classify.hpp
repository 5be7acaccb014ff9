// Filtered queries for pairs given as doubles (each double's exact value is classified): a
// floating-point stage whose error bound proves its sign, and exact rationals only when it
// cannot decide. The answers are always the exact ones.
#pragma once
#include "certify/query.hpp"
#include "numeric/predicates.hpp"

#include <cstdint>
#include <string>

namespace scalecert::internal {

// How often each stage decided: the counts of one predicate (predicates.hpp).
using StageCounts = filter::PredicateCounts;

class FastCurve {
  public:
    FastCurve(const Model& m, const TouchingCurve& c);
    Verdict classify(double rho1, double rho2) const;  // ρ1, ρ2 > 0
    // Statistics (curve_side), per object: use one object per thread.
    mutable filter::PredicateStats stats;
    StageCounts counts() const { return stats[filter::Predicate::CurveSide]; }

  private:
    const Model& m_;
    const TouchingCurve& c_;
    std::vector<double> breaks_;  // right ends of the envelope pieces, nearest doubles
    std::vector<double> a_, b_;   // slope and intercept of each piece, nearest doubles
};

class FastDirect {
  public:
    explicit FastDirect(const Model& m);
    Verdict classify(double rho1, double rho2) const;
    mutable filter::PredicateStats stats;  // lines_gap, per object
    StageCounts counts() const { return stats[filter::Predicate::LinesGap]; }

  private:
    const Model& m_;
    std::vector<double> nd_, h1_, h2_;
};

// Classifies many pairs on `threads` threads (a copy of f each); out[i] is the verdict for
// (r1[i], r2[i]). Returns the stage counts summed over the threads.
StageCounts classify_batch(const FastCurve& f, const std::vector<double>& r1, const std::vector<double>& r2,
                           std::vector<Verdict>& out, unsigned threads);

// Reads pairs, one "rho1 rho2" per line (text after '#' and blank lines ignored), each number
// read as the double strtod gives (with `single`, the float strtof gives), on `threads` threads
// over chunks of the text. Throws InputError("line N: ...") for the first bad line: two finite
// numbers > 0 are required.
void parse_pairs(const std::string& text, std::vector<double>& r1, std::vector<double>& r2, unsigned threads,
                 bool single = false);

// The verdicts as text, one name per line.
std::string verdict_lines(const std::vector<Verdict>& v);

}  // namespace scalecert::internal
