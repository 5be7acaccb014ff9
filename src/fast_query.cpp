#include "scalecert/fast_query.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

namespace scalecert {

namespace {
// Relative error budget of a few roundings (conversions to double, a product and two sums):
// the true bound is under 10 ulps; 1e-12 leaves three orders of magnitude to spare.
constexpr double kRel = 1e-12;
}  // namespace

FastCurve::FastCurve(const Model& m, const Curve& c) : m_(m), c_(c) {
    for (const EnvPiece& p : c.env.pieces) {
        const ContactLine& L = m.lines[p.line];
        a_.push_back(to_double_rn(L.slope));
        b_.push_back(to_double_rn(L.intercept));
        if (p.to) breaks_.push_back(to_double_rn(*p.to));
    }
}

Verdict FastCurve::classify(double r1, double r2) const {
    // The piece: binary search over the breakpoints, unless r1 is too close to one to be sure.
    size_t k = static_cast<size_t>(std::upper_bound(breaks_.begin(), breaks_.end(), r1) - breaks_.begin());
    bool near = (k < breaks_.size() && breaks_[k] - r1 <= kRel * std::fabs(r1)) ||
                (k > 0 && r1 - breaks_[k - 1] <= kRel * std::fabs(r1));
    if (!near) {
        double f = a_[k] * r1 + b_[k];
        double err = kRel * (std::fabs(a_[k] * r1) + std::fabs(b_[k])) + 1e-300;
        if (r2 < f - err) { ++counts.filtered; return Verdict::Separated; }
        if (r2 > f + err) { ++counts.filtered; return Verdict::Overlapping; }
    }
    ++counts.exact;
    return query(m_, c_, exact_from_double(r1), exact_from_double(r2), false).verdict;
}

FastDirect::FastDirect(const Model& m) : m_(m) {
    for (const ContactLine& L : m.lines) {
        nd_.push_back(to_double_rn(L.nd));
        h1_.push_back(to_double_rn(L.h1));
        h2_.push_back(to_double_rn(L.h2));
    }
}

Verdict FastDirect::classify(double r1, double r2) const {
    // Separated iff some n·d − ρ1 h1 − ρ2 h2 > 0; overlapping iff all < 0.
    bool all_negative = true;
    for (size_t i = 0; i < nd_.size(); ++i) {
        double t1 = r1 * h1_[i], t2 = r2 * h2_[i];
        double g = nd_[i] - t1 - t2;
        double err = kRel * (std::fabs(nd_[i]) + std::fabs(t1) + std::fabs(t2)) + 1e-300;
        if (g > err) { ++counts.filtered; return Verdict::Separated; }
        if (g >= -err) all_negative = false;
    }
    if (all_negative) { ++counts.filtered; return Verdict::Overlapping; }
    ++counts.exact;
    return query_direct(m_, exact_from_double(r1), exact_from_double(r2));
}

StageCounts classify_batch(const FastCurve& f, const std::vector<double>& r1, const std::vector<double>& r2,
                           std::vector<Verdict>& out, unsigned threads) {
    out.resize(r1.size());
    threads = std::max(1u, threads);
    std::vector<FastCurve> copies(threads, f);
    std::vector<std::thread> pool;
    size_t chunk = (r1.size() + threads - 1) / threads;
    for (unsigned t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            size_t end = std::min(r1.size(), (t + 1) * chunk);
            for (size_t i = t * chunk; i < end; ++i) out[i] = copies[t].classify(r1[i], r2[i]);
        });
    for (auto& th : pool) th.join();
    StageCounts sum;
    for (const FastCurve& c : copies) sum.filtered += c.counts.filtered, sum.exact += c.counts.exact;
    return sum;
}

}  // namespace scalecert
