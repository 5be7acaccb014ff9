#include "certify/classify.hpp"

#include "numeric/predicates.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <thread>

namespace scalecert::internal {

FastCurve::FastCurve(const Model& m, const TouchingCurve& c) : m_(m), c_(c) {
    for (const EnvPiece& p : c.env.pieces) {
        const ContactLine& L = m.lines[p.line];
        a_.push_back(to_double_rn(L.slope));
        b_.push_back(to_double_rn(L.intercept));
        if (p.to) breaks_.push_back(to_double_rn(*p.to));
    }
}

Verdict FastCurve::classify(double r1, double r2) const {
    // Predicate 4 (predicates.hpp): the piece by binary search over the breakpoints, trusted unless
    // r1 is too close to one to be sure; the side of its line, else the exact query.
    size_t k = static_cast<size_t>(std::upper_bound(breaks_.begin(), breaks_.end(), r1) - breaks_.begin());
    const bool near = (k < breaks_.size() && filter::bounds::near_breakpoint(breaks_[k], r1, false)) ||
                      (k > 0 && filter::bounds::near_breakpoint(breaks_[k - 1], r1, true));
    return verdict_of_sign(filter::curve_side(
        a_[k], b_[k], r1, r2, !near,
        [&] { return verdict_sign(query(m_, c_, exact_from_double(r1), exact_from_double(r2), false).verdict); },
        stats));
}

FastDirect::FastDirect(const Model& m) : m_(m) {
    for (const ContactLine& L : m.lines) {
        nd_.push_back(to_double_rn(L.nd));
        h1_.push_back(to_double_rn(L.h1));
        h2_.push_back(to_double_rn(L.h2));
    }
}

Verdict FastDirect::classify(double r1, double r2) const {
    // Separated iff some n·d − ρ1 h1 − ρ2 h2 > 0; overlapping iff all < 0 (predicate 4).
    return verdict_of_sign(filter::lines_side(
        nd_, h1_, h2_, r1, r2,
        [&] { return verdict_sign(query_direct(m_, exact_from_double(r1), exact_from_double(r2))); }, stats));
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
    filter::PredicateStats sum;
    for (const FastCurve& c : copies) sum += c.stats;
    return sum[filter::Predicate::CurveSide];
}

namespace {
bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

bool delimiter(const char* p, const char* e) { return p == e || blank(*p) || *p == '\n' || *p == '#'; }

// A decimal as every format takes it (CLAIMS.md, "Numbers"): a sign, digits with at most one
// point, an optional exponent. No "inf" or "nan"; hex floats are hex_float_syntax's.
bool decimal_text(const char* p, const char* e) {
    if (p < e && (*p == '+' || *p == '-')) ++p;
    size_t digits = 0;
    bool point = false;
    for (; p < e && (std::isdigit(static_cast<unsigned char>(*p)) || (*p == '.' && !point)); ++p)
        *p == '.' ? void(point = true) : void(++digits);
    if (digits == 0) return false;
    if (p < e && (*p == 'e' || *p == 'E')) {
        ++p;
        if (p < e && (*p == '+' || *p == '-')) ++p;
        if (p == e || !std::isdigit(static_cast<unsigned char>(*p))) return false;
        while (p < e && std::isdigit(static_cast<unsigned char>(*p))) ++p;
    }
    return p == e;
}

// One number at p, a decimal or a hex float, as strtod reads it (or with `single` as strtof: the float,
// rounded once): std::from_chars, correctly rounded like them; a leading '+' (which from_chars
// does not take) and results out of range go to strtod (strtof) itself. Advances p past the token.
bool number(const char*& p, const char* e, double& out, bool single) {
    const char* q = p;
    while (!delimiter(q, e)) ++q;
    if (!decimal_text(p, q)) {
        // A hex float (printf's %a) as strtod (strtof) reads it; from_chars takes none with 0x.
        std::string t(p, q);
        if (!hex_float_syntax(t)) return false;
        out = single ? static_cast<double>(std::strtof(t.c_str(), nullptr)) : std::strtod(t.c_str(), nullptr);
        p = q;
        return true;
    }
    float f = 0;
    auto r = single ? std::from_chars(p, q, f) : std::from_chars(p, q, out);
    if (r.ec == std::errc() && r.ptr == q) {
        if (single) out = static_cast<double>(f);
        p = q;
        return true;
    }
    std::string t(p, q);
    char* end = nullptr;
    out = single ? static_cast<double>(std::strtof(t.c_str(), &end)) : std::strtod(t.c_str(), &end);
    p = q;
    return end == t.c_str() + t.size();
}

// Parses the lines in [b, e) in one pass; returns the offset of the first bad line, or npos.
// Writes the pairs to o1, o2 (room for one per line) and their count to count (once, at the
// end: the threads' counts share a cache line).
size_t parse_chunk(const char* base, const char* b, const char* e, double* o1, double* o2, size_t& count, bool single) {
    size_t n = 0;
    const char* p = b;
    while (p < e) {
        const char* line = p;
        double v[2];
        int k = 0;
        bool ok = true;
        for (;;) {
            while (p < e && blank(*p)) ++p;
            if (p == e || *p == '\n' || *p == '#') break;
            ok = ok && k < 2 && number(p, e, v[k], single) && std::isfinite(v[k]) && v[k] > 0;
            ++k;
            if (!ok) break;
        }
        if (!ok || (k != 0 && k != 2)) return count = n, static_cast<size_t>(line - base);
        if (k == 2) o1[n] = v[0], o2[n] = v[1], ++n;
        if (p < e && *p == '#') p = std::find(p, e, '\n');
        if (p < e) ++p;  // the newline
    }
    count = n;
    return std::string::npos;
}
}  // namespace

void parse_pairs(const std::string& text, std::vector<double>& r1, std::vector<double>& r2, unsigned threads,
                 bool single) {
    threads = std::max(1u, threads);
    if (text.size() < (1u << 16)) threads = 1;
    // Chunks end at line ends. Each thread counts its lines, then writes its pairs straight into
    // the output at its offset (one slot per line); the gaps left by blank lines are closed last.
    const char* const end = text.data() + text.size();
    std::vector<const char*> cut{text.data()};
    for (unsigned t = 1; t < threads; ++t) {
        const char* p = std::find(std::max(text.data() + text.size() * t / threads, cut.back()), end, '\n');
        cut.push_back(p == end ? p : p + 1);
    }
    cut.push_back(end);
    std::vector<size_t> lines(threads), got(threads), bad(threads, std::string::npos), off(threads + 1, 0);
    auto each = [&](auto&& f) {
        std::vector<std::thread> pool;
        for (unsigned t = 1; t < threads; ++t) pool.emplace_back(f, t);
        f(0u);
        for (auto& th : pool) th.join();
    };
    each([&](unsigned t) { lines[t] = static_cast<size_t>(std::count(cut[t], cut[t + 1], '\n')) + 1; });
    for (unsigned t = 0; t < threads; ++t) off[t + 1] = off[t] + lines[t];
    r1.resize(off[threads]), r2.resize(off[threads]);
    each([&](unsigned t) {
        bad[t] = parse_chunk(text.data(), cut[t], cut[t + 1], r1.data() + off[t], r2.data() + off[t], got[t], single);
    });
    for (unsigned t = 0; t < threads; ++t)
        if (bad[t] != std::string::npos) {
            long line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(bad[t]), '\n');
            throw InputError(
                "line " + std::to_string(line) +
                ": expected two numbers > 0 (decimals such as 1.5 or 2e-3, or hex floats such as 0x1.8p0; not inf or "
                "nan)");
        }
    size_t n = got[0];
    for (unsigned t = 1; t < threads; ++t) {
        std::copy(r1.begin() + static_cast<long>(off[t]), r1.begin() + static_cast<long>(off[t] + got[t]),
                  r1.begin() + static_cast<long>(n));
        std::copy(r2.begin() + static_cast<long>(off[t]), r2.begin() + static_cast<long>(off[t] + got[t]),
                  r2.begin() + static_cast<long>(n));
        n += got[t];
    }
    r1.resize(n), r2.resize(n);
}

std::string verdict_lines(const std::vector<Verdict>& v) {
    std::string text;
    text.reserve(v.size() * 12);
    for (Verdict x : v) text += verdict_name(x), text += '\n';
    return text;
}

}  // namespace scalecert::internal
