#include "curve/scan.hpp"

#include "numeric/predicates.hpp"
#include "numeric/small_int.hpp"
#include "numeric/timing.hpp"
#include "geometry/witness.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <future>
#include <memory>
#include <numeric>
#include <optional>
#include <variant>

namespace scalecert::internal {

namespace {

std::atomic<std::uint64_t> g_handovers[kHandoverReasons];

// Each step of the walk returns its value, or where the walk stops (the hull model decides).
template <class T>
using Walked = std::variant<T, WalkStop>;
WalkStop stop(Handover h, int polyhedron = -1) { return {h, polyhedron}; }
// NAME = the value of EXPR, or return its stop from the enclosing function.
#define SCALECERT_WALK(name, expr)                                                                \
    auto name##_walked = (expr);                                                                  \
    if (const WalkStop* name##_stop = std::get_if<WalkStop>(&name##_walked)) return *name##_stop; \
    auto& name = std::get<0>(name##_walked)

// ---------------------------------------------------------------------------------------------
// Exact support queries on a point cloud.

// A direction: exact integers, their doubles (for the filter) and, when they fit, int64. Integers
// past 2^900 are scaled by one power of two 2^-e into the doubles (the same direction, so the same
// maximisers, and room for products with points up to 2^53): each double is then the integer's
// truncation times 2^-e exactly, with the relative error the filter allows for (predicates.hpp,
// 7), unless a coordinate falls below 2^-1000 (near the subnormals): then the direction is not
// finite for the filter.
struct Dir {
    Vec3z z;
    double d[3];
    std::int64_t s[3];
    bool small;
    bool finite = true;  // else the walk stops (Handover::NormalBeyondDoubles)
    explicit Dir(const Vec3z& v) : z(v) {
        small = true;
        long bits = 0;
        for (int k = 0; k < 3; ++k) {
            bits = std::max(bits, static_cast<long>(mpz_sizeinbase(v[k].get_mpz_t(), 2)));
            small = small && mpz_fits_slong_p(v[k].get_mpz_t());
            s[k] = small ? v[k].get_si() : 0;
        }
        const long shift = bits > 900 ? bits - 900 : 0;
        for (int k = 0; k < 3; ++k) {
            if (sgn(v[k]) == 0) {
                d[k] = 0;
                continue;
            }
            long e = 0;
            const double m = mpz_get_d_2exp(&e, v[k].get_mpz_t());  // v = m·2^e, 1/2 <= |m| < 1, truncated
            if (e - shift < -1000) {
                finite = false;
                d[k] = 0;
                continue;
            }
            d[k] = std::ldexp(m, static_cast<int>(e - shift));
        }
    }
};

// n·x exactly, for |x| ≤ 2^53: in 128 bits when n fits 64 (|products| < 2^116), else GMP.
Z dot_exact(const Dir& n, const std::int64_t* x) {
    if (n.small) return to_z(I128(n.s[0]) * x[0] + I128(n.s[1]) * x[1] + I128(n.s[2]) * x[2]);
    Z r = 0, t;
    for (int k = 0; k < 3; ++k) {
        mpz_mul_si(t.get_mpz_t(), n.z[k].get_mpz_t(), static_cast<long>(x[k]));
        r += t;
    }
    return r;
}

// max of u·X over the points `idx` of P (in P's integer frame), exactly, with the filter of bound 7
// (predicates.hpp): every true maximiser's double value is ≥ best − 2E, E = kScanSupport·Σ|u_k|·
// max|X_k| over these points; only those candidates are formed exactly. Linear in the points, and
// in machine arithmetic but for the few candidates (a face of 4,000 vertices against every edge
// normal of another was O(m1·m2) GMP rationals: 33 s).
Walked<Z> max_over(const IntPoints& P, const std::vector<int>& idx, const Vec3z& uz) {
    const Dir u(uz);
    if (!u.finite) return stop(Handover::NormalBeyondDoubles);
    double maxabs[3] = {0, 0, 0};
    for (int k : idx)
        for (int c = 0; c < 3; ++c)
            maxabs[c] = std::max(maxabs[c], std::fabs(static_cast<double>(P.at(static_cast<size_t>(k))[c])));
    double B = 0;
    for (int c = 0; c < 3; ++c) B += std::fabs(u.d[c]) * maxabs[c];
    const filter::ScanSupportFilter keep(B);
    std::vector<double> v(idx.size());
    double best = -INFINITY;
    for (size_t i = 0; i < idx.size(); ++i) {
        const std::int64_t* x = P.at(static_cast<size_t>(idx[i]));
        v[i] = u.d[0] * static_cast<double>(x[0]) + u.d[1] * static_cast<double>(x[1]) +
               u.d[2] * static_cast<double>(x[2]);
        best = std::max(best, v[i]);
    }
    std::optional<Z> top;
    for (size_t i = 0; i < idx.size(); ++i)
        if (keep.candidate(v[i], best)) {
            Z t = dot_exact(u, P.at(static_cast<size_t>(idx[i])));
            if (!top || t > *top) top = std::move(t);
        }
    return *top;
}

struct Support {
    std::vector<int> all;  // every point attaining the maximum, sorted by index
    Z value;               // the maximum of n·x over the points times the scale
};

// The points in a bounding-volume tree: each node's box holds its points (kept in tree order,
// with their doubles beside them, so that a query reads memory in order).
class Cloud {
  public:
    Cloud(const IntPoints& P, ScanStats& st) : P_(P), st_(st) {
        const size_t n = P.size();
        for (int k = 0; k < 3; ++k) maxabs_[k] = 0;
        for (size_t i = 0; i < 3 * n; ++i)
            maxabs_[i % 3] = std::max(maxabs_[i % 3], std::fabs(static_cast<double>(P.x[i])));
        // Points in Morton order (a space-filling curve over their box), then a balanced tree
        // over that order: halves of the order are spatially coherent, and no sort by axis is
        // needed (radix sort of the codes).
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (size_t i = 0; i < n; ++i)
            for (int k = 0; k < 3; ++k) {
                const double v = static_cast<double>(P.x[3 * i + k]);
                lo[k] = std::min(lo[k], v), hi[k] = std::max(hi[k], v);
            }
        // Spreads the low 21 bits of v to every third bit.
        auto spread = [](std::uint64_t v) {
            v &= 0x1fffff;
            v = (v | v << 32) & 0x1f00000000ffffULL;
            v = (v | v << 16) & 0x1f0000ff0000ffULL;
            v = (v | v << 8) & 0x100f00f00f00f00fULL;
            v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
            v = (v | v << 2) & 0x1249249249249249ULL;
            return v;
        };
        std::vector<std::uint64_t> key(n);
        for (size_t i = 0; i < n; ++i) {
            std::uint64_t code = 0;
            for (int k = 0; k < 3; ++k) {
                const double span = hi[k] - lo[k];
                auto c = static_cast<std::uint64_t>(
                    span > 0 ? (static_cast<double>(P.x[3 * i + k]) - lo[k]) / span * 2097151.0 : 0.0);
                code |= spread(std::min<std::uint64_t>(c, 2097151)) << k;
            }
            key[i] = code;
        }
        perm_.resize(n);
        std::iota(perm_.begin(), perm_.end(), 0u);
        {  // LSD radix sort of (key, index), 11 bits a pass
            std::vector<std::uint32_t> tmp(n);
            std::vector<std::uint64_t> ktmp(n);
            for (int shift = 0; shift < 63; shift += 11) {
                std::uint32_t cnt[2049] = {};
                for (size_t i = 0; i < n; ++i) ++cnt[((key[i] >> shift) & 0x7ff) + 1];
                for (size_t d = 1; d < 2049; ++d) cnt[d] += cnt[d - 1];
                for (size_t i = 0; i < n; ++i) {
                    const std::uint32_t at = cnt[(key[i] >> shift) & 0x7ff]++;
                    tmp[at] = perm_[i];
                    ktmp[at] = key[i];
                }
                perm_.swap(tmp);
                key.swap(ktmp);
            }
        }
        xd_.resize(3 * n);
        for (size_t i = 0; i < n; ++i)
            for (int k = 0; k < 3; ++k) xd_[3 * i + k] = static_cast<double>(P.x[3 * perm_[i] + k]);
        nodes_.reserve(4 * n / kLeaf + 2);
        build(0, static_cast<std::uint32_t>(n));
    }

    const IntPoints& points() const { return P_; }

    // Every maximiser of n·x, exactly. Filter (predicates.hpp, bound 7): every true maximiser has
    // a computed value ≥ best − 2E, and a box whose bound is below best − 4E holds no such point,
    // for E = kScanSupport·Σ|n_k|·max|x_k|. The candidates are then compared exactly.
    Walked<Support> support(const Vec3z& nz) const {
        ++st_.support_queries;
        const Dir n(nz);
        if (!n.finite) return stop(Handover::NormalBeyondDoubles);
        double B = 0;
        for (int k = 0; k < 3; ++k) B += std::fabs(n.d[k]) * maxabs_[k];
        if (!(B > 0) || !std::isfinite(B)) return stop(Handover::ZeroOrHugeNormal);
        const filter::ScanSupportFilter keep(B);
        double best = -INFINITY;
        std::uint64_t visited = 0;
        std::vector<std::pair<double, std::uint32_t>> cand;
        std::vector<std::pair<double, std::uint32_t>> stack;
        stack.push_back({ub(nodes_[0], n.d), 0});
        while (!stack.empty()) {
            auto [u, id] = stack.back();
            stack.pop_back();
            if (keep.box_excluded(u, best)) continue;
            const Node& nd = nodes_[id];
            if (nd.left < 0) {
                visited += nd.end - nd.begin;
                for (std::uint32_t i = nd.begin; i < nd.end; ++i) {
                    const double* x = &xd_[3 * i];
                    const double v = n.d[0] * x[0] + n.d[1] * x[1] + n.d[2] * x[2];
                    if (keep.candidate(v, best)) {
                        cand.push_back({v, i});
                        if (v > best) best = v;
                    }
                }
                if (cand.size() > filter::kScanPruneEvery) prune(cand, keep.floor(best));
            } else {
                const double ul = ub(nodes_[nd.left], n.d), ur = ub(nodes_[nd.right], n.d);
                if (ul < ur) {
                    stack.push_back({ul, static_cast<std::uint32_t>(nd.left)});
                    stack.push_back({ur, static_cast<std::uint32_t>(nd.right)});
                } else {
                    stack.push_back({ur, static_cast<std::uint32_t>(nd.right)});
                    stack.push_back({ul, static_cast<std::uint32_t>(nd.left)});
                }
            }
        }
        prune(cand, keep.floor(best));
        // Predicate 7's statistics: the points ruled out by the filter, the candidates left.
        st_.predicates.filtered(filter::Predicate::ScanSupport, visited - cand.size());
        st_.predicates.exact(filter::Predicate::ScanSupport, cand.size());
        Support s;
        bool first = true;
        for (const auto& [v, i] : cand) {
            const int idx = static_cast<int>(perm_[i]);
            Z val = dot_exact(n, P_.at(static_cast<size_t>(idx)));
            if (first || val > s.value) {
                s.value = std::move(val);
                s.all.assign(1, idx);
                first = false;
            } else if (val == s.value) {
                s.all.push_back(idx);
            }
        }
        std::sort(s.all.begin(), s.all.end());
        return s;
    }

    // The point (its index) with the largest double value of d·x: a guess (GJK's), by the same
    // tree with plain bounds, no filter and no exact stage.
    int dbest(const double* d) const {
        double best = -INFINITY;
        std::uint32_t at = 0;
        // A depth-first walk keeps at most one entry per level and one more: the tree is balanced,
        // so its depth is below 64 for any count of points that fits 32 bits.
        std::pair<double, std::uint32_t> stack[66];
        size_t top = 0;
        stack[top++] = {ub(nodes_[0], d), 0};
        while (top > 0) {
            auto [u, id] = stack[--top];
            if (u <= best) continue;
            const Node& nd = nodes_[id];
            if (nd.left < 0) {
                for (std::uint32_t i = nd.begin; i < nd.end; ++i) {
                    const double* x = &xd_[3 * i];
                    const double v = d[0] * x[0] + d[1] * x[1] + d[2] * x[2];
                    if (v > best) best = v, at = i;
                }
            } else {
                const double ul = ub(nodes_[nd.left], d), ur = ub(nodes_[nd.right], d);
                if (ul < ur) {
                    stack[top++] = {ul, static_cast<std::uint32_t>(nd.left)};
                    stack[top++] = {ur, static_cast<std::uint32_t>(nd.right)};
                } else {
                    stack[top++] = {ur, static_cast<std::uint32_t>(nd.right)};
                    stack[top++] = {ul, static_cast<std::uint32_t>(nd.left)};
                }
            }
        }
        return static_cast<int>(perm_[at]);
    }

  private:
    static constexpr std::uint32_t kLeaf = 16;
    struct Node {
        double lo[3], hi[3];
        std::uint32_t begin, end;
        std::int32_t left = -1, right = -1;
    };

    static double ub(const Node& nd, const double* d) {
        double u = 0;
        for (int k = 0; k < 3; ++k) u += std::max(d[k] * nd.lo[k], d[k] * nd.hi[k]);
        return u;
    }
    static void prune(std::vector<std::pair<double, std::uint32_t>>& c, double floor) {
        c.erase(std::remove_if(c.begin(), c.end(), [&](const auto& p) { return p.first < floor; }), c.end());
    }

    // A balanced tree over the order; boxes from the children's.
    std::int32_t build(std::uint32_t b, std::uint32_t e) {
        const auto id = static_cast<std::int32_t>(nodes_.size());
        nodes_.push_back({});
        Node nd;
        nd.begin = b;
        nd.end = e;
        if (e - b <= kLeaf) {
            for (int k = 0; k < 3; ++k) nd.lo[k] = INFINITY, nd.hi[k] = -INFINITY;
            for (std::uint32_t i = b; i < e; ++i)
                for (int k = 0; k < 3; ++k)
                    nd.lo[k] = std::min(nd.lo[k], xd_[3 * i + k]), nd.hi[k] = std::max(nd.hi[k], xd_[3 * i + k]);
        } else {
            const std::uint32_t mid = b + (e - b) / 2;
            nd.left = build(b, mid);
            nd.right = build(mid, e);
            const Node &l = nodes_[static_cast<size_t>(nd.left)], &r = nodes_[static_cast<size_t>(nd.right)];
            for (int k = 0; k < 3; ++k) nd.lo[k] = std::min(l.lo[k], r.lo[k]), nd.hi[k] = std::max(l.hi[k], r.hi[k]);
        }
        nodes_[static_cast<size_t>(id)] = nd;
        return id;
    }

    const IntPoints& P_;
    ScanStats& st_;
    std::vector<std::uint32_t> perm_;
    std::vector<double> xd_;
    std::vector<Node> nodes_;
    double maxabs_[3];
};

// ---------------------------------------------------------------------------------------------
// Support polygons and the faces of the Minkowski sum.

Vec3z zpoint(const IntPoints& P, int k) {
    const std::int64_t* x = P.at(static_cast<size_t>(k));
    return {to_z(x[0]), to_z(x[1]), to_z(x[2])};
}

// The vertices of the convex polygon spanned by the coplanar points `all` (maximisers of n):
// duplicates count once (the smallest index), points inside an edge or the polygon are dropped.
// `cycle` runs around the polygon (1 or 2 entries for a vertex or a segment); `sorted` is the
// feature as the hull path lists it.
struct Polygon {
    std::vector<int> cycle, sorted;
};

Polygon support_polygon(const IntPoints& P, const Vec3z& n, const std::vector<int>& all) {
    int ax = 0;  // drop the axis where n is largest: the projection keeps the polygon's shape
    for (int k = 1; k < 3; ++k)
        if (abs(n[k]) > abs(n[ax])) ax = k;
    const int u = (ax + 1) % 3, v = (ax + 2) % 3;
    std::vector<int> pts(all);
    std::sort(pts.begin(), pts.end(), [&](int a, int b) {
        const std::int64_t *pa = P.at(static_cast<size_t>(a)), *pb = P.at(static_cast<size_t>(b));
        if (pa[u] != pb[u]) return pa[u] < pb[u];
        if (pa[v] != pb[v]) return pa[v] < pb[v];
        return a < b;
    });
    pts.erase(std::unique(pts.begin(), pts.end(),
                          [&](int a, int b) {
                              const std::int64_t *pa = P.at(static_cast<size_t>(a)), *pb = P.at(static_cast<size_t>(b));
                              return pa[u] == pb[u] && pa[v] == pb[v];
                          }),
              pts.end());
    // Coordinates differ by < 2^55: cross products of differences < 2^111.
    auto turn = [&](int o, int a, int b) {
        const std::int64_t *po = P.at(static_cast<size_t>(o)), *pa = P.at(static_cast<size_t>(a)),
                           *pb = P.at(static_cast<size_t>(b));
        const I128 c = I128(pa[u] - po[u]) * (pb[v] - po[v]) - I128(pa[v] - po[v]) * (pb[u] - po[u]);
        return sgn128(c);
    };
    Polygon g;
    if (pts.size() <= 2) {
        g.cycle = pts;
    } else {  // Andrew's monotone chain, strict turns only
        std::vector<int> h(2 * pts.size());
        size_t k = 0;
        for (size_t i = 0; i < pts.size(); ++i) {
            while (k >= 2 && turn(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
            h[k++] = pts[i];
        }
        for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
            while (k >= t && turn(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
            h[k++] = pts[i];
        }
        h.resize(k - 1);
        g.cycle = h;
    }
    g.sorted = g.cycle;
    std::sort(g.sorted.begin(), g.sorted.end());
    return g;
}

// In-plane outward normals of the polygon's edges (both sides of a segment), each with the
// polygon's maximum of u·x (in the polyhedron's integer frame). The cycle is strictly convex, so
// an edge's outward normal is largest on the edge itself: at its two ends, nowhere else.
struct EdgeNormal {
    Vec3z u;
    Z top;  // max over the polygon of u·x
};
std::vector<EdgeNormal> edge_normals(const IntPoints& P, const Vec3z& n, const Polygon& g) {
    std::vector<EdgeNormal> out;
    const size_t m = g.cycle.size();
    if (m < 2) return out;
    std::vector<Vec3z> x;
    for (int k : g.cycle) x.push_back(zpoint(P, k));
    if (m == 2) {
        const Vec3z u = primitive(cross(sub(x[1], x[0]), n));
        const Z t = dotz(u, x[0]);  // = u·x[1]: u is orthogonal to the segment
        out.push_back({u, t});
        out.push_back({neg(u), -t});
        return out;
    }
    for (size_t i = 0; i < m; ++i) {
        const Vec3z& p = x[i];
        const Vec3z& q = x[(i + 1) % m];
        Vec3z u = cross(sub(q, p), n);
        if (sgn(dotz(u, sub(x[(i + 2) % m], p))) > 0) u = neg(u);
        u = primitive(u);
        out.push_back({u, dotz(u, p)});
    }
    return out;
}

// ---------------------------------------------------------------------------------------------
// The walk.

struct Piece {
    ContactLine L;
    Polygon F[2];
    std::optional<Q> lo, hi;              // where d lies in the face: [lo, hi] (none: unbounded)
    std::vector<Vec3z> exit_lo, exit_hi;  // the in-plane normals tight at each end
};

class Walker {
  public:
    Walker(Model& m, const Cloud& c1, const Cloud& c2) : m_(m), C_{&c1, &c2} {}

    Walked<Support> support(int i, const Vec3z& n) const { return C_[i]->support(n); }

    // The piece of normal n: exact line, support polygons and the interval where it holds.
    Walked<Piece> piece(const Vec3z& n) const {
        SCALECERT_WALK(s1, support(0, n));
        SCALECERT_WALK(s2, support(1, neg(n)));
        Piece p;
        p.F[0] = support_polygon(m_.scan->P[0], n, s1.all);
        p.F[1] = support_polygon(m_.scan->P[1], n, s2.all);
        p.L = make_line(m_, n, p.F[0].sorted, p.F[1].sorted, s1.value, s2.value);
        // G(x) = x(F1 − s1) + y(x)(s2 − F2) is two-dimensional only for a facet normal.
        const bool face2 =
            p.F[0].cycle.size() >= 3 || p.F[1].cycle.size() >= 3 ||
            (p.F[0].cycle.size() == 2 && p.F[1].cycle.size() == 2 &&
             !is_zero(cross(sub(zpoint(m_.scan->P[0], p.F[0].cycle[1]), zpoint(m_.scan->P[0], p.F[0].cycle[0])),
                            sub(zpoint(m_.scan->P[1], p.F[1].cycle[1]), zpoint(m_.scan->P[1], p.F[1].cycle[0])))));
        if (!face2) return stop(Handover::NotFacetNormal);
        // d ∈ G(x) iff for every in-plane edge normal u of either summand:
        //   x·max_{F1} u·(p − s1) + y(x)·max_{F2} u·(s2 − w) ≥ u·d,  y(x) = a·x + b.
        struct Con {
            Vec3z u;
            Q k, c;
        };
        std::vector<Con> cons;
        const Q S1 = Q(m_.scan->P[0].scale), S2 = Q(m_.scan->P[1].scale);
        for (int i = 0; i < 2; ++i) {
            const Vec3z ni = i == 0 ? n : neg(n);
            for (EdgeNormal& e : edge_normals(m_.scan->P[i], ni, p.F[i])) {
                // Summand 1: max u·(p − s1) = top/S1 − u·s1. Summand 2 (i = 1): the polygon of
                // P2 has outward normal e.u; the summand s2 − F2 has −e.u, with the same maximum
                // top/S2 − e.u·s2 of e.u·(w − s2) = (−e.u)·(s2 − w).
                const Vec3q uq = to_q(e.u);
                const Q h = Q(e.top) / (i == 0 ? S1 : S2) - dot(uq, m_.s[i]);
                Vec3z u = i == 0 ? e.u : neg(e.u);
                const Vec3q uu = to_q(u);
                // The other summand's maximum of u: max u·(x − s1) = max u·X / S1 − u·s1 over F1,
                // max u·(s2 − x) = u·s2 + max (−u)·X / S2 over F2.
                const int j = 1 - i;
                SCALECERT_WALK(top, j == 0 ? max_over(m_.scan->P[0], p.F[0].cycle, u)
                                           : max_over(m_.scan->P[1], p.F[1].cycle, neg(u)));
                const Q other = j == 0 ? Q(Q(top) / S1 - dot(uu, m_.s[0])) : Q(dot(uu, m_.s[1]) + Q(top) / S2);
                const Q A = i == 0 ? h : other, Bv = i == 0 ? other : h;
                cons.push_back({u, A + p.L.slope * Bv, p.L.intercept * Bv - dot(uu, m_.d)});
            }
        }
        // k·x + c ≥ 0 for each.
        for (const Con& c : cons) {
            if (sgn(c.k) == 0) {
                if (sgn(c.c) < 0) return stop(Handover::FaceNeverHoldsD);
                if (sgn(c.c) == 0) return stop(Handover::IdenticalLines);
                continue;
            }
            const Q r = -c.c / c.k;
            if (sgn(c.k) > 0) {
                if (!p.lo || r > *p.lo)
                    p.lo = r, p.exit_lo.assign(1, c.u);
                else if (r == *p.lo)
                    p.exit_lo.push_back(c.u);
            } else {
                if (!p.hi || r < *p.hi)
                    p.hi = r, p.exit_hi.assign(1, c.u);
                else if (r == *p.hi)
                    p.exit_hi.push_back(c.u);
            }
        }
        if (p.lo && p.hi && *p.lo >= *p.hi) return stop(Handover::ZeroLengthPiece);
        return p;
    }

    // The exact facet normal holding the curve at ρ1 = x: column generation on
    //   max d·n + z  s.t.  x·n·(v − s1) + z ≤ 0 (v ∈ P1),  −n·(w − s2) ≤ 1 (w ∈ P2),
    // whose optimum is f(x) (LP duality with the touching LP); rows enter as support queries
    // find them violated. A basic optimum is a facet normal of the sum.
    // None when the curve is not above 0 at x.
    Walked<std::optional<Vec3z>> start_normal(const Q& x, const std::vector<int> init[2]) {
        std::vector<std::vector<Q>> A;
        std::vector<Q> b;
        std::vector<char> have[2] = {std::vector<char>(m_.scan->P[0].size()), std::vector<char>(m_.scan->P[1].size())};
        auto add = [&](int i, int k) {
            if (have[i][static_cast<size_t>(k)]) return false;
            have[i][static_cast<size_t>(k)] = 1;
            const Vec3q v = sub(m_.pt(i, static_cast<size_t>(k)), m_.s[i]);
            if (i == 0)
                A.push_back({x * v[0], x * v[1], x * v[2], Q(1)}), b.push_back(Q(0));
            else
                A.push_back({-v[0], -v[1], -v[2], Q(0)}), b.push_back(Q(1));
            return true;
        };
        for (int i = 0; i < 2; ++i)
            for (int k : init[i]) add(i, k);
        const std::vector<Q> c{m_.d[0], m_.d[1], m_.d[2], Q(1)};
        for (int it = 0; it < 400; ++it) {
            ++m_.scan_stats.lp_solves;
            auto sol = maximise_free(A, b, c);
            if (!sol) return stop(Handover::StartLpNoOptimum);
            const Vec3q nq{(*sol)[0], (*sol)[1], (*sol)[2]};
            const Q& z = (*sol)[3];
            if (sgn(nq[0]) == 0 && sgn(nq[1]) == 0 && sgn(nq[2]) == 0) return std::optional<Vec3z>();
            const Vec3z N = primitive(nq);
            int k = 0;
            while (sgn(N[k]) == 0) ++k;
            const Q lambda = nq[k] / Q(N[k]);  // n = λN, λ > 0
            SCALECERT_WALK(s1, support(0, N));
            SCALECERT_WALK(s2, support(1, neg(N)));
            // h1(n) = λ(S1/scale1 − N·s1), h2(n) = λ(S2/scale2 + N·s2).
            const Vec3q Nq = to_q(N);
            const Q h1 = lambda * (Q(s1.value) / Q(m_.scan->P[0].scale) - dot(Nq, m_.s[0]));
            const Q h2 = lambda * (Q(s2.value) / Q(m_.scan->P[1].scale) + dot(Nq, m_.s[1]));
            bool added = false;
            if (x * h1 + z > 0)
                for (int v : s1.all) added = add(0, v) || added;
            if (h2 > 1)
                for (int w : s2.all) added = add(1, w) || added;
            if (!added) {
                if (sgn(dot(nq, m_.d) + z) <= 0) return std::optional<Vec3z>();
                m_.scan_stats.lp_rows = A.size();
                return std::optional<Vec3z>(N);
            }
        }
        return stop(Handover::StartLpUnsettled);
    }

    // The piece beyond `p`'s end (right: its upper end, else its lower end): gift wrapping about
    // the exit edge of the face, then the new piece's own interval decides.
    Walked<Piece> next(const Piece& p, bool right) {
        const std::vector<Vec3z>& ex = right ? p.exit_hi : p.exit_lo;
        const Q x = right ? *p.hi : *p.lo;
        if (ex.empty()) return stop(Handover::NoExitEdge);
        for (const Vec3z& u : ex)
            if (u != ex[0]) return stop(Handover::CornerAtSwitch);
        const Vec3z& n = p.L.normal;
        const Vec3z& o = ex[0];  // rotate n towards the outward normal of the exit edge
        // Each summand's vertex on the exit edge: P1's maximiser of o on F1; for the summand
        // s2 − F2, P2's minimiser of o on F2.
        std::optional<Vec3z> c[2];
        for (int i = 0; i < 2; ++i) {
            const Vec3z oi = i == 0 ? o : neg(o), ni = i == 0 ? n : neg(n);
            int a = -1;
            Z best;
            for (int k : p.F[i].cycle) {
                Z t = dotz(oi, zpoint(m_.scan->P[i], k));
                if (a < 0 || t > best) best = t, a = k;
            }
            SCALECERT_WALK(turned, wrap(i, ni, oi, a));
            c[i] = turned;
            if (c[i] && i == 1) c[i] = neg(*c[i]);
        }
        Vec3z nn;
        if (c[0] && c[1]) {
            // The smaller turn: tan θ ∝ (c·o)/(c·n).
            const Z l = dotz(*c[0], o) * dotz(*c[1], n), r = dotz(*c[1], o) * dotz(*c[0], n);
            nn = l <= r ? *c[0] : *c[1];
        } else if (c[0] || c[1]) {
            nn = c[0] ? *c[0] : *c[1];
        } else {
            return stop(Handover::NoNeighbour);
        }
        const Q y = p.L.at(x);
        if (sgn(y) <= 0) return stop(Handover::ReachesZero);
        SCALECERT_WALK(q, piece(nn));
        if (q.L.at(x) != y) return stop(Handover::MissesSwitch);
        if (right ? !(q.L.slope > p.L.slope) : !(q.L.slope < p.L.slope)) return stop(Handover::NoTurn);
        const bool covers =
            right ? (!q.lo || *q.lo <= x) && (!q.hi || *q.hi > x) : (!q.hi || *q.hi >= x) && (!q.lo || *q.lo < x);
        if (!covers) return stop(Handover::NoContinuation);
        ++m_.scan_stats.pieces_walked;
        return std::move(q);
    }

  private:
    // Rotating the plane of normal n (support vertex a) about t = n × o towards o: the first
    // normal at which another point of polyhedron i reaches the plane, if within a quarter turn.
    Walked<std::optional<Vec3z>> wrap(int i, const Vec3z& n, const Vec3z& o, int a) {
        const IntPoints& P = m_.scan->P[i];
        const Vec3z t = cross(n, o), xa = zpoint(P, a);
        Vec3z c = o;
        for (int it = 0; it < 200; ++it) {
            ++m_.scan_stats.gift_wrap_steps;
            SCALECERT_WALK(s, support(i, c));
            const Z ca = dotz(c, xa);
            if (s.value == ca) {
                if (it > 0) return std::optional<Vec3z>(primitive(c));
                for (int q : s.all)  // a quarter turn exactly: a point below the old plane on it
                    if (sgn(dotz(n, sub(zpoint(P, q), xa))) < 0) return std::optional<Vec3z>(primitive(o));
                return std::optional<Vec3z>();
            }
            c = cross(t, sub(zpoint(P, s.all.front()), xa));
            const int side = sgn(dotz(c, o));
            if (side == 0) return stop(Handover::WrapOnOldPlane);
            if (side < 0) c = neg(c);
            c = primitive(c);
        }
        return stop(Handover::WrapUnsettled);
    }

    Model& m_;
    const Cloud* C_[2];
};

// s strictly inside the hull of the points W (small): W spans 3 dimensions, and every plane
// through three of them with all of W on one side has s strictly on that side.
bool strictly_inside_few(const IntPoints& P, const std::vector<int>& W, const Vec3q& s) {
    std::vector<Vec3z> x;
    for (int k : W) x.push_back(zpoint(P, k));
    Z den;  // s·scale = sz / den
    const Vec3z sz = over_common_denominator({s[0] * P.scale, s[1] * P.scale, s[2] * P.scale}, den);
    bool solid = false;
    const size_t m = x.size();
    for (size_t a = 0; a < m; ++a)
        for (size_t b = a + 1; b < m; ++b)
            for (size_t c = b + 1; c < m; ++c) {
                const Vec3z nrm = cross(sub(x[b], x[a]), sub(x[c], x[a]));
                if (is_zero(nrm)) continue;
                const Z off = dotz(nrm, x[a]);
                int pos = 0, negc = 0;
                for (size_t k = 0; k < m; ++k) {
                    const int sg = sgn(dotz(nrm, x[k]) - off);
                    pos += sg > 0, negc += sg < 0;
                }
                if (pos && negc) continue;
                if (!pos && !negc) continue;  // all on the plane: no volume from this triple
                solid = true;
                const int want = pos ? 1 : -1;  // the side of W
                if (sgn(dotz(nrm, sz) - den * off) != want) return false;
            }
    return solid;
}

// The extreme points in 14 directions (the axes and the diagonals; the first index on ties),
// sorted, once each: the seeds' proof of interiority, and the start LP's first rows (which keep
// it bounded). One pass, no tree: exact in int64, as |a·x + b·y + c·z| ≤ 3·2^53.
std::vector<int> extreme_points(const IntPoints& P) {
    std::int64_t best[7][2];
    for (auto& b : best) b[0] = b[1] = INT64_MIN;  // below every value
    int arg[7][2] = {};
    for (size_t k = 0; k < P.size(); ++k) {
        const std::int64_t *p = P.at(k), x = p[0], y = p[1], z = p[2];
        const std::int64_t v[7] = {x, y, z, x + y + z, x + y - z, x - y + z, x - y - z};
        for (int d = 0; d < 7; ++d) {
            if (v[d] > best[d][0]) best[d][0] = v[d], arg[d][0] = static_cast<int>(k);    // + direction
            if (-v[d] > best[d][1]) best[d][1] = -v[d], arg[d][1] = static_cast<int>(k);  // − direction
        }
    }
    std::vector<int> out(&arg[0][0], &arg[0][0] + 14);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

// The two trees, one thread each.
std::pair<std::unique_ptr<Cloud>, std::unique_ptr<Cloud>> internal_trees(const CompactScene& sc, ScanStats& st) {
    auto second = std::async(std::launch::async, [&] { return std::make_unique<Cloud>(sc.P[1], st); });
    auto first = std::make_unique<Cloud>(sc.P[0], st);
    return {std::move(first), second.get()};
}

}  // namespace

bool scan_seeds_proved(const CompactScene& sc) {
    for (int i = 0; i < 2; ++i)
        if (sc.P[i].size() < 4 || sc.P[i].size() > kMaxPoints ||
            !strictly_inside_few(sc.P[i], extreme_points(sc.P[i]), sc.seed[i]))
            return false;
    return true;
}

std::vector<std::pair<int, Q>> scan_seed_weights(const CompactScene& sc, int i) {
    const std::vector<int> W = extreme_points(sc.P[i]);
    if (!strictly_inside_few(sc.P[i], W, sc.seed[i]))
        throw std::logic_error("scan_seed_weights: seed not proved inside");
    std::vector<Vec3q> A;
    for (int k : W) A.push_back(sc.P[i].point(static_cast<size_t>(k)));
    const auto cp = interior_common_point(A, {sc.seed[i]});
    if (!cp) throw std::logic_error("scan_seed_weights: no interior weights");
    std::vector<std::pair<int, Q>> w;
    for (size_t k = 0; k < W.size(); ++k) w.push_back({W[k], cp->lambda[k]});
    return w;
}

struct CloudPoints::Trees {
    ScanStats st;
    std::unique_ptr<Cloud> c[2];
};

CloudPoints::CloudPoints(std::shared_ptr<const CompactScene> sc) : sc_(std::move(sc)), t_(std::make_unique<Trees>()) {
    auto [a, b] = internal_trees(*sc_, t_->st);
    t_->c[0] = std::move(a);
    t_->c[1] = std::move(b);
}
CloudPoints::~CloudPoints() = default;
Vec3q CloudPoints::point(int i, int k) const { return sc_->P[i].point(static_cast<size_t>(k)); }
D3 CloudPoints::dpoint(int i, int k) const {
    const std::int64_t* x = sc_->P[i].at(static_cast<size_t>(k));
    const double s = sc_->P[i].scale.get_d();
    return {static_cast<double>(x[0]) / s, static_cast<double>(x[1]) / s, static_cast<double>(x[2]) / s};
}
const Vec3q& CloudPoints::seed(int i) const { return sc_->seed[i]; }
const Z& CloudPoints::scale(int i) const { return sc_->P[i].scale; }
Vec3z CloudPoints::zpoint(int i, int k) const {
    const std::int64_t* x = sc_->P[i].at(static_cast<size_t>(k));
    return {Z(static_cast<long>(x[0])), Z(static_cast<long>(x[1])), Z(static_cast<long>(x[2]))};
}
int CloudPoints::argmax(int i, const Vec3z& n) const {
    Walked<Support> s = t_->c[i]->support(n);
    if (!std::holds_alternative<WalkStop>(s)) return std::get<Support>(s).all.front();
    // A normal the trees' double filter cannot take (beyond doubles, or 0 there): every point,
    // exactly, in integers (linear, and no hull).
    const IntPoints& P = sc_->P[i];
    const Dir dir(n);
    int best = 0;
    Z bv;
    for (size_t k = 0; k < P.size(); ++k)
        if (Z v = dot_exact(dir, P.at(k)); k == 0 || v > bv) bv = std::move(v), best = static_cast<int>(k);
    return best;
}
int CloudPoints::dargmax(int i, const D3& d) const { return t_->c[i]->dbest(d.data()); }
std::uint64_t CloudPoints::support_queries() const { return t_->st.support_queries; }

namespace {
Walked<WalkModel> walk(std::shared_ptr<const CompactScene> sc, const std::optional<std::pair<Q, Q>>& cover) {
    StageClock clock;
    WalkModel m;
    // The reader's checks, on the counts and ranges (the points are not copied into m.scene).
    for (int i = 0; i < 2; ++i) {
        const size_t n = sc->P[i].size();
        if (n < 4 || n > kMaxPoints) return stop(Handover::PointCount, i);
        if (sgn(sc->lo[i]) <= 0 || sc->lo[i] > sc->hi[i]) return stop(Handover::Range, i);
        m.scene.P[i].seed = sc->seed[i];
        m.scene.P[i].seed_given = sc->seed_given[i];
        m.scene.lo[i] = sc->lo[i];
        m.scene.hi[i] = sc->hi[i];
        m.s[i] = sc->seed[i];
        m.P[i].scale = sc->P[i].scale;
    }
    m.scan = sc;
    set_seeds_in_integers(m);
    if (is_zero(m.dz)) return stop(Handover::SeedsCoincide);

    // The trees, kept with the model for the measures (CloudPoints); their statistics are the
    // walk's support queries.
    auto cloud = std::make_shared<CloudPoints>(sc);
    const Cloud &c1 = *cloud->trees().c[0], &c2 = *cloud->trees().c[1];
    clock.lap("scan: trees");
    Walker w(m, c1, c2);
    std::vector<int> init[2];
    for (int i = 0; i < 2; ++i) {
        init[i] = extreme_points(sc->P[i]);
        if (!strictly_inside_few(sc->P[i], init[i], m.s[i])) return stop(Handover::SeedNotProved, i);
    }
    const Vec3z dn = primitive(m.dz);
    SCALECERT_WALK(towards, w.support(0, dn));
    SCALECERT_WALK(away, w.support(1, neg(dn)));
    init[0].push_back(towards.all.front());
    init[1].push_back(away.all.front());
    clock.lap("scan: seeds");

    // The range the walk must prove: I1, widened to `cover` when asked (queries outside I1).
    const Q lo = cover ? std::min(sc->lo[0], cover->first) : sc->lo[0];
    const Q hi = cover ? std::max(sc->hi[0], cover->second) : sc->hi[0];
    std::vector<Piece> left, right;  // walked from the start: leftwards, rightwards
    // The start: at lo1, or, where the curve is ≤ 0 there, at lo1/2, lo1/4, ... (the curve is > 0
    // near ρ1 = 0 as d ≠ 0), so that the walk reaches the piece that takes the curve to 0.
    Q x0 = lo;
    std::optional<Vec3z> n0;
    for (int k = 0; k < 64; ++k, x0 /= 2) {
        SCALECERT_WALK(start, w.start_normal(x0, init));
        if ((n0 = start)) break;
    }
    if (!n0) return stop(Handover::CurveNotAbove0);
    {
        SCALECERT_WALK(p, w.piece(*n0));
        if ((p.lo && *p.lo > x0) || (p.hi && *p.hi < x0)) return stop(Handover::StartFaceMissesD);
        right.push_back(std::move(p));
    }
    clock.lap("scan: start");
    // Rightwards over I1. A piece whose line is at or below ρ2 = 0 at its end reaches 0 at some x0 inside its interval,
    // where it is proved: from x0 on the curve is that line (envelope.hpp), and the walk stops.
    auto reaches_zero = [](const Piece& p) { return !p.hi || sgn(p.L.at(*p.hi)) <= 0; };
    while (right.back().hi && *right.back().hi < hi && !reaches_zero(right.back())) {
        SCALECERT_WALK(q, w.next(right.back(), true));
        right.push_back(std::move(q));
    }
    // The growth distance: where y = x. Left of lo1 when the curve is below the diagonal there.
    auto crossing = [](const ContactLine& L) -> Q { return L.intercept / (Q(1) - L.slope); };
    if (right.front().L.at(x0) < x0) {
        const Piece* cur = &right.front();
        while (cur->lo && !(*cur->lo < crossing(cur->L))) {
            SCALECERT_WALK(q, w.next(*cur, false));
            left.push_back(std::move(q));
            cur = &left.back();
        }
    } else {
        while (right.back().hi && *right.back().hi < crossing(right.back().L)) {
            SCALECERT_WALK(q, w.next(right.back(), true));
            right.push_back(std::move(q));
        }
    }
    // The proof's range: the walked pieces are contiguous, from the leftmost one's start to the
    // rightmost one's end.
    const Piece& leftmost = left.empty() ? right.front() : left.back();
    m.walk_lo = leftmost.lo ? *leftmost.lo : Q(0);
    m.walk_hi = right.back().hi;
    if (reaches_zero(right.back())) m.walk_hi.reset();
    for (auto* v : {&left, &right})
        for (Piece& p : *v) m.lines.push_back(std::move(p.L));
    std::sort(m.lines.begin(), m.lines.end(),
              [](const ContactLine& a, const ContactLine& b) { return a.normal < b.normal; });
    for (size_t i = 1; i < m.lines.size(); ++i)
        if (m.lines[i].normal == m.lines[i - 1].normal) return stop(Handover::NormalTwice);
    m.stats.distinct_normals = m.lines.size();
    clock.lap("scan: walk");
    m.scan_stats.support_queries = cloud->trees().st.support_queries;
    m.scan_stats.predicates = cloud->trees().st.predicates;
    m.points = std::move(cloud);
    return m;
}
}  // namespace

#undef SCALECERT_WALK

const char* handover_text(Handover h) {
    switch (h) {
    case Handover::PointCount: return "point count";
    case Handover::Range: return "range";
    case Handover::SeedsCoincide: return "the seeds coincide";
    case Handover::SeedNotProved: return "seed not proved inside";
    case Handover::NormalBeyondDoubles: return "a normal beyond the double range";
    case Handover::ZeroOrHugeNormal: return "a zero or huge normal";
    case Handover::CurveNotAbove0: return "the curve is not above 0 near rho1 = 0";
    case Handover::StartLpNoOptimum: return "the start LP has no optimum";
    case Handover::StartLpUnsettled: return "the start LP did not converge";
    case Handover::StartFaceMissesD: return "the start face does not hold d";
    case Handover::NotFacetNormal: return "a normal that is not a facet normal of the sum";
    case Handover::FaceNeverHoldsD: return "a face that never holds d";
    case Handover::IdenticalLines: return "d on a face's edge all along a piece (identical lines)";
    case Handover::ZeroLengthPiece: return "a piece of zero length";
    case Handover::NoExitEdge: return "no exit edge";
    case Handover::CornerAtSwitch: return "d at a corner of a face at a switch point";
    case Handover::NoNeighbour: return "no neighbouring face within a quarter turn";
    case Handover::ReachesZero: return "the curve reaches rho2 <= 0";
    case Handover::MissesSwitch: return "the next line misses the switch point";
    case Handover::NoTurn: return "the next line does not turn the curve";
    case Handover::NoContinuation: return "the next piece does not continue the curve";
    case Handover::WrapOnOldPlane: return "gift wrapping met a point on the old plane";
    case Handover::WrapUnsettled: return "gift wrapping did not settle";
    case Handover::NormalTwice: return "a normal walked twice";
    }
    return "unknown";
}

std::string WalkStop::text() const {
    const std::string t = handover_text(reason);
    return polyhedron == 0 ? "P1: " + t : polyhedron == 1 ? "P2: " + t : t;
}

std::vector<std::uint64_t> handover_counts() {
    std::vector<std::uint64_t> out;
    for (const auto& c : g_handovers) out.push_back(c.load());
    return out;
}

WalkResult scan_model(std::shared_ptr<const CompactScene> sc, const std::optional<std::pair<Q, Q>>& cover) {
    Walked<WalkModel> w = walk(std::move(sc), cover);
    if (WalkStop* s = std::get_if<WalkStop>(&w)) {
        ++g_handovers[static_cast<int>(s->reason)];
        return {std::nullopt, *s};
    }
    return {std::move(std::get<WalkModel>(w)), std::nullopt};
}

}  // namespace scalecert::internal
