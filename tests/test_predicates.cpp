// Each filtered predicate of predicates.hpp at its bound: inputs built by hand so that the
// filter's value sits just outside its bound (the filter decides) and just inside it (the exact
// stage decides), the answer checked against exact arithmetic done here, and the deciding stage
// read from the predicate's statistics.
#include <boost/test/unit_test.hpp>

#include "certify/classify.hpp"
#include "curve/contact_lines.hpp"
#include "geometry/gauss_map.hpp"
#include "io/scene.hpp"
#include "numeric/predicates.hpp"

#include <cmath>
#include <random>

using namespace scalecert::internal;
using filter::Predicate;
using filter::PredicateStats;

namespace {
double p2(int e) { return std::ldexp(1.0, e); }
Z dot3(const Vec3z& a, const Vec3z& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3z zv(std::int64_t a, std::int64_t b, std::int64_t c) {
    return {Z(static_cast<long>(a)), Z(static_cast<long>(b)), Z(static_cast<long>(c))};
}
D3 dv(const Vec3z& v) { return {v[0].get_d(), v[1].get_d(), v[2].get_d()}; }
int sign_of_z(const Z& z) { return sgn(z); }
}  // namespace

// ---- 1. support_cmp ----------------------------------------------------------------------------

// sign of n·w − n·v through the predicate, with the exact stage done in GMP here.
int support_sign(const Vec3z& n, const Vec3z& w, const Vec3z& v, PredicateStats& st) {
    const D3 nd = dv(n), wd = dv(w), vd = dv(v);
    return filter::support_cmp(
        filter::support_approx(nd.data(), wd.data()), filter::support_approx(nd.data(), vd.data()),
        [&] { return sign_of_z(dot3(n, w) - dot3(n, v)); }, st);
}

BOOST_AUTO_TEST_CASE(support_cmp_at_its_bound) {
    // n = e_x, values V + k and V with V = 2^50: tol = 1e-14·(2V + k) ≈ 22.5.
    const std::int64_t V = std::int64_t(1) << 50;
    const Vec3z n = zv(1, 0, 0), v = zv(V, 0, 0);
    for (std::int64_t k : {23, -23, 22, -22, 1, 0}) {
        PredicateStats st;
        const int s = support_sign(n, zv(V + k, 0, 0), v, st);
        BOOST_TEST(s == (k > 0) - (k < 0));       // the exact answer
        const bool filtered = std::abs(k) >= 23;  // just outside the bound
        BOOST_TEST(st[Predicate::SupportCmp].filtered == (filtered ? 1u : 0u));
        BOOST_TEST(st[Predicate::SupportCmp].exact == (filtered ? 0u : 1u));
    }
    // One unit at 2^53: n·w = 2^53 + 1 rounds to 2^53 in doubles, the difference is 0 there,
    // and only the exact stage sees +1.
    PredicateStats st;
    const std::int64_t T = std::int64_t(1) << 53;
    BOOST_TEST(support_sign(zv(1, 1, 0), zv(T, 1, 0), zv(T, 0, 0), st) == 1);
    BOOST_TEST(support_sign(zv(1, 1, 0), zv(T, 0, 0), zv(T, 1, 0), st) == -1);
    BOOST_TEST(st[Predicate::SupportCmp].exact == 2u);
    BOOST_TEST(st[Predicate::SupportCmp].filtered == 0u);
    // Beyond the double range: not finite, never filtered.
    Vec3z huge{Z(1) << 1100, Z(0), Z(0)};
    Vec3z huge1{(Z(1) << 1100) + 1, Z(0), Z(0)};
    PredicateStats st2;
    BOOST_TEST(support_sign(zv(1, 0, 0), huge1, huge, st2) == 1);
    BOOST_TEST(st2[Predicate::SupportCmp].exact == 1u);
}

// ---- 2. arc_side -------------------------------------------------------------------------------

template <class V>
void arc_side_cases() {
    // u = e_x, x = e_y: (u × x)·p = p_z and (x × u)·p = −p_z; bound = 1e-10·|p|.
    const V u{1, 0, 0}, x{0, 1, 0};
    struct Case {
        std::int64_t py, pz;
        bool filtered;
    };
    // |p| = 2^33: bound 0.86 < 1 (filtered); |p| = 2^34: bound 1.72 > 1 (exact); p_z = 0: exact 0.
    for (const Case& c : {Case{std::int64_t(1) << 33, 1, true}, Case{std::int64_t(1) << 33, -1, true},
                          Case{std::int64_t(1) << 34, 1, false}, Case{std::int64_t(1) << 34, -1, false},
                          Case{std::int64_t(1) << 34, 0, false}, Case{1, 0, false}}) {
        const V p{0, c.py, c.pz};
        const Vec3z uz = zv(1, 0, 0), xz = zv(0, 1, 0), pz = zv(0, c.py, c.pz);
        for (bool x_first : {false, true}) {
            // exact: the determinant here, in GMP
            const Vec3z cr = x_first ? cross(xz, uz) : cross(uz, xz);
            const int expect = sign_of_z(dot3(cr, pz));
            PredicateStats st;
            int calls = 0;
            const int s = filter::arc_side(
                dv(uz), dv(xz), dv(pz), x_first, u,
                [&] {
                    ++calls;
                    return x;
                },
                p, st);
            BOOST_TEST(s == expect);
            BOOST_TEST(st[Predicate::ArcSide].filtered == (c.filtered ? 1u : 0u));
            BOOST_TEST(st[Predicate::ArcSide].exact == (c.filtered ? 0u : 1u));
            BOOST_TEST(calls == (c.filtered ? 0 : 1));  // the exact x is formed only when needed
        }
    }
}

BOOST_AUTO_TEST_CASE(arc_side_at_its_bound) {
    arc_side_cases<Vec3s>();
    arc_side_cases<Vec3z>();
    // Machine integers whose 128-bit products overflow: the GMP stage answers.
    const std::int64_t big = std::int64_t(1) << 61;
    const Vec3s u{big, 1, 0}, x{0, big, 1}, p{big, big, big};
    const Vec3z uz = zv(big, 1, 0), xz = zv(0, big, 1), pz = zv(big, big, big);
    PredicateStats st;
    const int s = filter::arc_side(
        dv(uz), dv(xz), dv(pz), false, u, [&] { return x; }, p, st);
    BOOST_TEST(s == sign_of_z(dot3(cross(uz, xz), pz)));
}

// ---- 3. dominated lines ------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(dominated_line_at_its_margin) {
    // Line 1: y = −x + 1. Line 0 above it by 3e-12 in slope and intercept: margins 1e-12 on each
    // value are cleared (dropped); by 1.5e-12 in the intercept they are not (kept: one-sided).
    BOOST_TEST(undominated({-1 + 3e-12, -1.0}, {1 + 3e-12, 1.0}) == std::vector<size_t>({0}));
    BOOST_TEST(undominated({-1 + 3e-12, -1.0}, {1 + 1.5e-12, 1.0}) == std::vector<size_t>({0, 1}));
    BOOST_TEST(undominated({-1 + 1.5e-12, -1.0}, {1 + 3e-12, 1.0}) == std::vector<size_t>({0, 1}));
    // Equal lines: neither certainly below the other.
    BOOST_TEST(undominated({-1.0, -1.0}, {1.0, 1.0}) == std::vector<size_t>({0, 1}));
    BOOST_TEST(filter::dominated_lower(1.0) < 1.0);
    BOOST_TEST(filter::dominated_upper(-1.0) > -1.0);
}

// ---- 4. queries ----------------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(query_filters_at_their_bounds) {
    // y = −ρ1 + 2^20 at ρ1 = 1: f = 2^20 − 1, err = 1e-12·(1 + 2^20) ≈ 1.05e-6.
    const double a = -1, b = p2(20), f = b - 1;
    BOOST_TEST(filter::bounds::curve_side_filter(a, b, 1, f - 2e-6) == 1);                // outside: separated
    BOOST_TEST(filter::bounds::curve_side_filter(a, b, 1, f + 2e-6) == -1);               // outside: overlapping
    BOOST_TEST(filter::bounds::curve_side_filter(a, b, 1, f - 0.5e-6) == 0);              // inside: exact stage
    BOOST_TEST(filter::bounds::curve_side_filter(a, b, 1, f) == 0);                       // on the line
    BOOST_TEST(filter::bounds::curve_side_filter(a, b, 1, std::nextafter(f, 0.0)) == 0);  // one ulp below
    // The breakpoint: within 1e-12·ρ1 of it the piece is not certain.
    BOOST_TEST(!filter::bounds::near_breakpoint(1.0, 1 + 2e-12, true));
    BOOST_TEST(filter::bounds::near_breakpoint(1.0, 1 + p2(-45), true));
    BOOST_TEST(filter::bounds::near_breakpoint(1.0, 1 - p2(-45), false));
    BOOST_TEST(filter::bounds::near_breakpoint(1.0, 1.0, false));
    // n·d − ρ1·h1 − ρ2·h2 with nd = 2^20, h1 = h2 = 1, ρ1 = 1: err ≈ 2.1e-6.
    BOOST_TEST(filter::bounds::lines_gap_filter(b, 1, 1, 1, f - p2(-16)) == 1);
    BOOST_TEST(filter::bounds::lines_gap_filter(b, 1, 1, 1, f + p2(-16)) == -1);
    BOOST_TEST(filter::bounds::lines_gap_filter(b, 1, 1, 1, f) == 0);
    BOOST_TEST(filter::bounds::lines_gap_filter(b, 1, 1, 1, std::nextafter(f, 0.0)) == 0);
    BOOST_TEST(filter::bounds::lines_gap_filter(b, 1, 1, 1, f - 1e-6) == 0);
    BOOST_TEST(filter::bounds::lines_gap_filter(INFINITY, INFINITY, 1, 1, 1) == 0);  // not a number: never decided
    // Underflow: tiny values are never decided on relative bounds alone.
    BOOST_TEST(filter::bounds::lines_gap_filter(1e-310, 1e-310, 1e-310, 1, 1e-320) == 0);
}

// The wrappers: the filter's sign where it is certain, else the exact stage's, each counted once;
// the exact stage runs only where the filter cannot tell. Values by hand: y = ρ1 + 1 and the line
// with n·d = 3, h1 = h2 = 1 (gap 3 − ρ1 − ρ2).
BOOST_AUTO_TEST_CASE(each_filtered_predicate_runs_its_exact_stage_only_when_unsure_and_counts_both) {
    using filter::Predicate;
    filter::PredicateStats st;
    int exact_calls = 0;
    auto exact = [&](int s) {
        return [&exact_calls, s] {
            ++exact_calls;
            return s;
        };
    };
    BOOST_TEST(filter::curve_side(1, 1, 1, 1, true, exact(7), st) == 1);   // 1 below 2: separated
    BOOST_TEST(filter::curve_side(1, 1, 1, 3, true, exact(7), st) == -1);  // 3 above 2: overlapping
    BOOST_TEST(exact_calls == 0);
    BOOST_TEST(filter::curve_side(1, 1, 1, 2, true, exact(0), st) == 0);   // on the line: the exact stage
    BOOST_TEST(filter::curve_side(1, 1, 1, 1, false, exact(5), st) == 5);  // not trusted: the exact stage
    BOOST_TEST(exact_calls == 2);
    BOOST_TEST(st[Predicate::CurveSide].filtered == 2u);
    BOOST_TEST(st[Predicate::CurveSide].exact == 2u);
    const std::vector<double> nd{3}, h1{1}, h2{1};
    exact_calls = 0;
    BOOST_TEST(filter::lines_side(nd, h1, h2, 1, 1, exact(7), st) == 1);      // gap 1
    BOOST_TEST(filter::lines_side(nd, h1, h2, 2, 2, exact(7), st) == -1);     // gap −1
    BOOST_TEST(filter::lines_side(nd, h1, h2, 1.5, 1.5, exact(0), st) == 0);  // gap 0: exact
    BOOST_TEST(exact_calls == 1);
    BOOST_TEST(st[Predicate::LinesGap].filtered == 2u);
    BOOST_TEST(st[Predicate::LinesGap].exact == 1u);
    // 2x + 3y − 5 at (1, 1) is 0: exact; at (2, 1) it is 2.
    exact_calls = 0;
    BOOST_TEST(filter::half_plane_side(2, 3, 5, 2, 1, exact(7), st) == 1);
    BOOST_TEST(filter::half_plane_side(2, 3, 5, 1, 1, exact(0), st) == 0);
    BOOST_TEST(exact_calls == 1);
    BOOST_TEST(st[Predicate::HalfPlaneSide].filtered == 1u);
    BOOST_TEST(st[Predicate::HalfPlaneSide].exact == 1u);
}

BOOST_AUTO_TEST_CASE(curve_query_on_the_curve_and_one_ulp_away) {
    HullModel m =
        build_model(load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/fig5_vf_ve_ee.json"));
    TouchingCurve c = build_curve(m);
    for (double r1 : {0.9, 1.0, 1.25, 1.7, 2.3}) {
        const Q y = c.env.value(m.lines, exact_from_double(r1));
        const double yd = to_double_rn(y);
        for (double r2 : {yd, std::nextafter(yd, 0.0), std::nextafter(yd, 10.0)}) {
            FastCurve fc(m, c);
            const Verdict v = fc.classify(r1, r2);
            // exact: r2 against the envelope's exact value
            const int s = cmp(exact_from_double(r2), y);
            BOOST_TEST((v == (s < 0 ? Verdict::Separated : s > 0 ? Verdict::Overlapping : Verdict::Touching)));
            BOOST_TEST(fc.stats[Predicate::CurveSide].exact == 1u);  // one ulp is inside the bound
            BOOST_TEST(fc.stats[Predicate::CurveSide].filtered == 0u);
        }
    }
}

// ---- 5. GJK's certificates ---------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(quick_certificates_at_their_bounds) {
    BOOST_TEST(filter::bounds::quick_gap_certified(1.1e-14, 1.0));
    BOOST_TEST(!filter::bounds::quick_gap_certified(0.9e-14, 1.0));
    BOOST_TEST(!filter::bounds::quick_gap_certified(1e-300, 1e-300));  // magnitudes below kQuickTiny
    BOOST_TEST(!filter::bounds::quick_gap_certified(NAN, 1.0));
    BOOST_TEST(filter::bounds::quick_cofactor_sign(1.1e-13, 1.0) == 1);
    BOOST_TEST(filter::bounds::quick_cofactor_sign(-1.1e-13, 1.0) == -1);
    BOOST_TEST(filter::bounds::quick_cofactor_sign(0.9e-13, 1.0) == 0);
    BOOST_TEST(filter::bounds::quick_cofactor_sign(0.0, 1.0) == 0);
    BOOST_TEST(filter::bounds::quick_cofactor_sign(1.0, INFINITY) == 0);
    BOOST_TEST(filter::bounds::quick_cofactor_sign(1e-260, 1e-260) == 0);
}

// ---- 6. Gauss-map candidate boxes ----------------------------------------------------------------

BOOST_AUTO_TEST_CASE(arc_candidates_at_the_padding) {
    // A: a quarter of the equator (box z in [−pad, pad]). B: from (1, 0, t) to (0, 1, t), whose
    // lowest z is at its ends, t/√(1 + t²): the boxes meet iff that is ≤ 2·pad.
    const double pad = filter::kArcBoxPad;
    const std::vector<Arc> A{{{1, 0, 0}, {0, 1, 0}}};
    auto pairs = [&](double t) { return arc_candidates(A, {Arc{{1, 0, t}, {0, 1, t}}}).size(); };
    BOOST_TEST(pairs(1.9 * pad) == 1u);
    BOOST_TEST(pairs(2.1 * pad) == 0u);
    // Arcs that cross (at (1,1,0)/√2) are always candidates, and so are arcs sharing an end.
    BOOST_TEST(arc_candidates(A, {Arc{{1, 1, -1}, {1, 1, 1}}}).size() == 1u);
    BOOST_TEST(arc_candidates(A, {Arc{{0, 1, 0}, {0, 0, 1}}}).size() == 1u);
    // A box is the whole sphere for a numerically degenerate arc.
    BOOST_TEST(arc_candidates(A, {Arc{{0, 0, 1}, {0, 0, 1}}}).size() == 1u);
    // And for an arc near a half turn, from (1, 0, 0) to (−1, δ, 0): |a×b| ≈ δ. Below
    // kArcIllConditioned (δ = 1e-7) it is a candidate with an arc at the north pole; above it
    // (δ = 1e-3, its plane known to 1e-13) it is not: its box stays within the padding of z = 0.
    const std::vector<Arc> pole{{{0, 0, 1}, {0, 0.1, 1}}};
    BOOST_TEST(arc_candidates({Arc{{1, 0, 0}, {-1, 1e-7, 0}}}, pole).size() == 1u);
    BOOST_TEST(arc_candidates({Arc{{1, 0, 0}, {-1, 1e-3, 0}}}, pole).size() == 0u);
}

// ---- 7. exact support on a point cloud ---------------------------------------------------------

BOOST_AUTO_TEST_CASE(scan_support_filter_at_its_bound) {
    // B = 2^53 (n = e_x, |x| ≤ 2^53): E = 2^-50·2^53 = 8. Candidates: v ≥ best − 16; a box is
    // excluded when its bound is < best − 32.
    const filter::ScanSupportFilter f(p2(53));
    BOOST_TEST(f.E == 8.0);
    const double best = p2(53);
    BOOST_TEST(f.candidate(best - 16, best));
    BOOST_TEST(!f.candidate(best - 18, best));
    BOOST_TEST(!f.box_excluded(best - 32, best));
    BOOST_TEST(f.box_excluded(best - 34, best));
    // Soundness against GMP: a true maximiser is always a candidate, for integer points up to 2^53
    // and normals of any size (their doubles rounded once), even where doubles tie or misorder.
    std::mt19937_64 g(7);
    std::uniform_int_distribution<std::int64_t> coord(-(std::int64_t(1) << 53), std::int64_t(1) << 53), small(-3, 3);
    for (int t = 0; t < 2000; ++t) {
        Vec3z n{Z(static_cast<long>(coord(g))) * Z(static_cast<long>(coord(g))) + 1, Z(static_cast<long>(coord(g))),
                Z(static_cast<long>(small(g)))};
        std::vector<std::array<std::int64_t, 3>> pts;
        const std::array<std::int64_t, 3> base{coord(g) / 2, coord(g) / 2, coord(g) / 2};
        for (int k = 0; k < 8; ++k) pts.push_back({base[0] + small(g), base[1] + small(g), base[2] + small(g)});
        const D3 nd = dv(n);
        double mx[3] = {0, 0, 0};
        for (const auto& x : pts)
            for (int c = 0; c < 3; ++c) mx[c] = std::max(mx[c], std::fabs(static_cast<double>(x[c])));
        const filter::ScanSupportFilter sf(std::fabs(nd[0]) * mx[0] + std::fabs(nd[1]) * mx[1] +
                                           std::fabs(nd[2]) * mx[2]);
        std::vector<double> v;
        double top = -INFINITY;
        Z best_exact;
        for (size_t k = 0; k < pts.size(); ++k) {
            const auto& x = pts[k];
            v.push_back(nd[0] * static_cast<double>(x[0]) + nd[1] * static_cast<double>(x[1]) +
                        nd[2] * static_cast<double>(x[2]));
            top = std::max(top, v.back());
            const Z e = dot3(n, zv(x[0], x[1], x[2]));
            if (k == 0 || e > best_exact) best_exact = e;
        }
        for (size_t k = 0; k < pts.size(); ++k)
            if (dot3(n, zv(pts[k][0], pts[k][1], pts[k][2])) == best_exact) BOOST_TEST(sf.candidate(v[k], top));
    }
}

// 8. A scaling pair against a part pair's half-plane: at the bound, on either side of a line with
// thirds (not doubles) for coefficients, exactly on it, and with inputs the filter must not read.
BOOST_AUTO_TEST_CASE(half_plane_side_at_its_bound) {
    using filter::region_double;
    using filter::bounds::half_plane_side_filter;
    // 1/3 x + 2/3 y >= 1 at (1 + e, 1): f = e/3, exact sign +1 for e > 0, −1 for e < 0.
    const Q a(1, 3), b(2, 3), c(1);
    for (int k : {10, 30, 40, 45, 48, 52, 60, 80}) {
        for (int sign : {1, -1}) {
            const Q x = Q(1) + Q(sign) / Q(Z(1) << k), y(1);
            const int f = half_plane_side_filter(region_double(a), region_double(b), region_double(c), region_double(x),
                                                 region_double(y));
            const int exact = sgn(Q(a * x + b * y - c));
            BOOST_TEST((f == 0 || f == exact), "k = " << k);
            if (k <= 40) BOOST_TEST(f == exact, "k = " << k);  // 2^-40/3 is far above 1e-14: decided
            if (k >= 48) BOOST_TEST(f == 0, "k = " << k);      // 2^-48/3 < 1e-14: left to the exact stage
        }
    }
    BOOST_TEST(half_plane_side_filter(region_double(a), region_double(b), region_double(c), 1.0, 1.0) ==
               0);  // on the line
    // A nonzero value below the normal range, or beyond the double range, is not a number here.
    BOOST_TEST(std::isnan(region_double(Q(Q(1) / Q(Z(1) << 1060)))));
    BOOST_TEST(std::isnan(region_double(Q(Z(1) << 1100))));
    BOOST_TEST(region_double(Q(0)) == 0.0);
    BOOST_TEST(half_plane_side_filter(std::nan(""), 1, 0, 1, 1) == 0);
}

// 9. A scaled coordinate s + ρ(x − s) enclosed in doubles: around exact values with thirds (not
// doubles), where cancellation leaves the value far below its terms, at zero, near the ends of the
// double range, and with inputs the filter must not read.
BOOST_AUTO_TEST_CASE(scaled_enclosure_holds_the_exact_value) {
    using filter::region_double;
    using filter::scaled_enclosure;
    std::mt19937_64 g(909);
    std::uniform_int_distribution<long> num(-1000000000L, 1000000000L), den(1, 1000000);
    auto enclosed = [&](const Q& s, const Q& rho, const Q& x) {
        const filter::Enclosure e = scaled_enclosure(region_double(s), region_double(rho), region_double(x));
        const Q v = s + rho * (x - s);
        if (std::isnan(e.lo) || std::isnan(e.hi)) return std::isnan(e.lo) && std::isnan(e.hi);
        return Q(e.lo) <= v && v <= Q(e.hi);
    };
    long checked = 0;
    for (int k = 0; k < 20000; ++k) {
        const Q s(num(g), den(g)), x(num(g), den(g)), rho(std::abs(num(g)) + 1, den(g));
        BOOST_TEST(enclosed(s, rho, x));
        // x next to s (the difference cancels), and ρ tiny or huge
        BOOST_TEST(enclosed(s, rho, s + Q(1, 3) / Q(Z(1) << 40)));
        BOOST_TEST(enclosed(s, Q(1, 3) / Q(Z(1) << 500), x));
        BOOST_TEST(enclosed(s, Q(Z(1) << 500) / 3, x));
        checked += 4;
    }
    // Cancellation to exactly 0: s + ρ(x − s) = 0 with s = 1/3, ρ = 1/2, x = −1/3.
    BOOST_TEST(enclosed(Q(1, 3), Q(1, 2), Q(-1, 3)));
    // Tight where the terms are of the value's size: width under 1e-13 relative.
    const filter::Enclosure t =
        scaled_enclosure(region_double(Q(1, 3)), region_double(Q(3, 2)), region_double(Q(7, 3)));
    BOOST_TEST((t.hi - t.lo) < 1e-13 * 10);
    // Beyond the doubles, or below their normal range: no enclosure, the exact ends decide.
    BOOST_TEST(std::isnan(scaled_enclosure(1.0, region_double(Q(Z(1) << 1100)), 2.0).lo));
    BOOST_TEST(std::isnan(scaled_enclosure(region_double(Q(Q(1) / Q(Z(1) << 1060))), 1.0, 1.0).hi));
    BOOST_TEST(std::isnan(scaled_enclosure(1e300, 1e300, -1e300).lo));                            // overflows
    BOOST_TEST(enclosed(Q(1) / Q(Z(1) << 1000), Q(1) / Q(Z(1) << 100), Q(3) / Q(Z(1) << 1000)));  // ρ(x − s) underflows
    BOOST_TEST(checked == 80000);
}

// ---- The statistics ------------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(stats_merge_per_predicate) {
    PredicateStats a, b;
    a.filtered(Predicate::ArcSide, 3);
    a.exact(Predicate::SupportCmp);
    b.filtered(Predicate::ArcSide);
    b.exact(Predicate::ScanSupport, 5);
    a += b;
    BOOST_TEST(a[Predicate::ArcSide].filtered == 4u);
    BOOST_TEST(a[Predicate::SupportCmp].exact == 1u);
    BOOST_TEST(a[Predicate::ScanSupport].exact == 5u);
    BOOST_TEST(a[Predicate::CurveSide].filtered + a[Predicate::CurveSide].exact == 0u);
    BOOST_TEST(std::string(filter::kPredicateNames[static_cast<unsigned>(Predicate::ScanSupport)]) == "scan_support");
}

// 11. A pose's determinant: the filter says "nonsingular" only when det R ≠ 0 exactly, and
// pose_singular (the filter, then integers) agrees with det R computed in rationals here, on
// rotations held in doubles, exactly singular matrices (a row the sum of the other two), matrices
// a hair from singular (an entry moved by one unit in the last place) and entries past the
// filter's range.
BOOST_AUTO_TEST_CASE(pose_determinant_filter_and_exact) {
    using scalecert::internal::Pose;
    std::mt19937_64 g(11);
    std::uniform_real_distribution<double> U(-1, 1);
    auto det = [](const Pose& m) {
        return Q(m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                 m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]));
    };
    int filtered = 0, singular = 0;
    for (int t = 0; t < 3000; ++t) {
        double a[3][3];
        for (auto& row : a)
            for (double& x : row) x = U(g);
        if (t % 3 == 1)  // row 2 = row 0 + row 1, exactly when the sums are exact (a few ulps off otherwise)
            for (int c = 0; c < 3; ++c) a[2][c] = a[0][c] + a[1][c];
        if (t % 3 == 2)
            for (int c = 0; c < 3; ++c) a[2][c] = std::nextafter(a[0][c] + a[1][c], 2.0);
        if (t % 50 == 0) a[1][1] = 1e-300;  // past the filter's range: the integers decide
        Pose m;
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) m[r][c] = Q(a[r][c]);
            m[r][3] = 0;
        }
        const bool exact_singular = sgn(det(m)) == 0;
        if (scalecert::internal::filter::pose_certainly_nonsingular(a)) {
            BOOST_TEST(!exact_singular, t);
            ++filtered;
        }
        BOOST_TEST(scalecert::internal::pose_singular(m) == exact_singular, t);
        singular += exact_singular;
    }
    BOOST_TEST(filtered >= 950);  // of the 980 generic matrices with every entry in range
    BOOST_TEST(singular > 100);
}

BOOST_AUTO_TEST_CASE(posed_boxes_apart_filter_by_hand_and_against_rationals) {
    using scalecert::internal::filter::boxes_certainly_apart;
    using scalecert::internal::filter::posed_box;
    // By hand: [-1, 1]^3 at the identity, and the same box moved 3 along x: their x gap is 1, so
    // they are more than 1/2 apart, and not more than 1 (the gap is exactly 1: the filter is unsure).
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, z[3] = {0, 0, 0}, x3[3] = {3, 0, 0};
    const double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    const auto a = posed_box(I, z, lo, hi), b = posed_box(I, x3, lo, hi);
    BOOST_TEST(boxes_certainly_apart(a, b, 0.5));
    BOOST_TEST(boxes_certainly_apart(b, a, 0.5));
    BOOST_TEST(!boxes_certainly_apart(a, b, 1.0));
    // Turned a quarter about z (x -> y): the box is the same set; along y the two overlap.
    const double Rz[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
    BOOST_TEST(boxes_certainly_apart(posed_box(Rz, z, lo, hi), b, 0.5));
    // An entry out of the filter's range (a subnormal): unsure, never "apart".
    const double tiny[3] = {0x1p-1060, 0, 0};
    BOOST_TEST(!posed_box(I, tiny, lo, hi).ok);
    BOOST_TEST(!boxes_certainly_apart(posed_box(I, tiny, lo, hi), b, 0.5));
    // Against the exact world boxes in rationals: random boxes at random (non-orthogonal) poses of
    // doubles, gaps near the margin. "Apart" is only ever said when the exact gap along some axis
    // exceeds m.
    std::mt19937_64 g(12);
    std::uniform_real_distribution<double> u(-1, 1);
    int apart = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        double M[2][9], t[2][3], l[2][3], h[2][3];
        for (int i = 0; i < 2; ++i) {
            for (double& v : M[i]) v = u(g);
            for (int k = 0; k < 3; ++k) {
                t[i][k] = 4 * u(g);
                l[i][k] = -std::fabs(u(g)) - 0x1p-20;
                h[i][k] = std::fabs(u(g)) + 0x1p-20;
            }
        }
        // The exact ends of each world box, and the exact largest gap over the axes.
        Q U[2][3], L[2][3];
        for (int i = 0; i < 2; ++i)
            for (int r = 0; r < 3; ++r) {
                U[i][r] = L[i][r] = exact_from_double(t[i][r]);
                for (int c = 0; c < 3; ++c) {
                    const Q p = exact_from_double(M[i][3 * r + c]) * exact_from_double(l[i][c]),
                            q = exact_from_double(M[i][3 * r + c]) * exact_from_double(h[i][c]);
                    U[i][r] += p > q ? p : q;
                    L[i][r] += p < q ? p : q;
                }
            }
        Q gap = -1000;
        for (int r = 0; r < 3; ++r) {
            if (L[1][r] - U[0][r] > gap) gap = L[1][r] - U[0][r];
            if (L[0][r] - U[1][r] > gap) gap = L[0][r] - U[1][r];
        }
        // The margin: the exact gap rounded to a double, and nudged by an ulp either way.
        double m = std::max(0.0, gap.get_d());
        m = trial % 3 == 0 ? std::nextafter(m, 1e9) : trial % 3 == 1 ? std::nextafter(m, -1e9) : m;
        if (m < 0) m = 0;
        const bool said =
            boxes_certainly_apart(posed_box(M[0], t[0], l[0], h[0]), posed_box(M[1], t[1], l[1], h[1]), m);
        if (said) BOOST_TEST(gap > exact_from_double(m), trial);
        // Far from the margin it decides: a margin half the gap.
        if (gap > 0)
            apart += boxes_certainly_apart(posed_box(M[0], t[0], l[0], h[0]), posed_box(M[1], t[1], l[1], h[1]),
                                           gap.get_d() / 2);
    }
    BOOST_TEST(apart > 100);
}
