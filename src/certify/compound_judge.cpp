// Judgements on two compounds at one scaling pair, with their proofs (compound_judge.hpp).
#include "certify/compound_judge.hpp"

#include "certify/judgements.hpp"
#include "certify/region_certificate.hpp"
#include "geometry/gjk.hpp"
#include "geometry/measures.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace scalecert::internal {

namespace {
// A common point of P1(ρ1) and P2(ρ2) on a double GJK's final simplex, exactly: weights w_k >= 0
// with Σ w_k = 1 and Σ w_k (a_k(ρ1) − b_k(ρ2)) = 0 over its points (a_k, b_k), by exact Gaussian
// elimination on those four equations (a weight left free where the points are dependent is 0).
// None when they have no such solution (GJK's simplex does not hold the origin exactly).
std::optional<Witness> simplex_witness(const Polyhedron& A, const Polyhedron& B, const Vec3q& s1, const Vec3q& s2,
                                       const Q& r1, const Q& r2, const std::vector<std::pair<int, int>>& simplex) {
    const size_t k = simplex.size();
    if (k == 0 || k > 4) return std::nullopt;
    auto scaled = [](const Vec3q& s, const Q& rho, const Vec3q& y) {
        return Vec3q{s[0] + rho * (y[0] - s[0]), s[1] + rho * (y[1] - s[1]), s[2] + rho * (y[2] - s[2])};
    };
    std::vector<Vec3q> a, b;
    for (const auto& [i, j] : simplex) {
        a.push_back(scaled(s1, r1, A.points[static_cast<size_t>(i)]));
        b.push_back(scaled(s2, r2, B.points[static_cast<size_t>(j)]));
    }
    // Rows: the three coordinates of Σ w_k (a_k − b_k) = 0 and Σ w_k = 1; column k is the right side.
    std::array<std::array<Q, 5>, 4> M;
    for (size_t c = 0; c < 3; ++c) {
        for (size_t t = 0; t < k; ++t) M[c][t] = a[t][c] - b[t][c];
        M[c][k] = 0;
    }
    for (size_t t = 0; t < k; ++t) M[3][t] = 1;
    M[3][k] = 1;
    std::vector<int> pivot_row(k, -1);
    size_t row = 0;
    for (size_t col = 0; col < k && row < 4; ++col) {
        size_t r = row;
        while (r < 4 && sgn(M[r][col]) == 0) ++r;
        if (r == 4) continue;  // a free weight: 0
        std::swap(M[r], M[row]);
        const Q inv = 1 / M[row][col];
        for (size_t t = col; t <= k; ++t) M[row][t] *= inv;
        for (size_t q = 0; q < 4; ++q)
            if (q != row && sgn(M[q][col]) != 0) {
                const Q f = M[q][col];
                for (size_t t = col; t <= k; ++t) M[q][t] -= f * M[row][t];
            }
        pivot_row[col] = static_cast<int>(row++);
    }
    for (size_t q = row; q < 4; ++q)
        if (sgn(M[q][k]) != 0) return std::nullopt;  // inconsistent
    std::vector<Q> w(k, Q(0));
    for (size_t col = 0; col < k; ++col)
        if (pivot_row[col] >= 0) {
            w[col] = M[static_cast<size_t>(pivot_row[col])][k];
            if (sgn(w[col]) < 0) return std::nullopt;
        }
    // The weights on each part's vertices (a vertex may be in several points of the simplex).
    std::map<int, Q> w1, w2;
    Witness out;
    out.rho1 = r1;
    out.rho2 = r2;
    Vec3q x{Q(0), Q(0), Q(0)}, y{Q(0), Q(0), Q(0)};
    Q total(0);
    for (size_t t = 0; t < k; ++t) {
        if (sgn(w[t]) == 0) continue;
        w1[simplex[t].first] += w[t];
        w2[simplex[t].second] += w[t];
        total += w[t];
        for (size_t c = 0; c < 3; ++c) x[c] += w[t] * a[t][c], y[c] += w[t] * b[t][c];
    }
    if (total != 1 || x != y) return std::nullopt;  // (the elimination is exact: never taken)
    for (const auto& [i, v] : w1) out.w1.push_back({i, v});
    for (const auto& [j, v] : w2) out.w2.push_back({j, v});
    out.point = x;
    return out;
}
}  // namespace

Witness pair_common_point(const Polyhedron& A, const Polyhedron& B, const Vec3q& s1, const Vec3q& s2, const Q& r1,
                          const Q& r2, long& fallbacks) {
    const GjkGuess g = gjk_guess(HullPoints(A, B, s1, s2), r1.get_d(), r2.get_d());
    if (std::optional<Witness> w = simplex_witness(A, B, s1, s2, r1, r2, g.simplex)) return std::move(*w);
    HullModel hm;  // the two parts and the seeds, for the LPs
    hm.P[0] = A;
    hm.P[1] = B;
    hm.s[0] = s1;
    hm.s[1] = s2;
    if (!g.v1.empty() && !g.v2.empty()) {
        if (std::optional<Witness> w = try_witness(hm, r1, r2, g.v1, g.v2)) return std::move(*w);
        ++fallbacks;
    }
    return make_witness(hm, r1, r2, hm.P[0].vertices, hm.P[1].vertices, false);
}

Witness pair_common_point(const HullModel& hm, const Q& r1, const Q& r2, long& fallbacks) {
    return pair_common_point(hm.P[0], hm.P[1], hm.s[0], hm.s[1], r1, r2, fallbacks);
}

// One pair's exact model (the two parts and the seeds), its facet normals' constraints, and its
// last exact distance: built when a judgement first needs them.
struct CompoundJudge::PairCache {
    HullModel hm;
    std::optional<std::vector<HalfPlane>> constraints;
    std::optional<std::array<Q, 2>> at;  // where `distance` was measured
    ProvedDistance distance;
};

namespace {
Json exact3(const Vec3q& v) {
    return Json::array({to_exact_string(v[0]), to_exact_string(v[1]), to_exact_string(v[2])});
}
// An axis normal as a code, 2c for +e_c and 2c + 1 for −e_c (cheap to compare in the loops over
// pairs); −1 for none.
int axis_code(int c, int side) { return 2 * c + (side > 0 ? 0 : 1); }
Vec3q axis(int c, int side);
Vec3q axis_of(int code) { return axis(code / 2, code % 2 ? -1 : 1); }
Vec3q axis(int c, int side) {
    Vec3q n{Q(0), Q(0), Q(0)};
    n[static_cast<size_t>(c)] = side;
    return n;
}
}  // namespace

CompoundJudge::CompoundJudge(const ExactScene& sc, const std::string& name) : sc_(sc), name_(name) {
    build_parts(sc, name, parts_);
    for (int i = 0; i < 2; ++i) {
        for (const Polyhedron& P : parts_[i]) unit_[i].push_back(bounding_box(P));
        Box all = unit_[i].front();
        for (const Box& b : unit_[i])
            for (size_t c = 0; c < 3; ++c) {
                if (b[c][0] < all[c][0]) all[c][0] = b[c][0];
                if (b[c][1] > all[c][1]) all[c][1] = b[c][1];
            }
        unit_[i].push_back(all);
        for (const Box& b : unit_[i]) {
            std::array<std::array<double, 2>, 3> d;
            for (size_t c = 0; c < 3; ++c)
                for (size_t e = 0; e < 2; ++e) d[c][e] = filter::region_double(b[c][e]);
            unit_d_[i].push_back(d);
        }
        for (size_t c = 0; c < 3; ++c) seed_d_[i][c] = filter::region_double(sc_.P[i].seed[c]);
    }
    d_ = sub(sc_.P[1].seed, sc_.P[0].seed);
}

CompoundJudge::~CompoundJudge() = default;

void CompoundJudge::check_blocks(size_t more) const {
    if (static_cast<double>(blocks_) + static_cast<double>(more) > kMaxCertificateBlocks)
        throw InputError(
            name_ + ": the certificate would hold more than " +
            std::to_string(static_cast<long>(kMaxCertificateBlocks)) +
            " blocks of part pairs (the limit: parts far from each other in their lists' order cannot share a block)");
}

void CompoundJudge::set_budget(long judgements, long distances, long comparisons, std::string message) {
    budget_ = std::array<long, 3>{counts_.judged + counts_.slabs + judgements, counts_.distances + distances,
                                  counts_.box_comparisons + comparisons};
    budget_message_ = std::move(message);
}

void CompoundJudge::check_budget() const {
    if (budget_ && (counts_.judged + counts_.slabs > (*budget_)[0] || counts_.distances > (*budget_)[1] ||
                    counts_.box_comparisons > (*budget_)[2]))
        throw InputError(budget_message_);
}

// s + ρ(box − s): ρ > 0 keeps the order along every axis (so the box of them all scales to the
// box of the scaled boxes).
CompoundJudge::Box CompoundJudge::scaled_box(int i, size_t k, const Q& rho) const {
    const Vec3q& s = sc_.P[i].seed;
    Box b = unit_[i][k];
    for (size_t c = 0; c < 3; ++c)
        for (Q& x : b[c]) x = s[c] + rho * (x - s[c]);
    return b;
}

CompoundJudge::PairCache& CompoundJudge::pair(int a, int b) {
    std::unique_ptr<PairCache>& p = cache_[{a, b}];
    if (!p) {
        const Polyhedron &A = parts_[0][static_cast<size_t>(a)], &B = parts_[1][static_cast<size_t>(b)];
        edge_work_ += static_cast<double>(A.edges.size()) * static_cast<double>(B.edges.size());
        if (cache_.size() > kMaxBuiltPairs || edge_work_ > kMaxEdgePairWork) {
            cache_.erase({a, b});
            throw InputError(name_ + ": the claims need more than " + std::to_string(kMaxBuiltPairs) +
                             " part pairs judged exactly, or more than 2*10^7 edge pairs over them (the limits of a "
                             "compound scene)");
        }
        p = std::make_unique<PairCache>();
        p->hm.P[0] = parts_[0][static_cast<size_t>(a)];
        p->hm.P[1] = parts_[1][static_cast<size_t>(b)];
        p->hm.s[0] = sc_.P[0].seed;
        p->hm.s[1] = sc_.P[1].seed;
        set_seeds_in_integers(p->hm);
    }
    return *p;
}

// Doubles enclosing a box's ends: down[c][e] <= end <= up[c][e] (not a number where the doubles
// cannot enclose it, so that the tests below never answer from it).
struct BoxBounds {
    double down[3][2], up[3][2];
};

// One object's parts scaled by ρ > 0: every box's ends enclosed in doubles by filter 9
// (predicates.hpp) from the unscaled boxes, with no rational formed; the exact ends of a box only
// where the doubles cannot decide a test. Index all() is the box of all the parts. Each test
// counts its comparisons into `tests`.
class ScaledParts {
  public:
    ScaledParts(const CompoundJudge& j, int i, const Q& rho, long& comparisons)
        : tests(comparisons),
          rho_d(filter::region_double(rho)),
          j_(j),
          i_(i),
          rho_(rho),
          n_(j.parts_[i].size()),
          d_(n_ + 1),
          exact_(n_ + 1) {
        const double* s = j.seed_d_[i];
        for (size_t k = 0; k <= n_; ++k)
            for (size_t c = 0; c < 3; ++c)
                for (size_t e = 0; e < 2; ++e) {
                    const filter::Enclosure en = filter::scaled_enclosure(s[c], rho_d, j.unit_d_[i][k][c][e]);
                    d_[k].down[c][e] = en.lo;
                    d_[k].up[c][e] = en.hi;
                }
    }
    size_t all() const { return n_; }
    const BoxBounds& d(size_t k) const { return d_[k]; }
    const std::array<std::array<Q, 2>, 3>& box(size_t k) {
        if (!exact_[k]) exact_[k] = j_.scaled_box(i_, k, rho_);
        return *exact_[k];
    }
    long& tests;
    const double rho_d;  // ρ by region_double

  private:
    const CompoundJudge& j_;
    int i_;
    Q rho_;
    size_t n_;
    std::vector<BoxBounds> d_;
    std::vector<std::optional<std::array<std::array<Q, 2>, 3>>> exact_;
};

namespace {
using Box3 = std::array<std::array<Q, 2>, 3>;
// Is box a of X below box b of Y along c, strictly (its end before the other's start)? The
// doubles decide when they prove it either way; else the exact ends.
bool below(ScaledParts& X, size_t a, ScaledParts& Y, size_t b, size_t c) {
    ++X.tests;
    const BoxBounds &xb = X.d(a), &yb = Y.d(b);
    if (xb.up[c][1] < yb.down[c][0]) return true;
    if (xb.down[c][1] >= yb.up[c][0]) return false;
    return X.box(a)[c][1] < Y.box(b)[c][0];
}
// The axis (and side: +1 when X's box lies below) along which two boxes are strictly apart;
// {-1, 0} when they are not.
std::pair<int, int> apart(ScaledParts& X, size_t a, ScaledParts& Y, size_t b) {
    for (size_t c = 0; c < 3; ++c) {
        if (below(X, a, Y, b, c)) return {static_cast<int>(c), 1};
        if (below(Y, b, X, a, c)) return {static_cast<int>(c), -1};
    }
    return {-1, 0};
}
// Does Y's box start at least √E past X's end along c (its start − X's end > 0, squared >= E)?
// Ed is E by region_double (not a number when E has no normal double). The doubles decide when
// their bounds prove it either way (each difference and square rounded one unit outward); else
// exactly.
bool axis_gap_at_least(ScaledParts& X, size_t a, ScaledParts& Y, size_t b, size_t c, const Q& E, double Ed) {
    ++X.tests;
    const BoxBounds &xb = X.d(a), &yb = Y.d(b);
    const double lo = std::nextafter(yb.down[c][0] - xb.up[c][1], -INFINITY);
    if (lo > 0 && std::nextafter(lo * lo, -INFINITY) >= std::nextafter(Ed, INFINITY)) return true;
    const double hi = std::nextafter(yb.up[c][0] - xb.down[c][1], INFINITY);
    if (hi <= 0 || std::nextafter(hi * hi, INFINITY) < std::nextafter(Ed, -INFINITY)) return false;
    const Q g = Y.box(b)[c][0] - X.box(a)[c][1];
    return sgn(g) > 0 && g * g >= E;
}
// From box x to box y: the vector u between their nearest points (0 along an axis where they
// overlap). Every point of y exceeds every point of x by |u|² or more along u (axis by axis).
Vec3q gap_vector(const Box3& x, const Box3& y) {
    Vec3q u{Q(0), Q(0), Q(0)};
    for (size_t c = 0; c < 3; ++c) {
        if (x[c][1] < y[c][0])
            u[c] = y[c][0] - x[c][1];
        else if (y[c][1] < x[c][0])
            u[c] = y[c][1] - x[c][0];
    }
    return u;
}
Vec3q gap_vector(ScaledParts& X, size_t a, ScaledParts& Y, size_t b) { return gap_vector(X.box(a), Y.box(b)); }
// Is |u|² >= E > 0 for the gap vector u between box a of X and box b of Y? Along each axis the
// gap is max(0, y's start − x's end, x's start − y's end): its bounds from the enclosures, rounded
// one unit outward at every step, decide when they can (none from an end that is not a number);
// else the exact vector.
bool gap_at_least(ScaledParts& X, size_t a, ScaledParts& Y, size_t b, const Q& E, double Ed) {
    ++X.tests;
    const BoxBounds &xb = X.d(a), &yb = Y.d(b);
    bool finite = std::isfinite(Ed);
    double lo = 0, hi = 0;
    for (size_t c = 0; c < 3 && finite; ++c) {
        const double v[4] = {xb.down[c][0], xb.up[c][1], yb.down[c][0], yb.up[c][1]};
        const double w[4] = {xb.up[c][0], xb.down[c][1], yb.up[c][0], yb.down[c][1]};
        for (int k = 0; k < 4; ++k) finite = finite && std::isfinite(v[k]) && std::isfinite(w[k]);
        if (!finite) break;
        const double glo = std::max({0.0, std::nextafter(yb.down[c][0] - xb.up[c][1], -INFINITY),
                                     std::nextafter(xb.down[c][0] - yb.up[c][1], -INFINITY)});
        const double ghi = std::max({0.0, std::nextafter(yb.up[c][0] - xb.down[c][1], INFINITY),
                                     std::nextafter(xb.up[c][0] - yb.down[c][1], INFINITY)});
        lo = std::nextafter(lo + std::nextafter(glo * glo, -INFINITY), -INFINITY);
        hi = std::nextafter(hi + std::nextafter(ghi * ghi, INFINITY), INFINITY);
    }
    if (finite && sgn(E) > 0) {
        if (lo > 0 && lo >= std::nextafter(Ed, INFINITY)) return true;
        if (hi < std::nextafter(Ed, -INFINITY)) return false;
    }
    const Vec3q u = gap_vector(X, a, Y, b);
    const Q uu = dot(u, u);
    return sgn(uu) > 0 && uu >= E;
}
}  // namespace

int CompoundJudge::pair_sign(int a, int b, const Q& r1, const Q& r2, ScaledParts& X, ScaledParts& Y, int* code,
                             Vec3q* normal, int prefer) {
    const size_t ia = static_cast<size_t>(a), ib = static_cast<size_t>(b);
    *code = -1;
    // The preferred axis first, when the boxes are apart along it (the run then goes on).
    if (prefer >= 0) {
        const size_t c = static_cast<size_t>(prefer / 2);
        if (prefer % 2 == 0 ? below(X, ia, Y, ib, c) : below(Y, ib, X, ia, c)) {
            ++counts_.boxed;
            *code = prefer;
            return -1;
        }
    }
    const auto [c, side] = apart(X, ia, Y, ib);
    if (c >= 0) {
        ++counts_.boxed;
        *code = axis_code(c, side);
        return -1;
    }
    ++counts_.judged;
    check_budget();
    PairCache& p = pair(a, b);
    if (!p.constraints) p.constraints = pair_constraints(p.hm.P[0], p.hm.P[1], sc_.P[0].seed, sc_.P[1].seed);
    // The least sign of a ρ1 + b ρ2 − c over the constraints (filter 8, exactly when it cannot
    // tell), and the first constraint that attains it.
    int least = 1;
    for (const HalfPlane& h : *p.constraints) {
        const int s = h.side(r1, r2, X.rho_d, Y.rho_d, predicates_);
        if (s < least) {
            least = s;
            if (normal) *normal = to_q(h.normal);
            if (s < 0) break;
        }
    }
    return least;
}

namespace {
struct PlaneBlock {
    int a0, a1, b0, b1;
    int code;  // an axis normal (axis_code), or −1: then `normal`
    Vec3q normal;
};
Json blocks_json(const std::vector<PlaneBlock>& blocks) {
    Json out = Json::array();
    for (const PlaneBlock& b : blocks)
        out.push_back(Json{{"P1_parts", range_json(b.a0, b.a1)},
                           {"P2_parts", range_json(b.b0, b.b1)},
                           {"normal", exact3(b.code >= 0 ? axis_of(b.code) : b.normal)}});
    return out;
}
// Appends [a, a] x [b, b] with an axis normal (code >= 0) or the normal n, joining the run before
// it in the row when the normal is the same (every pair of the run is then separated by it, and
// so is the block's union).
void add_block(std::vector<PlaneBlock>& blocks, int a, int b, int code, const Vec3q& n = Vec3q{}) {
    if (!blocks.empty()) {
        PlaneBlock& last = blocks.back();
        if (last.a0 == a && last.a1 == a && last.b1 == b - 1 && last.code == code && (code >= 0 || last.normal == n)) {
            last.b1 = b;
            return;
        }
    }
    blocks.push_back({a, a, b, b, code, code >= 0 ? Vec3q{} : n});
}
// The run a block ends in at pair b − 1 of row a, if any: its axis code (−1: none, or not an axis).
int run_code(const std::vector<PlaneBlock>& blocks, int a, int b) {
    return !blocks.empty() && blocks.back().a0 == a && blocks.back().a1 == a && blocks.back().b1 == b - 1
               ? blocks.back().code
               : -1;
}
// Among the axis normals that ok(b, code) accepts for pair b of a row, the one that holds for the
// longest run b, b + 1, ... (ties: the first), so that one block covers the run; −1 when ok
// accepts none. Each candidate is scanned ahead only as far as it holds.
template <class Ok>
int longest_axis(int b, int n, Ok ok) {
    int best = -1, reach = 0;
    for (int code = 0; code < 6; ++code) {
        if (!ok(b, code)) continue;
        int e = b + 1;
        while (e < n && ok(e, code)) ++e;
        if (e - b > reach) reach = e - b, best = code;
    }
    return best;
}
}  // namespace

CompoundVerdict CompoundJudge::verdict(const Q& r1, const Q& r2, Json* proof) {
    const int m = static_cast<int>(parts_[0].size()), n = static_cast<int>(parts_[1].size());
    ScaledParts X(*this, 0, r1, counts_.box_comparisons), Y(*this, 1, r2, counts_.box_comparisons);
    std::vector<PlaneBlock> blocks;
    CompoundVerdict v;
    const auto [c, side] = apart(X, X.all(), Y, Y.all());
    if (c >= 0) {
        blocks.push_back({0, m - 1, 0, n - 1, axis_code(c, side), {}});
    } else {
        for (int a = 0; a < m; ++a) {
            check_budget();
            const size_t ia = static_cast<size_t>(a);
            const auto [ca, sa] = apart(X, ia, Y, Y.all());
            if (ca >= 0) {
                counts_.boxed += n;
                blocks.push_back({a, a, 0, n - 1, axis_code(ca, sa), {}});
                continue;
            }
            // Boxes apart along n (+e_c: part a's below part b's).
            auto apart_along = [&](int b, int code) {
                const size_t c = static_cast<size_t>(code / 2), ib = static_cast<size_t>(b);
                return code % 2 == 0 ? below(X, ia, Y, ib, c) : below(Y, ib, X, ia, c);
            };
            for (int b = 0; b < n; ++b) {
                Vec3q nrm;
                // With a proof, the axis that holds longest (one block for the run); without, any.
                int code = proof ? run_code(blocks, a, b) : -1;
                if (proof && (code < 0 || !apart_along(b, code))) code = longest_axis(b, n, apart_along);
                const int s = pair_sign(a, b, r1, r2, X, Y, &code, &nrm, code);
                if (s > 0) {
                    v = {scalecert::Verdict::Overlapping, a, b};
                    if (proof) {
                        PairCache& p = pair(a, b);
                        std::vector<int> all1(p.hm.P[0].vertices), all2v(p.hm.P[1].vertices);
                        const Witness w = make_witness(p.hm, r1, r2, all1, all2v, true);
                        *proof = Json{{"verdict", "overlapping"},
                                      {"pair", Json::array({a, b})},
                                      {"interior", Json{{"P1", weights_json(w.w1)}, {"P2", weights_json(w.w2)}}}};
                    }
                    return v;
                }
                if (s == 0 && v.part1 < 0) v = {scalecert::Verdict::Touching, a, b};
                if (proof) add_block(blocks, a, b, code, nrm);  // (blocks only for a proof: m·n of them at worst)
            }
            if (proof) check_blocks(blocks.size());
        }
    }
    if (proof) {
        blocks_ += blocks.size();
        *proof = Json{{"verdict", verdict_name(v.verdict)}, {"blocks", blocks_json(blocks)}};
        if (v.verdict == scalecert::Verdict::Touching) {
            long fallbacks = 0;
            const Witness w = pair_common_point(pair(v.part1, v.part2).hm, r1, r2, fallbacks);
            (*proof)["pair"] = Json::array({v.part1, v.part2});
            (*proof)["witness"] = Json{{"P1", weights_json(w.w1)}, {"P2", weights_json(w.w2)}};
        }
    }
    return v;
}

CompoundJudge::Distance CompoundJudge::distance(const Q& r1, const Q& r2, Json* proof) {
    const CompoundVerdict v = verdict(r1, r2);
    if (v.verdict != scalecert::Verdict::Separated) {
        // They meet: a common point of the deciding pair.
        long fallbacks = 0;
        const Witness w = pair_common_point(pair(v.part1, v.part2).hm, r1, r2, fallbacks);
        if (proof)
            *proof = Json{{"squared", "0"},
                          {"pair", Json::array({v.part1, v.part2})},
                          {"P1", weights_json(w.w1)},
                          {"P2", weights_json(w.w2)}};
        return {Q(0), w.point, w.point, v.part1, v.part2};
    }
    const int m = static_cast<int>(parts_[0].size()), n = static_cast<int>(parts_[1].size());
    ScaledParts X(*this, 0, r1, counts_.box_comparisons), Y(*this, 1, r2, counts_.box_comparisons);
    auto exact_pair = [&](int a, int b) -> const ProvedDistance& {
        PairCache& p = pair(a, b);
        if (!p.at || (*p.at)[0] != r1 || (*p.at)[1] != r2) {
            ++counts_.distances;
            check_budget();
            p.distance = proved_distance(p.hm, r1, r2);
            p.at = std::array<Q, 2>{r1, r2};
        }
        return p.distance;
    };
    // A first guess (doubles only choose the work): the pair whose boxes are nearest bounds the
    // distance by its double GJK distance; among the pairs whose boxes are within that, the one
    // nearest by its GJK distance is measured exactly. The blocks below then prove every pair at
    // least that far apart, or find a nearer one and start again.
    Distance best;
    {
        auto box_gap2 = [&](int a, int b) {  // from the enclosures (not a number: 0, nearest)
            const BoxBounds &x = X.d(static_cast<size_t>(a)), &y = Y.d(static_cast<size_t>(b));
            double g2 = 0;
            for (size_t c = 0; c < 3; ++c) {
                const double g = std::max({0.0, y.down[c][0] - x.up[c][1], x.down[c][0] - y.up[c][1]});
                g2 += g * g;
            }
            return g2;
        };
        auto gjk2 = [&](int a, int b) {  // the double GJK distance, squared (not a number: infinite)
            const GjkGuess g = gjk_guess(HullPoints(parts_[0][static_cast<size_t>(a)],
                                                    parts_[1][static_cast<size_t>(b)], sc_.P[0].seed, sc_.P[1].seed),
                                         r1.get_d(), r2.get_d());
            const double d2 = g.distance * g.distance;
            return d2 >= 0 ? d2 : INFINITY;
        };
        counts_.box_comparisons += static_cast<long>(m) * n;
        check_budget();
        double least = INFINITY;
        std::pair<int, int> first{0, 0};
        for (int a = 0; a < m; ++a)
            for (int b = 0; b < n; ++b)
                if (const double g = box_gap2(a, b); g < least) least = g, first = {a, b};
        double bound = gjk2(first.first, first.second);
        std::vector<std::pair<double, std::pair<int, int>>> near;
        for (int a = 0; a < m; ++a)
            for (int b = 0; b < n; ++b)
                if (const double g = box_gap2(a, b); !(g > bound * (1 + 1e-6))) near.push_back({g, {a, b}});
        std::sort(near.begin(), near.end());
        std::pair<int, int> nearest = first;
        double nearest2 = bound;
        for (const auto& [g, ab] : near) {
            if (g > nearest2 * (1 + 1e-6)) break;
            if (ab == first) continue;
            if (const double d2 = gjk2(ab.first, ab.second); d2 < nearest2) nearest2 = d2, nearest = ab;
        }
        const ProvedDistance& d = exact_pair(nearest.first, nearest.second);
        best = {d.d.squared, d.d.p1, d.d.p2, nearest.first, nearest.second};
    }
    // The lower bound: blocks whose normal u holds gap(u) >= |u|² >= E (boxes), gap(N)² >= E·|N|²
    // (a double GJK's direction, proved exactly) or gap = |u|² = E_ab >= E (a pair's own closest
    // points). A pair found closer restarts the blocks with its distance.
    for (;;) {
        const Q E = best.squared;
        const double Ed = filter::region_double(E);
        std::vector<PlaneBlock> blocks;
        bool restart = false;
        if (gap_at_least(X, X.all(), Y, Y.all(), E, Ed)) {
            if (proof) blocks.push_back({0, m - 1, 0, n - 1, -1, gap_vector(X, X.all(), Y, Y.all())});
        } else {
            for (int a = 0; a < m && !restart; ++a) {
                check_budget();
                const size_t ia = static_cast<size_t>(a);
                if (gap_at_least(X, ia, Y, Y.all(), E, Ed)) {
                    if (proof) blocks.push_back({a, a, 0, n - 1, -1, gap_vector(X, ia, Y, Y.all())});
                    continue;
                }
                // An axis along which the boxes are √E apart or more (the run's axis first, so
                // that the run goes on), else the vector between the boxes.
                auto far_along = [&](int bb, int code) {
                    const size_t c = static_cast<size_t>(code / 2), ib = static_cast<size_t>(bb);
                    return code % 2 == 0 ? axis_gap_at_least(X, ia, Y, ib, c, E, Ed)
                                         : axis_gap_at_least(Y, ib, X, ia, c, E, Ed);
                };
                for (int b = 0; b < n; ++b) {
                    const size_t ib = static_cast<size_t>(b);
                    int code = proof ? run_code(blocks, a, b) : -1;
                    if (proof && (code < 0 || !far_along(b, code))) code = longest_axis(b, n, far_along);
                    for (int k = 0; !proof && k < 6 && code < 0; ++k)
                        if (far_along(b, k)) code = k;
                    if (code >= 0) {
                        if (proof) add_block(blocks, a, b, code);
                        continue;
                    }
                    if (gap_at_least(X, ia, Y, ib, E, Ed)) {
                        if (proof) add_block(blocks, a, b, -1, gap_vector(X, ia, Y, ib));
                        continue;
                    }
                    Vec3z N;
                    if ((a != best.part1 || b != best.part2) && slab_at_least(a, b, r1, r2, E, &N)) {
                        if (proof) add_block(blocks, a, b, -1, to_q(N));
                        continue;
                    }
                    const ProvedDistance& d = exact_pair(a, b);
                    if (d.d.squared < E) {
                        best = {d.d.squared, d.d.p1, d.d.p2, a, b};
                        restart = true;
                        break;
                    }
                    if (proof) add_block(blocks, a, b, -1, sub(d.d.p2, d.d.p1));
                }
                if (proof) check_blocks(blocks.size());
            }
        }
        if (restart) continue;
        if (!proof) return best;
        blocks_ += blocks.size();
        // The closest points' weights in their parts.
        const ProvedDistance& d = exact_pair(best.part1, best.part2);
        Json w1, w2;
        if (!d.d.w1.empty() && !d.d.w2.empty()) {
            w1 = weights_json(d.d.w1), w2 = weights_json(d.d.w2);
        } else {
            bool in1 = false, in2 = false;
            const Polyhedron &A = parts_[0][static_cast<size_t>(best.part1)],
                             &B = parts_[1][static_cast<size_t>(best.part2)];
            w1 = membership_proof(A, sc_.P[0].seed, r1, d.d.p1, &in1)["in"];
            w2 = membership_proof(B, sc_.P[1].seed, r2, d.d.p2, &in2)["in"];
            if (!in1 || !in2) throw std::logic_error("compound distance: a closest point outside its part");
        }
        *proof = Json{{"squared", to_exact_string(E)},
                      {"pair", Json::array({best.part1, best.part2})},
                      {"P1", w1},
                      {"P2", w2},
                      {"apart", blocks_json(blocks)}};
        return best;
    }
}

bool CompoundJudge::slab_at_least(int a, int b, const Q& r1, const Q& r2, const Q& E, Vec3z* normal) {
    ++counts_.slabs;
    check_budget();
    const Polyhedron &A = parts_[0][static_cast<size_t>(a)], &B = parts_[1][static_cast<size_t>(b)];
    const GjkGuess g = gjk_guess(HullPoints(A, B, sc_.P[0].seed, sc_.P[1].seed), r1.get_d(), r2.get_d());
    // The direction from A towards B is −closest (closest: a point of A − B); rounded to integers
    // of up to 53 bits. Any nonzero N serves: the exact gap below decides.
    const D3& v = g.closest;
    const double top = std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2])});
    if (!(top > 0) || !std::isfinite(top)) return false;
    Vec3z N;
    for (size_t c = 0; c < 3; ++c) N[c] = Z(std::nearbyint(-v[c] / top * 0x1p52));
    if (is_zero(N)) return false;
    N = primitive(N);  // (the same slab, in fewer digits)
    // gap(N) = min over B(ρ2) of N·y − max over A(ρ1) of N·x = N·d − ρ1 hA(N) − ρ2 hB(N).
    const Vec3q nq = to_q(N);
    const Q ha = A.support(N) - dot(nq, sc_.P[0].seed), hb = B.support(neg(N)) + dot(nq, sc_.P[1].seed);
    const Q gap = dot(nq, d_) - r1 * ha - r2 * hb;
    if (sgn(gap) <= 0 || gap * gap < E * dot(nq, nq)) return false;
    *normal = std::move(N);
    return true;
}

int CompoundJudge::locate(int i, const Q& rho, const Vec3q& x, Json* proof) const {
    const Vec3q& s = sc_.P[i].seed;
    if (proof) {
        Json outs = Json::array();
        for (size_t k = 0; k < parts_[i].size(); ++k) {
            bool inside = false;
            Json p = membership_proof(parts_[i][k], s, rho, x, &inside);
            if (inside) {
                *proof = Json{{"part", k}, {"in", p["in"]}};
                return static_cast<int>(k);
            }
            outs.push_back(p["out"]);
        }
        *proof = Json{{"out", outs}};
        return -1;
    }
    // Without a proof: a part whose scaled box the doubles show x to lie beyond (filter 9 for the
    // box, x's double widened by a unit each way) cannot hold it; the others are placed exactly.
    const double rd = filter::region_double(rho);
    double lo[3], hi[3];
    for (size_t c = 0; c < 3; ++c) {
        const double xd = filter::region_double(x[c]);
        lo[c] = std::nextafter(xd, -INFINITY), hi[c] = std::nextafter(xd, INFINITY);
    }
    std::optional<Vec3q> y;  // x unscaled: s + (x − s)/ρ
    for (size_t k = 0; k < parts_[i].size(); ++k) {
        bool beyond = false;
        for (size_t c = 0; c < 3 && !beyond; ++c) {
            const filter::Enclosure e0 = filter::scaled_enclosure(seed_d_[i][c], rd, unit_d_[i][k][c][0]),
                                    e1 = filter::scaled_enclosure(seed_d_[i][c], rd, unit_d_[i][k][c][1]);
            beyond = hi[c] < e0.lo || lo[c] > e1.hi;
        }
        if (beyond) continue;
        if (!y) y = Vec3q{s[0] + (x[0] - s[0]) / rho, s[1] + (x[1] - s[1]) / rho, s[2] + (x[2] - s[2]) / rho};
        if (parts_[i][k].place(*y).side <= 0) return static_cast<int>(k);
    }
    return -1;
}

int CompoundJudge::near(int i, const Q& rho, const Vec3q& x, const Q& abs, Json* proof) const {
    const Vec3q& s = sc_.P[i].seed;
    Json outs = Json::array();
    for (size_t k = 0; k < parts_[i].size(); ++k) {
        Json p;
        if (near_proof(HullPoints(parts_[i][k], parts_[i][k], s, s), 0, rho, x, abs, proof ? &p : nullptr)) {
            if (proof) *proof = Json{{"part", k}, {"near", p["near"]}};
            return static_cast<int>(k);
        }
        if (proof) outs.push_back(p["out"]);
    }
    if (proof) *proof = Json{{"out", outs}};
    return -1;
}

MeasuredDepth CompoundJudge::pair_depth(int a, int b, const Q& r1, const Q& r2, Json* proof) {
    PairCache& p = pair(a, b);  // counted against the limits of pairs judged exactly
    const HullPoints S(p.hm);
    std::optional<MeasuredDepth> d = measured_depth(S, r1, r2);
    if (!d) d = depth_from_distance(S, exact_distance(p.hm, r1, r2), r1, r2);
    if (proof) *proof = depth_proof(&p.hm, *d, r1, r2);
    return *d;
}

Q CompoundJudge::pair_directional_depth(int a, int b, const Vec3q& n, const Q& r1, const Q& r2) {
    return directional_depth_squared(HullPoints(pair(a, b).hm), n, r1, r2);
}

std::pair<Q, Q> CompoundJudge::plane_extents(const Vec3q& n, const Q& r1, const Q& r2) const {
    // max over P1(ρ1) of n·x = n·s1 + ρ1 (max over P1 of n·v − n·s1) for ρ1 > 0, and min over P2(ρ2)
    // likewise: each part's extreme vertex by its filtered climb along N, the primitive integer
    // vector along n, then n·v exactly at those vertices only.
    if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0) return {Q(0), Q(0)};
    const Vec3z N = primitive(n);
    std::optional<Q> ext[2];  // max n·v over P1's parts, min over P2's
    for (int i = 0; i < 2; ++i) {
        const Vec3z dir = i == 0 ? N : neg(N);
        for (const Polyhedron& P : parts_[i]) {
            const Q t = dot(n, P.points[static_cast<size_t>(P.argmax(dir).front())]);
            if (!ext[i] || (i == 0 ? t > *ext[i] : t < *ext[i])) ext[i] = t;
        }
    }
    const Q ns1 = dot(n, sc_.P[0].seed), ns2 = dot(n, sc_.P[1].seed);
    return {Q(ns1 + r1 * (*ext[0] - ns1)), Q(ns2 + r2 * (*ext[1] - ns2))};
}

}  // namespace scalecert::internal
