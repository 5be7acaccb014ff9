#include "scalecert/int_points.hpp"

#include "scalecert/small_int.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>

namespace scalecert::internal {

Vec3q IntPoints::point(size_t k) const {
    Vec3q v;
    for (int c = 0; c < 3; ++c) {
        mpq_set_si(v[c].get_mpq_t(), static_cast<long>(x[3 * k + c]), 1);
        if (scale != 1) v[c] /= scale;
    }
    return v;
}

Vec3q IntPoints::mean() const {
    I128 s[3] = {0, 0, 0};  // n ≤ 2^20 points of ≤ 2^53: sums below 2^74
    for (size_t k = 0; k < size(); ++k)
        for (int c = 0; c < 3; ++c) s[c] += x[3 * k + c];
    Vec3q m;
    for (int c = 0; c < 3; ++c) {
        m[c] = Q(to_z(s[c]), scale * Z(static_cast<unsigned long>(size())));
        m[c].canonicalize();
    }
    return m;
}

std::optional<IntPoints> int_points(const std::vector<Vec3q>& pts) {
    IntPoints r;
    for (const Vec3q& v : pts)
        for (const Q& c : v) {
            mpz_lcm(r.scale.get_mpz_t(), r.scale.get_mpz_t(), c.get_den_mpz_t());
            if (mpz_sizeinbase(r.scale.get_mpz_t(), 2) > 53) return std::nullopt;
        }
    r.x.resize(3 * pts.size());
    const Z bound(static_cast<long>(kMaxIntCoord));
    for (size_t k = 0; k < pts.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            const Q& q = pts[k][c];
            Z v = q.get_num() * (r.scale / q.get_den());
            if (abs(v) > bound) return std::nullopt;
            r.x[3 * k + c] = v.get_si();
        }
    return r;
}

std::vector<Vec3q> q_points(const IntPoints& p) {
    std::vector<Vec3q> out(p.size());
    for (size_t k = 0; k < p.size(); ++k) out[k] = p.point(k);
    return out;
}

namespace {
// The C locale's isspace, inline.
inline bool space(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }

struct Cursor {
    const char* p;
    const char* end;
    // The next whitespace-separated token; false at the end of the text.
    bool next(const char*& b, const char*& e) {
        while (p < end && space(*p)) ++p;
        if (p == end) return false;
        b = p;
        while (p < end && !space(*p)) ++p;
        e = p;
        return true;
    }
};

// A plain decimal as mantissa × 10^exp10; false for anything else.
bool decimal(const char* b, const char* e, std::int64_t& mant, int& exp10) {
    bool neg = false;
    if (b < e && (*b == '+' || *b == '-')) neg = *b++ == '-';
    std::int64_t m = 0;
    int digits = 0, frac = 0;
    bool any = false;
    auto digit = [&](char ch) {
        if (m != 0 || ch != '0') ++digits;
        m = m * 10 + (ch - '0');
    };
    while (b < e && *b >= '0' && *b <= '9') { if (digits >= 18) return false; digit(*b++); any = true; }
    if (!any) return false;
    if (b < e && *b == '.') {
        ++b;
        bool f = false;
        while (b < e && *b >= '0' && *b <= '9') { if (digits >= 18) return false; digit(*b++); ++frac; f = true; }
        if (!f) return false;
    }
    int ex = 0;
    if (b < e && (*b == 'e' || *b == 'E')) {
        ++b;
        bool eneg = false;
        if (b < e && (*b == '+' || *b == '-')) eneg = *b++ == '-';
        int nd = 0;
        while (b < e && *b >= '0' && *b <= '9') { if (++nd > 3) return false; ex = ex * 10 + (*b++ - '0'); }
        if (nd == 0) return false;
        if (eneg) ex = -ex;
    }
    if (b != e) return false;
    mant = neg ? -m : m;
    exp10 = ex - frac;
    return true;
}

bool count(const char* b, const char* e, size_t& out) {
    if (e - b < 1 || e - b > 9) return false;
    out = 0;
    for (; b < e; ++b) {
        if (*b < '0' || *b > '9') return false;
        out = out * 10 + static_cast<size_t>(*b - '0');
    }
    return true;
}
}  // namespace

std::optional<IntPoints> parse_off_fast(const std::string& text) { return parse_off_fast(text.data(), text.size()); }

std::optional<IntPoints> read_off_fast(const std::string& path) {
    // Mapped, not copied: the text is read once, from the page cache. Anything unusual (not a
    // regular file, empty, over the limit, unreadable) is left to the full reader.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return std::nullopt;
    struct stat st {};
    std::optional<IntPoints> r;
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0 && static_cast<unsigned long long>(st.st_size) <= kMaxSceneBytes) {
        const auto size = static_cast<size_t>(st.st_size);
        void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
        if (p != MAP_FAILED) {
            r = parse_off_fast(static_cast<const char*>(p), size);
            ::munmap(p, size);
        }
    }
    ::close(fd);
    return r;
}

std::optional<IntPoints> parse_off_fast(const char* data, size_t size) {
    Cursor c{data, data + size};
    const char *b, *e;
    if (!c.next(b, e) || std::string(b, e) != "OFF") return std::nullopt;
    size_t nv = 0, nf = 0, ne = 0;
    if (!c.next(b, e) || !count(b, e, nv) || !c.next(b, e) || !count(b, e, nf) || !c.next(b, e) || !count(b, e, ne))
        return std::nullopt;
    if (nv < 4 || nv > kMaxPoints) return std::nullopt;
    // Mantissas go straight into the output, then are scaled in place to the common power of ten.
    IntPoints r;
    r.x.resize(3 * nv);
    std::vector<std::int8_t> ex(3 * nv);
    int lowest = 0;
    for (size_t i = 0; i < 3 * nv; ++i) {
        int x10;
        if (!c.next(b, e) || !decimal(b, e, r.x[i], x10) || x10 < -18 || x10 > 18) return std::nullopt;
        ex[i] = static_cast<std::int8_t>(x10);
        if (r.x[i] != 0 && x10 < lowest) lowest = x10;
    }
    // Every token read so far passed the grammar above, which has no '#': the file has no
    // comment before its last vertex, and the full reader would read the same numbers.
    mpz_ui_pow_ui(r.scale.get_mpz_t(), 10, static_cast<unsigned long>(-lowest));
    static const std::int64_t p10[19] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000,
                                        10000000000, 100000000000, 1000000000000, 10000000000000, 100000000000000,
                                        1000000000000000, 10000000000000000, 100000000000000000, 1000000000000000000};
    for (size_t i = 0; i < 3 * nv; ++i) {
        std::int64_t v = r.x[i];
        if (v != 0) {
            const int shift = ex[i] - lowest;  // 0..36
            if (shift > 18 || __builtin_mul_overflow(v, p10[shift], &v)) return std::nullopt;
        }
        if (v > kMaxIntCoord || v < -kMaxIntCoord) return std::nullopt;
        r.x[i] = v;
    }
    return r;
}

std::optional<CompactScene> compact_scene(const Scene& sc) {
    CompactScene cs;
    for (int i = 0; i < 2; ++i) {
        auto p = int_points(sc.P[i].points);
        if (!p) return std::nullopt;
        cs.P[i] = std::move(*p);
        cs.seed[i] = sc.P[i].seed;
        cs.seed_given[i] = sc.P[i].seed_given;
        cs.lo[i] = sc.lo[i];
        cs.hi[i] = sc.hi[i];
    }
    return cs;
}

Scene full_scene(const CompactScene& cs) {
    Scene sc;
    for (int i = 0; i < 2; ++i) {
        sc.P[i].points = q_points(cs.P[i]);
        sc.P[i].seed = cs.seed[i];
        sc.P[i].seed_given = cs.seed_given[i];
        sc.lo[i] = cs.lo[i];
        sc.hi[i] = cs.hi[i];
    }
    return sc;
}

}  // namespace scalecert::internal
