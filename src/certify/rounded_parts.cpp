#include "certify/rounded_parts.hpp"

#include "certify/judgements.hpp"
#include "certify/region_certificate.hpp"
#include "compound/region.hpp"
#include "geometry/measures.hpp"

#include <algorithm>
#include <cmath>

namespace scalecert::internal {

namespace {
// The relative error bound of a double sum of products of rounded inputs (a few dozen roundings,
// each at most 2^-53 of its result: 10^-14 is above 45 of them), and an absolute term for results
// that underflow.
constexpr double kRel = 1e-14, kTiny = 1e-300;

double dbl(const Q& q) { return to_double_rn(q); }

// The filters' error bounds are relative, with kTiny for results that underflow: they hold when
// every input (a point, a seed, a radius, a pose's entry, ρ, a tolerance) is 0 or a double well
// inside the normal range, so that rounding it is a relative error; else the filters stand aside
// and every pair is judged exactly.
bool fits(const Q& q) {
    if (sgn(q) == 0) return true;
    const double x = std::abs(dbl(q));
    return x >= 0x1p-500 && x <= 0x1p500;
}
}  // namespace

RoundedParts::RoundedParts(const ExactScene& sc, const std::string& name) : sc_(sc), name_(name) {
    const size_t m = std::max<size_t>(1, sc.P[0].parts.size()), n = std::max<size_t>(1, sc.P[1].parts.size());
    if (m * n > kMaxPartPairs)
        throw InputError(name + ": " + std::to_string(m) + " x " + std::to_string(n) + " part pairs, more than " +
                         std::to_string(kMaxPartPairs) + " (the limit)");
    for (int i = 0; i < 2; ++i) {
        const PolyInput& in = sc_.P[i];
        const std::string which = i == 0 ? "P1" : "P2";
        const size_t n = std::max<size_t>(1, in.parts.size());
        for (size_t k = 0; k < n; ++k) {
            const std::vector<Vec3q>& pts = in.parts.empty() ? in.points : in.parts[k];
            const Q r = in.part_radius(k);
            body_[i].push_back(
                rounded_body(pts, in.seed, r, name + ": " + (in.parts.empty() ? which : part_label(i, in, k))));
            radius_[i].push_back(r);
            std::array<double, 10> b{INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY, dbl(r)};
            for (const D3& x : body_[i].back()->dpts)
                for (int a = 0; a < 3; ++a) b[a] = std::min(b[a], x[a]), b[3 + a] = std::max(b[3 + a], x[a]);
            for (int a = 0; a < 3; ++a) b[7 + a] = std::abs(b[a]) + std::abs(b[3 + a]);
            base_.box[i].push_back(b);
            base_.off[i].push_back(base_.pts[i].size());
            for (const D3& x : body_[i].back()->dpts) {
                base_.pts[i].push_back(x);
                for (int a = 0; a < 3; ++a) base_.pts_mag[i] = std::max(base_.pts_mag[i], std::abs(x[a]));
            }
            for (const Vec3q& x : pts) base_.safe = base_.safe && fits(x[0]) && fits(x[1]) && fits(x[2]);
            base_.safe = base_.safe && fits(r);
        }
        base_.off[i].push_back(base_.pts[i].size());
        for (int a = 0; a < 3; ++a) {
            base_.seed[i][a] = dbl(in.seed[a]), base_.seed_mag[i][a] = std::abs(base_.seed[i][a]);
            base_.safe = base_.safe && fits(in.seed[a]);
        }
    }
}

RoundedParts::Frame RoundedParts::frame(const Poses& pose) const {
    if (!pose[0] && !pose[1]) return base_;
    Frame F = base_;
    for (int i = 0; i < 2; ++i) {
        if (!pose[i]) continue;
        double m[3][4];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) {
                m[r][c] = dbl((*pose[i])[r][c]);
                F.safe = F.safe && fits((*pose[i])[r][c]);
            }
        // A box of centre c and half-extents h moves into the box of centre R·c + t and
        // half-extents |R|·h; its magnitude |R|(|c| + h) + |t| bounds every term computed.
        for (auto& b : F.box[i]) {
            double c[3], h[3], cm[3];
            for (int a = 0; a < 3; ++a) c[a] = (b[a] + b[3 + a]) / 2, h[a] = (b[3 + a] - b[a]) / 2, cm[a] = b[7 + a];
            for (int r = 0; r < 3; ++r) {
                double x = m[r][3], half = 0, mag = std::abs(m[r][3]);
                for (int a = 0; a < 3; ++a) {
                    x += m[r][a] * c[a];
                    half += std::abs(m[r][a]) * h[a];
                    mag += std::abs(m[r][a]) * (cm[a] + std::abs(h[a]));
                }
                b[r] = x - half;
                b[3 + r] = x + half;
                b[7 + r] = 2 * mag + std::abs(b[r]) + std::abs(b[3 + r]);
            }
        }
        // The points: R·p + t, each coordinate within 10^-14 of Σ|R||p| + |t| (so of its bound).
        double row_mag = 0;
        for (int r = 0; r < 3; ++r)
            row_mag =
                std::max(row_mag, std::abs(m[r][3]) +
                                      (std::abs(m[r][0]) + std::abs(m[r][1]) + std::abs(m[r][2])) * base_.pts_mag[i]);
        F.pts_mag[i] = row_mag;
        for (D3& x : F.pts[i]) {
            const D3 p = x;
            for (int r = 0; r < 3; ++r) x[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3];
        }
        double s[3];
        for (int a = 0; a < 3; ++a) s[a] = F.seed[i][a];
        for (int r = 0; r < 3; ++r) {
            double x = m[r][3], mag = std::abs(m[r][3]);
            for (int a = 0; a < 3; ++a) x += m[r][a] * s[a], mag += std::abs(m[r][a]) * std::abs(s[a]);
            F.seed[i][r] = x;
            F.seed_mag[i][r] = mag + std::abs(x);
        }
    }
    return F;
}

std::shared_ptr<const RoundedPoints> RoundedParts::pair(int a, int b) const {
    return std::make_shared<const RoundedPoints>(body_[0][static_cast<size_t>(a)], body_[1][static_cast<size_t>(b)]);
}

ExactScene RoundedParts::pair_scene(int a, int b) const {
    ExactScene s;
    const int k[2] = {a, b};
    for (int i = 0; i < 2; ++i) {
        const RoundedBody& o = *body_[i][static_cast<size_t>(k[i])];
        s.P[i].points = o.pts;
        s.P[i].seed = o.seed;
        s.P[i].seed_given = true;
        s.P[i].radius = radius_[i][static_cast<size_t>(k[i])];
        s.P[i].radius_given = true;
        s.lo[i] = sc_.lo[i];
        s.hi[i] = sc_.hi[i];
    }
    return s;
}

bool RoundedParts::boxes_apart(const Frame& F, int a, int b, double r1, double r2, double* gap) {
    // Along each axis the widened box of part a at ρ1 is [s1 + ρ1(lo − s1) − ρ1·r, s1 + ρ1(hi − s1)
    // + ρ1·r]; the gap between two such intervals in doubles is within kRel of the sum of the
    // magnitudes of its terms (and kTiny) of the exact gap.
    if (gap) *gap = 0;
    if (!F.safe) return false;
    const auto& A = F.box[0][static_cast<size_t>(a)];
    const auto& B = F.box[1][static_cast<size_t>(b)];
    const double *s1 = F.seed[0], *s2 = F.seed[1];
    bool apart = false;
    double sum = 0;
    for (int x = 0; x < 3; ++x) {
        const double a_lo = s1[x] + r1 * (A[x] - s1[x]) - r1 * A[6], a_hi = s1[x] + r1 * (A[3 + x] - s1[x]) + r1 * A[6];
        const double b_lo = s2[x] + r2 * (B[x] - s2[x]) - r2 * B[6], b_hi = s2[x] + r2 * (B[3 + x] - s2[x]) + r2 * B[6];
        const double m1 = F.seed_mag[0][x] + r1 * (A[7 + x] + 2 * F.seed_mag[0][x] + A[6]),
                     m2 = F.seed_mag[1][x] + r2 * (B[7 + x] + 2 * F.seed_mag[1][x] + B[6]);
        const double err = kRel * (m1 + m2) + kTiny;
        const double g = std::max(b_lo - a_hi, a_lo - b_hi) - err;  // NaN when an input is not finite
        if (g > 0) {
            apart = true;
            sum += g * g;
        }
    }
    if (gap) *gap = std::isfinite(sum) ? std::sqrt(sum) * (1 - kRel) : 0;
    return apart;
}

RoundedParts::Bounds RoundedParts::support_bounds(const Frame& F, int a, int b, double r1, double r2) {
    if (!F.safe) return {};
    const auto& A = F.box[0][static_cast<size_t>(a)];
    const auto& B = F.box[1][static_cast<size_t>(b)];
    const double *s1 = F.seed[0], *s2 = F.seed[1];
    // Part a at ρ1 is s1 + ρ1(p − s1) over its points p: along u its support is (1 − ρ1)·u·s1 +
    // ρ1·max u·p, plus ρ1·r|u|; part b's least is (1 − ρ2)·u·s2 + ρ2·min u·q, less ρ2·r|u|.
    double u[3], ca[3], cb[3];
    for (int x = 0; x < 3; ++x) {
        ca[x] = s1[x] + r1 * ((A[x] + A[3 + x]) / 2 - s1[x]);
        cb[x] = s2[x] + r2 * ((B[x] + B[3 + x]) / 2 - s2[x]);
        u[x] = cb[x] - ca[x];
    }
    const double U = std::abs(u[0]) + std::abs(u[1]) + std::abs(u[2]),
                 len = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    Bounds out;
    // (Below 2^-450 the squares of u's coordinates may underflow, and |u| with them.)
    if (!(len > 0x1p-450) || !std::isfinite(len)) return out;
    double hi = -INFINITY, lo = INFINITY;
    const D3 *pa = nullptr, *qb = nullptr;
    for (size_t k = F.off[0][static_cast<size_t>(a)]; k < F.off[0][static_cast<size_t>(a) + 1]; ++k) {
        const D3& p = F.pts[0][k];
        const double v = u[0] * p[0] + u[1] * p[1] + u[2] * p[2];
        if (v > hi) hi = v, pa = &p;
    }
    for (size_t k = F.off[1][static_cast<size_t>(b)]; k < F.off[1][static_cast<size_t>(b) + 1]; ++k) {
        const D3& q = F.pts[1][k];
        const double v = u[0] * q[0] + u[1] * q[1] + u[2] * q[2];
        if (v < lo) lo = v, qb = &q;
    }
    if (!pa || !qb) return out;
    const double us1 = u[0] * s1[0] + u[1] * s1[1] + u[2] * s1[2], us2 = u[0] * s2[0] + u[1] * s2[1] + u[2] * s2[2];
    const double R = r1 * A[6] + r2 * B[6];
    const double gap = ((1 - r2) * us2 + r2 * lo) - ((1 - r1) * us1 + r1 * hi) - R * len;
    // Every term is within kRel of U times its coordinates' magnitudes (or of R·|u|).
    const double m1 = F.seed_mag[0][0] + F.seed_mag[0][1] + F.seed_mag[0][2],
                 m2 = F.seed_mag[1][0] + F.seed_mag[1][1] + F.seed_mag[1][2];
    const double err =
        kRel * (U * ((1 + r1) * m1 + (1 + r2) * m2 + r1 * F.pts_mag[0] + r2 * F.pts_mag[1]) + R * len) + kTiny;
    if (std::isfinite(gap) && std::isfinite(err)) out.lower = (gap - err) / len * (1 - kRel);
    // The two extreme points, scaled: their distance less R is at least the pair's distance.
    double d2 = 0;
    for (int x = 0; x < 3; ++x) {
        const double e = (s2[x] + r2 * ((*qb)[x] - s2[x])) - (s1[x] + r1 * ((*pa)[x] - s1[x]));
        d2 += e * e;
    }
    const double up = std::sqrt(d2) - R;
    const double uerr =
        kRel * ((1 + r1) * m1 + (1 + r2) * m2 + 3 * (r1 * F.pts_mag[0] + r2 * F.pts_mag[1]) + R) + kTiny;
    if (std::isfinite(up) && std::isfinite(uerr)) out.upper = up + uerr;
    return out;
}

bool RoundedParts::scan(const Frame& F, int a, int b) {
    const size_t n = F.off[0][static_cast<size_t>(a) + 1] - F.off[0][static_cast<size_t>(a)] +
                     F.off[1][static_cast<size_t>(b) + 1] - F.off[1][static_cast<size_t>(b)];
    if (scanned_ + n > kMaxScannedPoints) return false;
    scanned_ += n;
    return true;
}

void RoundedParts::count_exact(int a, int b) {
    ++counts_.exact;
    const double work = static_cast<double>(body_[0][static_cast<size_t>(a)]->pts.size() +
                                            body_[1][static_cast<size_t>(b)]->pts.size());
    work_in_call_ += work;
    if (++exact_in_call_ > kMaxExactPartPairs)
        throw InputError(name_ + ": more than " + std::to_string(kMaxExactPartPairs) +
                         " part pairs need an exact judgement in one judgement (the limit)");
    if (work_in_call_ > kMaxExactWork)
        throw InputError(name_ + ": the part pairs one judgement judges exactly hold more than " +
                         std::to_string(static_cast<long>(kMaxExactWork)) + " points in all (the limit)");
    if (run_left_ >= 0 && --run_left_ < 0)
        throw InputError(name_ + ": the claims need more than " + std::to_string(kMaxExactPartPairsInAll) +
                         " exact part-pair judgements in all (the limit for one run of certify-fp)");
}

void RoundedParts::start_judgement() {
    exact_in_call_ = 0;
    work_in_call_ = 0;
    scanned_ = 0;
}

RoundedParts::PairState RoundedParts::pair_state(int a, int b, const Q& rho1, const Q& rho2, const Poses& pose) {
    count_exact(a, b);
    const std::shared_ptr<const RoundedPoints> S = pair(a, b);
    std::optional<PosedPoints> at;
    if (pose[0] || pose[1]) at.emplace(*S, pose);
    const PointSets& P = at ? static_cast<const PointSets&>(*at) : *S;
    const auto [rank, flat] = S->difference_span(P);
    PairState st;
    st.hulls = hull_measure(P, rank, flat, rho1, rho2);
    st.R = rho1 * radius_[0][static_cast<size_t>(a)] + rho2 * radius_[1][static_cast<size_t>(b)];
    st.verdict = rounded_verdict(st.hulls, st.R);
    return st;
}

RoundedParts::Decided RoundedParts::verdict(const Q& rho1, const Q& rho2, const Poses& pose) {
    start_judgement();
    Frame F = frame(pose);
    F.safe = F.safe && fits(rho1) && fits(rho2);
    const double r1 = dbl(rho1), r2 = dbl(rho2);
    // The pairs the doubles cannot part, the deepest by their supports first (the likeliest to
    // overlap, which ends the search).
    struct Candidate {
        double lower;
        int a, b;
    };
    std::vector<Candidate> open;
    for (int a = 0; a < static_cast<int>(parts(0)); ++a)
        for (int b = 0; b < static_cast<int>(parts(1)); ++b) {
            if (boxes_apart(F, a, b, r1, r2)) {
                ++counts_.boxed;
                continue;
            }
            const double lower = scan(F, a, b) ? support_bounds(F, a, b, r1, r2).lower : -INFINITY;
            if (lower > 0) {
                ++counts_.boxed;
                continue;
            }
            open.push_back({std::isnan(lower) ? -INFINITY : lower, a, b});
        }
    std::stable_sort(open.begin(), open.end(),
                     [](const Candidate& x, const Candidate& y) { return x.lower < y.lower; });
    Decided out;
    for (const Candidate& c : open) {
        const Verdict v = pair_state(c.a, c.b, rho1, rho2, pose).verdict;
        if (v == Verdict::Overlapping) return {v, c.a, c.b};
        // The first touching pair in the parts' order.
        if (v == Verdict::Touching && (out.a < 0 || std::pair(c.a, c.b) < std::pair(out.a, out.b))) out = {v, c.a, c.b};
    }
    return out;
}

RoundedParts::Nearest RoundedParts::nearest(const Q& rho1, const Q& rho2, const Poses& pose) {
    start_judgement();
    Frame F = frame(pose);
    F.safe = F.safe && fits(rho1) && fits(rho2);
    const double r1 = dbl(rho1), r2 = dbl(rho2);
    // The pairs by the doubles' lower bound on their distance, nearest first.
    struct Candidate {
        double gap;
        int a, b;
    };
    std::vector<Candidate> cand;
    cand.reserve(parts(0) * parts(1));
    for (int a = 0; a < static_cast<int>(parts(0)); ++a)
        for (int b = 0; b < static_cast<int>(parts(1)); ++b) {
            double g = 0;
            boxes_apart(F, a, b, r1, r2, &g);
            cand.push_back({g, a, b});
        }
    std::stable_sort(cand.begin(), cand.end(), [](const Candidate& x, const Candidate& y) { return x.gap < y.gap; });
    // The supports' bounds, nearest boxes first, while the boxes are nearer than some pair's upper
    // bound: the pairs past it (by their boxes or supports) are not the nearest.
    double upper = INFINITY;  // at least the nearest pair's distance
    std::vector<Candidate> open;
    for (size_t k = 0; k < cand.size(); ++k) {
        const Candidate& c = cand[k];
        if (c.gap > upper) {
            counts_.boxed += static_cast<long>(cand.size() - k);
            break;
        }
        const Bounds s = scan(F, c.a, c.b) ? support_bounds(F, c.a, c.b, r1, r2) : Bounds{};
        // Below 0 some pair meets: then the pairs apart (lower bound > 0) are not needed.
        upper = std::min(upper, std::max(s.upper, 0.0));
        open.push_back({std::max(c.gap, std::isnan(s.lower) ? -INFINITY : s.lower), c.a, c.b});
    }
    std::stable_sort(open.begin(), open.end(), [](const Candidate& x, const Candidate& y) { return x.gap < y.gap; });
    Nearest best;
    for (size_t k = 0; k < open.size(); ++k) {
        const Candidate& c = open[k];
        // Every pair from here on is at least c.gap apart, which is past the best: done.
        if (c.gap > upper) {
            counts_.boxed += static_cast<long>(open.size() - k);
            break;
        }
        PairState st = pair_state(c.a, c.b, rho1, rho2, pose);
        if (st.verdict != Verdict::Separated) return {c.a, c.b, std::move(st)};
        const Q& E = st.hulls.distance.squared;
        if (best.a >= 0) {
            // (√E − R) − (√E' − R') < 0, exactly.
            const Q& E0 = best.state.hulls.distance.squared;
            if (sign_two_sqrts(best.state.R - st.R, Q(1), E, Q(-1), E0) >= 0) continue;
        }
        // √E − R in doubles, bounded above (E and R rounded relatively: within the normal range).
        const double dE = dbl(E), dR = dbl(st.R);
        if (fits(E) && fits(st.R)) {
            const double u = std::sqrt(dE) * (1 + kRel) - dR * (1 - kRel) + kTiny;
            if (!std::isnan(u)) upper = std::min(upper, u);
        }
        best = {c.a, c.b, std::move(st)};
    }
    if (best.a < 0) throw std::logic_error("RoundedParts::nearest: every pair was set aside");
    return best;
}

int RoundedParts::locate(int i, const Q& rho, const Vec3q& x, const Q& abs, bool* near, const Poses& pose) const {
    *near = false;
    int first_near = -1;
    const Frame F = frame(pose);
    const double r = dbl(rho), ad = dbl(abs);
    const double xd[3] = {dbl(x[0]), dbl(x[1]), dbl(x[2])};
    const bool filter = F.safe && fits(rho) && fits(abs) && fits(x[0]) && fits(x[1]) && fits(x[2]);
    for (size_t k = 0; k < parts(i); ++k) {
        // Outside the part's box widened by ρr + abs, by more than the doubles' error: out.
        const auto& B = F.box[i][k];
        const double *s = F.seed[i], *sm = F.seed_mag[i];
        bool out = false;
        for (int a = 0; a < 3 && filter && !out; ++a) {
            const double lo = s[a] + r * (B[a] - s[a]) - r * B[6] - ad,
                         hi = s[a] + r * (B[3 + a] - s[a]) + r * B[6] + ad;
            const double err = kRel * (sm[a] + r * (B[7 + a] + 2 * sm[a] + B[6]) + ad + std::abs(xd[a])) + kTiny;
            out = std::max(lo - xd[a], xd[a] - hi) > err;
        }
        if (out) continue;
        const std::shared_ptr<const RoundedPoints> S =
            i == 0 ? pair(static_cast<int>(k), 0) : pair(0, static_cast<int>(k));
        std::optional<PosedPoints> at;
        if (pose[0] || pose[1]) at.emplace(*S, pose);
        const ExactDistance d = point_to_body(at ? static_cast<const PointSets&>(*at) : *S, i, rho, x);
        const Q m = rho * radius_[i][k];
        if (d.squared <= m * m) return static_cast<int>(k);
        if (first_near < 0 && sgn(abs) > 0 && sign_minus_sqrt(m + abs, Q(1), d.squared) >= 0)
            first_near = static_cast<int>(k);
    }
    *near = first_near >= 0;
    return first_near;
}

std::array<Q, 6> RoundedParts::widened_box(int i, size_t k, const Q& rho, const Poses& pose) const {
    const std::shared_ptr<const RoundedPoints> S = i == 0 ? pair(static_cast<int>(k), 0) : pair(0, static_cast<int>(k));
    std::optional<PosedPoints> at;
    if (pose[0] || pose[1]) at.emplace(*S, pose);
    const PointSets& P = at ? static_cast<const PointSets&>(*at) : *S;
    std::array<Q, 6> b;
    const int n = static_cast<int>(body_[i][k]->pts.size());
    for (int j = 0; j < n; ++j) {
        const Vec3q x = P.point(i, j);
        for (int a = 0; a < 3; ++a) {
            if (j == 0 || x[a] < b[a]) b[a] = x[a];
            if (j == 0 || x[a] > b[3 + a]) b[3 + a] = x[a];
        }
    }
    const Vec3q& s = P.seed(i);
    const Q m = rho * radius_[i][k];
    for (int a = 0; a < 3; ++a) {
        b[a] = s[a] + rho * (b[a] - s[a]) - m;
        b[3 + a] = s[a] + rho * (b[3 + a] - s[a]) + m;
    }
    return b;
}

Q RoundedParts::extent(int i, size_t k, const Vec3q& n, const Q& rho, const Poses& pose) const {
    const std::shared_ptr<const RoundedPoints> S = i == 0 ? pair(static_cast<int>(k), 0) : pair(0, static_cast<int>(k));
    std::optional<PosedPoints> at;
    if (pose[0] || pose[1]) at.emplace(*S, pose);
    const auto e = plane_extents(at ? static_cast<const PointSets&>(*at) : *S, n, rho, rho);
    return i == 0 ? e.first : e.second;
}

// ---- the rules ---------------------------------------------------------------------------------

namespace {
// The squared distance between two boxes lo[3], hi[3] (0 when they meet).
Q box_gap_sq(const std::array<Q, 6>& A, const std::array<Q, 6>& B) {
    Q g = 0;
    for (int a = 0; a < 3; ++a) {
        const Q d = B[a] > A[3 + a] ? Q(B[a] - A[3 + a]) : A[a] > B[3 + a] ? Q(A[a] - B[3 + a]) : Q(0);
        g += d * d;
    }
    return g;
}
bool boxes_apart_exactly(const std::array<Q, 6>& A, const std::array<Q, 6>& B) {
    for (int a = 0; a < 3; ++a)
        if (B[a] > A[3 + a] || A[a] > B[3 + a]) return true;
    return false;
}
// Every part's widened box at (ρ1, ρ2), exact.
std::array<std::vector<std::array<Q, 6>>, 2> all_boxes(const RoundedParts& J, const Q& r1, const Q& r2,
                                                       const RoundedParts::Poses& pose) {
    std::array<std::vector<std::array<Q, 6>>, 2> out;
    for (int i = 0; i < 2; ++i)
        for (size_t k = 0; k < J.parts(i); ++k)
            out[static_cast<size_t>(i)].push_back(J.widened_box(i, k, i ? r2 : r1, pose));
    return out;
}
// A pair's entry in a proof: {"pair": [a, b], "hulls": its hulls' proof}, appended to `list`,
// which may hold at most kMaxExactPartPairs (InputError past it, naming the scene).
void add_pair(Json& list, int a, int b, const RoundedParts::PairState& st, const Q& r1, const Q& r2,
              const std::string& name) {
    if (list.size() >= static_cast<size_t>(kMaxExactPartPairs))
        throw InputError(name + ": a proof would list more than " + std::to_string(kMaxExactPartPairs) +
                         " part pairs whose widened boxes meet (the limit for one judgement)");
    list.push_back(Json{{"pair", Json::array({a, b})}, {"hulls", rounded_hulls_proof(st.hulls, r1, r2)}});
}
// Is x in object i at ρ: the first part within ρr of it, else the first within abs more (`near`),
// else −1 (as RoundedParts::locate), with its proof: {"part": k, "within" or "near": weights}, or
// {"out": [each part's {"out": normal}]}.
int member_proof(const RoundedParts& J, int i, const Q& rho, const Vec3q& x, const Tolerance& tol,
                 const RoundedParts::Poses& pose, bool* near, Json* proof) {
    int first_near = -1;
    Json near_proof, outs = Json::array();
    for (size_t k = 0; k < J.parts(i); ++k) {
        const std::shared_ptr<const RoundedPoints> S =
            i == 0 ? J.pair(static_cast<int>(k), 0) : J.pair(0, static_cast<int>(k));
        std::optional<PosedPoints> at;
        if (pose[0] || pose[1]) at.emplace(*S, pose);
        bool nk = false;
        Json pk;
        const bool in =
            rounded_member(at ? static_cast<const PointSets&>(*at) : *S, i, rho, rho * J.radius(i, k), x, tol, nk, &pk);
        if (in && !nk) {
            pk["part"] = static_cast<int>(k);
            *proof = std::move(pk);
            *near = false;
            return static_cast<int>(k);
        }
        if (in && first_near < 0) {
            first_near = static_cast<int>(k);
            near_proof = std::move(pk);
            near_proof["part"] = first_near;
        }
        if (!in) outs.push_back(std::move(pk));
    }
    *near = first_near >= 0;
    *proof = first_near >= 0 ? std::move(near_proof) : Json{{"out", std::move(outs)}};
    return first_near;
}
}  // namespace

RoundedPartsRules::RoundedPartsRules(std::shared_ptr<RoundedParts> parts, const Tolerance& tolerance)
    : ClaimRules(tolerance), parts_(std::move(parts)) {
    parts_->start_run();
}
RoundedPartsRules::~RoundedPartsRules() { parts_->end_run(); }

std::string RoundedPartsRules::refusal(ClaimType t) const {
    switch (t) {
    case ClaimType::Verdict:
    case ClaimType::Plane:
    case ClaimType::Witness:
    case ClaimType::Distance:
    case ClaimType::Depth:
    case ClaimType::SignedDistance: return {};
    default:
        return "on objects made of parts with radii certify-fp takes verdict, separating_plane, witness_point, "
               "distance, and penetration_depth and signed_distance of one part pair";
    }
}

std::optional<std::array<int, 2>> RoundedPartsRules::part_pair(const std::optional<std::array<int, 2>>& given,
                                                               const std::string& where) const {
    if (!given)
        throw InputError(where +
                         ".parts: missing: a penetration depth or a signed distance on objects made of parts is a "
                         "contact of one part pair (parts = {part of P1, part of P2})");
    const size_t counts[2] = {parts_->parts(0), parts_->parts(1)};
    check_part_pair(*given, counts, where);
    return given;
}

std::string RoundedPartsRules::certificate(Json entries) const {
    return compound_judgements_text(parts_->scene(), tol_.rel, tol_.abs, std::move(entries));
}

Judged RoundedPartsRules::judge(const TypedClaim& c, Proof* proof) {
    Judged g;
    if (proof) proof->claim = exact_claim_json(c);
    if (!c.no_answer.empty()) {
        if (proof) proof->proof = Json{{"no_answer", c.no_answer}};
        return g;
    }
    RoundedParts& J = *parts_;
    J.start_judgement();
    const RoundedParts::Poses& pose = c.pose;
    if (c.type == ClaimType::Depth || c.type == ClaimType::SignedDistance) {
        // One part pair, by the rules of two objects with a radius (at the claim's poses).
        if (!c.parts) throw std::logic_error("RoundedPartsRules: a contact with no part pair");
        const int a = (*c.parts)[0], b = (*c.parts)[1];
        RoundedRules pair(std::make_shared<const ExactScene>(J.pair_scene(a, b)), J.pair(a, b), tol_);
        TypedClaim bare = c;
        bare.parts.reset();
        g = pair.judge(bare, proof);
        if (proof) proof->claim = exact_claim_json(c);
        g.part1 = a;
        g.part2 = b;
        return g;
    }
    switch (c.type) {
    case ClaimType::Verdict: {
        auto& d = g.set<VerdictJudged>();
        const RoundedParts::Decided e = J.verdict(c.rho1, c.rho2, pose);
        d.exact = e.verdict;
        g.part1 = e.a;
        g.part2 = e.b;
        g.right = verdict_matches(c.verdict, d.exact);
        if (!proof) break;
        // Overlapping: the pair that overlaps. Else every pair whose widened boxes meet (the
        // others are apart by them).
        Json pairs = Json::array();
        if (e.verdict == Verdict::Overlapping) {
            add_pair(pairs, e.a, e.b, J.pair_state(e.a, e.b, c.rho1, c.rho2, pose), c.rho1, c.rho2, J.name());
        } else {
            const auto boxes = all_boxes(J, c.rho1, c.rho2, pose);
            for (int a = 0; a < static_cast<int>(J.parts(0)); ++a)
                for (int b = 0; b < static_cast<int>(J.parts(1)); ++b)
                    if (!boxes_apart_exactly(boxes[0][static_cast<size_t>(a)], boxes[1][static_cast<size_t>(b)]))
                        add_pair(pairs, a, b, J.pair_state(a, b, c.rho1, c.rho2, pose), c.rho1, c.rho2, J.name());
        }
        proof->proof = Json{{"verdict", verdict_name(e.verdict)}, {"pairs", std::move(pairs)}};
        return g;
    }
    case ClaimType::Witness: {
        auto& d = g.set<WitnessJudged>();
        Json p1, p2;
        d.in_part1 = proof ? member_proof(J, 0, c.rho1, c.point, tol_, pose, &d.near1, &p1)
                           : J.locate(0, c.rho1, c.point, tol_.abs, &d.near1, pose);
        d.in_part2 = proof ? member_proof(J, 1, c.rho2, c.point, tol_, pose, &d.near2, &p2)
                           : J.locate(1, c.rho2, c.point, tol_.abs, &d.near2, pose);
        if (proof) proof->proof = Json{{"P1", std::move(p1)}, {"P2", std::move(p2)}};
        d.in1 = d.in_part1 >= 0;
        d.in2 = d.in_part2 >= 0;
        if (c.with_verdict) d.exact_verdict = J.verdict(c.rho1, c.rho2, pose).verdict;
        g.right = d.in1 && d.in2;
        return g;
    }
    case ClaimType::Distance: {
        const RoundedParts::Nearest n = J.nearest(c.rho1, c.rho2, pose);
        Json closest_proof;
        const ExactDistance& e = n.state.hulls.distance;
        const Q& R = n.state.R;
        auto& d = g.set<DistanceJudged>();
        g.part1 = n.a;
        g.part2 = n.b;
        g.radii = std::array<Q, 2>{c.rho1 * J.radius(0, static_cast<size_t>(n.a)),
                                   c.rho2 * J.radius(1, static_cast<size_t>(n.b))};
        // The hulls of a pair that meets may overlap (no distance): the objects meet, distance 0.
        const bool apart = n.state.verdict == Verdict::Separated;
        d.exact_squared = apart ? e.squared : Q(0);
        d.exact_p1 = e.p1;
        d.exact_p2 = e.p2;
        if (!apart) g.radii = std::array<Q, 2>{Q(0), Q(0)};
        // A length: at LEN = 0 one below 0 is wrong (Tolerance::close_sq).
        d.value_right =
            (sgn(tol_.abs) > 0 || sgn(c.value) >= 0) &&
            (apart ? tol_.close_value(c.value, 1, e.squared, Q(-R)) : tol_.close_value(c.value, 0, Q(0), Q(0)));
        g.right = d.value_right;
        if (c.closest) {
            const auto& [p, q] = *c.closest;
            const Vec3q pq = sub(q, p);
            d.closest_squared = pq[0] * pq[0] + pq[1] * pq[1] + pq[2] * pq[2];
            Json p1, p2;
            d.in_part1 = proof ? member_proof(J, 0, c.rho1, p, tol_, pose, &d.near1, &p1)
                               : J.locate(0, c.rho1, p, tol_.abs, &d.near1, pose);
            d.in_part2 = proof ? member_proof(J, 1, c.rho2, q, tol_, pose, &d.near2, &p2)
                               : J.locate(1, c.rho2, q, tol_.abs, &d.near2, pose);
            if (proof) closest_proof = Json{{"P1", std::move(p1)}, {"P2", std::move(p2)}};
            d.in1 = d.in_part1 >= 0;
            d.in2 = d.in_part2 >= 0;
            // |q − p| ≤ (1 + rel)·(√E − R) + 2·abs apart; ≤ 2·abs when the objects meet.
            const Q k = 1 + tol_.rel;
            const bool near_enough =
                apart ? sign_two_sqrts(k * R - 2 * tol_.abs, Q(1), d.closest_squared, Q(-k), e.squared) <= 0
                      : d.closest_squared <= 4 * tol_.abs * tol_.abs;
            d.closest_right = d.in1 && d.in2 && near_enough;
            g.right = g.right && *d.closest_right;
        }
        if (!proof) break;
        // The nearest pair's hulls; apart, every other pair whose widened boxes lie nearer than
        // the distance (√G < √E − R), each with its hulls (the others are as far by their boxes).
        Json pr{{"pair", Json::array({n.a, n.b})}, {"hulls", rounded_hulls_proof(n.state.hulls, c.rho1, c.rho2)}};
        if (apart) {
            Json others = Json::array();
            const auto boxes = all_boxes(J, c.rho1, c.rho2, pose);
            for (int a = 0; a < static_cast<int>(J.parts(0)); ++a)
                for (int b = 0; b < static_cast<int>(J.parts(1)); ++b) {
                    if (a == n.a && b == n.b) continue;
                    const Q G = box_gap_sq(boxes[0][static_cast<size_t>(a)], boxes[1][static_cast<size_t>(b)]);
                    if (sign_two_sqrts(R, Q(1), G, Q(-1), e.squared) >= 0) continue;
                    add_pair(others, a, b, J.pair_state(a, b, c.rho1, c.rho2, pose), c.rho1, c.rho2, J.name());
                }
            pr["others"] = std::move(others);
        }
        if (c.closest) pr["closest"] = std::move(closest_proof);
        proof->proof = std::move(pr);
        return g;
    }
    case ClaimType::Plane: {
        // Right when it is right for every pair: the part of P1 reaching farthest along n (its
        // hull's extent plus ρr·|n|, compared exactly) against the part of P2 starting nearest.
        auto& d = g.set<PlaneJudged>();
        const Vec3q& n = c.normal;
        const Q N = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        Q m1, m2;
        for (int i = 0; i < 2; ++i)
            for (size_t k = 0; k < J.parts(i); ++k) {
                const Q& rho = i == 0 ? c.rho1 : c.rho2;
                const Q e = J.extent(i, k, n, rho, pose), m = rho * J.radius(i, k);
                Q& best_e = i == 0 ? d.c1 : d.c2;
                Q& best_m = i == 0 ? m1 : m2;
                // P1: e + m√N beyond best_e + best_m√N; P2: e − m√N below best_e − best_m√N.
                const bool better = k == 0 || (i == 0 ? sign_minus_sqrt(e - best_e, best_m - m, N) > 0
                                                      : sign_minus_sqrt(best_e - e, best_m - m, N) > 0);
                if (better) best_e = e, best_m = m;
            }
        g.radii = std::array<Q, 2>{m1, m2};
        g.right = rounded_plane_right(tol_, d.c1, d.c2, m1, m2, n, c.offset);
        break;
    }
    default: throw std::logic_error("RoundedPartsRules: a claim of the curve");
    }
    if (proof) proof->proof = Json::object();
    return g;
}

}  // namespace scalecert::internal
