// scalecert-check: an independent checker for scalecert certificates (partition files, query
// answers and certify-fp's judgements). It shares no code with the engine: GMP rationals, the
// standard library and a JSON reader. Every claim is re-derived from the scene stored in the file, and nothing in the file is
// trusted: its kind is an explicit field, every object must have exactly the documented keys,
// duplicate keys are rejected, indices must be exact integers in range, and contact labels are
// recomputed from all maximisers. See certificates/FORMAT.md ("What the checker rejects").
// Exit 0: valid. Exit 1: the first claim that fails, on stderr. Exit 2: the file cannot be read
// (missing, too large, not strict JSON, too deeply nested, out of memory).
#include <gmpxx.h>
#include <nlohmann/json.hpp>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <map>
#include <memory>
#include <new>
#include <numeric>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace scalecert_check {
using J = nlohmann::json;
using Q = mpq_class;
using V3 = std::array<Q, 3>;
using P2 = std::array<Q, 2>;

// Limits on what is read at all (FORMAT.md): beyond them the file is unreadable (exit 2).
constexpr size_t kMaxFileBytes = size_t(1) << 30;  // 1 GiB
constexpr size_t kMaxDepth = 32;                    // certificates nest 7 levels deep

struct Invalid { std::string what; };  // a claim that fails: exit 1
struct Unreadable { std::string what; };  // not a readable file: exit 2

long g_claims = 0;
void claim(bool ok, const std::string& what) {
    ++g_claims;
    if (!ok) throw Invalid{what};
}
// The same, with the message built only when the claim fails (one that prints a number: a
// conversion to decimal costs more than the comparison).
template <class F>
void claim_lazy(bool ok, F what) {
    ++g_claims;
    if (!ok) throw Invalid{what()};
}

// ---- strict JSON (RFC 8259) -----------------------------------------------------------------
// nlohmann's SAX parser in strict mode without comments; this handler builds the tree itself so
// that it can reject duplicate keys (nlohmann keeps the last) and nesting deeper than kMaxDepth.
class StrictTree : public nlohmann::json_sax<J> {
public:
    J root;
    std::string error;
    bool null() override { return put(J(nullptr)); }
    bool boolean(bool v) override { return put(J(v)); }
    bool number_integer(number_integer_t v) override { return put(J(v)); }
    bool number_unsigned(number_unsigned_t v) override { return put(J(v)); }
    bool number_float(number_float_t v, const string_t&) override { return put(J(v)); }
    bool string(string_t& s) override { return put(J(std::move(s))); }
    bool binary(binary_t&) override { return fail("binary values are not JSON"); }
    bool start_object(std::size_t) override { return open(J::object()); }
    bool start_array(std::size_t) override { return open(J::array()); }
    bool end_object() override { stack_.pop_back(); return true; }
    bool end_array() override { stack_.pop_back(); return true; }
    bool key(string_t& k) override {
        if (stack_.back()->contains(k)) return fail("duplicate key \"" + printable(k) + "\"");
        key_ = std::move(k);
        return true;
    }
    bool parse_error(std::size_t pos, const std::string&, const nlohmann::detail::exception&) override {
        if (error.empty()) error = "not strict JSON (RFC 8259) near byte " + std::to_string(pos);
        return false;
    }
    static std::string printable(const std::string& s) {
        std::string out;
        for (unsigned char c : s.substr(0, 40)) out += (c < 0x20 || c == 0x7f) ? '?' : static_cast<char>(c);
        return s.size() > 40 ? out + "..." : out;
    }

private:
    std::vector<J*> stack_;
    std::string key_;
    bool fail(const std::string& why) {
        if (error.empty()) error = why;
        return false;
    }
    J* place(J v) {
        if (stack_.empty()) { root = std::move(v); return &root; }
        J& top = *stack_.back();
        if (top.is_array()) { top.push_back(std::move(v)); return &top.back(); }
        return &(top[key_] = std::move(v));
    }
    bool put(J v) { place(std::move(v)); return true; }
    bool open(J v) {
        if (stack_.size() >= kMaxDepth) return fail("nested deeper than " + std::to_string(kMaxDepth) + " levels");
        stack_.push_back(place(std::move(v)));
        return true;
    }
};

J parse_strict(const std::string& text) {
    // nlohmann's reader stops at a NUL byte as at the end of the input: what follows one would
    // go unread. A byte-order mark is not JSON either (RFC 8259 forbids writing one).
    if (text.find('\0') != std::string::npos) throw Unreadable{"not strict JSON: a NUL byte in the text"};
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) throw Unreadable{"not strict JSON: a byte-order mark"};
    StrictTree t;
    if (!J::sax_parse(text, &t, J::input_format_t::json, true, false)) throw Unreadable{t.error.empty() ? "not strict JSON" : t.error};
    return std::move(t.root);
}

// ---- shapes ---------------------------------------------------------------------------------
// o is an object with every key of `required`, and no key outside required ∪ optional.
void shape(const J& o, const std::string& where, std::initializer_list<const char*> required,
           std::initializer_list<const char*> optional = {}) {
    claim(o.is_object(), (where.empty() ? std::string("the file") : where) + " is an object");
    for (const char* k : required) claim(o.contains(k), where + (where.empty() ? "" : ".") + k + " is present");
    for (auto it = o.begin(); it != o.end(); ++it) {
        bool known = false;
        for (const char* k : required) known = known || it.key() == k;
        for (const char* k : optional) known = known || it.key() == k;
        claim(known, (where.empty() ? std::string("the file") : where) + " has no field \"" + StrictTree::printable(it.key()) + "\"");
    }
}
const J& at(const J& o, const char* k) { return o.find(k).value(); }  // after shape(): present

// A JSON integer >= 0 written without sign, fraction or exponent (nlohmann reads "-0" as a signed
// integer: refused).
bool natural(const J& j) { return j.is_number_unsigned(); }

// An index: a JSON integer (no fraction, no exponent) with 0 <= i < n.
size_t index(const J& j, size_t n, const std::string& where) {
    claim(natural(j), where + " is a non-negative JSON integer");
    const unsigned long long v = j.get<unsigned long long>();
    claim(v < n, where + " = " + std::to_string(v) + " is an index below " + std::to_string(n));
    return static_cast<size_t>(v);
}
// A nonempty list of distinct indices below n.
std::vector<int> index_list(const J& j, size_t n, const std::string& where) {
    claim(j.is_array() && !j.empty(), where + " is a nonempty list of indices");
    std::vector<int> out;
    std::set<size_t> seen;
    for (size_t k = 0; k < j.size(); ++k) {
        size_t i = index(j[k], n, where + "[" + std::to_string(k) + "]");
        claim(seen.insert(i).second, where + " names each vertex once");
        out.push_back(static_cast<int>(i));
    }
    return out;
}
// x is in v (ascending: every vertex list the checker builds is).
bool has(const std::vector<int>& v, int x) { return std::binary_search(v.begin(), v.end(), x); }

// ---- numbers -------------------------------------------------------------------------------
// An exact number: "p" or "p/q", in lowest terms, q > 0.
Q num(const J& j, const std::string& where) {
    claim(j.is_string(), where + " is an exact number string");
    const std::string& s = j.get_ref<const std::string&>();
    size_t slash = s.find('/');
    auto is_int = [](const std::string& t, bool sign) {
        size_t b = (sign && !t.empty() && t[0] == '-') ? 1 : 0;
        return t.size() > b && t.find_first_not_of("0123456789", b) == std::string::npos &&
               (t.size() == b + 1 || t[b] != '0');
    };
    bool ok = slash == std::string::npos ? is_int(s, true) : is_int(s.substr(0, slash), true) && is_int(s.substr(slash + 1), false);
    claim(ok, where + " = '" + StrictTree::printable(s) + "' is an integer or p/q");
    Q q(s, 10);
    claim(sgn(q.get_den()) > 0, where + " has a nonzero denominator");
    Q c = q;
    c.canonicalize();
    claim(c.get_str() == s, where + " = '" + StrictTree::printable(s) + "' is in lowest terms");
    return c;
}

// The double nearest to q, ties to even (GMP only); ±infinity when that rounding overflows.
double nearest(const Q& q) {
    if (sgn(q) == 0) return 0.0;
    mpz_class n = abs(q.get_num()), d = q.get_den(), m, r, D;
    long e = static_cast<long>(mpz_sizeinbase(n.get_mpz_t(), 2)) - static_cast<long>(mpz_sizeinbase(d.get_mpz_t(), 2)) - 53;
    for (int it = 0; it < 4; ++it) {
        mpz_class N = n;
        D = d;
        if (e < -1074) e = -1074;
        if (e > 2000) break;  // far beyond the double range: infinity below
        if (e < 0) N <<= static_cast<unsigned long>(-e); else D <<= static_cast<unsigned long>(e);
        mpz_fdiv_qr(m.get_mpz_t(), r.get_mpz_t(), N.get_mpz_t(), D.get_mpz_t());
        if (m >= (mpz_class(1) << 53)) { ++e; continue; }
        if (m < (mpz_class(1) << 52) && e > -1074) { --e; continue; }
        break;
    }
    if (e > 2000) return sgn(q) < 0 ? -HUGE_VAL : HUGE_VAL;
    int c = cmp(mpz_class(2 * r), D);
    if (c > 0 || (c == 0 && mpz_odd_p(m.get_mpz_t()))) ++m;
    double v = std::ldexp(m.get_d(), static_cast<int>(e));  // overflows to infinity past the range
    return sgn(q) < 0 ? -v : v;
}
// The `_double` of q: the nearest double, bit for bit (so -0 is not 0), or null exactly when the
// nearest double would be infinite (the value is beyond the double range).
bool is_nearest(const J& d, const Q& q) {
    const double x = nearest(q);
    if (std::isinf(x)) return d.is_null();
    if (!d.is_number()) return false;
    const double y = d.get<double>();
    return y == x && std::signbit(y) == std::signbit(x);
}

// An exact field `key` of o, with its neighbour `key_double` (shape() has required both).
Q field(const J& o, const std::string& key, const std::string& where) {
    const std::string w = where.empty() ? key : where + "." + key;
    Q q = num(o.at(key), w);
    claim_lazy(is_nearest(o.at(key + "_double"), q), [&] { return w + "_double is the nearest double to " + StrictTree::printable(q.get_str()); });
    return q;
}
std::vector<Q> fields(const J& o, const std::string& key, size_t n, const std::string& where) {
    claim(o.at(key).is_array() && o.at(key).size() == n, where + "." + key + " has " + std::to_string(n) + " entries");
    const J& dd = o.at(key + "_double");
    claim(dd.is_array() && dd.size() == n, where + "." + key + "_double has " + std::to_string(n) + " entries");
    std::vector<Q> out;
    for (size_t i = 0; i < n; ++i) {
        std::string w = where + "." + key + "[" + std::to_string(i) + "]";
        out.push_back(num(o.at(key)[i], w));
        claim(is_nearest(dd[i], out.back()), w + "_double is the nearest double");
    }
    return out;
}

Q dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 cross(const V3& a, const V3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
bool nonzero(const V3& v) { return sgn(v[0]) || sgn(v[1]) || sgn(v[2]); }
V3 point(const J& j, const std::string& where) {
    claim(j.is_array() && j.size() == 3, where + " is a point of 3 coordinates");
    return {num(j[0], where + "[0]"), num(j[1], where + "[1]"), num(j[2], where + "[2]")};
}

// ---- the work limit ---------------------------------------------------------------------------
// The support scans cost (distinct normals) × (vertices), and a vertex named in a list costs its
// own digits wherever it is named: products of sizes the file does not pay for one by one. Each
// such step is counted here, in units of about a nanosecond, before it runs; past g_work_per_byte
// units a byte of the file (at least g_min_work) the file is refused as unreadable (exit 2), at a
// point that depends on the file only. Certificates the engine writes use a few units a byte
// (FORMAT.md, "What the checker costs"). (Variables, not constants, for the tests.)
double g_work_per_byte = 600, g_min_work = 6e8;
double g_work = 0, g_budget = 6e8;
void spend(double units) {
    g_work += units;
    if (g_work > g_budget)
        throw Unreadable{"beyond the checker's work limit (" + std::to_string(static_cast<long long>(g_work_per_byte)) +
                         " units a byte of the file; FORMAT.md \"What the checker costs\")"};
}
double limbs(const mpz_class& z) { return static_cast<double>(mpz_size(z.get_mpz_t())); }
// Rational arithmetic on numbers of the file and the scene, counted before it runs: `ops`
// operations (each a product and the gcd that keeps it in lowest terms) whose operands total m
// limbs, at 30 + m²/16 units each: above the measured cost (GMP's products and gcds are quadratic
// at the sizes certificates hold, and cost less than counted beyond). A number stored once but
// used by every judgement — a tolerance, a seed — is counted at each use. (Measured: seeds of
// 100 and 1,000 limbs cost 36 µs and 1 ms a plane judgement, counted 120,000 and 1.2·10^7 units;
// a tolerance of 100 limbs 25 µs a distance judgement, counted 88,000.)
double qsize(const Q& q) { return limbs(q.get_num()) + limbs(q.get_den()); }
void spend_ops(double ops, double m) { spend(ops * (30 + m * m / 16)); }

// ---- support scans --------------------------------------------------------------------------
// Every support value h_i(n) and every list of maximisers is a scan of all the vertices of a
// polytope, once per normal direction: with the lists of normals a file may hold, the checker's
// largest cost. The scan compares u·X_k, X_k = D v_k, over the vertices v_k, where D > 0 is the
// lcm of the denominators of the polytope's vertex coordinates (at most 2^16384, the engine's own
// limit): this orders the vertices as u·(v_k − s_i) does. Exact in every case, in the cheapest
// arithmetic the numbers allow. The vertices whose X coordinates are all below 2^62 in magnitude
// are also held as int64; with every such |X| < 2^b and an integer u with every |u_c| < 2^c they
// are scanned
//   - b + c <= 61: in int64. Each product u_c X_c is below 2^61 in magnitude, each partial sum
//     below 3·2^61 < 2^63: no overflow;
//   - b <= 62 and c <= 62: in __int128. Each product is below 2^124 in magnitude, each partial
//     sum below 3·2^124 < 2^126 < 2^127;
//   - otherwise (a normal past 2^62): in mpz.
// The other vertices (a few large numbers among many small ones cost the small ones nothing) in
// mpz, and the two maxima compared in mpz. The maximisers found are exactly those of the
// rational comparison, in ascending order (tests/test_checker.cpp compares both on random scenes
// of every number kind, mixed sizes among them).
class Scan {
public:
    Scan(const std::vector<V3>& v, const std::string& what) : n_(v.size()) {
        for (const V3& p : v)
            for (const Q& c : p) {
                if (mpz_cmp_ui(c.get_den_mpz_t(), 1) != 0) mpz_lcm(D_.get_mpz_t(), D_.get_mpz_t(), c.get_den_mpz_t());
                if (mpz_sizeinbase(D_.get_mpz_t(), 2) > 16384)
                    throw Unreadable{"the common denominator of " + what + "'s vertex coordinates has more than 16384 bits (scalecert's own limit)"};
            }
        spend(static_cast<double>(n_) * (10 + 3 * limbs(D_)));
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
    // The vertices k (of `subset`, ascending, or of all) at which u·v_k is largest, ascending.
    // u has integer coordinates.
    std::vector<int> argmax(const std::array<mpz_class, 3>& u, const std::vector<int>* subset = nullptr) const {
        int ub = 0;
        for (const mpz_class& c : u) ub = std::max(ub, static_cast<int>(mpz_sizeinbase(c.get_mpz_t(), 2)));
        int64_t w[3] = {0, 0, 0};
        const bool small_u = small_int(u[0].get_mpz_t(), w[0]) && small_int(u[1].get_mpz_t(), w[1]) && small_int(u[2].get_mpz_t(), w[2]);
        // The machine-size vertices (at compact positions) and the others.
        std::vector<int> mlist, blist;
        const bool all = !subset;
        if (subset)
            for (int k : *subset) (pos_[static_cast<size_t>(k)] >= 0 ? mlist.push_back(pos_[static_cast<size_t>(k)]) : blist.push_back(k));
        const std::vector<int>& bl = all ? big_ : blist;
        const size_t nm = all ? X_[0].size() : mlist.size();
        std::vector<int> mout, bout;
        mpz_class mbest, bbest;
        if (nm > 0) {
            const int* at = all ? nullptr : mlist.data();
            const int64_t *x = X_[0].data(), *y = X_[1].data(), *z = X_[2].data();
            if (small_u && bits_ + ub <= 61) {
                spend(static_cast<double>(nm));
                const int64_t a = w[0], b = w[1], c = w[2];
                auto value = [=](size_t k) { return a * x[k] + b * y[k] + c * z[k]; };
                const int64_t best = at ? scan<int64_t>(nm, at, value, mout) : scan<int64_t>(nm, value, mout);
                if (all && bl.empty()) return mout;  // every vertex is at its own position
                mbest = static_cast<long>(best);
            } else if (small_u) {
                spend(2.0 * static_cast<double>(nm));
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
                if (all) list = orig_;
                else for (int p : mlist) list.push_back(orig_[static_cast<size_t>(p)]);
                mout = mpz_scan(u, list, mbest);
            }
        }
        if (!bl.empty()) bout = mpz_scan(u, bl, bbest);
        if (bout.empty()) return mout;
        if (mout.empty()) return bout;
        const int c = cmp(mbest, bbest);
        if (c != 0) return c > 0 ? mout : bout;
        std::vector<int> both;  // equal maxima: the two ascending lists merged
        std::merge(mout.begin(), mout.end(), bout.begin(), bout.end(), std::back_inserter(both));
        return both;
    }
    const mpz_class& D() const { return D_; }
    const std::array<mpz_class, 3>& X(size_t k) const { return Z_[k]; }  // D v_k
    size_t size() const { return n_; }

private:
    size_t n_;
    mpz_class D_ = 1;
    std::vector<std::array<mpz_class, 3>> Z_;  // X_k = D v_k
    // The vertices whose X coordinates are all below 2^62 in magnitude, held as int64 at compact
    // positions (orig_: position -> vertex, pos_: vertex -> position or -1), and the others (big_).
    std::vector<int64_t> X_[3];
    std::vector<int> orig_, pos_, big_;
    int bits_ = 0;         // every machine |X| < 2^bits_
    double big_limbs_[3] = {0, 0, 0};  // the limbs of the others' X, by coordinate

    // z as an int64 when |z| < 2^62 (and long holds it); false otherwise.
    static bool small_int(mpz_srcptr z, int64_t& out) {
        if (mpz_sizeinbase(z, 2) > 62 || !mpz_fits_slong_p(z)) return false;
        out = mpz_get_si(z);
        return true;
    }
    static mpz_class from128(__int128 v) {
        const bool neg = v < 0;
        unsigned __int128 a = neg ? -static_cast<unsigned __int128>(v) : static_cast<unsigned __int128>(v);
        mpz_class r(static_cast<unsigned long>(static_cast<uint64_t>(a >> 64)));
        r <<= 64;
        r += static_cast<unsigned long>(static_cast<uint64_t>(a));
        return neg ? mpz_class(-r) : r;
    }
    // u·X_k over the vertices of `list` (ascending) in GMP integers: the maximisers, ascending, and
    // the maximum in `best`. About 40 units a vertex and half a unit a limb product (measured: 45 ns
    // a vertex of one-limb numbers, 250 ns for 256-limb coordinates and a one-limb normal).
    std::vector<int> mpz_scan(const std::array<mpz_class, 3>& u, const std::vector<int>& list, mpz_class& best) const {
        double units = 40 * static_cast<double>(list.size());
        for (int c = 0; c < 3; ++c) {
            double lx = 0;
            if (&list == &big_) lx = big_limbs_[c];
            else for (int k : list) lx += limbs(Z_[static_cast<size_t>(k)][c]);
            units += 0.5 * std::max(1.0, limbs(u[c])) * lx;
        }
        spend(units);
        std::vector<int> out;
        mpz_class v;
        for (int k : list) {
            const auto& X = Z_[static_cast<size_t>(k)];
            mpz_mul(v.get_mpz_t(), u[0].get_mpz_t(), X[0].get_mpz_t());
            mpz_addmul(v.get_mpz_t(), u[1].get_mpz_t(), X[1].get_mpz_t());
            mpz_addmul(v.get_mpz_t(), u[2].get_mpz_t(), X[2].get_mpz_t());
            const int c = out.empty() ? 1 : cmp(v, best);
            if (c > 0) { mpz_swap(best.get_mpz_t(), v.get_mpz_t()); out.clear(); }
            if (c >= 0) out.push_back(k);
        }
        return out;
    }
    // All vertices, in one pass: the running maximum in a register, the list touched only when
    // a vertex reaches it (rarely, once the maximum is found). Returns the maximum.
    template <class T, class F>
    static T scan(size_t n, F value, std::vector<int>& out) {
        out.reserve(8);
        out.push_back(0);
        T best = value(0);
        for (size_t k = 1; k < n; ++k) {
            const T v = value(k);
            if (__builtin_expect(v >= best, 0)) {
                if (v > best) { best = v; out.clear(); }
                out.push_back(static_cast<int>(k));
            }
        }
        return best;
    }
    // The positions of a list (ascending), in one pass.
    template <class T, class F>
    static T scan(size_t n, const int* at, F value, std::vector<int>& out) {
        T best{};
        for (size_t j = 0; j < n; ++j) {
            const size_t k = static_cast<size_t>(at[j]);
            const T v = value(k);
            if (out.empty() || v >= best) {
                if (out.empty() || v > best) { best = v; out.clear(); }
                out.push_back(static_cast<int>(k));
            }
        }
        return best;
    }
};

using Z3 = std::array<mpz_class, 3>;
mpz_class dotz(const Z3& a, const Z3& b) {
    mpz_class r;
    mpz_mul(r.get_mpz_t(), a[0].get_mpz_t(), b[0].get_mpz_t());
    mpz_addmul(r.get_mpz_t(), a[1].get_mpz_t(), b[1].get_mpz_t());
    mpz_addmul(r.get_mpz_t(), a[2].get_mpz_t(), b[2].get_mpz_t());
    return r;
}
Z3 ints(const V3& n) { return {n[0].get_num(), n[1].get_num(), n[2].get_num()}; }  // an integer vector

// ---- the scene ------------------------------------------------------------------------------
// The claims compare exact values of the file against values recomputed from the scene. A value
// from the scene is an integer over one joint denominator D*, the lcm of both polytopes' vertex
// denominators and the seeds' (S_i = D* s_i, Delta = D* (s2 − s1), H_i = D* h_i): every
// recomputed quantity is then an integer combination of the scene's numbers, and each comparison
// with a number p/q of the file, p D* = q H, costs a product by the file's own number, never a gcd
// of two of the scene's numbers (which would cost, per normal or per named vertex, a power of
// digits the file pays for once).
struct Scene {
    std::vector<V3> P[2];
    V3 s[2];
    Q lo[2], hi[2];
    std::unique_ptr<Scan> scan[2];
    mpz_class Dj = 1, E[2];  // D* and D*/D_i
    Z3 S[2], Delta;          // D* s_i and D* (s2 − s1)
    std::array<Q, 3> sdv[2]; // D_i s_i = S_i / E_i (exact rationals), for the combinations over D_i
    void prepare() {
        for (int i = 0; i < 2; ++i) {
            mpz_lcm(Dj.get_mpz_t(), Dj.get_mpz_t(), scan[i]->D().get_mpz_t());
            for (const Q& c : s[i]) mpz_lcm(Dj.get_mpz_t(), Dj.get_mpz_t(), c.get_den_mpz_t());
        }
        spend(100 + 20 * limbs(Dj));
        for (int i = 0; i < 2; ++i) {
            E[i] = Dj / scan[i]->D();
            for (int c = 0; c < 3; ++c) {
                mpz_divexact(S[i][c].get_mpz_t(), Dj.get_mpz_t(), s[i][c].get_den_mpz_t());
                S[i][c] *= s[i][c].get_num();
            }
            sdv[i] = {Q(S[i][0], E[i]), Q(S[i][1], E[i]), Q(S[i][2], E[i])};
            for (Q& q : sdv[i]) q.canonicalize();
        }
        for (int c = 0; c < 3; ++c) Delta[c] = S[1][c] - S[0][c];
    }

    // D* h_i(u) for an integer u, given a vertex k attaining the maximum of u·v: u·X_k E_i − u·S_i
    // (h_1(n) = n·(v − s1) with u = n; h_2(n) = −n·(w − s2) with u = −n).
    mpz_class support_at(int i, const Z3& u, int k) const {
        spend_at(i, k);
        mpz_class r = dotz(u, scan[i]->X(static_cast<size_t>(k))) * E[i];
        r -= dotz(u, S[i]);
        return r;
    }
    // h_i(n), max over the vertices of σ n·(v − s_i) (σ = +1 for P1, −1 for P2), and every vertex
    // attaining it (ascending): the rational value (tests compare it with a plain rational scan).
    Q h(int i, const V3& n, std::vector<int>* argmax = nullptr) const {
        Z3 u = ints(n);
        if (i == 1) for (auto& c : u) c = -c;
        std::vector<int> m = scan[i]->argmax(u);
        Q r(support_at(i, u, m[0]), Dj);
        r.canonicalize();
        if (argmax) *argmax = std::move(m);
        return r;
    }
    // Both support values of n over D* (H_i = D* h_i(n)) and their maximisers, computed once per
    // direction: n = g p with p primitive and g > 0 has the maximisers of p and H_i(n) = g H_i(p)
    // (h is positively homogeneous), so a normal repeated, or listed again as a multiple, costs no
    // second scan. Returns the direction's entry (the same pointer for the same direction).
    struct Support { mpz_class H[2]; std::vector<int> max[2]; };
    const Support* support(const V3& n, mpz_class H_out[2], const std::vector<int>* max_out[2] = nullptr) const {
        mpz_class g = 0;
        for (const Q& c : n) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_num_mpz_t());
        Z3 p;
        std::string key;
        for (int c = 0; c < 3; ++c) {
            mpz_divexact(p[c].get_mpz_t(), n[c].get_num_mpz_t(), g.get_mpz_t());
            key += p[c].get_str(16) + ",";
        }
        auto it = cache_.find(key);
        if (it == cache_.end()) {
            Support e;
            for (int i = 0; i < 2; ++i) {
                Z3 u = p;
                if (i == 1) for (auto& c : u) c = -c;
                e.max[i] = scan[i]->argmax(u);
                e.H[i] = support_at(i, u, e.max[i][0]);
            }
            it = cache_.emplace(std::move(key), std::move(e)).first;
        }
        for (int i = 0; i < 2; ++i) {
            H_out[i] = it->second.H[i] * g;
            if (max_out) max_out[i] = &it->second.max[i];
        }
        return &it->second;
    }
    // q == H / D* (q a number of the file, H over D*).
    bool over(const Q& q, const mpz_class& H) const { return q.get_num() * Dj == q.get_den() * H; }
    Q value(const mpz_class& H) const { Q r(H, Dj); r.canonicalize(); return r; }  // H / D*, for messages
    // The work of one product by vertex k's integers and D*'s (a place on a line, a support value).
    void spend_at(int i, int k) const {
        const Z3& x = scan[i]->X(static_cast<size_t>(k));
        spend(20 + 4 * (limbs(x[0]) + limbs(x[1]) + limbs(x[2]) + limbs(E[i]) + limbs(S[i][0]) + limbs(S[i][1]) + limbs(S[i][2])));
    }

private:
    mutable std::map<std::string, Support> cache_;
};
const char* kPoly[2] = {"P1", "P2"};

// The dimension of the affine hull of a vertex set, in one pass: a vertex that does not raise it
// lies in the hull of those before, which only grows. On X_k = D v_k (the same dimension).
int affine_dim(const Scene& sc, int i, const std::vector<int>& idx) {
    const Scan& s = *sc.scan[i];
    const Z3& o = s.X(static_cast<size_t>(idx[0]));
    int dim = 0;
    Z3 e1, c, v, x;
    for (int k : idx) {
        const Z3& p = s.X(static_cast<size_t>(k));
        const double l = 1 + limbs(p[0]) + limbs(p[1]) + limbs(p[2]) + limbs(o[0]) + limbs(o[1]) + limbs(o[2]);
        spend(30 + 4 * l * l);
        for (int j = 0; j < 3; ++j) v[j] = p[j] - o[j];
        const bool nz = sgn(v[0]) || sgn(v[1]) || sgn(v[2]);
        if (dim == 0 && nz) { e1 = v; dim = 1; continue; }
        if (dim == 1) {
            x = {e1[1] * v[2] - e1[2] * v[1], e1[2] * v[0] - e1[0] * v[2], e1[0] * v[1] - e1[1] * v[0]};
            if (sgn(x[0]) || sgn(x[1]) || sgn(x[2])) { c = x; dim = 2; }
            continue;
        }
        if (dim == 2 && sgn(dotz(c, v)) != 0) return 3;
    }
    return dim;
}
// The letter of a vertex set: the dimension of its affine hull (V: a point, E: a segment, F: a
// polygon or more).
char dimension_letter(const Scene& sc, int i, const std::vector<int>& idx) { return "VEFF"[affine_dim(sc, i, idx)]; }

void read_ranges(Scene& sc, const J& j);
Scene read_scene(const J& j) {
    shape(j, "scene", {"P1", "P2", "I1", "I2"});
    Scene sc;
    for (int i = 0; i < 2; ++i) {
        const std::string w = std::string("scene.") + kPoly[i];
        const J& p = at(j, kPoly[i]);
        shape(p, w, {"vertices", "seed"});
        const J& vs = at(p, "vertices");
        claim(vs.is_array(), w + ".vertices is a list");
        for (size_t k = 0; k < vs.size(); ++k) sc.P[i].push_back(point(vs[k], w + ".vertices[" + std::to_string(k) + "]"));
        claim(sc.P[i].size() >= 4, w + " has at least 4 vertices");
        sc.s[i] = point(at(p, "seed"), w + ".seed");
        sc.scan[i] = std::make_unique<Scan>(sc.P[i], kPoly[i]);
    }
    sc.prepare();
    read_ranges(sc, j);
    return sc;
}

// I1 and I2 of a scene object: [lo, hi] with 0 < lo <= hi.
void read_ranges(Scene& sc, const J& j) {
    const char* iv[2] = {"I1", "I2"};
    for (int i = 0; i < 2; ++i) {
        const J& r = at(j, iv[i]);
        claim(r.is_array() && r.size() == 2, std::string("scene.") + iv[i] + " is [lo, hi]");
        sc.lo[i] = num(r[0], std::string("scene.") + iv[i] + "[0]");
        sc.hi[i] = num(r[1], std::string("scene.") + iv[i] + "[1]");
        claim(sgn(sc.lo[i]) > 0 && sc.lo[i] <= sc.hi[i], std::string("scene.") + iv[i] + " has 0 < lo <= hi");
    }
}

// Weights [[index, "w"], ...] over polyhedron i: distinct indices, w > 0, sum 1. Returns
// D_i Σ w v = Σ w X: each term a product of the file's weight and the scene's integers.
// Indices are into the vertices [base, base + count) of the polyhedron (a compound's part), base
// added: by default all of them.
std::array<Q, 3> combination(const Scene& sc, int i, const J& w, const std::string& where, std::vector<int>* used = nullptr,
                             size_t base = 0, size_t count = SIZE_MAX) {
    if (count == SIZE_MAX) count = sc.P[i].size();
    claim(w.is_array() && !w.empty(), where + " is a nonempty list of weights");
    std::set<size_t> seen;
    Q total = 0;
    std::array<Q, 3> x{Q(0), Q(0), Q(0)};
    for (size_t k = 0; k < w.size(); ++k) {
        std::string wk = where + "[" + std::to_string(k) + "]";
        claim(w[k].is_array() && w[k].size() == 2, wk + " is [index, weight]");
        size_t idx = base + index(w[k][0], count, wk + " index");
        claim(seen.insert(idx).second, wk + " names a distinct vertex");
        Q l = num(w[k][1], wk + " weight");
        claim(sgn(l) > 0, wk + " weight is > 0");
        // The running sums' denominators can grow with every term (weights over coprime
        // denominators), and each addition costs their size, gcd included: counted first.
        spend(100 * (limbs(total.get_den()) + limbs(x[0].get_den()) + limbs(x[1].get_den()) + limbs(x[2].get_den())));
        total += l;
        const Z3& X = sc.scan[i]->X(idx);
        spend(100 + 10 * (1 + limbs(l.get_num()) + limbs(l.get_den())) * (1 + limbs(X[0]) + limbs(X[1]) + limbs(X[2])));
        for (int c = 0; c < 3; ++c) x[c] += l * Q(X[c]);
        if (used) used->push_back(static_cast<int>(idx));
    }
    claim(total == 1, where + " weights sum to 1");
    return x;
}

// The seed is a strictly positive combination of vertices that span 3 dimensions: interior.
void check_seed_interior(const Scene& sc, const J& j) {
    shape(j, "seed_interior", {"P1", "P2"});
    for (int i = 0; i < 2; ++i) {
        std::string w = std::string("seed_interior.") + kPoly[i];
        std::vector<int> used;
        claim(combination(sc, i, at(j, kPoly[i]), w, &used) == sc.sdv[i], w + " combines to the seed");
        const bool spans = affine_dim(sc, i, used) == 3;
        claim(spans, w + " uses vertices spanning 3 dimensions");
    }
}

// A witness: a common point of P1(ρ1) and P2(ρ2), s + ρ Σ λ (v − s) on each side. With
// c = Σ λ X / D_i (combination()), the point y = s + ρ (c − s) equals p iff
// ρ D_i c = D_i p + (ρ − 1) D_i s: products of the file's numbers and the scene's.
// parts: for a compound, each side's part as [base, count) of its vertices (combination()).
P2 check_witness(const Scene& sc, const J& w, const std::string& where, std::vector<int>* used = nullptr,
                 const std::array<std::array<size_t, 2>, 2>* parts = nullptr) {
    shape(w, where, {"rho1", "rho1_double", "rho2", "rho2_double", "point", "point_double", "P1", "P2"});
    Q r1 = field(w, "rho1", where), r2 = field(w, "rho2", where);
    claim(sgn(r1) >= 0 && sgn(r2) >= 0, where + " scalings are >= 0");
    std::vector<Q> x = fields(w, "point", 3, where);
    const Q* r[2] = {&r1, &r2};
    for (int i = 0; i < 2; ++i) {
        std::array<Q, 3> c = combination(sc, i, at(w, kPoly[i]), where + "." + kPoly[i], used ? &used[i] : nullptr,
                                         parts ? (*parts)[i][0] : 0, parts ? (*parts)[i][1] : SIZE_MAX);
        const Q D(sc.scan[i]->D());
        bool on = true;
        for (int k = 0; k < 3; ++k) on = on && *r[i] * c[k] == x[k] * D + (*r[i] - 1) * sc.sdv[i][k];
        claim(on, where + ".point lies in " + kPoly[i] + "(rho" + std::to_string(i + 1) + ")");
    }
    return {r1, r2};
}

V3 normal(const J& j, const std::string& where) {
    claim(j.is_array() && j.size() == 3, where + " is a normal of 3 integers");
    V3 n = point(j, where);
    for (const Q& c : n) claim(c.get_den() == 1, where + " has integer components");
    claim(nonzero(n), where + " is nonzero");
    return n;
}

std::string contact_string(const J& j, const std::string& where) {
    claim(j.is_string() && j.get_ref<const std::string&>().size() == 2, where + " is a two-letter contact");
    return j.get<std::string>();
}

// ---- the partition ----------------------------------------------------------------------------
struct Line { Q a, b; Q at(const Q& x) const { return a * x + b; } };

// A convex polygon given counter-clockwise, whose vertices may repeat or lie inside an edge, in
// its one written form: its corners only (no repeated or collinear vertices), from the lowest
// (then leftmost) one; a polygon of two distinct points as the two sorted, of one as that point.
// One pass with a stack drops every vertex collinear with its neighbours, then the same at the
// wrap-around: linear. Every polygon the checker builds is such a list (the rectangle, the
// boxes, their clips by one line, the overlap region below); for them this is what removing
// collinear vertices one at a time, in any order, gives: the corners of a convex polygon are the
// vertices at which it turns, and dropping a vertex where it does not turn changes no other turn.
// (tests/test_checker.cpp compares it with that removal on random polygons.)
std::vector<P2> normalize(const std::vector<P2>& p) {
    auto turn = [](const P2& o, const P2& a, const P2& b) { return sgn((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])); };
    std::vector<P2> d;
    for (const P2& v : p) if (d.empty() || d.back() != v) d.push_back(v);
    while (d.size() > 1 && d.front() == d.back()) d.pop_back();
    std::vector<P2> q;
    if (d.size() <= 2) q = std::move(d);
    else {
        for (P2& v : d) {
            while (q.size() >= 2 && turn(q[q.size() - 2], q.back(), v) == 0) q.pop_back();
            q.push_back(std::move(v));
        }
        size_t b = 0;  // the polygon is q[b..]: the wrap-around, last against first and first against last
        while (q.size() - b > 2) {
            if (q.back() == q[b] || turn(q[q.size() - 2], q.back(), q[b]) == 0) q.pop_back();
            else if (turn(q.back(), q[b], q[b + 1]) == 0) ++b;
            else break;
        }
        q.erase(q.begin(), q.begin() + static_cast<long>(b));
    }
    if (q.size() == 2 && q[1] < q[0]) std::swap(q[0], q[1]);
    if (q.size() > 2) std::rotate(q.begin(), std::min_element(q.begin(), q.end(), [](const P2& a, const P2& b) { return a[1] != b[1] ? a[1] < b[1] : a[0] < b[0]; }), q.end());
    return q;
}

// The convex polygon p cut to a x + b y >= c (not counted: the callers count it).
std::vector<P2> half_plane_cut(const std::vector<P2>& p, const Q& a, const Q& b, const Q& c) {
    std::vector<P2> out;
    for (size_t i = 0; i < p.size(); ++i) {
        const P2 &u = p[i], &v = p[(i + 1) % p.size()];
        const Q fu = a * u[0] + b * u[1] - c, fv = a * v[0] + b * v[1] - c;
        if (sgn(fu) >= 0) out.push_back(u);
        if (sgn(fu) * sgn(fv) < 0) { Q t = fu / (fu - fv); out.push_back({u[0] + t * (v[0] - u[0]), u[1] + t * (v[1] - u[1])}); }
    }
    return normalize(out);
}
// p cut to ρ2 >= L(ρ1) (above) or ρ2 <= L(ρ1).
std::vector<P2> clip(const std::vector<P2>& p, const Line& L, bool above) {
    return above ? half_plane_cut(p, -L.a, Q(1), L.b) : half_plane_cut(p, L.a, Q(-1), -L.b);
}

// The overlap region I1 × I2 ∩ {ρ2 >= curve}, from the pieces once they are verified: contiguous
// over I1, each nonempty, neighbouring lines equal at their common end (the switch points), slopes
// increasing. So the curve c is continuous and convex on I1, and each piece's line, which agrees
// with c on an interval, supports it: L_k <= c on all of I1, and max_k L_k = c there. Clipping the
// rectangle by every line (the earlier method, O(K) clips of polygons of up to K + 4 vertices)
// therefore gives the set {(ρ1, ρ2) in the rectangle : ρ2 >= c(ρ1)}, which this walk lists
// directly, counter-clockwise: the lower chain max(c, lo2) from its left end to hi1 (the curve's
// breakpoints above lo2, where c meets lo2, the corner (hi1, lo2)), then (hi1, hi2) and the top
// edge back. Its corners are those of that same convex set, so normalize() writes it exactly as
// before (tests/test_checker.cpp compares both on random convex curves). Slopes are −h1/h2 < 0:
// c decreases. A rectangle without area (lo = hi in I1 or I2) keeps the clipping, which is linear
// for a polygon of at most two points.
std::vector<P2> overlap_region(const Scene& sc, const std::vector<P2>& rect, const std::vector<Line>& lines,
                               const std::vector<std::array<Q, 2>>& ranges) {
    const Q &x0 = sc.lo[0], &x1 = sc.hi[0], &y0 = sc.lo[1], &y1 = sc.hi[1];
    if (rect.size() < 3) {
        std::vector<P2> over = rect;
        for (const Line& L : lines) if (!over.empty()) over = clip(over, L, true);
        return over;
    }
    if (lines.back().at(x1) > y1) return {};  // the rectangle lies below the curve
    // The left end: lo1 when c(lo1) <= hi2, else where c meets hi2 (in the first piece whose right
    // end is on or below hi2).
    size_t k = 0;
    Q xl = x0;
    if (lines[0].at(x0) > y1) {
        while (lines[k].at(ranges[k][1]) > y1) ++k;
        xl = (y1 - lines[k].b) / lines[k].a;
    }
    std::vector<P2> w;
    Q y = lines[k].at(xl);
    if (y <= y0) w.push_back({xl, y0});  // the curve is at or below lo2 from xl on
    else {
        w.push_back({xl, y});
        for (;; ++k) {
            const Q& xr = ranges[k][1];
            y = lines[k].at(xr);
            if (y <= y0) {  // c meets lo2 in this piece
                w.push_back({(y0 - lines[k].b) / lines[k].a, y0});
                break;
            }
            w.push_back({xr, y});
            if (k + 1 == lines.size()) break;
        }
    }
    w.push_back({x1, y0 > y ? y0 : y});
    w.push_back({x1, y1});
    w.push_back({xl, y1});
    return normalize(w);
}

std::vector<P2> polygon(const J& j, const std::string& where) {
    const J& vs = at(j, "vertices");
    const J& ds = at(j, "vertices_double");
    claim(vs.is_array() && ds.is_array() && ds.size() == vs.size(), where + ".vertices and vertices_double are lists of one length");
    std::vector<P2> out;
    for (size_t k = 0; k < vs.size(); ++k) {
        std::string w = where + ".vertices[" + std::to_string(k) + "]";
        claim(vs[k].is_array() && vs[k].size() == 2 && ds[k].is_array() && ds[k].size() == 2, w + " is a point");
        P2 p{num(vs[k][0], w), num(vs[k][1], w)};
        claim(is_nearest(ds[k][0], p[0]) && is_nearest(ds[k][1], p[1]), w + "_double is the nearest double");
        out.push_back(p);
    }
    return out;
}

// Engine statistics: an annotation, but of a fixed shape (non-negative integers).
void check_model(const J& m) {
    auto count = [](const J& j, const std::string& w) { claim(natural(j), w + " is a count"); };
    if (m.is_object() && m.contains("engine")) {  // the walk's statistics (no hull)
        claim(at(m, "engine") == J("scan"), "model.engine is \"scan\"");
        shape(m, "model", {"engine", "P1", "P2", "contact_lines", "support_queries", "gift_wrap_steps", "start_lp", "decided_by_filter",
                           "decided_exactly"});
        for (const char* p : kPoly) {
            shape(at(m, p), std::string("model.") + p, {"points"});
            count(at(at(m, p), "points"), std::string("model.") + p + ".points");
        }
        for (const char* k : {"contact_lines", "support_queries", "gift_wrap_steps"}) count(at(m, k), std::string("model.") + k);
        shape(at(m, "start_lp"), "model.start_lp", {"solves", "rows"});
        for (const char* k : {"solves", "rows"}) count(at(at(m, "start_lp"), k), std::string("model.start_lp.") + k);
        for (const char* k : {"decided_by_filter", "decided_exactly"}) {
            shape(at(m, k), std::string("model.") + k, {"support_comparisons"});
            count(at(at(m, k), "support_comparisons"), std::string("model.") + k + ".support_comparisons");
        }
        return;
    }
    shape(m, "model", {"P1", "P2", "facet_normals", "contact_lines", "edge_pairs_tested", "gauss_arc_crossings", "decided_by_filter", "decided_exactly"});
    for (const char* p : kPoly) {
        shape(at(m, p), std::string("model.") + p, {"vertices", "edges", "faces"});
        for (const char* k : {"vertices", "edges", "faces"}) count(at(at(m, p), k), std::string("model.") + p + "." + k);
    }
    for (const char* k : {"facet_normals", "contact_lines", "edge_pairs_tested", "gauss_arc_crossings"}) count(at(m, k), std::string("model.") + k);
    for (const char* k : {"decided_by_filter", "decided_exactly"}) {
        shape(at(m, k), std::string("model.") + k, {"arc_signs", "support_comparisons"});
        for (const char* s : {"arc_signs", "support_comparisons"}) count(at(at(m, k), s), std::string("model.") + k + "." + s);
    }
}
void annotation_string(const J& o, const char* key, const std::string& where) {
    if (o.contains(key)) claim(at(o, key).is_string(), where + "." + key + " is a string");
}

// The contact at a switch point between pieces with normals n and m, both touching at (ρ1, ρ2):
// P_i(ρ_i) ∩ P_j(ρ_j) lies on both planes, so on their common line ℓ (n × m). On polyhedron i the
// vertices maximising both normals (A_i, all of them) scale onto ℓ, spanning a segment S_i; the
// touching set is T = S_1 ∩ S_2, and the contact feature of i is the smallest face holding T: S_i
// (E) when T reaches into S_i's interior, else the one end it meets (V). Returns the letters, and
// in g the vertices of each feature.
std::string switch_contact(const Scene& sc, const V3& n, const V3& m, const Q rho[2], const std::vector<int> A[2],
                           std::vector<int> g[2], const std::string& where) {
    const V3 uq = cross(n, m);
    claim(nonzero(uq), where + ": the neighbouring pieces' normals are not parallel");
    const Z3 u = ints(uq), minus_u{-u[0], -u[1], -u[2]};
    // A vertex's place on ℓ is t_k = u·(s_i + ρ_i (v_k − s_i)), which increases with u·v_k since
    // ρ_i > 0 (ρ1 >= lo1 > 0; ρ2 > 0 at a touching switch): the ends of S_i are the vertices of A_i
    // extreme along u and −u, which the exact scan finds. D* t_k = (1 − ρ_i) u·S_i + ρ_i u·X_k E_i.
    std::vector<int> top[2], bottom[2];
    Q lo[2], hi[2];
    for (int i = 0; i < 2; ++i) {
        claim(!A[i].empty(), where + ": some vertex of " + kPoly[i] + " attains both neighbouring pieces' support values");
        top[i] = sc.scan[i]->argmax(u, &A[i]);
        bottom[i] = sc.scan[i]->argmax(minus_u, &A[i]);
        const Q us(dotz(u, sc.S[i]));
        auto place = [&](int k) -> Q {
            sc.spend_at(i, k);
            return (1 - rho[i]) * us + rho[i] * Q(dotz(u, sc.scan[i]->X(static_cast<size_t>(k))) * sc.E[i]);
        };
        hi[i] = place(top[i][0]);
        lo[i] = place(bottom[i][0]);
    }
    const Q tlo = std::max(lo[0], lo[1]), thi = std::min(hi[0], hi[1]);
    claim(tlo <= thi, where + ": the contact features of P1 and P2 meet");
    std::string label;
    for (int i = 0; i < 2; ++i) {
        const bool edge = lo[i] < hi[i] && thi > lo[i] && tlo < hi[i];
        // all of S_i, or the vertices at the end T meets (t_k == lo_i: bottom; t_k == hi_i: top)
        g[i] = edge ? A[i] : thi == lo[i] ? bottom[i] : top[i];
        label += edge ? 'E' : 'V';
    }
    return label;
}

// The curve over [lo, hi] (a partition's over I1, a judgement's proof over its window): the
// "pieces", "switch_points" and "curve_ends" of c. Each piece's line, from a normal's support
// values, is a lower bound of the curve f everywhere (below it that normal separates); the
// witnesses at the switch points and ends (common points) bound f above there, and the set of
// meeting pairs is convex, so f is each piece's line over the piece's range. Where a piece falls
// to rho2 = 0 a witness there (s2 in P1(x0)) shows f <= 0 from x0 on. Slopes increase from piece
// to piece, so every switch point listed is a break of f, and there is no other in (lo, hi).
// `pre` prefixes the messages; range_name names [lo, hi] in them.
struct CurveFacts {
    std::vector<Line> lines;
    std::vector<V3> normals;
    std::vector<std::array<Q, 2>> ranges;
    std::vector<std::string> contacts;  // each piece's contact label; empty where rho2 <= 0 all along it
    struct Switch { Q x, y; std::string contact; };
    std::vector<Switch> switches;  // in increasing rho1, all with rho2 > 0
    Q end_rho2[2];
    // The piece holding x in [lo, hi] (at a switch point, the one to its right).
    size_t piece_at(const Q& x) const {
        // the first piece whose range ends beyond x (the last one if none does)
        size_t lo = 0, hi = ranges.size() - 1;
        while (lo < hi) {
            const size_t mid = (lo + hi) / 2;
            spend_ops(1, qsize(x) + qsize(ranges[mid][1]));
            if (x >= ranges[mid][1]) lo = mid + 1; else hi = mid;
        }
        return lo;
    }
    Q at(const Q& x) const {
        const Line& L = lines[piece_at(x)];
        spend_ops(2, qsize(x) + qsize(L.a) + qsize(L.b));
        return L.at(x);
    }
};
CurveFacts check_curve(const Scene& sc, const J& c, const Q& lo, const Q& hi, const std::string& pre, const std::string& range_name) {
    const J& pieces = at(c, "pieces");
    claim(pieces.is_array() && !pieces.empty(), pre + "pieces is a nonempty list");
    CurveFacts cf;
    std::vector<Line>& lines = cf.lines;
    std::vector<V3>& normals = cf.normals;
    std::vector<std::array<Q, 2>>& ranges = cf.ranges;
    std::vector<std::array<const std::vector<int>*, 2>> maxi;  // each piece's maximisers on P1, P2 (in the scene's cache)
    for (size_t k = 0; k < pieces.size(); ++k) {
        const J& p = pieces[k];
        std::string w = pre + "pieces[" + std::to_string(k) + "]";
        claim(p.is_object() && p.contains("contact"), w + ".contact is present");
        const bool touches = !at(p, "contact").is_null();
        if (touches)
            shape(p, w, {"rho1", "rho1_double", "slope", "slope_double", "intercept", "intercept_double", "contact", "features",
                         "contact_witness", "normal", "h1", "h1_double", "h2", "h2_double", "support_vertices"},
                  {"closed_form", "same_line_normals", "zero_witness"});
        else
            shape(p, w, {"rho1", "rho1_double", "slope", "slope_double", "intercept", "intercept_double", "contact",
                         "normal", "h1", "h1_double", "h2", "h2_double", "support_vertices"},
                  {"closed_form", "same_line_normals", "zero_witness"});
        annotation_string(p, "closed_form", w);
        cf.contacts.emplace_back();
        V3 n = normal(at(p, "normal"), w + ".normal");
        mpz_class H[2];  // D* h1, D* h2
        const std::vector<int>* f[2];
        const Scene::Support* own = sc.support(n, H, f);
        const Q h1 = field(p, "h1", w);
        claim_lazy(sc.over(h1, H[0]) && sgn(H[0]) > 0, [&] { return w + ".h1 = max n.(v - s1) over P1, recomputed: " + sc.value(H[0]).get_str(); });
        const Q h2 = field(p, "h2", w);
        claim_lazy(sc.over(h2, H[1]) && sgn(H[1]) > 0, [&] { return w + ".h2 = max -n.(w - s2) over P2, recomputed: " + sc.value(H[1]).get_str(); });
        // The line from h1, h2 (now known to be the recomputed values): slope −h1/h2, and the
        // intercept b with b h2 = n·d.
        const Q a = field(p, "slope", w);
        claim(a == -h1 / h2, w + ".slope = -h1/h2");
        const Q b = field(p, "intercept", w);
        claim(sc.over(b * h2, dotz(ints(n), sc.Delta)), w + ".intercept = n.d/h2");
        const Line L{a, b};
        std::vector<Q> r = fields(p, "rho1", 2, w);
        claim(r[0] < r[1] || (pieces.size() == 1 && r[0] == r[1]), w + ".rho1 is a nonempty range");
        const J& sv = at(p, "support_vertices");
        shape(sv, w + ".support_vertices", {"P1", "P2"});
        for (int i = 0; i < 2; ++i)
            claim(has(*f[i], static_cast<int>(index(at(sv, kPoly[i]), sc.P[i].size(), w + ".support_vertices." + kPoly[i]))),
                  w + ".support_vertices attain the support values");
        // The contact features G1, G2: the vertices maximising every listed normal with this line.
        // Every touching normal maximises on the touching set T, so T lies in G1(ρ1) ∩ G2(ρ2)
        // whatever normals are listed; the witness below, a point of T in the relative interiors of
        // both, shows no smaller face holds T (a list missing a touching normal cannot have one).
        // Each direction's maximisers enter the intersection once (a normal listed again, or a
        // multiple of one, has the same maximisers): the intersections cost no more than the scans.
        std::vector<int> Gs[2];
        const std::vector<int>* G[2] = {f[0], f[1]};
        if (p.contains("same_line_normals")) {
            const J& sl = at(p, "same_line_normals");
            // At most four: each must shrink G1 or G2 to a proper face, of lower dimension, so more
            // are never needed, and each costs a scan of every vertex.
            claim(sl.is_array() && !sl.empty() && sl.size() <= 4, w + ".same_line_normals is a list of 1 to 4 normals");
            std::set<const Scene::Support*> seen{own};
            for (const J& o : sl) {
                V3 m = normal(o, w + ".same_line_normals[]");
                mpz_class g[2];  // D* h1(m), D* h2(m): the same line iff h2 > 0, −h1 = a h2 and m·d = b h2
                const std::vector<int>* fm[2];
                const Scene::Support* dir = sc.support(m, g, fm);
                claim(sgn(g[1]) > 0 && -g[0] * L.a.get_den() == L.a.get_num() * g[1] &&
                          dotz(ints(m), sc.Delta) * L.b.get_den() == L.b.get_num() * g[1],
                      w + ".same_line_normals give the same line");
                bool shrinks = false;  // (a direction listed again, or the piece's own, shrinks nothing)
                if (seen.insert(dir).second)
                    for (int i = 0; i < 2; ++i) {
                        std::vector<int> both;
                        std::set_intersection(G[i]->begin(), G[i]->end(), fm[i]->begin(), fm[i]->end(), std::back_inserter(both));
                        shrinks = shrinks || both.size() < G[i]->size();
                        Gs[i] = std::move(both);
                        G[i] = &Gs[i];
                    }
                claim(shrinks, w + ".same_line_normals each shrink the contact features");
            }
        }
        if (!touches) {
            claim(sgn(L.at(r[0])) <= 0, w + ".contact is null only where rho2 <= 0 all along the piece");
        } else {
            claim(!G[0]->empty() && !G[1]->empty(), w + ": the same-line normals share maximisers on P1 and on P2");
            const std::string label{dimension_letter(sc, 0, *G[0]), dimension_letter(sc, 1, *G[1])};
            claim(contact_string(at(p, "contact"), w + ".contact") == label,
                  w + ".contact is " + label + ", the smallest faces holding the touching set");
            cf.contacts.back() = label;
            const J& feats = at(p, "features");
            shape(feats, w + ".features", {"P1", "P2"});
            std::vector<int> used[2];
            const P2 at_ = check_witness(sc, at(p, "contact_witness"), w + ".contact_witness", used);
            claim(sgn(at_[0]) > 0 && sgn(at_[1]) > 0 && r[0] <= at_[0] && at_[0] <= r[1] && at_[1] == L.at(at_[0]),
                  w + ".contact_witness is at a point of the piece with rho2 > 0");
            for (int i = 0; i < 2; ++i) {
                // Vertices of the feature that span it (the scene may hold more points on it).
                std::vector<int> fl = index_list(at(feats, kPoly[i]), sc.P[i].size(), w + ".features." + kPoly[i]);
                for (int v : fl) claim(has(*G[i], v), w + ".features." + kPoly[i] + " lists only points of the contact feature");
                claim(affine_dim(sc, i, fl) == affine_dim(sc, i, *G[i]), w + ".features." + kPoly[i] + " spans the contact feature");
                std::sort(used[i].begin(), used[i].end());
                for (int v : used[i]) claim(has(*G[i], v), w + ".contact_witness." + kPoly[i] + " weights only vertices of the contact feature");
                claim(affine_dim(sc, i, used[i]) == affine_dim(sc, i, *G[i]),
                      w + ".contact_witness." + kPoly[i] + " lies in the relative interior of the contact feature");
            }
        }
        // A piece whose ρ2 falls from > 0 to ≤ 0 is proved touching down to ρ2 = 0 by a witness at
        // the crossing (x0, 0): there P2(0) is the seed s2, which must lie in P1(x0). (Its other
        // end is a switch point or curve end with ρ2 > 0, witnessed below; the set of meeting
        // pairs is convex, so the piece between is touching: not only where I2 reaches.)
        const bool crosses = sgn(L.at(r[0])) > 0 && sgn(L.at(r[1])) <= 0;
        claim(p.contains("zero_witness") == crosses, w + ".zero_witness is given exactly when rho2 falls to 0 along the piece");
        if (crosses)
            claim(check_witness(sc, at(p, "zero_witness"), w + ".zero_witness") == P2{-L.b / L.a, Q(0)},
                  w + ".zero_witness is where the piece reaches rho2 = 0");
        lines.push_back(L);
        normals.push_back(n);
        maxi.push_back({f[0], f[1]});
        ranges.push_back({r[0], r[1]});
    }
    claim(ranges.front()[0] == lo && ranges.back()[1] == hi, pre + "pieces cover " + range_name + " from end to end");
    const J& sw = at(c, "switch_points");
    claim(sw.is_array() && sw.size() + 1 == pieces.size(), pre + "switch_points: one between each two pieces");
    for (size_t k = 0; k + 1 < pieces.size(); ++k) {
        std::string w = pre + "switch_points[" + std::to_string(k) + "]";
        claim(ranges[k][1] == ranges[k + 1][0], pre + "pieces " + std::to_string(k) + " and " + std::to_string(k + 1) + " are contiguous");
        claim(lines[k].a < lines[k + 1].a, "the curve is convex: slopes increase at " + w);
        claim(sw[k].is_object() && sw[k].contains("rho2") && sw[k]["rho2"].is_string(), w + ".rho2 is present");
        const bool touching = sgn(num(sw[k]["rho2"], w + ".rho2")) > 0;
        if (touching) shape(sw[k], w, {"rho1", "rho1_double", "rho2", "rho2_double", "contact", "features", "witness"}, {"equation"});
        else shape(sw[k], w, {"rho1", "rho1_double", "rho2", "rho2_double", "contact"}, {"equation"});
        annotation_string(sw[k], "equation", w);
        Q x = field(sw[k], "rho1", w), y = field(sw[k], "rho2", w);
        claim(x == ranges[k][1] && y == lines[k].at(x) && y == lines[k + 1].at(x), w + " is where the neighbouring lines meet");
        if (!touching) {
            // From where it reaches ρ2 = 0 the curve is one line (FORMAT.md): no switch point there.
            claim(false, w + " lies at rho2 > 0: from rho2 = 0 on, the curve goes on as one line");
            claim(at(sw[k], "contact").is_null(), w + ".contact is null: at rho2 <= 0 nothing touches");
            continue;
        }
        claim(check_witness(sc, at(sw[k], "witness"), w + ".witness") == P2{x, y}, w + " is touching (witness at the switch point)");
        // The contact label, recomputed from all maximisers of both neighbouring normals.
        std::vector<int> A[2], g[2];
        for (int i = 0; i < 2; ++i)
            std::set_intersection(maxi[k][i]->begin(), maxi[k][i]->end(), maxi[k + 1][i]->begin(), maxi[k + 1][i]->end(), std::back_inserter(A[i]));
        const Q rho[2] = {x, y};
        const std::string label = switch_contact(sc, normals[k], normals[k + 1], rho, A, g, w);
        claim(contact_string(at(sw[k], "contact"), w + ".contact") == label, w + ".contact is " + label + ", the features touching there");
        cf.switches.push_back({x, y, label});
        const J& feats = at(sw[k], "features");
        shape(feats, w + ".features", {"P1", "P2"});
        for (int i = 0; i < 2; ++i)
            for (int v : index_list(at(feats, kPoly[i]), sc.P[i].size(), w + ".features." + kPoly[i]))
                claim(has(g[i], v), w + ".features lists only vertices of the contact feature");
    }
    const J& ends = at(c, "curve_ends");
    claim(ends.is_array() && ends.size() == 2, pre + "curve_ends has the two ends");
    for (int e = 0; e < 2; ++e) {
        std::string w = pre + "curve_ends[" + std::to_string(e) + "]";
        claim(ends[e].is_object() && ends[e].contains("rho2") && ends[e]["rho2"].is_string(), w + ".rho2 is present");
        const bool touching = sgn(num(ends[e]["rho2"], w + ".rho2")) > 0;
        // A curve at or below ρ2 = 0 already at lo1 is anchored by a witness at (lo1, 0): the seed s2
        // in P1(lo1), so every pair with ρ1 >= lo1 and ρ2 > 0 meets (P1 only grows): the curve is
        // <= 0 all along I1, as claimed. (Without it any line of some normal could be claimed there.)
        const bool anchored = touching || e == 0;
        if (anchored) shape(ends[e], w, {"rho1", "rho1_double", "rho2", "rho2_double", "witness"});
        else shape(ends[e], w, {"rho1", "rho1_double", "rho2", "rho2_double"});
        Q x = field(ends[e], "rho1", w), y = field(ends[e], "rho2", w);
        const Line& L = e == 0 ? lines.front() : lines.back();
        claim(x == (e == 0 ? lo : hi) && y == L.at(x), w + " is the curve at the end of " + range_name);
        cf.end_rho2[e] = y;
        if (touching) claim(check_witness(sc, at(ends[e], "witness"), w + ".witness") == P2{x, y}, w + " is touching");
        else if (anchored)
            claim(check_witness(sc, at(ends[e], "witness"), w + ".witness") == P2{x, Q(0)},
                  w + ".witness is at (rho1, 0): the seed of P2 lies in P1(rho1)");
    }
    return cf;
}

void check_partition(const J& c) {
    shape(c, "", {"format", "kind", "pieces", "switch_points", "growth_distance", "growth_distance_double",
                  "growth_distance_in_rectangle", "curve_ends", "growth_distance_certificate", "regions", "seed_interior", "scene"},
          {"model", "growth_distance_note"});
    const Scene sc = read_scene(at(c, "scene"));
    check_seed_interior(sc, at(c, "seed_interior"));
    if (c.contains("model")) check_model(at(c, "model"));
    const CurveFacts cf = check_curve(sc, c, sc.lo[0], sc.hi[0], "", "I1");
    const std::vector<Line>& lines = cf.lines;
    const std::vector<std::array<Q, 2>>& ranges = cf.ranges;
    // Growth distance: (ρ*, ρ*) touches — the plane of n has n.d = ρ*(h1 + h2) and a witness — or
    // the seeds coincide and ρ* = 0.
    Q g = field(c, "growth_distance", "");
    const J& gc = at(c, "growth_distance_certificate");
    claim(gc.is_object(), "growth_distance_certificate is an object");
    if (gc.contains("seeds_coincide")) {
        shape(gc, "growth_distance_certificate", {"seeds_coincide"});
        claim(at(gc, "seeds_coincide") == J(true), "growth_distance_certificate.seeds_coincide is true");
        claim(!sgn(sc.Delta[0]) && !sgn(sc.Delta[1]) && !sgn(sc.Delta[2]) && sgn(g) == 0, "growth distance 0: the seeds coincide");
    } else {
        shape(gc, "growth_distance_certificate", {"normal", "h1", "h1_double", "h2", "h2_double", "witness"});
        V3 n = normal(at(gc, "normal"), "growth_distance_certificate.normal");
        mpz_class H[2];  // D* h1, D* h2
        sc.support(n, H);
        claim(sc.over(field(gc, "h1", "growth_distance_certificate"), H[0]) && sc.over(field(gc, "h2", "growth_distance_certificate"), H[1]),
              "growth_distance_certificate support values recomputed");
        claim(sgn(H[0]) > 0 && sgn(H[1]) > 0 && dotz(ints(n), sc.Delta) * g.get_den() == g.get_num() * (H[0] + H[1]),
              "the growth distance's plane touches at (rho*, rho*)");
        claim(check_witness(sc, at(gc, "witness"), "growth_distance_certificate.witness") == P2{g, g}, "growth distance witness is at (rho*, rho*)");
    }
    if (c.contains("growth_distance_note"))
        claim(at(c, "growth_distance_note").is_string() && sgn(g) == 0, "growth_distance_note is a string, written only when the growth distance is 0");
    bool inside = g >= sc.lo[0] && g <= sc.hi[0] && g >= sc.lo[1] && g <= sc.hi[1];
    claim(at(c, "growth_distance_in_rectangle").is_boolean() && at(c, "growth_distance_in_rectangle").get<bool>() == inside, "growth_distance_in_rectangle is right");
    for (size_t k = 0; k < lines.size(); ++k)
        if (g >= ranges[k][0] && g <= ranges[k][1]) claim(lines[k].at(g) == g, "the growth distance lies on piece " + std::to_string(k));
    // Regions: the rectangle cut along the curve, recomputed here and compared vertex by vertex.
    const J& reg = at(c, "regions");
    shape(reg, "regions", {"overlap", "separated"});
    std::vector<P2> rect = normalize({{sc.lo[0], sc.lo[1]}, {sc.hi[0], sc.lo[1]}, {sc.hi[0], sc.hi[1]}, {sc.lo[0], sc.hi[1]}});
    const std::vector<P2> over = overlap_region(sc, rect, lines, ranges);
    const J& ov = at(reg, "overlap");
    shape(ov, "regions.overlap", {"vertices", "vertices_double", "witnesses"});
    claim(polygon(ov, "regions.overlap") == over, "regions.overlap is the rectangle on and above the curve");
    const J& wit = at(ov, "witnesses");
    claim(wit.is_array() && wit.size() == over.size(), "every vertex of the overlap polygon has a witness");
    for (size_t k = 0; k < over.size(); ++k)
        claim(check_witness(sc, wit[k], "regions.overlap.witnesses[" + std::to_string(k) + "]") == over[k], "overlap witness " + std::to_string(k) + " is at its vertex");
    std::vector<std::vector<P2>> seps;
    std::vector<size_t> owners;
    for (size_t k = 0; k < lines.size(); ++k) {
        std::vector<P2> box = normalize({{ranges[k][0], sc.lo[1]}, {ranges[k][1], sc.lo[1]}, {ranges[k][1], sc.hi[1]}, {ranges[k][0], sc.hi[1]}});
        if (box.size() < 3) continue;
        std::vector<P2> s = clip(box, lines[k], false);
        Q area = 0;
        for (size_t i = 0; i < s.size(); ++i) area += s[i][0] * s[(i + 1) % s.size()][1] - s[i][1] * s[(i + 1) % s.size()][0];
        if (s.size() >= 3 && sgn(area) > 0) { seps.push_back(s); owners.push_back(k); }
    }
    const J& sr = at(reg, "separated");
    claim(sr.is_array() && sr.size() == seps.size(), "regions.separated has one polygon per piece with area below the curve");
    for (size_t k = 0; k < seps.size(); ++k) {
        std::string w = "regions.separated[" + std::to_string(k) + "]";
        shape(sr[k], w, {"piece", "vertices", "vertices_double"});
        claim(index(at(sr[k], "piece"), lines.size(), w + ".piece") == owners[k], w + ".piece names its piece");
        claim(polygon(sr[k], w) == seps[k], w + " is the rectangle strictly below its piece");
    }
}

// ---- a query answer ----------------------------------------------------------------------------
void check_verdict(const Scene& sc, const Q& r1, const Q& r2, const std::string& v, const J& cert);
void check_query(const J& c) {
    shape(c, "", {"format", "kind", "verdict", "rho1", "rho1_double", "rho2", "rho2_double", "certificate", "seed_interior", "scene"},
          {"segment"});
    claim(!c.contains("segment") || at(c, "segment").is_object(), "segment is an object (an annotation: not checked)");
    const J& vj = at(c, "verdict");
    claim(vj.is_string(), "verdict is a string");
    const std::string v = vj.get<std::string>();
    claim(v == "separated" || v == "touching" || v == "overlapping", "the verdict is separated, touching or overlapping");
    const Scene sc = read_scene(at(c, "scene"));
    check_seed_interior(sc, at(c, "seed_interior"));
    Q r1 = field(c, "rho1", ""), r2 = field(c, "rho2", "");
    claim(sgn(r1) > 0 && sgn(r2) > 0, "the scalings are > 0");
    check_verdict(sc, r1, r2, v, at(c, "certificate"));
}

// The certificate of verdict v (separated, touching or overlapping) at (r1, r2) > 0: its plane
// and witness (a query answer's "certificate"; the seeds are proved interior).
void check_verdict(const Scene& sc, const Q& r1, const Q& r2, const std::string& v, const J& cert) {
    if (v == "separated") shape(cert, "certificate", {"plane"});
    if (v == "touching") shape(cert, "certificate", {"plane", "witness"});
    if (v == "overlapping") shape(cert, "certificate", {"witness"});
    if (v == "separated" || v == "touching") {
        const J& pl = at(cert, "plane");
        shape(pl, "plane", {"normal", "offset", "offset_double", "P1_max", "P1_max_double", "P2_min", "P2_min_double", "support_vertices", "contact"});
        V3 n = normal(at(pl, "normal"), "plane.normal");
        mpz_class H[2];  // D* h1, D* h2
        const std::vector<int>* f[2];
        sc.support(n, H, f);
        const std::vector<int> &f1 = *f[0], &f2 = *f[1];
        // D* times n·s1 + rho1 h1 and n·s2 − rho2 h2 (D* > 0 keeps their order)
        const Q c1 = Q(dotz(ints(n), sc.S[0])) + r1 * Q(H[0]), c2 = Q(dotz(ints(n), sc.S[1])) - r2 * Q(H[1]), D(sc.Dj);
        const J& sv = at(pl, "support_vertices");
        shape(sv, "plane.support_vertices", {"P1", "P2"});
        claim(has(f1, static_cast<int>(index(at(sv, "P1"), sc.P[0].size(), "plane.support_vertices.P1"))) &&
              has(f2, static_cast<int>(index(at(sv, "P2"), sc.P[1].size(), "plane.support_vertices.P2"))), "plane.support_vertices attain the extremes");
        claim(contact_string(at(pl, "contact"), "plane.contact") == std::string{dimension_letter(sc, 0, f1), dimension_letter(sc, 1, f2)}, "plane.contact is the dimension of the extreme sets");
        claim(field(pl, "P1_max", "plane") * D == c1 && field(pl, "P2_min", "plane") * D == c2, "plane.P1_max and P2_min recomputed from the vertices");
        claim(field(pl, "offset", "plane") * D == (c1 + c2) / 2, "plane.offset is midway");
        claim(v == "separated" ? c1 < c2 : c1 == c2, v == "separated" ? "the plane separates strictly" : "the plane supports both");
    }
    if (v == "touching") claim(check_witness(sc, at(cert, "witness"), "witness") == P2{r1, r2}, "the witness is at the queried pair");
    if (v == "overlapping") {
        P2 w = check_witness(sc, at(cert, "witness"), "witness");
        claim(w[0] < r1 && w[1] < r2, "the witness is at a smaller pair, hence interior to both");
    }
}


// ---- a judgements file --------------------------------------------------------------------------
// certify-fp's judgements, each re-derived from its claim and its proof (FORMAT.md, "A judgements
// file"): the file's "right" must be the judgement these rules give, CLAIMS.md's rules.
namespace judge {

// n·L for the least L > 0 making every component an integer; L in *scale.
V3 integral(const V3& n, mpz_class* scale) {
    mpz_class L = 1;
    for (const Q& c : n) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), c.get_den_mpz_t());
    *scale = L;
    return {n[0] * L, n[1] * L, n[2] * L};
}
// max over P_i(rho) of n·x, for a nonzero rational n: n·s_i + rho max_v n·(v − s_i), the maximum a
// scan of every vertex (h(1, m) is max −m·(w − s2), so P2's takes m = −n).
double vsize(const V3& v) { return std::max({qsize(v[0]), qsize(v[1]), qsize(v[2])}); }
Q reach(const Scene& sc, int i, const V3& n, const Q& rho) {
    spend_ops(12, vsize(n) + vsize(sc.s[i]) + qsize(rho) + 2 * limbs(sc.Dj));
    mpz_class L;
    V3 u = integral(n, &L);
    if (i == 1) for (Q& c : u) c = -c;
    return dot(n, sc.s[i]) + rho * sc.h(i, u) / Q(L);
}
Q reach_min(const Scene& sc, int i, const V3& n, const Q& rho) { return -reach(sc, i, {-n[0], -n[1], -n[2]}, rho); }
// s_i + rho (Σ w v − s_i) for weights over P_i's vertices.
V3 body_point(const Scene& sc, int i, const Q& rho, const J& w, const std::string& where) {
    const std::array<Q, 3> c = combination(sc, i, w, where);
    spend_ops(12, vsize(sc.s[i]) + qsize(rho) + std::max({qsize(c[0]), qsize(c[1]), qsize(c[2])}) + limbs(sc.scan[i]->D()));
    const Q D(sc.scan[i]->D());
    V3 x;
    for (int k = 0; k < 3; ++k) x[k] = sc.s[i][k] + rho * (c[k] / D - sc.s[i][k]);
    return x;
}
// Is x in P_i(rho)? Proved by {"in": weights} combining to x, or {"out": normal} whose plane x
// lies strictly beyond.
bool member(const Scene& sc, int i, const Q& rho, const V3& x, const J& p, const std::string& where) {
    claim(p.is_object() && p.size() == 1 && (p.contains("in") || p.contains("out")), where + " is {\"in\": weights} or {\"out\": normal}");
    if (p.contains("in")) {
        claim(body_point(sc, i, rho, at(p, "in"), where + ".in") == x, where + ".in combines to the point");
        return true;
    }
    const V3 n = normal(at(p, "out"), where + ".out");
    spend_ops(3, vsize(n) + vsize(x));
    claim(dot(n, x) > reach(sc, i, n, rho), where + ".out: the point lies strictly beyond the body's extent along the normal");
    return false;
}
struct Rules {
    Q tol;
    bool close(const Q& c, const Q& e) const {
        spend_ops(3, qsize(c) + qsize(e) + qsize(tol));
        return abs(c - e) <= tol * abs(e);
    }
    bool close_sq(const Q& c, const Q& E) const {
        spend_ops(8, 2 * qsize(c) + qsize(E) + 2 * qsize(tol));
        if (sgn(c) < 0) return false;
        const Q lo = 1 - tol, hi = 1 + tol;
        return (sgn(lo) <= 0 || lo * lo * E <= c * c) && c * c <= hi * hi * E;
    }
    bool within_above(const Q& x, const Q& E) const {
        spend_ops(5, qsize(x) + qsize(E) + 2 * qsize(tol));
        return E <= x && x <= (1 + tol) * (1 + tol) * E;
    }
};
Q positive(const J& o, const char* key, const std::string& where) {
    const Q q = num(at(o, key), where + "." + key);
    claim(sgn(q) > 0, where + "." + key + " is > 0");
    return q;
}
V3 nonzero_vector(const J& j, const std::string& where) {
    const V3 n = point(j, where);
    claim(nonzero(n), where + " is nonzero");
    return n;
}
// h_M(n) = max over P1(r1) of n·x − min over P2(r2) of n·y: the depth along n times |n| (< 0: the
// plane separates).
Q hM(const Scene& sc, const V3& n, const Q& r1, const Q& r2) { return reach(sc, 0, n, r1) - reach_min(sc, 1, n, r2); }

// A closed surface of triangles over points of the Minkowski difference P1(r1) − P2(r2), each
// triangle's plane at least sqrt(E) from the origin, which it has on its inner side. The radial
// projection of such a surface covers every direction (its degree is its total solid angle over
// 4π, > 0 as every triangle's is), so along every unit u some point t·u of it, hence of the
// difference, has t >= sqrt(E): the depth is at least sqrt(E).
void check_lower_bound(const Scene& sc, const Q& r1, const Q& r2, const Q& E, const J& proof, const std::string& where) {
    const J& pts = at(proof, "points");
    const J& tris = at(proof, "triangles");
    claim(pts.is_array() && pts.size() >= 4, where + ".points has at least 4 points");
    claim(tris.is_array() && tris.size() >= 4, where + ".triangles has at least 4 triangles");
    // In integers, so that no point or triangle pays for the seeds' digits more than once: a point
    // of M is z = c0 + y with c0 = (1 − r1) s1 − (1 − r2) s2 (the same for all) and y = r1 v − r2 w.
    // Over Dy = lcm(b1 D1, b2 D2) (r_i = a_i/b_i, D_i the vertices' common denominator, X = D_i v):
    // Y = Dy y = k1 X_v − k2 X_w, k_i = a_i Dy/(b_i D_i). A triangle's N = (Y_b − Y_a) × (Y_c − Y_a)
    // is Dy² times the true one (c0 cancels), and with c0 = C/Dc its offset N·(c0 + y_a) is
    // N·W_a/(Dy³ Dc), W_a = Dy C + Dc Y_a. So off > 0 iff N·W_a > 0, and off² >= E |N|² iff
    // q (N·W_a)² >= p Dy² Dc² |N|² for E = p/q. Counted before each product, by its operands' limbs.
    auto prod = [](double la, double lb) { return 2 + la * lb; };
    const mpz_class b1 = r1.get_den(), b2 = r2.get_den();
    spend_ops(14, vsize(sc.s[0]) + vsize(sc.s[1]) + qsize(r1) + qsize(r2) + limbs(sc.scan[0]->D()) + limbs(sc.scan[1]->D()));
    mpz_class Dy, d1 = b1 * sc.scan[0]->D(), d2 = b2 * sc.scan[1]->D();
    mpz_lcm(Dy.get_mpz_t(), d1.get_mpz_t(), d2.get_mpz_t());
    const mpz_class k1 = r1.get_num() * (Dy / d1), k2 = r2.get_num() * (Dy / d2);
    V3 c0;
    for (int c = 0; c < 3; ++c) c0[c] = (1 - r1) * sc.s[0][c] - (1 - r2) * sc.s[1][c];
    mpz_class Dc = 1;
    for (const Q& c : c0) mpz_lcm(Dc.get_mpz_t(), Dc.get_mpz_t(), c.get_den_mpz_t());
    Z3 DyC;
    for (int c = 0; c < 3; ++c) DyC[c] = Dy * (c0[c].get_num() * (Dc / c0[c].get_den()));
    const mpz_class T = E.get_num() * Dy * Dy * Dc * Dc, q = E.get_den();
    const double lk = std::max(limbs(k1), limbs(k2)), lDc = limbs(Dc), lDyC = std::max({limbs(DyC[0]), limbs(DyC[1]), limbs(DyC[2])});
    spend(50 * (lDyC + 1) * (limbs(E.get_num()) + 4 * limbs(Dy) + 2 * lDc + 1));
    std::vector<Z3> Y, W;
    std::vector<double> yl, wl;
    for (size_t k = 0; k < pts.size(); ++k) {
        const std::string w = where + ".points[" + std::to_string(k) + "]";
        claim(pts[k].is_array() && pts[k].size() == 2, w + " is [vertex of P1, vertex of P2]");
        const size_t a = index(pts[k][0], sc.P[0].size(), w), b = index(pts[k][1], sc.P[1].size(), w);
        const Z3 &Xa = sc.scan[0]->X(a), &Xb = sc.scan[1]->X(b);
        double lx = 0;
        for (int c = 0; c < 3; ++c) lx = std::max({lx, limbs(Xa[c]), limbs(Xb[c])});
        spend(100 + 6 * prod(lk, lx) + 3 * prod(lDc, lk + lx + 1));
        Z3 y, wv;
        double ly = 0, lw = 0;
        for (int c = 0; c < 3; ++c) {
            y[c] = k1 * Xa[c] - k2 * Xb[c];
            wv[c] = DyC[c] + Dc * y[c];
            ly = std::max(ly, limbs(y[c]));
            lw = std::max(lw, limbs(wv[c]));
        }
        Y.push_back(std::move(y));
        W.push_back(std::move(wv));
        yl.push_back(ly);
        wl.push_back(lw);
    }
    const double lT = limbs(T), lq = limbs(q);
    std::map<std::pair<size_t, size_t>, int> edges;
    for (size_t t = 0; t < tris.size(); ++t) {
        const std::string w = where + ".triangles[" + std::to_string(t) + "]";
        claim(tris[t].is_array() && tris[t].size() == 3, w + " is 3 point indices");
        size_t v[3];
        for (int k = 0; k < 3; ++k) v[k] = index(tris[t][k], Y.size(), w);
        const double ly = 1 + std::max({yl[v[0]], yl[v[1]], yl[v[2]]}), ln = 2 * ly + 1, lnw = ln + wl[v[0]] + 1;
        spend(200 + 6 * prod(ly, ly) + 3 * prod(ln, wl[v[0]]) + prod(lnw, lnw) + prod(lq, 2 * lnw) + 3 * prod(ln, ln) + prod(lT, 2 * ln + 2));
        Z3 e1, e2;
        for (int c = 0; c < 3; ++c) e1[c] = Y[v[1]][c] - Y[v[0]][c], e2[c] = Y[v[2]][c] - Y[v[0]][c];
        const Z3 N = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        const mpz_class off = dotz(N, W[v[0]]);
        claim(sgn(off) > 0, w + " has the origin strictly on its inner side");
        claim(q * off * off >= T * dotz(N, N), w + "'s plane lies at least the depth from the origin");
        for (int k = 0; k < 3; ++k) claim(++edges[{v[k], v[(k + 1) % 3]}] == 1, w + ": each directed edge is used once");
    }
    for (const auto& [e, n] : edges)
        claim(edges.count({e.second, e.first}) == 1, where + ".triangles form a closed surface (every edge is shared with opposite orientation)");
}

// A curve proof: the exact curve over its window [a, b] (check_curve), 0 <= a < b.
struct Window {
    CurveFacts f;
    Q a, b;
    // f <= 0 at b: nothing touches from b on, so no switch point lies beyond it.
    bool reaches_zero() const { return sgn(f.end_rho2[1]) <= 0; }
};
Window curve_window(const Scene& sc, const J& pr, const std::string& wp) {
    shape(pr, wp, {"rho1", "rho1_double", "pieces", "switch_points", "curve_ends"});
    const std::vector<Q> r = fields(pr, "rho1", 2, wp);
    claim(sgn(r[0]) >= 0 && r[0] < r[1], wp + ".rho1 is a window [a, b] with 0 <= a < b");
    return {check_curve(sc, pr, r[0], r[1], wp + ".", wp + ".rho1"), r[0], r[1]};
}
std::pair<Q, Q> scaling_pair(const J& j, const std::string& where) {
    claim(j.is_array() && j.size() == 2, where + " is [rho1, rho2]");
    const Q x = num(j[0], where), y = num(j[1], where);
    claim(sgn(x) > 0 && sgn(y) > 0, where + " has scalings > 0");
    return {x, y};
}
std::string claimed_contact(const J& o, const std::string& where) {
    const std::string c = contact_string(at(o, "contact"), where + ".contact");
    claim(c.find_first_not_of("VEF") == std::string::npos, where + ".contact is two of V, E, F");
    return c;
}

// A curve claim, by CLAIMS.md's "Curve claims" (rules 1-4), against the curve proved over a
// window holding the claimed range [lo, hi] with room on both sides (so every switch point of f
// in the closed range is known, and whether lo or hi is one).
bool judge_curve(const Rules& R, const J& cl, const Window& W, const std::string& wc, const std::string& wp) {
    struct Seg { Q x0, y0, x1, y1; std::optional<std::string> label; };
    std::vector<Seg> segs;
    std::vector<std::pair<Q, Q>> claimed;  // the claimed switch points
    if (cl.contains("vertices")) {
        shape(cl, wc, {"kind", "vertices"}, {"switch_points"});
        const J& v = at(cl, "vertices");
        claim(v.is_array() && v.size() >= 2, wc + ".vertices has at least 2 points");
        std::vector<std::pair<Q, Q>> p;
        for (size_t i = 0; i < v.size(); ++i) p.push_back(scaling_pair(v[i], wc + ".vertices[" + std::to_string(i) + "]"));
        for (size_t i = 0; i + 1 < p.size(); ++i) {
            claim(p[i].first < p[i + 1].first, wc + ".vertices: rho1 increases");
            segs.push_back({p[i].first, p[i].second, p[i + 1].first, p[i + 1].second, std::nullopt});
        }
        for (size_t i = 1; i + 1 < p.size(); ++i)  // bends: where the polyline's slope changes
            if ((p[i].second - p[i - 1].second) * (p[i + 1].first - p[i].first) != (p[i + 1].second - p[i].second) * (p[i].first - p[i - 1].first))
                claimed.push_back(p[i]);
    } else {
        shape(cl, wc, {"kind", "pieces"}, {"switch_points"});
        const J& ps = at(cl, "pieces");
        claim(ps.is_array() && !ps.empty(), wc + ".pieces is a nonempty list");
        for (size_t i = 0; i < ps.size(); ++i) {
            const std::string w = wc + ".pieces[" + std::to_string(i) + "]";
            shape(ps[i], w, {"rho1", "slope", "intercept"}, {"contact"});
            const J& r = at(ps[i], "rho1");
            claim(r.is_array() && r.size() == 2, w + ".rho1 is [from, to]");
            const Q x0 = num(r[0], w + ".rho1"), x1 = num(r[1], w + ".rho1");
            const Q a = num(at(ps[i], "slope"), w + ".slope"), b = num(at(ps[i], "intercept"), w + ".intercept");
            claim(sgn(x0) > 0 && x0 < x1, w + ".rho1 is a range of scalings > 0");
            claim(segs.empty() || x0 == segs.back().x1, w + " starts where the piece before ends");
            const Q y0 = a * x0 + b, y1 = a * x1 + b;
            claim(sgn(y0) > 0 && sgn(y1) > 0, w + " stays at rho2 > 0");
            if (!segs.empty()) claimed.push_back({x0, segs.back().y1});  // the value there is the left piece's
            std::optional<std::string> label;
            if (ps[i].contains("contact")) label = claimed_contact(ps[i], w);
            segs.push_back({x0, y0, x1, y1, label});
        }
    }
    const Q lo = segs.front().x0, hi = segs.back().x1;
    if (cl.contains("switch_points")) {
        const J& sw = at(cl, "switch_points");
        claim(sw.is_array(), wc + ".switch_points is a list");
        claimed.clear();
        for (size_t i = 0; i < sw.size(); ++i) {
            const auto p = scaling_pair(sw[i], wc + ".switch_points[" + std::to_string(i) + "]");
            claim(lo <= p.first && p.first <= hi, wc + ".switch_points lie in the claimed range");
            claimed.push_back(p);
        }
    }
    claim(W.a < lo && hi < W.b, wp + ".rho1 holds the claimed range with room on both sides");
    const CurveFacts& f = W.f;
    // 1. f > 0 over the range: f descends, so at hi.
    const bool positive = sgn(f.at(hi)) > 0;
    // 2. The values, at the segments' ends and at f's switch points inside them (found by binary
    // search: the switch points are in increasing rho1).
    auto first = [&](const Q& x, bool or_at) {  // the first switch point with rho1 > x (or_at: >= x)
        size_t lo = 0, hi = f.switches.size();
        while (lo < hi) {
            const size_t mid = (lo + hi) / 2;
            spend_ops(1, qsize(x) + qsize(f.switches[mid].x));
            if (f.switches[mid].x > x || (or_at && f.switches[mid].x == x)) hi = mid; else lo = mid + 1;
        }
        return lo;
    };
    auto first_after = [&](const Q& x) { return first(x, false); };
    bool within = true;
    for (const Seg& s : segs) {
        within = within && R.close(s.y0, f.at(s.x0)) && R.close(s.y1, f.at(s.x1));
        for (size_t k = first_after(s.x0); k < f.switches.size() && f.switches[k].x < s.x1; ++k) {
            const auto& sw = f.switches[k];
            spend_ops(6, qsize(s.x0) + qsize(s.x1) + qsize(s.y0) + qsize(s.y1) + qsize(sw.x));
            within = within && R.close(s.y0 + (s.y1 - s.y0) * (sw.x - s.x0) / (s.x1 - s.x0), sw.y);
        }
    }
    // 3. Switch points: exact ones in [lo, hi] paired with claimed ones, each the other's nearest
    // in rho1 (ties: the first listed).
    std::vector<const CurveFacts::Switch*> exact;
    for (size_t k = first(lo, true); k < f.switches.size() && f.switches[k].x <= hi; ++k) exact.push_back(&f.switches[k]);
    // (Linear searches, each comparison counted: quadratic only in what the claim lists.)
    auto nearest_claimed = [&](const Q& x) {
        size_t b = 0;
        for (size_t i = 1; i < claimed.size(); ++i) {
            spend_ops(4, qsize(claimed[i].first) + qsize(claimed[b].first) + qsize(x));
            if (abs(claimed[i].first - x) < abs(claimed[b].first - x)) b = i;
        }
        return b;
    };
    auto nearest_exact = [&](const Q& x) {
        size_t b = 0;
        for (size_t i = 1; i < exact.size(); ++i) {
            spend_ops(4, qsize(exact[i]->x) + qsize(exact[b]->x) + qsize(x));
            if (abs(exact[i]->x - x) < abs(exact[b]->x - x)) b = i;
        }
        return b;
    };
    bool switches_right = true;
    std::vector<bool> used(claimed.size(), false);
    for (size_t i = 0; i < exact.size(); ++i) {
        const bool at_end = exact[i]->x == lo || exact[i]->x == hi;
        size_t k = 0;
        if (claimed.empty() || nearest_exact(claimed[k = nearest_claimed(exact[i]->x)].first) != i) {
            if (!at_end) switches_right = false;  // missed
            continue;
        }
        used[k] = true;
        if (!R.close(claimed[k].first, exact[i]->x) || !R.close(claimed[k].second, exact[i]->y)) switches_right = false;  // misplaced
    }
    for (bool u : used) switches_right = switches_right && u;  // none extra
    // 4. Each claimed contact is f's at its segment's midpoint (a switch point's there).
    bool contacts_right = true;
    for (const Seg& s : segs) {
        if (!s.label) continue;
        const Q mid = (s.x0 + s.x1) / 2;
        std::string e = positive ? f.contacts[f.piece_at(mid)] : std::string("none");
        const size_t k = first_after(mid);
        if (k > 0 && f.switches[k - 1].x == mid) e = f.switches[k - 1].contact;
        contacts_right = contacts_right && *s.label == e;
    }
    return positive && within && switches_right && contacts_right;
}

// A switch-point claim: right when the exact switch point nearest in rho1 (ties: the smaller
// rho1) lies within the tolerance in both coordinates, with the claimed contact. The window must
// hold every rho1 as near to the claim as that one (or reach rho1 = 0, or rho2 <= 0, on its side):
// then no nearer one exists. With no switch point at all, the window spans 0 to rho2 <= 0.
// A switch-point claim is right when some exact switch point matches it: both coordinates within
// the tolerance (|c − x| <= tol·x) and the contact, when claimed. Every ρ1 = x with |c1 − x| <= tol·x
// lies in [c1/(1 + tol), c1/(1 − tol)] (beyond c1/(1 + tol) without end when tol >= 1), so the window
// must hold that range strictly inside (or start at 0, or go on to where the curve reaches ρ2 <= 0,
// past which there is no switch point): then every switch point that could match is listed.
bool judge_switch_point(const Rules& R, const J& cl, const Window& W, const std::string& wc, const std::string& wp) {
    shape(cl, wc, {"kind", "rho1", "rho2"}, {"contact"});
    const Q c1 = positive(cl, "rho1", wc), c2 = positive(cl, "rho2", wc);
    std::optional<std::string> label;
    if (cl.contains("contact")) label = claimed_contact(cl, wc);
    spend_ops(4, 2 * qsize(c1) + 2 * qsize(R.tol));
    const Q lo = c1 / (1 + R.tol);
    // (Strictly: the window lists the switch points strictly inside it.)
    claim(sgn(W.a) == 0 || W.a < lo, wp + ".rho1 starts below every rho1 within the tolerance of the claim");
    claim(W.reaches_zero() || (R.tol < 1 && c1 / (1 - R.tol) < W.b), wp + ".rho1 ends beyond every rho1 within the tolerance of the claim");
    for (const auto& sw : W.f.switches)
        if (R.close(c1, sw.x) && R.close(c2, sw.y) && (!label || *label == sw.contact)) return true;
    return false;
}

// One judgement; returns whether the claim is right by the rules.
bool judge(const Scene& sc, const Rules& R, const J& cl, const J& pr, const std::string& where) {
    claim(cl.is_object() && cl.contains("kind") && cl["kind"].is_string(), where + ".claim has a kind");
    claim(pr.is_object(), where + ".proof is an object");
    const std::string kind = cl["kind"].get<std::string>();
    const std::string wc = where + ".claim", wp = where + ".proof";
    if (kind == "verdict") {
        shape(cl, wc, {"kind", "rho1", "rho2", "verdict"});
        shape(pr, wp, {"verdict", "certificate"});
        const Q r1 = positive(cl, "rho1", wc), r2 = positive(cl, "rho2", wc);
        claim(at(cl, "verdict").is_string() && at(pr, "verdict").is_string(), where + ": verdicts are strings");
        const std::string c = at(cl, "verdict").get<std::string>(), v = at(pr, "verdict").get<std::string>();
        claim(c == "separated" || c == "touching" || c == "overlapping" || c == "intersecting", wc + ".verdict is separated, touching, overlapping or intersecting");
        claim(v == "separated" || v == "touching" || v == "overlapping", wp + ".verdict is separated, touching or overlapping");
        check_verdict(sc, r1, r2, v, at(pr, "certificate"));
        return c == "intersecting" ? v != "separated" : c == v;
    }
    if (kind == "growth_distance") {
        shape(cl, wc, {"kind", "value"});
        shape(pr, wp, {"value"}, {"normal", "witness"});
        const Q c = num(at(cl, "value"), wc + ".value");
        claim(sgn(c) >= 0, wc + ".value is >= 0");
        const Q g = num(at(pr, "value"), wp + ".value");
        if (sgn(g) == 0) {
            claim(!pr.contains("normal") && !pr.contains("witness"), wp + ": a growth distance of 0 has no normal or witness");
            claim(sc.s[0] == sc.s[1], wp + ": a growth distance of 0 needs coinciding seeds");
        } else {
            claim(sgn(g) > 0 && pr.contains("normal") && pr.contains("witness"), wp + " has a normal and a witness");
            const V3 n = normal(at(pr, "normal"), wp + ".normal");
            mpz_class H[2];
            sc.support(n, H);
            spend_ops(4, limbs(sc.Delta[0]) + limbs(sc.Delta[1]) + limbs(sc.Delta[2]) + limbs(H[0]) + limbs(H[1]) + qsize(g) + vsize(n));
            claim(sgn(H[0] + H[1]) > 0, wp + ".normal: h1 + h2 > 0");
            claim(Q(dotz(ints(n), sc.Delta)) == g * Q(H[0] + H[1]), wp + ": n·d = value (h1 + h2), so (rho, rho) is separated below it");
            claim(check_witness(sc, at(pr, "witness"), wp + ".witness") == P2{g, g}, wp + ".witness is at (value, value)");
        }
        return R.close(c, g);
    }
    if (kind == "separating_plane") {
        shape(cl, wc, {"kind", "rho1", "rho2", "normal"}, {"offset"});
        claim(pr.empty(), wp + " is empty (the checker computes the extents)");
        const Q r1 = positive(cl, "rho1", wc), r2 = positive(cl, "rho2", wc);
        const V3 n = nonzero_vector(at(cl, "normal"), wc + ".normal");
        const Q c1 = reach(sc, 0, n, r1), c2 = reach_min(sc, 1, n, r2);
        bool right = c1 < c2;
        if (cl.contains("offset")) {
            const Q d = num(at(cl, "offset"), wc + ".offset");
            right = right && c1 < d && d < c2;
        }
        return right;
    }
    if (kind == "witness_point") {
        shape(cl, wc, {"kind", "rho1", "rho2", "point"});
        shape(pr, wp, {"P1", "P2"});
        const Q r1 = positive(cl, "rho1", wc), r2 = positive(cl, "rho2", wc);
        const V3 x = point(at(cl, "point"), wc + ".point");
        const bool in1 = member(sc, 0, r1, x, at(pr, "P1"), wp + ".P1"), in2 = member(sc, 1, r2, x, at(pr, "P2"), wp + ".P2");
        return in1 && in2;
    }
    if (kind == "distance") {
        shape(cl, wc, {"kind", "rho1", "rho2", "value"}, {"closest"});
        const bool closest = cl.contains("closest");
        if (closest) shape(pr, wp, {"squared", "P1", "P2", "closest"});
        else shape(pr, wp, {"squared", "P1", "P2"});
        const Q r1 = positive(cl, "rho1", wc), r2 = positive(cl, "rho2", wc);
        const Q c = num(at(cl, "value"), wc + ".value");
        const Q E = num(at(pr, "squared"), wp + ".squared");
        const V3 p = body_point(sc, 0, r1, at(pr, "P1"), wp + ".P1"), q = body_point(sc, 1, r2, at(pr, "P2"), wp + ".P2");
        spend_ops(12, 2 * (vsize(p) + vsize(q)) + qsize(E));
        const V3 u = sub(q, p);
        claim(dot(u, u) == E, wp + ".squared is |q − p|² of its closest points");
        if (sgn(E) > 0) {
            claim(reach(sc, 0, u, r1) == dot(u, p), wp + ": no point of P1 lies beyond p along q − p");
            claim(reach_min(sc, 1, u, r2) == dot(u, q), wp + ": no point of P2 lies before q along q − p");
        }
        bool right = R.close_sq(c, E);
        if (closest) {
            const J& cp = at(cl, "closest");
            claim(cp.is_array() && cp.size() == 2, wc + ".closest is [point, point]");
            const V3 a = point(cp[0], wc + ".closest[0]"), b = point(cp[1], wc + ".closest[1]");
            const J& pc = at(pr, "closest");
            shape(pc, wp + ".closest", {"P1", "P2"});
            const bool in1 = member(sc, 0, r1, a, at(pc, "P1"), wp + ".closest.P1"), in2 = member(sc, 1, r2, b, at(pc, "P2"), wp + ".closest.P2");
            spend_ops(6, 2 * (vsize(a) + vsize(b)));
            const V3 ab = sub(b, a);
            right = right && in1 && in2 && R.within_above(dot(ab, ab), E);
        }
        return right;
    }
    if (kind == "penetration_depth") {
        shape(cl, wc, {"kind", "rho1", "rho2", "value"}, {"direction"});
        const Q r1 = positive(cl, "rho1", wc), r2 = positive(cl, "rho2", wc);
        const Q c = num(at(cl, "value"), wc + ".value");
        std::optional<V3> dir;
        if (cl.contains("direction")) dir = nonzero_vector(at(cl, "direction"), wc + ".direction");
        if (pr.contains("separated")) {
            shape(pr, wp, {"separated"});
            const V3 n = normal(at(pr, "separated"), wp + ".separated");
            claim(sgn(hM(sc, n, r1, r2)) < 0, wp + ".separated: the plane separates the pair strictly");
            return false;  // a depth claimed of a separated pair
        }
        Q E;
        if (pr.contains("common")) {
            shape(pr, wp, {"squared", "direction", "common"});
            claim(num(at(pr, "squared"), wp + ".squared") == 0, wp + ".squared is 0 for a touching pair");
            const V3 n = normal(at(pr, "direction"), wp + ".direction");
            claim(sgn(hM(sc, n, r1, r2)) == 0, wp + ".direction: the plane supports both bodies");
            const J& cm = at(pr, "common");
            shape(cm, wp + ".common", {"P1", "P2"});
            claim(body_point(sc, 0, r1, at(cm, "P1"), wp + ".common.P1") == body_point(sc, 1, r2, at(cm, "P2"), wp + ".common.P2"),
                  wp + ".common is a point of both bodies");
            E = 0;
        } else {
            shape(pr, wp, {"squared", "direction", "points", "triangles"});
            E = num(at(pr, "squared"), wp + ".squared");
            claim(sgn(E) > 0, wp + ".squared is > 0");
            const V3 n = normal(at(pr, "direction"), wp + ".direction");
            const Q g = hM(sc, n, r1, r2);
            spend_ops(4, 2 * qsize(g) + qsize(E) + 2 * vsize(n));
            claim(sgn(g) > 0 && g * g == E * dot(n, n), wp + ".direction: the depth along it is sqrt(squared)");
            check_lower_bound(sc, r1, r2, E, pr, wp);
        }
        bool right = R.close_sq(c, E);
        if (dir) {
            const Q g = hM(sc, *dir, r1, r2);
            spend_ops(4, 2 * qsize(g) + 2 * vsize(*dir));
            Q along = g * g / dot(*dir, *dir);
            if (sgn(g) < 0) along = -along;
            right = right && R.within_above(along, E);
        }
        return right;
    }
    if (kind == "curve") return judge_curve(R, cl, curve_window(sc, pr, wp), wc, wp);
    if (kind == "switch_point") return judge_switch_point(R, cl, curve_window(sc, pr, wp), wc, wp);
    if (kind == "curve_point") {  // a line `curve RHO1 RHO2`: rho2 is f(rho1), exactly (tolerance 0)
        shape(cl, wc, {"kind", "rho1", "rho2"});
        const Q r1 = positive(cl, "rho1", wc), r2 = positive(cl, "rho2", wc);
        const Window W = curve_window(sc, pr, wp);
        claim(W.a <= r1 && r1 <= W.b, wp + ".rho1 holds the claimed rho1");
        const Q f = W.f.at(r1);
        return sgn(f) > 0 && R.close(r2, f);
    }
    claim(false, wc + ".kind is verdict, growth_distance, separating_plane, witness_point, distance, penetration_depth, curve, "
                      "switch_point or curve_point");
    return false;
}
}  // namespace judge

std::string g_summary;  // appended to the line printed for a valid file
// Every entry {"index", "claim", "right", "proof"} of a judgements list: distinct indices, and
// "right" the judgement that judge(claim, proof, where) gives. Returns how many are right.
// A claim the program gave no answer in (FORMAT.md, "A judgements file"): the proof names a field
// where the claim's kind answers, and the claim has it null, or, for a normal or a direction,
// three exact zeros. Such a claim is wrong.
void check_no_answer(const J& cl, const J& pr, const std::string& where) {
    claim(cl.is_object() && cl.contains("kind") && cl["kind"].is_string(), where + ".claim has a kind");
    shape(pr, where + ".proof", {"no_answer"});
    claim(at(pr, "no_answer").is_string(), where + ".proof.no_answer is a string");
    const std::string kind = cl["kind"].get<std::string>(), f = at(pr, "no_answer").get<std::string>();
    static const std::map<std::string, std::set<std::string>> answers = {
        {"growth_distance", {"value"}}, {"curve_point", {"rho2"}}, {"switch_point", {"rho1", "rho2"}},
        {"separating_plane", {"normal", "offset"}}, {"witness_point", {"point"}}, {"distance", {"value", "closest"}},
        {"penetration_depth", {"value", "direction"}}};
    const auto k = answers.find(kind);
    claim(k != answers.end() && k->second.count(f) == 1, where + ".proof.no_answer names a field where a " + kind + " claim answers");
    claim(cl.contains(f), where + ".claim has the field " + f);
    const J& v = cl[f];
    if (v.is_null()) return;
    claim(f == "normal" || f == "direction", where + ".claim." + f + " is null");
    claim(v.is_array() && v.size() == 3, where + ".claim." + f + " is null or three zeros");
    for (const J& x : v) claim(sgn(num(x, where + ".claim." + f)) == 0, where + ".claim." + f + " is null or three zeros");
}

template <class Judge>
size_t judge_all(const J& js, Judge judge) {
    claim(js.is_array(), "judgements is a list");
    std::set<size_t> indices;
    size_t rights = 0;
    for (size_t k = 0; k < js.size(); ++k) {
        const std::string w = "judgements[" + std::to_string(k) + "]";
        shape(js[k], w, {"index", "claim", "right", "proof"});
        claim(natural(at(js[k], "index")) && indices.insert(at(js[k], "index").get<size_t>()).second, w + ".index is a distinct natural number");
        claim(at(js[k], "right").is_boolean(), w + ".right is true or false");
        const J& pr = at(js[k], "proof");
        const bool no_answer = pr.is_object() && pr.contains("no_answer");
        if (no_answer) check_no_answer(at(js[k], "claim"), pr, w);
        const bool right = !no_answer && judge(at(js[k], "claim"), pr, w);
        claim(right == at(js[k], "right").get<bool>(), w + ".right must be the judgement the rules give, which is " + (right ? "right" : "wrong"));
        rights += right;
    }
    return rights;
}
// A tolerance as the checker prints it: a long one by its size, never by a prefix (a prefix hides
// a factor of 10^61).
std::string tolerance_shown(const Q& tol) {
    const std::string t = tol.get_str();
    if (t.size() <= 40) return t;
    char b[64];
    std::snprintf(b, sizeof b, "%.6g", nearest(tol));
    return std::string("~") + b + " (an exact fraction of " + std::to_string(t.size()) + " characters)";
}
void check_judgements(const J& c) {
    shape(c, "", {"format", "kind", "tolerance", "judgements", "seed_interior", "scene"});
    const Scene sc = read_scene(at(c, "scene"));
    check_seed_interior(sc, at(c, "seed_interior"));
    judge::Rules R{num(at(c, "tolerance"), "tolerance")};
    claim(sgn(R.tol) >= 0, "tolerance is >= 0");
    const J& js = at(c, "judgements");
    const size_t rights = judge_all(js, [&](const J& cl, const J& pr, const std::string& w) { return judge::judge(sc, R, cl, pr, w); });
    // What the file proves, in the line the checker prints: the judgements and their tolerance
    // (a forged tolerance makes wrong values right, and stays valid: it is the file's claim).
    // A long tolerance is shown by its size, never by a prefix (a prefix hides a factor of 10^61).
    g_summary = "; judgements: " + std::to_string(rights) + " right, " + std::to_string(js.size() - rights) + " wrong, tolerance " + tolerance_shown(R.tol);
}

// ---- a compound partition ----------------------------------------------------------------------
// Two objects made of convex parts, every part of object i scaled about its one seed s_i (which
// need lie in no part). The objects meet at (ρ1, ρ2) iff some part pair (A, B) does, and the file
// proves each pair's meeting set M in the rectangle on its own (FORMAT.md, "A compound
// partition"): an entry covers a block of pairs (P1 parts a0..a1 × P2 parts b0..b1) and lists
// normals n, each giving, over the vertices of the block's parts, the half-plane
// ρ1 hA(n) + ρ2 hB(n) >= n·d (hA over the P1 parts, hB over the P2 parts: never smaller than one
// pair's, so a point outside the half-plane is separated for every pair of the block). The
// rectangle cut by them all is recomputed here and must be the listed polygon: outside it some
// normal separates. A block of more than one pair must cut it to nothing; a single pair's polygon
// carries a witness at each corner, and the set of (x, ρ1, ρ2) with x in A(ρ1) ∩ B(ρ2) is convex,
// so the pair meets on the whole polygon. The blocks must cover every pair exactly once. So a
// point of the rectangle is in the overlap region iff it lies in some listed polygon.
constexpr size_t kMaxCompoundParts = 10000;  // parts an object: scalecert's own limit

// half_plane_cut, counted before it runs: each vertex's value (3 operations) and each crossing (about 8), every
// operation on the line's numbers and the largest vertex (counting the first vertex only would let
// a polygon with huge corners be cut by 40,000 small normals for 97 s).
std::vector<P2> cut(const std::vector<P2>& p, const Q& a, const Q& b, const Q& c) {
    double big = 0;
    for (const P2& v : p) big = std::max(big, qsize(v[0]) + qsize(v[1]));
    spend_ops(11.0 * static_cast<double>(p.size() + 1), qsize(a) + qsize(b) + qsize(c) + big);
    return half_plane_cut(p, a, b, c);
}

// [first, last] of a part range, 0 <= first <= last < n.
std::array<size_t, 2> part_range(const J& j, size_t n, const std::string& where) {
    claim(j.is_array() && j.size() == 2, where + " is [first, last]");
    const size_t a = index(j[0], n, where + "[0]"), b = index(j[1], n, where + "[1]");
    claim(a <= b, where + " has first <= last");
    return {a, b};
}

// A scene of two objects made of parts: each object's parts, their vertices held as one list
// (part k: [start[k], start[k + 1])), every part spanning 3 dimensions.
struct CompoundScene {
    Scene sc;
    std::vector<size_t> start[2];
    size_t parts(int i) const { return start[i].size() - 1; }
    // The vertices of parts first..last of object i, ascending.
    std::vector<int> verts(int i, size_t first, size_t last) const {
        std::vector<int> v;
        for (size_t k = start[i][first]; k < start[i][last + 1]; ++k) v.push_back(static_cast<int>(k));
        return v;
    }
};
CompoundScene read_compound_scene(const J& sj) {
    CompoundScene cs;
    Scene& sc = cs.sc;
    std::vector<size_t>(&start)[2] = cs.start;
    shape(sj, "scene", {"P1", "P2", "I1", "I2"});
    for (int i = 0; i < 2; ++i) {
        const std::string w = std::string("scene.") + kPoly[i];
        const J& p = at(sj, kPoly[i]);
        shape(p, w, {"parts", "seed"});
        const J& parts = at(p, "parts");
        claim(parts.is_array() && !parts.empty(), w + ".parts is a nonempty list");
        if (parts.size() > kMaxCompoundParts)
            throw Unreadable{w + " has more than " + std::to_string(kMaxCompoundParts) + " parts (scalecert's own limit)"};
        for (size_t k = 0; k < parts.size(); ++k) {
            const std::string wk = w + ".parts[" + std::to_string(k) + "]";
            shape(parts[k], wk, {"vertices"});
            const J& vs = at(parts[k], "vertices");
            claim(vs.is_array() && !vs.empty(), wk + ".vertices is a nonempty list");
            start[i].push_back(sc.P[i].size());
            for (size_t v = 0; v < vs.size(); ++v) sc.P[i].push_back(point(vs[v], wk + ".vertices[" + std::to_string(v) + "]"));
        }
        start[i].push_back(sc.P[i].size());
        sc.s[i] = point(at(p, "seed"), w + ".seed");
        sc.scan[i] = std::make_unique<Scan>(sc.P[i], kPoly[i]);
    }
    sc.prepare();
    read_ranges(sc, sj);
    // Each part spans 3 dimensions, as scalecert requires of its input (the claims would hold for
    // flat parts too: the file states a scene the engine reads).
    for (int i = 0; i < 2; ++i)
        for (size_t k = 0; k + 1 < start[i].size(); ++k) {
            std::vector<int> idx(start[i][k + 1] - start[i][k]);
            std::iota(idx.begin(), idx.end(), static_cast<int>(start[i][k]));
            claim(affine_dim(sc, i, idx) == 3, std::string("scene.") + kPoly[i] + ".parts[" + std::to_string(k) + "] spans 3 dimensions");
        }
    return cs;
}

void check_compound_partition(const J& c) {
    shape(c, "", {"format", "kind", "pairs", "growth_set", "scene"}, {"statistics"});
    const CompoundScene cs = read_compound_scene(at(c, "scene"));
    const Scene& sc = cs.sc;
    const std::vector<size_t>(&start)[2] = cs.start;
    if (c.contains("statistics")) {
        const J& st = at(c, "statistics");
        shape(st, "statistics", {"pairs", "pruned", "built", "entries", "witness_fallbacks"});
        for (const char* k : {"pairs", "pruned", "built", "entries", "witness_fallbacks"})
            claim(natural(at(st, k)), std::string("statistics.") + k + " is a count");
    }
    const size_t m = start[0].size() - 1, n = start[1].size() - 1;
    const std::vector<P2> rect = normalize({{sc.lo[0], sc.lo[1]}, {sc.hi[0], sc.lo[1]}, {sc.hi[0], sc.hi[1]}, {sc.lo[0], sc.hi[1]}});
    // Every pair covered once: a bit a pair.
    spend(static_cast<double>(m) * static_cast<double>(n) / 8);
    std::vector<bool> covered(m * n, false);
    size_t count = 0;
    struct Diagonal { Q from, to; size_t a, b; };
    std::vector<Diagonal> diag;  // each listed polygon where it meets ρ1 = ρ2
    size_t meeting = 0;
    const J& pairs = at(c, "pairs");
    claim(pairs.is_array() && !pairs.empty(), "pairs is a nonempty list");
    std::array<size_t, 2> previous{0, 0};
    for (size_t e = 0; e < pairs.size(); ++e) {
        const std::string w = "pairs[" + std::to_string(e) + "]";
        const J& pe = pairs[e];
        shape(pe, w, {"P1_parts", "P2_parts", "normals", "vertices", "vertices_double", "witnesses"});
        const std::array<size_t, 2> ra = part_range(at(pe, "P1_parts"), m, w + ".P1_parts"), rb = part_range(at(pe, "P2_parts"), n, w + ".P2_parts");
        claim(e == 0 || std::array<size_t, 2>{ra[0], rb[0]} > previous, w + " comes after the entry before it (by first P1 part, then first P2 part)");
        previous = {ra[0], rb[0]};
        spend(static_cast<double>(ra[1] - ra[0] + 1) * static_cast<double>(rb[1] - rb[0] + 1));
        for (size_t a = ra[0]; a <= ra[1]; ++a)
            for (size_t b = rb[0]; b <= rb[1]; ++b) {
                if (covered[a * n + b])  // (the message only when it fails: a block may cover 10^8 pairs)
                    claim(false, w + " covers the pair (" + std::to_string(a) + ", " + std::to_string(b) + ") a second time");
                covered[a * n + b] = true;
                ++count;
            }
        // The block's vertices on each side, ascending, and the half-planes of its normals.
        std::vector<int> verts[2];
        const std::array<size_t, 2>* r[2] = {&ra, &rb};
        for (int i = 0; i < 2; ++i)
            for (size_t k = start[i][(*r[i])[0]]; k < start[i][(*r[i])[1] + 1]; ++k) verts[i].push_back(static_cast<int>(k));
        const J& ns = at(pe, "normals");
        claim(ns.is_array(), w + ".normals is a list");
        std::vector<P2> poly = rect;
        for (size_t k = 0; k < ns.size(); ++k) {
            const V3 nv = normal(ns[k], w + ".normals[" + std::to_string(k) + "]");
            mpz_class H[2];
            for (int i = 0; i < 2; ++i) {
                Z3 u = ints(nv);
                if (i == 1) for (auto& x : u) x = -x;
                const std::vector<int> best = sc.scan[i]->argmax(u, &verts[i]);
                H[i] = sc.support_at(i, u, best[0]);  // D* hA(n), D* hB(n)
            }
            spend_ops(1, 3 * (limbs(sc.Delta[0]) + limbs(sc.Delta[1]) + limbs(sc.Delta[2])));
            const mpz_class C = dotz(ints(nv), sc.Delta);  // D* n·d
            if (!poly.empty()) poly = cut(poly, Q(H[0]), Q(H[1]), Q(C));
        }
        claim(polygon(pe, w) == poly, w + ".vertices is the rectangle cut by its normals' half-planes");
        const J& wit = at(pe, "witnesses");
        claim(wit.is_array() && wit.size() == poly.size(), w + " has a witness at each vertex");
        if (poly.empty()) continue;
        claim(ra[0] == ra[1] && rb[0] == rb[1], w + " is one pair: a block of pairs must meet nowhere in the rectangle");
        const std::array<std::array<size_t, 2>, 2> parts{{{start[0][ra[0]], start[0][ra[0] + 1] - start[0][ra[0]]},
                                                          {start[1][rb[0]], start[1][rb[0] + 1] - start[1][rb[0]]}}};
        for (size_t k = 0; k < poly.size(); ++k)
            claim(check_witness(sc, wit[k], w + ".witnesses[" + std::to_string(k) + "]", nullptr, &parts) == poly[k],
                  w + ".witnesses[" + std::to_string(k) + "] is at its vertex");
        ++meeting;
        std::vector<P2> d = cut(cut(poly, Q(-1), Q(1), Q(0)), Q(1), Q(-1), Q(0));  // on ρ1 = ρ2
        if (!d.empty()) {
            Q t0 = d[0][0], t1 = d[0][0];
            for (const P2& x : d) t0 = std::min(t0, x[0]), t1 = std::max(t1, x[0]);
            diag.push_back({t0, t1, ra[0], rb[0]});
        }
    }
    claim(count == m * n, "the entries cover every part pair (" + std::to_string(count) + " of " + std::to_string(m * n) + ")");
    // The growth set: where the objects meet on ρ1 = ρ2, the union of the pairs' intervals, each
    // with the pair that meets at its start (the least start, then the first pair by part).
    std::sort(diag.begin(), diag.end(), [](const Diagonal& x, const Diagonal& y) {
        return x.from != y.from ? x.from < y.from : std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
    });
    std::vector<Diagonal> merged;
    for (const Diagonal& d : diag) {
        if (!merged.empty() && d.from <= merged.back().to) {
            if (d.to > merged.back().to) merged.back().to = d.to;
        } else {
            merged.push_back(d);
        }
    }
    const J& gs = at(c, "growth_set");
    claim(gs.is_array() && gs.size() == merged.size(), "growth_set has one interval per connected piece of the overlap region on rho1 = rho2 (" +
                                                           std::to_string(merged.size()) + ")");
    for (size_t k = 0; k < merged.size(); ++k) {
        const std::string w = "growth_set[" + std::to_string(k) + "]";
        shape(gs[k], w, {"from", "from_double", "to", "to_double", "first_contact"});
        claim(field(gs[k], "from", w) == merged[k].from && field(gs[k], "to", w) == merged[k].to, w + " is the interval recomputed from the pairs");
        const J& fc = at(gs[k], "first_contact");
        shape(fc, w + ".first_contact", {"P1_part", "P2_part"});
        claim(index(at(fc, "P1_part"), m, w + ".first_contact.P1_part") == merged[k].a &&
                  index(at(fc, "P2_part"), n, w + ".first_contact.P2_part") == merged[k].b,
              w + ".first_contact is the first pair meeting at its start");
    }
    g_summary = "; compound: " + std::to_string(m) + " x " + std::to_string(n) + " part pairs, " + std::to_string(meeting) +
                " meeting somewhere in I1 x I2";
}

// ---- a compound judgements file ----------------------------------------------------------------
// certify-fp's judgements on two objects made of parts (FORMAT.md, "A compound judgements file"),
// each re-derived from its claim and its proof by CLAIMS.md's rules ("Objects made of parts").
namespace compound {

// max over the parts first..last of object i, scaled by rho about the object's seed, of n·x (n a
// nonzero rational): n·s + rho max over their vertices of n·(v − s), a scan of those vertices.
Q block_reach(const CompoundScene& cs, int i, const V3& n, const Q& rho, size_t first, size_t last) {
    const Scene& sc = cs.sc;
    spend_ops(12, judge::vsize(n) + judge::vsize(sc.s[i]) + qsize(rho) + 2 * limbs(sc.Dj));
    mpz_class L;
    const Z3 u = ints(judge::integral(n, &L));
    const std::vector<int> verts = cs.verts(i, first, last);
    spend(5.0 * static_cast<double>(verts.size()));  // the list itself, and the scan's gathering through it
    const std::vector<int> best = sc.scan[i]->argmax(u, &verts);
    Q h(sc.support_at(i, u, best[0]), sc.Dj * L);  // max over the vertices of u·(v − s), over L
    h.canonicalize();
    return dot(n, sc.s[i]) + rho * h;
}
// The least over the same parts of n·x.
Q block_floor(const CompoundScene& cs, int i, const V3& n, const Q& rho, size_t first, size_t last) {
    return -block_reach(cs, i, {-n[0], -n[1], -n[2]}, rho, first, last);
}
// s + rho (Σ w v − s) for weights over part k of object i (indices into the part's own points).
V3 part_point(const CompoundScene& cs, int i, size_t k, const Q& rho, const J& w, const std::string& where, std::vector<int>* used = nullptr) {
    const Scene& sc = cs.sc;
    const std::array<Q, 3> c = combination(sc, i, w, where, used, cs.start[i][k], cs.start[i][k + 1] - cs.start[i][k]);
    spend_ops(12, judge::vsize(sc.s[i]) + qsize(rho) + std::max({qsize(c[0]), qsize(c[1]), qsize(c[2])}) + limbs(sc.scan[i]->D()));
    const Q D(sc.scan[i]->D());
    V3 x;
    for (int d = 0; d < 3; ++d) x[d] = sc.s[i][d] + rho * (c[d] / D - sc.s[i][d]);
    return x;
}
// [k, j]: a part of P1 and a part of P2.
std::array<size_t, 2> part_pair(const CompoundScene& cs, const J& j, const std::string& where) {
    claim(j.is_array() && j.size() == 2, where + " is [P1 part, P2 part]");
    return {index(j[0], cs.parts(0), where + "[0]"), index(j[1], cs.parts(1), where + "[1]")};
}
// Is x in object i at rho? {"part": k, "in": weights} combining to x in part k, or
// {"out": [a normal per part]}, x strictly beyond each part's extent along its normal.
bool member(const CompoundScene& cs, int i, const Q& rho, const V3& x, const J& p, const std::string& where) {
    claim(p.is_object(), where + " is an object");
    if (p.contains("out")) {
        shape(p, where, {"out"});
        const J& o = at(p, "out");
        claim(o.is_array() && o.size() == cs.parts(i), where + ".out has a normal for each part");
        for (size_t k = 0; k < o.size(); ++k) {
            const std::string wk = where + ".out[" + std::to_string(k) + "]";
            const V3 n = normal(o[k], wk);
            spend_ops(3, judge::vsize(n) + judge::vsize(x));
            claim(dot(n, x) > block_reach(cs, i, n, rho, k, k), wk + ": the point lies strictly beyond the part's extent along the normal");
        }
        return false;
    }
    shape(p, where, {"part", "in"});
    const size_t k = index(at(p, "part"), cs.parts(i), where + ".part");
    claim(part_point(cs, i, k, rho, at(p, "in"), where + ".in") == x, where + ".in combines to the point");
    return true;
}
// Blocks {"P1_parts", "P2_parts", "normal"} covering every part pair once, in increasing (first
// P1 part, first P2 part) order; ok(c1, c2, n) judges each block by the largest n·x over its P1
// parts at rho1 (c1) and the least over its P2 parts at rho2 (c2).
template <class Ok>
void check_blocks(const CompoundScene& cs, const Q& r1, const Q& r2, const J& bs, const std::string& where, Ok ok) {
    const size_t m = cs.parts(0), n = cs.parts(1);
    claim(bs.is_array() && !bs.empty(), where + " is a nonempty list");
    spend(static_cast<double>(m) * static_cast<double>(n) / 8);
    std::vector<bool> covered(m * n, false);
    size_t count = 0;
    std::array<size_t, 2> previous{0, 0};
    for (size_t e = 0; e < bs.size(); ++e) {
        const std::string w = where + "[" + std::to_string(e) + "]";
        shape(bs[e], w, {"P1_parts", "P2_parts", "normal"});
        const std::array<size_t, 2> ra = part_range(at(bs[e], "P1_parts"), m, w + ".P1_parts"), rb = part_range(at(bs[e], "P2_parts"), n, w + ".P2_parts");
        claim(e == 0 || std::array<size_t, 2>{ra[0], rb[0]} > previous, w + " comes after the block before it (by first P1 part, then first P2 part)");
        previous = {ra[0], rb[0]};
        spend(static_cast<double>(ra[1] - ra[0] + 1) * static_cast<double>(rb[1] - rb[0] + 1));
        for (size_t a = ra[0]; a <= ra[1]; ++a)
            for (size_t b = rb[0]; b <= rb[1]; ++b) {
                if (covered[a * n + b])  // (the message only when it fails: a block may cover 10^8 pairs)
                    claim(false, w + " covers the pair (" + std::to_string(a) + ", " + std::to_string(b) + ") a second time");
                covered[a * n + b] = true;
                ++count;
            }
        const V3 nv = judge::nonzero_vector(at(bs[e], "normal"), w + ".normal");
        const Q c1 = block_reach(cs, 0, nv, r1, ra[0], ra[1]), c2 = block_floor(cs, 1, nv, r2, rb[0], rb[1]);
        ok(c1, c2, nv, w);
    }
    claim(count == m * n, where + " covers every part pair (" + std::to_string(count) + " of " + std::to_string(m * n) + ")");
}

bool judge_claim(const CompoundScene& cs, const judge::Rules& R, const J& cl, const J& pr, const std::string& where) {
    const Scene& sc = cs.sc;
    claim(cl.is_object() && cl.contains("kind") && cl["kind"].is_string(), where + ".claim has a kind");
    claim(pr.is_object(), where + ".proof is an object");
    const std::string kind = cl["kind"].get<std::string>();
    const std::string wc = where + ".claim", wp = where + ".proof";
    if (kind == "verdict") {
        shape(cl, wc, {"kind", "rho1", "rho2", "verdict"});
        const Q r1 = judge::positive(cl, "rho1", wc), r2 = judge::positive(cl, "rho2", wc);
        // (at() reads a key that shape() has seen: the proof's verdict is looked up first.)
        claim(pr.contains("verdict") && pr.find("verdict")->is_string() && at(cl, "verdict").is_string(), where + ": verdicts are strings");
        const std::string c = at(cl, "verdict").get<std::string>(), v = pr.find("verdict")->get<std::string>();
        claim(c == "separated" || c == "touching" || c == "overlapping" || c == "intersecting", wc + ".verdict is separated, touching, overlapping or intersecting");
        if (v == "overlapping") {
            // A point inside a part of each: strictly positive weights on points spanning 3
            // dimensions lie inside their hull, hence inside the part, and scaling keeps it inside.
            shape(pr, wp, {"verdict", "pair", "interior"});
            const std::array<size_t, 2> kj = part_pair(cs, at(pr, "pair"), wp + ".pair");
            const J& in = at(pr, "interior");
            shape(in, wp + ".interior", {"P1", "P2"});
            std::vector<int> used[2];
            const V3 x = part_point(cs, 0, kj[0], r1, at(in, "P1"), wp + ".interior.P1", &used[0]);
            const V3 y = part_point(cs, 1, kj[1], r2, at(in, "P2"), wp + ".interior.P2", &used[1]);
            claim(x == y, wp + ".interior is one point of both parts");
            for (int i = 0; i < 2; ++i)
                claim(affine_dim(sc, i, used[i]) == 3, wp + ".interior." + kPoly[i] + " uses points spanning 3 dimensions (an interior point)");
        } else if (v == "touching" || v == "separated") {
            // Every pair apart by a plane (weakly: no interiors meet; strictly: none meets); touching
            // also needs a common point of one pair.
            const bool touching = v == "touching";
            if (touching) shape(pr, wp, {"verdict", "blocks", "pair", "witness"});
            else shape(pr, wp, {"verdict", "blocks"});
            check_blocks(cs, r1, r2, at(pr, "blocks"), wp + ".blocks", [&](const Q& c1, const Q& c2, const V3&, const std::string& w) {
                spend_ops(1, qsize(c1) + qsize(c2));
                if (touching) claim(c1 <= c2, w + ": the plane separates its block's pairs (weakly)");
                else claim(c1 < c2, w + ": the plane separates its block's pairs strictly");
            });
            if (touching) {
                const std::array<size_t, 2> kj = part_pair(cs, at(pr, "pair"), wp + ".pair");
                const J& wt = at(pr, "witness");
                shape(wt, wp + ".witness", {"P1", "P2"});
                claim(part_point(cs, 0, kj[0], r1, at(wt, "P1"), wp + ".witness.P1") == part_point(cs, 1, kj[1], r2, at(wt, "P2"), wp + ".witness.P2"),
                      wp + ".witness is a point of both parts");
            }
        } else {
            claim(false, wp + ".verdict is separated, touching or overlapping");
        }
        return c == "intersecting" ? v != "separated" : c == v;
    }
    if (kind == "separating_plane") {
        shape(cl, wc, {"kind", "rho1", "rho2", "normal"}, {"offset"});
        claim(pr.empty(), wp + " is empty (the checker computes the extents)");
        const Q r1 = judge::positive(cl, "rho1", wc), r2 = judge::positive(cl, "rho2", wc);
        const V3 n = judge::nonzero_vector(at(cl, "normal"), wc + ".normal");
        const Q c1 = block_reach(cs, 0, n, r1, 0, cs.parts(0) - 1), c2 = block_floor(cs, 1, n, r2, 0, cs.parts(1) - 1);
        bool right = c1 < c2;
        if (cl.contains("offset")) {
            const Q d = num(at(cl, "offset"), wc + ".offset");
            right = right && c1 < d && d < c2;
        }
        return right;
    }
    if (kind == "witness_point") {
        shape(cl, wc, {"kind", "rho1", "rho2", "point"});
        shape(pr, wp, {"P1", "P2"});
        const Q r1 = judge::positive(cl, "rho1", wc), r2 = judge::positive(cl, "rho2", wc);
        const V3 x = point(at(cl, "point"), wc + ".point");
        const bool in1 = member(cs, 0, r1, x, at(pr, "P1"), wp + ".P1"), in2 = member(cs, 1, r2, x, at(pr, "P2"), wp + ".P2");
        return in1 && in2;
    }
    if (kind == "distance") {
        shape(cl, wc, {"kind", "rho1", "rho2", "value"}, {"closest"});
        const Q r1 = judge::positive(cl, "rho1", wc), r2 = judge::positive(cl, "rho2", wc);
        const Q c = num(at(cl, "value"), wc + ".value");
        claim(pr.contains("squared"), wp + ".squared is present");
        const Q E = num(*pr.find("squared"), wp + ".squared");
        claim(sgn(E) >= 0, wp + ".squared is >= 0");
        if (sgn(E) > 0) shape(pr, wp, {"squared", "pair", "P1", "P2", "apart"}, {"closest"});
        else shape(pr, wp, {"squared", "pair", "P1", "P2"}, {"closest"});
        claim(cl.contains("closest") == pr.contains("closest"), wp + ".closest is there exactly when the claim has closest points");
        // The upper bound: two points of the objects, sqrt(E) apart.
        const std::array<size_t, 2> kj = part_pair(cs, at(pr, "pair"), wp + ".pair");
        const V3 p = part_point(cs, 0, kj[0], r1, at(pr, "P1"), wp + ".P1"), q = part_point(cs, 1, kj[1], r2, at(pr, "P2"), wp + ".P2");
        const V3 pq{q[0] - p[0], q[1] - p[1], q[2] - p[2]};
        spend_ops(6, 2 * judge::vsize(pq));
        claim(dot(pq, pq) == E, wp + ": the points P1 and P2 are sqrt(squared) apart");
        // The lower bound: every pair at least sqrt(E) apart, gap(u) >= sqrt(E) |u| over each block.
        if (sgn(E) > 0)
            check_blocks(cs, r1, r2, at(pr, "apart"), wp + ".apart", [&](const Q& c1, const Q& c2, const V3& u, const std::string& w) {
                const Q gap = c2 - c1;
                spend_ops(6, 2 * qsize(gap) + qsize(E) + 2 * judge::vsize(u));
                claim(sgn(gap) > 0 && gap * gap >= E * dot(u, u), w + ": its pairs are at least sqrt(squared) apart along the normal");
            });
        bool right = R.close_sq(c, E);
        if (cl.contains("closest")) {
            const J& cp = at(cl, "closest");
            claim(cp.is_array() && cp.size() == 2, wc + ".closest is [point, point]");
            const V3 a = point(cp[0], wc + ".closest[0]"), b = point(cp[1], wc + ".closest[1]");
            const J& pc = at(pr, "closest");
            shape(pc, wp + ".closest", {"P1", "P2"});
            const bool in1 = member(cs, 0, r1, a, at(pc, "P1"), wp + ".closest.P1"), in2 = member(cs, 1, r2, b, at(pc, "P2"), wp + ".closest.P2");
            const V3 ab{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
            spend_ops(6, 2 * judge::vsize(ab));
            right = right && in1 && in2 && R.within_above(dot(ab, ab), E);
        }
        return right;
    }
    claim(false, wc + ".kind is verdict, separating_plane, witness_point or distance (the claims on objects made of parts)");
    return false;
}

}  // namespace compound

void check_compound_judgements(const J& c) {
    shape(c, "", {"format", "kind", "tolerance", "judgements", "scene"});
    const CompoundScene cs = read_compound_scene(at(c, "scene"));
    judge::Rules R{num(at(c, "tolerance"), "tolerance")};
    claim(sgn(R.tol) >= 0, "tolerance is >= 0");
    const J& js = at(c, "judgements");
    const size_t rights = judge_all(js, [&](const J& cl, const J& pr, const std::string& w) { return compound::judge_claim(cs, R, cl, pr, w); });
    g_summary = "; compound judgements: " + std::to_string(rights) + " right, " + std::to_string(js.size() - rights) + " wrong, tolerance " +
                tolerance_shown(R.tol) + "; " + std::to_string(cs.parts(0)) + " x " + std::to_string(cs.parts(1)) + " part pairs";
}

// Checks a whole file's text. Returns the exit status; `message` is the line to print.
int check_text(const std::string& text, std::string& message) {
    g_claims = 0;
    g_summary.clear();
    g_work = 0;
    g_budget = std::max(g_min_work, g_work_per_byte * static_cast<double>(text.size()));
    try {
        if (text.size() > kMaxFileBytes) throw Unreadable{"larger than " + std::to_string(kMaxFileBytes) + " bytes"};
        const J c = parse_strict(text);
        try {
            claim(c.is_object() && c.contains("format") && c["format"] == J("scalecert-2"), "format is scalecert-2");
            claim(c.contains("kind") && c["kind"].is_string(), "kind is present");
            const std::string kind = c["kind"].get<std::string>();
            if (kind == "partition") check_partition(c);
            else if (kind == "query") check_query(c);
            else if (kind == "judgements") check_judgements(c);
            else if (kind == "compound_partition") check_compound_partition(c);
            else if (kind == "compound_judgements") check_compound_judgements(c);
            else claim(false, "kind is partition, query, judgements, compound_partition or compound_judgements (got '" + StrictTree::printable(kind) + "': not a certificate)");
        } catch (const Invalid& e) {
            message = "invalid: " + e.what;
            return 1;
        } catch (const J::exception& e) {
            message = std::string("invalid: mistyped field (") + e.what() + ")";
            return 1;
        }
    } catch (const Unreadable& e) {
        message = "error: " + e.what;
        return 2;
    } catch (const std::bad_alloc&) {
        message = "error: out of memory";
        return 2;
    } catch (const std::length_error&) {
        message = "error: out of memory";
        return 2;
    }
    message = "valid: " + std::to_string(g_claims) + " claims checked" + g_summary;
    return 0;
}
}  // namespace scalecert_check

#ifndef SCALECERT_CHECK_NO_MAIN
namespace {
// GMP aborts when an allocation fails: here that becomes std::bad_alloc, exit 2.
void* gmp_alloc(size_t n) {
    if (void* p = std::malloc(n)) return p;
    throw std::bad_alloc();
}
void* gmp_realloc(void* p, size_t, size_t n) {
    if (void* q = std::realloc(p, n)) return q;
    throw std::bad_alloc();
}
void gmp_free(void* p, size_t) { std::free(p); }
}  // namespace

int main(int argc, char** argv) {
    mp_set_memory_functions(gmp_alloc, gmp_realloc, gmp_free);
    if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
        std::cout << "usage: scalecert-check CERTIFICATE.json\n\n"
                     "Checks a scalecert certificate (a partition, a query answer or certify-fp's judgements;\n"
                     "certificates/FORMAT.md), re-deriving every claim from the scene stored in it.\n"
                     "Prints one line.\n"
                     "Exit status: 0 valid, 1 invalid (the first claim that fails), 2 unreadable or refused\n"
                     "(not a regular file, too large, malformed JSON, past the work limit).\n"
                     "A file named --help or --version: give it as ./--help.\n";
        return 0;
    }
#ifdef SCALECERT_VERSION_STRING
    if (argc == 2 && std::strcmp(argv[1], "--version") == 0) {
        std::cout << "scalecert-check " SCALECERT_VERSION_STRING "\n";
        return 0;
    }
#endif
    if (argc != 2) {
        std::cerr << "usage: scalecert-check CERTIFICATE.json (scalecert-check --help)\n";
        return 2;
    }
    std::string name = scalecert_check::StrictTree::printable(argv[1]), text;
    try {
        // Opened without blocking (a FIFO with no writer, a terminal) and refused unless a
        // regular file: a FIFO, socket, device or directory is never read. (The engine has the
        // same rule in its own code; the checker shares none.)
        auto refuse = [&](const std::string& why) {
            std::cerr << "scalecert-check: error: " << name << ": " << why << "\n";
            return 2;
        };
        auto kind = [](mode_t m) -> std::string {
            if (S_ISDIR(m)) return "is a directory";
            if (S_ISFIFO(m)) return "is a named pipe (FIFO)";
            if (S_ISSOCK(m)) return "is a socket";
            if (S_ISCHR(m)) return "is a character device";
            if (S_ISBLK(m)) return "is a block device";
            return "is not a regular file";
        };
        const std::string not_regular = ", not a certificate file (only regular files are read)";
        struct stat st {};
        if (::stat(argv[1], &st) == 0 && !S_ISREG(st.st_mode)) return refuse(kind(st.st_mode) + not_regular);
        const int fd = ::open(argv[1], O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) return refuse(std::string("cannot open (") + std::strerror(errno) + ")");
        if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
            ::close(fd);
            return refuse(kind(st.st_mode) + not_regular);
        }
        if (static_cast<unsigned long long>(st.st_size) > scalecert_check::kMaxFileBytes) {
            ::close(fd);
            return refuse("larger than 1 GiB");
        }
        ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
        char buf[1 << 16];
        bool too_big = false, failed = false;
        for (;;) {
            const ssize_t got = ::read(fd, buf, sizeof buf);
            if (got < 0 && errno == EINTR) continue;
            if (got <= 0) {
                failed = got < 0;
                break;
            }
            text.append(buf, static_cast<size_t>(got));
            if (text.size() > scalecert_check::kMaxFileBytes) { too_big = true; break; }
        }
        ::close(fd);
        if (failed) return refuse("cannot read");
        if (too_big) return refuse("larger than 1 GiB");
        std::string message;
        int status = scalecert_check::check_text(text, message);
        (status == 0 ? std::cout : std::cerr) << (status == 0 ? "" : "scalecert-check: ") << (status == 2 ? "error: " + name + ": " + message.substr(7) : message) << "\n";
        return status;
    } catch (const std::bad_alloc&) {
        std::cerr << "scalecert-check: error: " << name << ": out of memory\n";
        return 2;
    }
}
#endif
