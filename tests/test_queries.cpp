// Random exact scenes: the curve query, the direct query and the brute-force classifier agree, at
// random points and exactly on, just above and just below the curve; certificates hold.
#include <boost/test/unit_test.hpp>

#include "support.hpp"

using namespace scalecert::internal;

namespace {
// Checks a query certificate by direct evaluation on the scaled vertices.
void check_certificate(const Model& m, const QueryAnswer& r) {
    const ExactScene& sc = m.scene;
    if (r.plane) {
        const Vec3q n = to_q(m.lines[r.plane->line].normal);
        for (const Vec3q& v : sc.P[0].points) BOOST_TEST(dot(n, test::scaled(v, m.s[0], r.rho1)) <= r.plane->c1);
        for (const Vec3q& w : sc.P[1].points) BOOST_TEST(dot(n, test::scaled(w, m.s[1], r.rho2)) >= r.plane->c2);
        BOOST_TEST((r.verdict == Verdict::Separated ? r.plane->c1 < r.plane->c2 : r.plane->c1 == r.plane->c2));
    }
    if (r.witness) {
        const Witness& w = *r.witness;
        Vec3q x{Q(0), Q(0), Q(0)}, y{Q(0), Q(0), Q(0)};
        Q s1 = 0, s2 = 0;
        for (const auto& [i, l] : w.w1) {
            BOOST_TEST(sgn(l) > 0);
            s1 += l;
            Vec3q p = test::scaled(sc.P[0].points[i], m.s[0], w.rho1);
            for (int k = 0; k < 3; ++k) x[k] += l * p[k];
        }
        for (const auto& [j, u] : w.w2) {
            BOOST_TEST(sgn(u) > 0);
            s2 += u;
            Vec3q p = test::scaled(sc.P[1].points[j], m.s[1], w.rho2);
            for (int k = 0; k < 3; ++k) y[k] += u * p[k];
        }
        BOOST_TEST(s1 == 1);
        BOOST_TEST(s2 == 1);
        BOOST_TEST((x == w.point && y == w.point));
        if (r.verdict == Verdict::Overlapping)
            BOOST_TEST((w.rho1 < r.rho1 && w.rho2 < r.rho2));
        else
            BOOST_TEST((w.rho1 == r.rho1 && w.rho2 == r.rho2));
    }
}
}  // namespace

BOOST_AUTO_TEST_CASE(random_points_agree_with_brute_force) {
    std::mt19937 g(5);
    std::uniform_int_distribution<int> num(1, 400);
    int counts[3] = {0, 0, 0};
    for (int t = 0; t < 40; ++t) {
        ExactScene sc = test::random_scene(g, 4 + t % 6, 4 + (t / 6) % 6);
        HullModel m = build_model(sc);
        TouchingCurve c = build_curve(m);
        test::Brute brute(sc);
        auto probe = [&](const Q& r1, const Q& r2) {
            int b = brute.classify(sc, r1, r2);
            QueryAnswer r = query(m, c, r1, r2);
            BOOST_TEST(test::verdict_sign(r.verdict) == b);
            BOOST_TEST(test::verdict_sign(query_direct(m, r1, r2)) == b);
            check_certificate(m, r);
            ++counts[b + 1];
        };
        for (int k = 0; k < 15; ++k) probe(test::qc(num(g), 100), test::qc(num(g), 100));
        // On the curve and 2^-k above and below it: touching exactly where the curve says.
        for (int k = 0; k < 6; ++k) {
            Q r1 = test::qc(num(g), 100);
            Q f = c.env.value(m.lines, r1);
            if (sgn(f) <= 0) continue;
            Q eps = f / Q(Z(1) << (4 * k + 1));
            probe(r1, f);
            probe(r1, f + eps);
            probe(r1, f - eps);
        }
        for (const CurveSwitch& s : c.switches)
            if (sgn(s.rho2) > 0) probe(s.rho1, s.rho2);
    }
    BOOST_TEST_MESSAGE("overlapping " << counts[0] << ", touching " << counts[1] << ", separated " << counts[2]);
    BOOST_TEST(counts[0] > 100);
    BOOST_TEST(counts[1] > 100);
    BOOST_TEST(counts[2] > 100);
}

BOOST_AUTO_TEST_CASE(partition_regions_agree_with_brute_force) {
    // Every vertex of the overlap polygon overlaps or touches; every vertex of a separated polygon
    // not on the curve is separated, and a point strictly inside each separated polygon too.
    std::mt19937 g(17);
    for (int t = 0; t < 15; ++t) {
        ExactScene sc = test::random_scene(g, 5 + t % 5, 5);
        sc.lo[0] = Q(1, 2);
        sc.hi[0] = Q(3);
        sc.lo[1] = Q(1, 3);
        sc.hi[1] = Q(5, 2);
        HullModel m = build_model(sc);
        TouchingCurve c = build_curve(m);
        Partition p = build_partition(m, c);
        test::Brute brute(sc);
        BOOST_TEST(p.overlap_witnesses.size() == p.overlap.size());
        for (const Pt2& v : p.overlap) BOOST_TEST(brute.classify(sc, v[0], v[1]) <= 0);
        for (const SeparatedRegion& r : p.separated) {
            Pt2 centre{Q(0), Q(0)};
            for (const Pt2& v : r.verts) centre[0] += v[0], centre[1] += v[1];
            centre[0] /= Q(static_cast<long>(r.verts.size()));
            centre[1] /= Q(static_cast<long>(r.verts.size()));
            BOOST_TEST(brute.classify(sc, centre[0], centre[1]) == 1);
        }
    }
}

BOOST_AUTO_TEST_CASE(a_face_with_a_143_digit_normal_is_not_dropped) {
    // Found by the `scene` fuzz target: one vertex with a 117-digit denominator gives a face of
    // P1 a 143-digit normal. The dominance pre-filter approximated its line with doubles whose
    // products overflowed, read the intercept as 0, and dropped a line of the curve: the engine's
    // curve lay below the true one. Brute force (no hull, no pre-filter) is the oracle here, on
    // and 2^-30 around the curve at every switch point and mid-piece.
    const ExactScene sc = load_scene(std::string(SCALECERT_SOURCE_DIR) + "/tests/data/fuzz_huge_denominator_face.json");
    const HullModel m = build_model(sc);
    const TouchingCurve c = build_curve(m);
    const test::Brute brute(sc);
    int checked = 0;
    for (const CurvePiece& p : c.pieces)
        for (const Q& x : {p.from, Q((p.from + p.to) / 2), p.to}) {
            const Q y = c.env.value(m.lines, x);
            if (sgn(y) <= 0) continue;
            BOOST_TEST(brute.classify(sc, x, y) == 0, "on the curve at rho1 = " << x);
            BOOST_TEST(brute.classify(sc, x, y * Q(1073741823, 1073741824)) == 1);
            BOOST_TEST(brute.classify(sc, x, y * Q(1073741825, 1073741824)) == -1);
            ++checked;
        }
    BOOST_TEST(checked >= 3);
}
