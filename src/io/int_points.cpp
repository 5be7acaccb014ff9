#include "io/int_points.hpp"
#include "io/files.hpp"
#include "io/mesh.hpp"

#include "numeric/small_int.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <future>

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

inline bool digit(char c) { return c >= '0' && c <= '9'; }

// A decimal at p as mantissa × 10^exp10 (at most 18 significant digits and a 3-digit
// exponent), moving p past it; false for anything else. The OFF reader's grammar,
// [+-]digits[.digits][e[+-]digits], or with `json` RFC 8259's: no '+', no leading zeros.
__attribute__((always_inline)) inline bool read_decimal(const char*& p, const char* e, bool json, std::int64_t& mant,
                                                        int& exp10) {
    const char* q = p;
    bool neg = false;
    if (q < e && (*q == '-' || (!json && *q == '+'))) neg = *q++ == '-';
    if (q == e || !digit(*q)) return false;
    std::int64_t m = 0;
    int digits = 0, frac = 0;
    auto take = [&] {
        if ((m != 0 || *q != '0') && ++digits > 18) return false;
        m = m * 10 + (*q++ - '0');
        return true;
    };
    if (json && *q == '0')
        ++q;
    else
        while (q < e && digit(*q))
            if (!take()) return false;
    if (q < e && *q == '.') {
        if (++q == e || !digit(*q)) return false;
        for (; q < e && digit(*q); ++frac)
            if (!take()) return false;
    }
    int ex = 0;
    if (q < e && (*q == 'e' || *q == 'E')) {
        bool eneg = false;
        if (++q < e && (*q == '+' || *q == '-')) eneg = *q++ == '-';
        if (q == e || !digit(*q)) return false;
        for (int nd = 0; q < e && digit(*q);) {
            if (++nd > 3) return false;
            ex = ex * 10 + (*q++ - '0');
        }
        if (eneg) ex = -ex;
    }
    p = q;
    mant = neg ? -m : m;
    exp10 = ex - frac;
    return true;
}

// RFC 8259's number grammar: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
bool json_number(const char* b, const char* e) {
    if (b < e && *b == '-') ++b;
    if (b == e || *b < '0' || *b > '9') return false;
    if (*b == '0')
        ++b;
    else
        while (b < e && *b >= '0' && *b <= '9') ++b;
    if (b < e && *b == '.') {
        ++b;
        if (b == e || *b < '0' || *b > '9') return false;
        while (b < e && *b >= '0' && *b <= '9') ++b;
    }
    if (b < e && (*b == 'e' || *b == 'E')) {
        ++b;
        if (b < e && (*b == '+' || *b == '-')) ++b;
        if (b == e || *b < '0' || *b > '9') return false;
        while (b < e && *b >= '0' && *b <= '9') ++b;
    }
    return b == e;
}

// Whether mant × 10^exp10 (|mant| < 10^18, |exp10| <= 18) is what `numbers` reads it as: exact
// always; a double (float32) when its odd part has at most 53 (24) bits, 5^-exp10 dividing mant.
// (Its magnitude, 10^-36 to 10^36, is within both formats' normal range.)
bool binary_exact(std::int64_t mant, int exp10, Numbers numbers) {
    if (numbers == Numbers::Exact || mant == 0) return true;
    unsigned __int128 v = static_cast<unsigned __int128>(mant < 0 ? -static_cast<__int128>(mant) : mant);
    for (int k = 0; k < exp10; ++k) v *= 5;
    for (int k = 0; k < -exp10; ++k) {
        if (v % 5 != 0) return false;
        v /= 5;
    }
    while ((v & 1) == 0) v >>= 1;
    return v < (static_cast<unsigned __int128>(1) << (numbers == Numbers::Float32 ? 24 : 53));
}

// Mantissas × 10^ex to integers over the common scale 10^-lowest, within kMaxIntCoord.
bool scale_to(IntPoints& r, const std::vector<std::int8_t>& ex, int lowest) {
    mpz_ui_pow_ui(r.scale.get_mpz_t(), 10, static_cast<unsigned long>(-lowest));
    static const std::int64_t p10[19] = {1,
                                         10,
                                         100,
                                         1000,
                                         10000,
                                         100000,
                                         1000000,
                                         10000000,
                                         100000000,
                                         1000000000,
                                         10000000000,
                                         100000000000,
                                         1000000000000,
                                         10000000000000,
                                         100000000000000,
                                         1000000000000000,
                                         10000000000000000,
                                         100000000000000000,
                                         1000000000000000000};
    for (size_t i = 0; i < r.x.size(); ++i) {
        std::int64_t v = r.x[i];
        if (v != 0) {
            const int shift = ex[i] - lowest;  // 0..36
            if (shift > 18 || __builtin_mul_overflow(v, p10[shift], &v)) return false;
        }
        if (v > kMaxIntCoord || v < -kMaxIntCoord) return false;
        r.x[i] = v;
    }
    return true;
}

// Calls f on the file's bytes, mapped; nothing for anything but a regular, non-empty file of at
// most kMaxSceneBytes (the full reader then reads it, or words the error). Opened as every input
// is (open_regular_file): never blocking, a FIFO or device never read.
template <class F>
void map_file(const std::string& path, F&& f) {
    int fd = -1;
    size_t size = 0;
    try {
        fd = open_regular_file(path, "file", false, &size);
    } catch (const InputError&) {
        return;
    }
    if (size > 0 && size <= kMaxSceneBytes) {
        void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
        if (p != MAP_FAILED) {
            f(static_cast<const char*>(p), size);
            ::munmap(p, size);
        }
    }
    ::close(fd);
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

std::optional<IntPoints> parse_off_fast(const std::string& text, Numbers numbers) {
    return parse_off_fast(text.data(), text.size(), numbers);
}

std::optional<IntPoints> read_off_fast(const std::string& path, Numbers numbers) {
    std::optional<IntPoints> r;
    map_file(path, [&](const char* p, size_t n) { r = parse_off_fast(p, n, numbers); });
    return r;
}

std::optional<IntPoints> parse_off_fast(const char* data, size_t size, Numbers numbers) {
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
        if (!c.next(b, e) || !read_decimal(b, e, false, r.x[i], x10) || b != e || x10 < -18 || x10 > 18 ||
            !binary_exact(r.x[i], x10, numbers))
            return std::nullopt;
        ex[i] = static_cast<std::int8_t>(x10);
        if (r.x[i] != 0 && x10 < lowest) lowest = x10;
    }
    // Every token read so far passed the grammar above, which has no '#': the file has no
    // comment before its last vertex, and the full reader would read the same numbers.
    if (!scale_to(r, ex, lowest)) return std::nullopt;
    return r;
}

namespace {
// A scene file in the one shape the fast reader takes: {"P1": {"vertices": [[x,y,z], ...],
// "seed": [x,y,z]}, "P2": ..., "I1": [lo,hi], "I2": [lo,hi]}, keys in any order, each once, JSON
// numbers only. Everything it accepts, parse_scene_text accepts with the same values; the rest
// goes there.
class SceneScanner {
  public:
    SceneScanner(const char* b, const char* e, Numbers numbers) : p_(b), e_(e), numbers_(numbers) {}

    std::optional<CompactScene> scene() {
        CompactScene cs;
        bool seen[4] = {false, false, false, false};
        size_t values = 1;
        if (!lit('{')) return std::nullopt;
        for (bool first = true;; first = false) {
            if (!first && !lit(',')) break;
            std::string k;
            if (!key(k)) return std::nullopt;
            const int which = k == "P1" ? 0 : k == "P2" ? 1 : k == "I1" ? 2 : k == "I2" ? 3 : -1;
            if (which < 0 || seen[which]) return std::nullopt;
            seen[which] = true;
            ++values;
            if (which < 2) {
                if (!poly(cs, which, values)) return std::nullopt;
            } else {
                std::vector<Q> r;
                if (!numbers(r, 2)) return std::nullopt;
                values += 2;
                cs.lo[which - 2] = r[0];
                cs.hi[which - 2] = r[1];
            }
        }
        if (!lit('}')) return std::nullopt;
        ws();
        if (p_ != e_ || !(seen[0] && seen[1]) || values > kMaxJsonValues) return std::nullopt;
        for (int i = 0; i < 2; ++i)
            if (!seen[2 + i]) cs.lo[i] = cs.hi[i] = 1;  // no scaling: the objects as they are
        for (int i = 0; i < 2; ++i) {
            if (cs.P[i].size() < 4 || sgn(cs.lo[i]) <= 0 || cs.lo[i] > cs.hi[i])
                return std::nullopt;  // the reader words these
            if (!cs.seed_given[i]) cs.seed[i] = cs.P[i].mean();
        }
        return cs;
    }

  private:
    void ws() {
        while (p_ < e_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\n' || *p_ == '\r')) ++p_;
    }
    bool lit(char c) {
        ws();
        if (p_ < e_ && *p_ == c) return ++p_, true;
        return false;
    }
    bool key(std::string& k) {
        if (!lit('"')) return false;
        const char* b = p_;
        while (p_ < e_ && *p_ != '"') {
            if (*p_ == '\\' || static_cast<unsigned char>(*p_) < 0x20 || static_cast<unsigned char>(*p_) >= 0x80)
                return false;
            ++p_;
        }
        if (p_ == e_) return false;
        k.assign(b, p_++);
        return lit(':');
    }
    // A JSON number's text.
    bool number(const char*& b, const char*& e) {
        ws();
        b = p_;
        while (p_ < e_ &&
               (*p_ == '-' || *p_ == '+' || *p_ == '.' || *p_ == 'e' || *p_ == 'E' || (*p_ >= '0' && *p_ <= '9')))
            ++p_;
        e = p_;
        return json_number(b, e);
    }
    bool numbers(std::vector<Q>& out, size_t n) {
        if (!lit('[')) return false;
        for (size_t i = 0; i < n; ++i) {
            if (i && !lit(',')) return false;
            const char *b, *e;
            if (!number(b, e)) return false;
            try {
                const std::string text(b, e);
                if (!binary_is_exact(text, numbers_)) return false;
                out.push_back(parse_exact(text));
            } catch (const InputError&) {
                return false;
            }
        }
        return lit(']');
    }
    bool poly(CompactScene& cs, int i, size_t& values) {
        if (!lit('{')) return false;
        bool verts = false, seed = false;
        for (bool first = true;; first = false) {
            if (!first && !lit(',')) break;
            std::string k;
            if (!key(k)) return false;
            ++values;
            if (k == "vertices" && !verts) {
                verts = true;
                if (!vertices(cs.P[i], values)) return false;
            } else if (k == "seed" && !seed) {
                seed = true;
                std::vector<Q> s;
                if (!numbers(s, 3)) return false;
                values += 3;
                cs.seed[i] = {s[0], s[1], s[2]};
                cs.seed_given[i] = true;
            } else {
                return false;
            }
        }
        return verts && lit('}');
    }
    bool vertices(IntPoints& P, size_t& values) {
        if (!lit('[')) return false;
        std::vector<std::int8_t> ex;
        // Room for the rest of the file at 3 numbers in 6 bytes (address space only: pages are
        // touched as they fill).
        const auto room = std::min<size_t>(3 * kMaxPoints + 3, static_cast<size_t>(e_ - p_) / 2);
        P.x.reserve(room);
        ex.reserve(room);
        int lowest = 0;
        if (!lit(']')) {
            for (;;) {
                if (!lit('[')) return false;
                for (int k = 0; k < 3; ++k) {
                    if (k && !lit(',')) return false;
                    std::int64_t m;
                    int x10;
                    ws();
                    const char* q = p_;  // a local cursor: kept in a register
                    if (!read_decimal(q, e_, true, m, x10) || x10 < -18 || x10 > 18 || !binary_exact(m, x10, numbers_))
                        return false;
                    p_ = q;
                    P.x.push_back(m);
                    ex.push_back(static_cast<std::int8_t>(x10));
                    if (m != 0 && x10 < lowest) lowest = x10;
                }
                if (!lit(']')) return false;
                if (P.size() > kMaxPoints) return false;
                if (lit(']')) break;
                if (!lit(',')) return false;
            }
        }
        values += 4 * P.size();
        return scale_to(P, ex, lowest);
    }
    const char* p_;
    const char* e_;
    Numbers numbers_;
};
}  // namespace

std::optional<CompactScene> parse_scene_fast(const char* data, size_t size, Numbers numbers) {
    return SceneScanner(data, data + size, numbers).scene();
}

std::optional<CompactScene> read_scene_fast(const std::string& path, Numbers numbers) {
    std::optional<CompactScene> r;
    map_file(path, [&](const char* p, size_t n) { r = parse_scene_fast(p, n, numbers); });
    return r;
}

std::optional<CompactScene> compact_from_off(const std::string path[2], const Q lo[2], const Q hi[2],
                                             const std::optional<Vec3q> seed[2], Numbers numbers) {
    for (int i = 0; i < 2; ++i)
        if (sgn(lo[i]) <= 0 || lo[i] > hi[i]) return std::nullopt;
    std::future<std::optional<IntPoints>> read[2];
    for (int i = 0; i < 2; ++i)
        read[i] = std::async(std::launch::async, [&path, i, numbers]() -> std::optional<IntPoints> {
            try {
                if (mesh_format_of(path[i]) != MeshFormat::Off) return std::nullopt;
            } catch (const InputError&) {
                return std::nullopt;  // the full reader words it
            }
            return read_off_fast(path[i], numbers);
        });
    std::optional<IntPoints> pts[2];
    for (int i = 0; i < 2; ++i) pts[i] = read[i].get();  // both threads joined before returning
    if (!pts[0] || !pts[1]) return std::nullopt;
    CompactScene cs;
    for (int i = 0; i < 2; ++i) {
        cs.P[i] = std::move(*pts[i]);
        cs.lo[i] = lo[i];
        cs.hi[i] = hi[i];
        cs.seed_given[i] = seed[i].has_value();
        cs.seed[i] = seed[i] ? *seed[i] : cs.P[i].mean();
    }
    return cs;
}

std::optional<CompactScene> compact_scene(const ExactScene& sc) {
    if (sc.made_of_parts()) return std::nullopt;  // a compound is not one polyhedron
    if (sc.rounded()) return std::nullopt;        // nor is an object with a radius
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

ExactScene full_scene(const CompactScene& cs) {
    ExactScene sc;
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
