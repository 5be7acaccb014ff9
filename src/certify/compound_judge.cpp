// Judgements on two compounds at one scaling pair, with their proofs (compound_judge.hpp).
#include "certify/compound_judge.hpp"

#include "certify/judgements.hpp"
#include "geometry/gjk.hpp"
#include "geometry/measures.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace scalecert::internal {

Witness pair_common_point(const HullModel& hm, const Q& r1, const Q& r2, long& fallbacks) {
    const GjkGuess g = gjk_guess(hm, r1.get_d(), r2.get_d());
    if (!g.v1.empty() && !g.v2.empty()) {
        if (std::optional<Witness> w = try_witness(hm, r1, r2, g.v1, g.v2)) return std::move(*w);
        ++fallbacks;
    }
    return make_witness(hm, r1, r2, hm.P[0].vertices, hm.P[1].vertices, false);
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
Json range_json(int from, int to) { return Json::array({from, to}); }
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
    for (int i = 0; i < 2; ++i)
        for (const Polyhedron& P : parts_[i]) unit_[i].push_back(bounding_box(P));
}

CompoundJudge::~CompoundJudge() = default;

void CompoundJudge::check_blocks(size_t more) const {
    if (static_cast<double>(blocks_) + static_cast<double>(more) > kMaxCertificateBlocks)
        throw InputError(
            name_ + ": the certificate would hold more than " +
            std::to_string(static_cast<long>(kMaxCertificateBlocks)) +
            " blocks of part pairs (the limit: parts far from each other in their lists' order cannot share a block)");
}

// s + ρ(box − s): ρ > 0 keeps the order along every axis.
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

// Doubles enclosing a box's ends: down[c][e] <= end <= up[c][e] (mpq's get_d truncates, within
// one unit in the last place of a normal double; NaN where get_d is not one, so that the filter
// below never answers from it).
struct BoxBounds {
    double down[3][2], up[3][2];
};

namespace {
BoxBounds bounds_of(const std::array<std::array<Q, 2>, 3>& b) {
    BoxBounds r;
    for (size_t c = 0; c < 3; ++c)
        for (size_t e = 0; e < 2; ++e) {
            const double d = filter::region_double(b[c][e]);
            r.down[c][e] = std::nextafter(d, -INFINITY);
            r.up[c][e] = std::nextafter(d, INFINITY);
        }
    return r;
}
// Is x's end along c below y's start, strictly (x[c][1] < y[c][0])? The doubles decide when they
// can prove it either way; else the exact ends.
bool below(const std::array<std::array<Q, 2>, 3>& x, const BoxBounds& xb, const std::array<std::array<Q, 2>, 3>& y,
           const BoxBounds& yb, size_t c) {
    if (xb.up[c][1] < yb.down[c][0]) return true;
    if (xb.down[c][1] >= yb.up[c][0]) return false;
    return x[c][1] < y[c][0];
}
// The axis (and side: +1 when the first box lies below) along which two boxes are strictly apart;
// {-1, 0} when they are not.
std::pair<int, int> apart(const std::array<std::array<Q, 2>, 3>& x, const BoxBounds& xb,
                          const std::array<std::array<Q, 2>, 3>& y, const BoxBounds& yb) {
    for (size_t c = 0; c < 3; ++c) {
        if (below(x, xb, y, yb, c)) return {static_cast<int>(c), 1};
        if (below(y, yb, x, xb, c)) return {static_cast<int>(c), -1};
    }
    return {-1, 0};
}
// Does y start at least √E past x's end along c (y[c][0] − x[c][1] > 0, its square >= E)? Ed is
// E's double (region_double: NaN when not a normal double). The doubles decide when their bounds
// prove it either way (each difference and square rounded by one unit outward); else exactly.
bool axis_gap_at_least(const std::array<std::array<Q, 2>, 3>& x, const BoxBounds& xb,
                       const std::array<std::array<Q, 2>, 3>& y, const BoxBounds& yb, size_t c, const Q& E, double Ed) {
    const double lo = std::nextafter(yb.down[c][0] - xb.up[c][1], -INFINITY);
    if (lo > 0 && std::nextafter(lo * lo, -INFINITY) >= std::nextafter(Ed, INFINITY)) return true;
    const double hi = std::nextafter(yb.up[c][0] - xb.down[c][1], INFINITY);
    if (hi <= 0 || std::nextafter(hi * hi, INFINITY) < std::nextafter(Ed, -INFINITY)) return false;
    const Q g = y[c][0] - x[c][1];
    return sgn(g) > 0 && g * g >= E;
}
std::pair<int, int> apart(const std::array<std::array<Q, 2>, 3>& x, const std::array<std::array<Q, 2>, 3>& y) {
    return apart(x, bounds_of(x), y, bounds_of(y));
}
// The box holding both.
std::array<std::array<Q, 2>, 3> join(const std::vector<std::array<std::array<Q, 2>, 3>>& boxes) {
    std::array<std::array<Q, 2>, 3> u = boxes.front();
    for (const auto& b : boxes)
        for (size_t c = 0; c < 3; ++c) {
            if (b[c][0] < u[c][0]) u[c][0] = b[c][0];
            if (b[c][1] > u[c][1]) u[c][1] = b[c][1];
        }
    return u;
}
// From box x to box y: the vector u between their nearest points (0 along an axis where they
// overlap). Every point of y exceeds every point of x by |u|² or more along u (axis by axis).
Vec3q gap_vector(const std::array<std::array<Q, 2>, 3>& x, const std::array<std::array<Q, 2>, 3>& y) {
    Vec3q u{Q(0), Q(0), Q(0)};
    for (size_t c = 0; c < 3; ++c) {
        if (x[c][1] < y[c][0])
            u[c] = y[c][0] - x[c][1];
        else if (y[c][1] < x[c][0])
            u[c] = y[c][1] - x[c][0];
    }
    return u;
}
}  // namespace

int CompoundJudge::pair_sign(int a, int b, const Q& r1, const Q& r2, const std::vector<Box>& b1,
                             const std::vector<Box>& b2, const std::vector<BoxBounds>& d1,
                             const std::vector<BoxBounds>& d2, int* code, Vec3q* normal, int prefer) {
    const Box &x = b1[static_cast<size_t>(a)], &y = b2[static_cast<size_t>(b)];
    const BoxBounds &xd = d1[static_cast<size_t>(a)], &yd = d2[static_cast<size_t>(b)];
    *code = -1;
    // The preferred axis first, when the boxes are apart along it (the run then goes on).
    if (prefer >= 0) {
        const size_t c = static_cast<size_t>(prefer / 2);
        if (prefer % 2 == 0 ? below(x, xd, y, yd, c) : below(y, yd, x, xd, c)) {
            ++counts_.boxed;
            *code = prefer;
            return -1;
        }
    }
    const auto [c, side] = apart(x, xd, y, yd);
    if (c >= 0) {
        ++counts_.boxed;
        *code = axis_code(c, side);
        return -1;
    }
    ++counts_.judged;
    PairCache& p = pair(a, b);
    if (!p.constraints) {
        const Vec3q d = sub(sc_.P[1].seed, sc_.P[0].seed);
        std::vector<HalfPlane> hs;
        for (const Vec3z& n : minkowski_facet_normals(p.hm.P[0], p.hm.P[1])) {
            const Vec3q nq = to_q(n);
            HalfPlane h;
            h.a = p.hm.P[0].support(n) - dot(nq, sc_.P[0].seed);
            h.b = p.hm.P[1].support(neg(n)) + dot(nq, sc_.P[1].seed);
            h.c = dot(nq, d);
            h.normal = n;
            hs.push_back(std::move(h));
        }
        p.constraints = std::move(hs);
    }
    int least = 1;
    for (const HalfPlane& h : *p.constraints) {
        const int s = sgn(Q(h.a * r1 + h.b * r2 - h.c));
        if (s < least) {
            least = s;
            if (normal) *normal = to_q(h.normal);
            if (s < 0) break;
        }
    }
    return least;
}

namespace {
struct Block {
    int a0, a1, b0, b1;
    int code;  // an axis normal (axis_code), or −1: then `normal`
    Vec3q normal;
};
Json blocks_json(const std::vector<Block>& blocks) {
    Json out = Json::array();
    for (const Block& b : blocks)
        out.push_back(Json{{"P1_parts", range_json(b.a0, b.a1)},
                           {"P2_parts", range_json(b.b0, b.b1)},
                           {"normal", exact3(b.code >= 0 ? axis_of(b.code) : b.normal)}});
    return out;
}
// Appends [a, a] x [b, b] with an axis normal (code >= 0) or the normal n, joining the run before
// it in the row when the normal is the same (every pair of the run is then separated by it, and
// so is the block's union).
void add_block(std::vector<Block>& blocks, int a, int b, int code, const Vec3q& n = Vec3q{}) {
    if (!blocks.empty()) {
        Block& last = blocks.back();
        if (last.a0 == a && last.a1 == a && last.b1 == b - 1 && last.code == code && (code >= 0 || last.normal == n)) {
            last.b1 = b;
            return;
        }
    }
    blocks.push_back({a, a, b, b, code, code >= 0 ? Vec3q{} : n});
}
// The run a block ends in at pair b − 1 of row a, if any: its axis code (−1: none, or not an axis).
int run_code(const std::vector<Block>& blocks, int a, int b) {
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

CompoundJudge::Verdict CompoundJudge::verdict(const Q& r1, const Q& r2, Json* proof) {
    const int m = static_cast<int>(parts_[0].size()), n = static_cast<int>(parts_[1].size());
    std::vector<Box> b1, b2;
    for (int k = 0; k < m; ++k) b1.push_back(scaled_box(0, static_cast<size_t>(k), r1));
    for (int k = 0; k < n; ++k) b2.push_back(scaled_box(1, static_cast<size_t>(k), r2));
    const Box all2 = join(b2);
    const BoxBounds all2d = bounds_of(all2);
    std::vector<BoxBounds> d1, d2;
    for (const Box& b : b1) d1.push_back(bounds_of(b));
    for (const Box& b : b2) d2.push_back(bounds_of(b));
    std::vector<Block> blocks;
    Verdict v;
    const auto [c, side] = apart(join(b1), all2);
    if (c >= 0) {
        blocks.push_back({0, m - 1, 0, n - 1, axis_code(c, side), {}});
    } else {
        for (int a = 0; a < m; ++a) {
            const auto [ca, sa] = apart(b1[static_cast<size_t>(a)], d1[static_cast<size_t>(a)], all2, all2d);
            if (ca >= 0) {
                counts_.boxed += n;
                blocks.push_back({a, a, 0, n - 1, axis_code(ca, sa), {}});
                continue;
            }
            // Boxes apart along n (+e_c: part a's below part b's).
            auto apart_along = [&](int b, int code) {
                const size_t c = static_cast<size_t>(code / 2), ia = static_cast<size_t>(a),
                             ib = static_cast<size_t>(b);
                return code % 2 == 0 ? below(b1[ia], d1[ia], b2[ib], d2[ib], c)
                                     : below(b2[ib], d2[ib], b1[ia], d1[ia], c);
            };
            for (int b = 0; b < n; ++b) {
                Vec3q nrm;
                // With a proof, the axis that holds longest (one block for the run); without, any.
                int code = proof ? run_code(blocks, a, b) : -1;
                if (proof && (code < 0 || !apart_along(b, code))) code = longest_axis(b, n, apart_along);
                const int s = pair_sign(a, b, r1, r2, b1, b2, d1, d2, &code, &nrm, code);
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

namespace {
Vec3q scaled(const Vec3q& s, const Q& rho, const Vec3q& y) {
    return {s[0] + rho * (y[0] - s[0]), s[1] + rho * (y[1] - s[1]), s[2] + rho * (y[2] - s[2])};
}
}  // namespace

CompoundJudge::Distance CompoundJudge::distance(const Q& r1, const Q& r2, Json* proof) {
    const Verdict v = verdict(r1, r2);
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
    std::vector<Box> b1, b2;
    for (int k = 0; k < m; ++k) b1.push_back(scaled_box(0, static_cast<size_t>(k), r1));
    for (int k = 0; k < n; ++k) b2.push_back(scaled_box(1, static_cast<size_t>(k), r2));
    // A first guess: the pairs whose boxes (in doubles: they only choose the work) are nearest,
    // measured exactly; the blocks below then prove every pair at least that far apart, or find
    // a nearer one and start again.
    std::vector<std::array<std::array<double, 2>, 3>> f1, f2;
    auto doubles = [](const Box& b) {
        return std::array<std::array<double, 2>, 3>{{{b[0][0].get_d(), b[0][1].get_d()},
                                                     {b[1][0].get_d(), b[1][1].get_d()},
                                                     {b[2][0].get_d(), b[2][1].get_d()}}};
    };
    for (const Box& b : b1) f1.push_back(doubles(b));
    for (const Box& b : b2) f2.push_back(doubles(b));
    auto box_gap2 = [&](int a, int b) {
        double g2 = 0;
        for (size_t c = 0; c < 3; ++c) {
            const auto &x = f1[static_cast<size_t>(a)][c], &y = f2[static_cast<size_t>(b)][c];
            const double g = std::max({0.0, y[0] - x[1], x[0] - y[1]});
            g2 += g * g;
        }
        return g2;
    };
    auto exact_pair = [&](int a, int b) -> const ProvedDistance& {
        PairCache& p = pair(a, b);
        if (!p.at || (*p.at)[0] != r1 || (*p.at)[1] != r2) {
            ++counts_.distances;
            p.distance = proved_distance(p.hm, r1, r2);
            p.at = std::array<Q, 2>{r1, r2};
        }
        return p.distance;
    };
    Distance best;
    {
        double least = INFINITY;
        std::pair<int, int> first{0, 0};
        for (int a = 0; a < m; ++a)
            for (int b = 0; b < n; ++b)
                if (const double g = box_gap2(a, b); g < least) least = g, first = {a, b};
        const ProvedDistance& d = exact_pair(first.first, first.second);
        best = {d.d.squared, d.d.p1, d.d.p2, first.first, first.second};
        // Every pair whose boxes may be nearer than that, nearest first.
        const double bound = best.squared.get_d() * (1 + 1e-9);
        std::vector<std::pair<double, std::pair<int, int>>> near;
        for (int a = 0; a < m; ++a)
            for (int b = 0; b < n; ++b)
                if (const double g = box_gap2(a, b); g <= bound) near.push_back({g, {a, b}});
        std::sort(near.begin(), near.end());
        for (const auto& [lb, ab] : near) {
            const ProvedDistance& e = exact_pair(ab.first, ab.second);
            if (e.d.squared < best.squared) best = {e.d.squared, e.d.p1, e.d.p2, ab.first, ab.second};
        }
    }
    // The lower bound: blocks whose normal u holds gap(u) ≥ |u|² ≥ E (boxes) or gap = |u|² = E_ab ≥ E
    // (a pair's own closest points). A pair found closer restarts the blocks with its distance.
    std::vector<BoxBounds> d1, d2;
    for (const Box& b : b1) d1.push_back(bounds_of(b));
    for (const Box& b : b2) d2.push_back(bounds_of(b));
    for (;;) {
        const Q E = best.squared;
        const double Ed = filter::region_double(E);
        std::vector<Block> blocks;
        bool restart = false;
        const Box all2 = join(b2);
        const Vec3q whole = gap_vector(join(b1), all2);
        if (dot(whole, whole) >= E) {
            blocks.push_back({0, m - 1, 0, n - 1, -1, whole});
        } else {
            for (int a = 0; a < m && !restart; ++a) {
                const Vec3q row = gap_vector(b1[static_cast<size_t>(a)], all2);
                if (dot(row, row) >= E) {
                    blocks.push_back({a, a, 0, n - 1, -1, row});
                    continue;
                }
                for (int b = 0; b < n; ++b) {
                    const Box &x = b1[static_cast<size_t>(a)], &y = b2[static_cast<size_t>(b)];
                    const BoxBounds& xd = d1[static_cast<size_t>(a)];
                    // An axis along which the boxes are √E apart or more (the run's axis first,
                    // so that the run goes on), else the vector between the boxes.
                    auto far_along = [&](int bb, int code) {
                        const Box& yy = b2[static_cast<size_t>(bb)];
                        const BoxBounds& yyd = d2[static_cast<size_t>(bb)];
                        const size_t c = static_cast<size_t>(code / 2);
                        return code % 2 == 0 ? axis_gap_at_least(x, xd, yy, yyd, c, E, Ed)
                                             : axis_gap_at_least(yy, yyd, x, xd, c, E, Ed);
                    };
                    int code = proof ? run_code(blocks, a, b) : -1;
                    if (proof && (code < 0 || !far_along(b, code))) code = longest_axis(b, n, far_along);
                    for (int k = 0; !proof && k < 6 && code < 0; ++k)
                        if (far_along(b, k)) code = k;
                    if (code >= 0) {
                        if (proof) add_block(blocks, a, b, code);
                        continue;
                    }
                    const Vec3q u = gap_vector(x, y);
                    if (sgn(dot(u, u)) > 0 && dot(u, u) >= E) {
                        if (proof) add_block(blocks, a, b, -1, u);
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

int CompoundJudge::locate(int i, const Q& rho, const Vec3q& x, Json* proof) const {
    const Vec3q& s = sc_.P[i].seed;
    Json outs = Json::array();
    for (size_t k = 0; k < parts_[i].size(); ++k) {
        bool inside = false;
        Json p = membership_proof(parts_[i][k], s, rho, x, &inside);
        if (inside) {
            if (proof) *proof = Json{{"part", k}, {"in", p["in"]}};
            return static_cast<int>(k);
        }
        if (proof) outs.push_back(p["out"]);
    }
    if (proof) *proof = Json{{"out", outs}};
    return -1;
}

std::pair<Q, Q> CompoundJudge::plane_extents(const Vec3q& n, const Q& r1, const Q& r2) const {
    std::optional<Q> ext[2];  // max over P1(ρ1), min over P2(ρ2)
    for (int i = 0; i < 2; ++i) {
        const Vec3q& s = sc_.P[i].seed;
        const Q& rho = i == 0 ? r1 : r2;
        for (const Polyhedron& P : parts_[i])
            for (int v : P.vertices) {
                const Q t = dot(n, scaled(s, rho, P.points[static_cast<size_t>(v)]));
                if (!ext[i] || (i == 0 ? t > *ext[i] : t < *ext[i])) ext[i] = t;
            }
    }
    return {*ext[0], *ext[1]};
}

}  // namespace scalecert::internal
