#include "scalecert/fast_query.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
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

namespace {
bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// One number token [b, e): std::from_chars (correctly rounded, like strtod); forms it does not
// take (a leading '+', hexadecimal, "infinity"...) go to strtod itself.
bool number(const char* b, const char* e, double& out) {
    auto r = std::from_chars(b, e, out);
    if (r.ec == std::errc() && r.ptr == e) return true;
    std::string t(b, e);
    char* end = nullptr;
    out = std::strtod(t.c_str(), &end);
    return end == t.c_str() + t.size() && !t.empty();
}

// Parses the lines in [b, e); returns the offset of the first bad line, or npos.
size_t parse_chunk(const char* base, const char* b, const char* e, std::vector<double>& r1, std::vector<double>& r2) {
    const size_t lines = static_cast<size_t>(std::count(b, e, '\n')) + 1;
    r1.reserve(lines), r2.reserve(lines);
    while (b < e) {
        const char* nl = std::find(b, e, '\n');
        const char* end = std::find(b, nl, '#');
        double v[2];
        int k = 0;
        bool ok = true;
        for (const char* p = b; ok;) {
            while (p < end && blank(*p)) ++p;
            if (p == end) break;
            const char* q = p;
            while (q < end && !blank(*q)) ++q;
            ok = k < 2 && number(p, q, v[k]) && std::isfinite(v[k]) && v[k] > 0;
            ++k;
            p = q;
        }
        if (!ok || (k != 0 && k != 2)) return static_cast<size_t>(b - base);
        if (k == 2) r1.push_back(v[0]), r2.push_back(v[1]);
        b = nl == e ? e : nl + 1;
    }
    return std::string::npos;
}
}  // namespace

void parse_pairs(const std::string& text, std::vector<double>& r1, std::vector<double>& r2, unsigned threads) {
    threads = std::max(1u, threads);
    if (text.size() < (1u << 16)) threads = 1;
    // Chunks end at line ends.
    std::vector<const char*> cut{text.data()};
    for (unsigned t = 1; t < threads; ++t) {
        const char* p = text.data() + text.size() * t / threads;
        p = std::find(std::max(p, cut.back()), text.data() + text.size(), '\n');
        cut.push_back(p == text.data() + text.size() ? p : p + 1);
    }
    cut.push_back(text.data() + text.size());
    std::vector<std::vector<double>> a(threads), b(threads);
    std::vector<size_t> bad(threads, std::string::npos);
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t)
        pool.emplace_back([&, t] { bad[t] = parse_chunk(text.data(), cut[t], cut[t + 1], a[t], b[t]); });
    for (auto& th : pool) th.join();
    for (unsigned t = 0; t < threads; ++t)
        if (bad[t] != std::string::npos) {
            long line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(bad[t]), '\n');
            throw InputError("line " + std::to_string(line) + ": expected two finite numbers > 0");
        }
    size_t n = 0;
    for (const auto& v : a) n += v.size();
    r1.clear(), r2.clear();
    r1.reserve(n), r2.reserve(n);
    for (unsigned t = 0; t < threads; ++t) {
        r1.insert(r1.end(), a[t].begin(), a[t].end());
        r2.insert(r2.end(), b[t].begin(), b[t].end());
    }
}

std::string verdict_lines(const std::vector<Verdict>& v) {
    std::string text;
    text.reserve(v.size() * 12);
    for (Verdict x : v) text += verdict_name(x), text += '\n';
    return text;
}

}  // namespace scalecert
