// The scan path (scan.hpp) against the hull path: the same curve document, byte for byte apart
// from the engine statistics ("model"), on random scenes of every number kind and on the bundled
// scenes; and the compact OFF reader against the full one.
#include <boost/test/unit_test.hpp>

#include "files.hpp"
#include "io/mesh.hpp"
#include "curve/scan.hpp"
#include "support.hpp"
#include "session/session.hpp"
#include "geometry/measures.hpp"
#include "certify/golden.hpp"
#include "certify/judgements.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace scalecert::internal;
using test::qc;

namespace {

std::string without_model(const Model& m, const TouchingCurve& c) {
    Json j = curve_json(m, c);
    j.erase("model");
    return dump(j);
}

struct Tally {
    int scanned = 0, fell_back = 0;
};

// Compares both paths on a scene; returns whether the scan path decided it.
bool compare(const ExactScene& sc, const std::string& what, Tally& t) {
    const HullModel hm = build_model(sc);
    const std::string hull = without_model(hm, build_curve(hm));
    auto cs = compact_scene(sc);
    if (!cs) {  // beyond machine integers (e.g. doubles with 52-bit fractions): the hull path only
        ++t.fell_back;
        return false;
    }
    const WalkResult r = scan_model(std::make_shared<CompactScene>(std::move(*cs)));
    if (!r.model) {
        ++t.fell_back;
        return false;
    }
    const Model& sm = *r.model;
    const TouchingCurve c = build_curve(sm);
    BOOST_TEST(curve_json(sm, c)["model"]["engine"] == "scan");
    BOOST_TEST(without_model(sm, c) == hull, what);
    ++t.scanned;
    return true;
}

// Points near a sphere of radius R about o, coordinates multiples of 1/den.
std::vector<Vec3q> sphere(std::mt19937& g, int n, double R, long den, const Vec3q& o) {
    std::normal_distribution<double> N(0, 1);
    std::vector<Vec3q> p;
    for (int i = 0; i < n; ++i) {
        double x = N(g), y = N(g), z = N(g), l = std::sqrt(x * x + y * y + z * z);
        p.push_back({o[0] + qc(std::lround(R * den * x / l), den), o[1] + qc(std::lround(R * den * y / l), den),
                     o[2] + qc(std::lround(R * den * z / l), den)});
    }
    return p;
}

ExactScene with_means(ExactScene sc, const Q& lo, const Q& hi) {
    for (int i = 0; i < 2; ++i) {
        sc.lo[i] = lo;
        sc.hi[i] = hi;
    }
    finish_scene(sc, "test");
    return sc;
}

}  // namespace

// Near-spheres, the case the scan path exists for, in integers, decimals (k/1000), fractions
// (k/7) and binary fractions (k/2^20, what doubles of that grid are): the scan path must decide
// every one and agree with the hull path.
BOOST_AUTO_TEST_CASE(near_spheres_of_every_number_kind) {
    std::mt19937 g(11);
    Tally t;
    const long dens[] = {1, 1000, 7, 1L << 20};
    for (long den : dens)
        for (int rep = 0; rep < 6; ++rep) {
            std::uniform_int_distribution<int> n(40, 400), off(-3, 3);
            const double R = 50 + 10 * rep;
            ExactScene sc;
            sc.P[0].points = sphere(g, n(g), R, den, {Q(0), Q(0), Q(0)});
            sc.P[1].points = sphere(g, n(g), R * (1 + 0.2 * rep), den, {Q(3 * R), Q(off(g) * 10), Q(off(g) * 10)});
            sc = with_means(sc, qc(1, 2), Q(2));
            BOOST_TEST(compare(sc, "near-sphere den " + std::to_string(den) + " #" + std::to_string(rep), t));
        }
    BOOST_TEST_MESSAGE("near-spheres: " << t.scanned << " by the scan path");
}

// The session (session.hpp) takes verdicts from the walk where it proved the curve, with no hull,
// and from the hull elsewhere: both must be the hull path's verdicts, at pairs on, above and
// below the curve, inside the walked range and far outside it (ρ1 up to 8 with I1 = [1/2, 2]).
BOOST_AUTO_TEST_CASE(session_verdicts_from_the_walk_equal_the_hull_paths) {
    std::mt19937 g(23);
    int walked = 0, checked = 0, on_walk = 0;
    for (int rep = 0; rep < 4; ++rep) {
        ExactScene sc;
        sc.P[0].points = sphere(g, 1200, 60, 1, {Q(0), Q(0), Q(0)});
        sc.P[1].points = sphere(g, 1200, 70, 1, {Q(200), Q(10 * rep), Q(-5)});
        sc = with_means(sc, qc(1, 2), Q(2));
        Session s(sc, "test");
        const HullModel hm = build_model(sc);
        const TouchingCurve hc = build_curve(hm);
        if (!s.walked()) continue;
        ++walked;
        std::uniform_int_distribution<int> x(1, 64);
        for (int k = 0; k < 60; ++k) {
            const Q r1 = qc(x(g), 8), f = hc.env.value(hm.lines, r1);
            for (const Q& r2 : {f, Q(f * qc(1023, 1024)), Q(f * qc(1025, 1024)), qc(x(g), 8)}) {
                if (sgn(r2) <= 0) continue;
                on_walk += s.walk_covers(r1, r1);
                BOOST_TEST(s.verdict(r1, r2) == query(hm, hc, r1, r2, false).verdict);
                ++checked;
            }
        }
        BOOST_TEST(s.curve_value(Q(1)) == hc.env.value(hm.lines, Q(1)));
        // Verdicts inside the walked range alone build no hull.
        Session t(sc, "test");
        for (int k = 0; k < 20; ++k) t.verdict(qc(x(g) % 12 + 4, 8), Q(1));  // ρ1 in [1/2, 15/8] ⊂ I1
        BOOST_TEST(!t.hull_built());
        BOOST_TEST(t.walked());
    }
    BOOST_TEST(walked >= 3);
    // Pairs outside I1 (ρ1 up to 8) are decided by a wider walk, not by the hull model.
    BOOST_TEST(on_walk == checked);
}

// Golden data on a walked scene comes from the walk and the points' trees, with no hull model:
// its queries are the hull path's (the exact verdicts, distances, depths, depth directions and
// planes are unique; the closest points' difference too), and its curve document differs only in the engine statistics.
BOOST_AUTO_TEST_CASE(golden_answers_on_the_walk_equal_the_hull_paths) {
    std::mt19937 g(31);
    ExactScene sc;
    sc.P[0].points = sphere(g, 1200, 60, 1, {Q(0), Q(0), Q(0)});
    sc.P[1].points = sphere(g, 1200, 70, 1, {Q(150), Q(10), Q(-5)});
    sc = with_means(sc, qc(1, 2), Q(2));
    Session walk(sc, "test"), hull(sc, "test", Engine::Hull);
    const ClaimModels &wm = walk.claim_models(), &hm = hull.claim_models();
    GoldenAnswers a = golden_answers(sc, walk.curve_model(), walk.curve(), wm, {});
    GoldenAnswers b = golden_answers(sc, hull.curve_model(), hull.curve(), hm, {});
    BOOST_TEST(walk.walked());
    BOOST_TEST(!walk.hull_built());
    BOOST_TEST(a.queries.size() >= 7 * 13u);
    // The closest points are one pair of many where the nearest features are parallel: each pair
    // is compared by its difference, which the distance fixes (checked, with their membership, in
    // test_audit's golden test).
    auto unpaired = [](Json q) {
        for (Json& r : q) {
            Json& m = r["measure_at_doubles"];
            if (!m.contains("closest_P1")) continue;
            Vec3q d;
            for (int i = 0; i < 3; ++i)
                d[i] = parse_exact(m["closest_P2"][i].get<std::string>()) -
                       parse_exact(m["closest_P1"][i].get<std::string>());
            m.erase("closest_P1");
            m.erase("closest_P2");
            m["difference"] = Json::array({to_exact_string(d[0]), to_exact_string(d[1]), to_exact_string(d[2])});
        }
        return q;
    };
    BOOST_TEST(dump(unpaired(a.queries)) == dump(unpaired(b.queries)));
    BOOST_TEST(a.queries.size() == b.queries.size());
    BOOST_TEST(a.curve["model"]["engine"] == "scan");
    a.curve.erase("model");
    b.curve.erase("model");
    BOOST_TEST(dump(a.curve) == dump(b.curve));
}

BOOST_AUTO_TEST_CASE(verdicts_outside_I1_and_at_coincident_seeds_build_no_hull) {
    // A query far left or right of I1 must not fall back to the hull model (4,000-gon prisms:
    // 90 s, 8.4 GB), nor a query with coincident seeds, where every pair overlaps. Crossed 100-gon
    // prisms (test above), I1 = [1/2, 2].
    const ExactScene sc = test::crossed_prism_scene(100);
    const HullModel hm = build_model(sc);
    const TouchingCurve hc = build_curve(hm);
    Session s(sc, "test", Engine::Scan);
    for (const Q& r1 : {qc(1, 1000), qc(1, 10), Q(1000)})
        for (const Q& r2 : {qc(1, 1000), Q(1), Q(1000)})
            BOOST_TEST(s.verdict(r1, r2) == query(hm, hc, r1, r2, false).verdict);
    BOOST_TEST(s.walked());
    BOOST_TEST(!s.hull_built());
    // The same prisms about one seed: every pair overlaps (derived: the seed is inside both).
    ExactScene co = sc;
    co.P[1].points = co.P[0].points;
    co.P[1].seed = co.P[0].seed;
    Session c(co, "test", Engine::Scan);
    for (const Q& r : {qc(1, 1000), Q(1), Q(1000)}) BOOST_TEST((c.verdict(r, r) == Verdict::Overlapping));
    BOOST_TEST(!c.hull_built());
}

// Random small polytopes (many coplanar points, degenerate contacts): whatever the scan path
// decides must agree; it may hand the rest to the hull path, but not most of them.
BOOST_AUTO_TEST_CASE(random_scenes_agree_or_fall_back) {
    std::mt19937 g(5);
    Tally t;
    for (int rep = 0; rep < 120; ++rep) {
        std::uniform_int_distribution<int> n(4, 30);
        ExactScene sc = test::random_scene(g, n(g), n(g));
        // Keep I1 where the curve is above 0 for most scenes, and vary it.
        std::uniform_int_distribution<int> a(1, 8);
        const Q lo = qc(a(g), 8), hi = lo + qc(a(g), 4);
        for (int i = 0; i < 2; ++i) sc.lo[i] = lo, sc.hi[i] = hi;
        compare(sc, "random #" + std::to_string(rep), t);
    }
    BOOST_TEST_MESSAGE("random: " << t.scanned << " by the scan path, " << t.fell_back << " by the hull path");
    BOOST_TEST(t.scanned >= 60);
}

// Crossed prisms (the bench's family, scalecert-bench --queries): a regular n-gon rounded to
// integers, extruded along z for P1 and along x for P2 above it. The Minkowski sum has O(n^2) facet
// normals; the curve reaches ρ2 = 0 inside I1 and goes on as one line (envelope.hpp), so the walk
// decides every one, and the scan path has byte for byte the hull path's curve.
BOOST_AUTO_TEST_CASE(crossed_prisms_are_walked_to_rho2_zero) {
    Tally t;
    for (int n : {8, 13, 40, 100}) {
        const ExactScene sc = test::crossed_prism_scene(n);
        const HullModel hm = build_model(sc);
        const TouchingCurve hc = build_curve(hm);
        BOOST_TEST(sgn(hm.lines[hc.env.pieces[hc.pieces.back().env].line].at(Q(2))) < 0);  // reaches 0 in I1
        BOOST_TEST(compare(sc, "crossed " + std::to_string(n) + "-gon prisms", t));
    }
    BOOST_TEST(t.scanned == 4);
}

// Decimal boxes turned by exact rotations (faces, edges and vertices in contact, (V,E) switches).
BOOST_AUTO_TEST_CASE(turned_boxes_in_decimals) {
    Tally t;
    for (int rep = 0; rep < 12; ++rep) {
        ExactScene sc;
        for (int x : {-1, 1})
            for (int y : {-1, 1})
                for (int z : {-1, 1}) sc.P[0].points.push_back({Q(x), Q(y), qc(z * 3, 2)});
        // cos = 0.6, sin = 0.8 (3-4-5): decimals, turned about z then x, shifted by rep/10.
        for (int x : {-2, 2})
            for (int y : {-1, 1})
                for (int z : {-1, 1}) {
                    const Q X = qc(6 * x - 8 * y, 10), Y = qc(8 * x + 6 * y, 10), Z = Q(z);
                    const Q Y2 = qc(6, 10) * Y - qc(8, 10) * Z, Z2 = qc(8, 10) * Y + qc(6, 10) * Z;
                    sc.P[1].points.push_back({X + 4, Y2 + qc(rep, 10), Z2 + qc(rep, 20)});
                }
        sc = with_means(sc, qc(1, 2), Q(3));
        compare(sc, "turned box #" + std::to_string(rep), t);
    }
    BOOST_TEST_MESSAGE("boxes: " << t.scanned << " by the scan path, " << t.fell_back << " by the hull path");
    BOOST_TEST(t.scanned >= 6);
}

// The walk returns why it hands a scene over, and each hand-over is counted, per reason.
BOOST_AUTO_TEST_CASE(handovers_are_returned_and_counted) {
    auto cube = [](long cx, long cy, long cz) {
        std::vector<Vec3q> v;
        for (long x : {-1, 1})
            for (long y : {-1, 1})
                for (long z : {-1, 1}) v.push_back({Q(cx + x), Q(cy + y), Q(cz + z)});
        return v;
    };
    auto walk = [](ExactScene sc) {
        sc = with_means(sc, Q(1, 2), Q(2));
        auto cs = compact_scene(sc);
        BOOST_TEST_REQUIRE(cs.has_value());
        return scan_model(std::make_shared<CompactScene>(std::move(*cs)));
    };
    auto count = [](Handover h) { return handover_counts()[static_cast<size_t>(h)]; };
    // Cubes about one centre: d = 0, nothing to walk.
    ExactScene same;
    same.P[0].points = cube(0, 0, 0);
    for (const Vec3q& p : cube(0, 0, 0)) same.P[1].points.push_back({p[0] * 2, p[1] * 2, p[2] * 2});
    const std::uint64_t before = count(Handover::SeedsCoincide);
    const WalkResult r = walk(same);
    BOOST_TEST(!r.model.has_value());
    BOOST_TEST_REQUIRE(r.stop.has_value());
    BOOST_TEST((r.stop->reason == Handover::SeedsCoincide));
    BOOST_TEST(r.stop->text() == "the seeds coincide");
    BOOST_TEST(count(Handover::SeedsCoincide) == before + 1);
    // Unit cubes [-1, 1]^3 about 0 and about (3, 3, 0): their Minkowski sum is a box, and d = (3, 3, 0)
    // runs along its vertical edge between the faces of normals x and y, whose lines are both
    // ρ1 + ρ2 = 3 (h1 = h2 = 1, n·d = 3): identical lines, which the walk hands over.
    ExactScene diag;
    diag.P[0].points = cube(0, 0, 0);
    diag.P[1].points = cube(3, 3, 0);
    const WalkResult e = walk(diag);
    BOOST_TEST_REQUIRE(e.stop.has_value());
    BOOST_TEST((e.stop->reason == Handover::IdenticalLines));
    BOOST_TEST(e.stop->text() == "d on a face's edge all along a piece (identical lines)");
    // The hull path decides it: ρ2 = 3 − ρ1.
    const HullModel hm = build_model(with_means(diag, Q(1, 2), Q(2)));
    const TouchingCurve hc = build_curve(hm);
    BOOST_TEST_REQUIRE(hc.pieces.size() == 1u);
    BOOST_TEST(hm.lines[hc.env.pieces[hc.pieces[0].env].line].slope == -1);
    BOOST_TEST(hm.lines[hc.env.pieces[hc.pieces[0].env].line].intercept == 3);
    // Every reason has its words.
    for (int k = 0; k < kHandoverReasons; ++k)
        BOOST_TEST(std::string(handover_text(static_cast<Handover>(k))) != "unknown");
}

// Every bundled scene: the same document either way (each may fall back).
BOOST_AUTO_TEST_CASE(bundled_scenes) {
    Tally t;
    for (const auto& e :
         std::filesystem::directory_iterator(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes")) {
        if (!e.is_regular_file()) continue;  // (compound/: objects made of parts)
        const ExactScene sc = load_scene(e.path().string());
        compare(sc, e.path().filename().string(), t);
    }
    BOOST_TEST_MESSAGE("bundled: " << t.scanned << " by the scan path, " << t.fell_back << " by the hull path");
    BOOST_TEST(t.scanned + t.fell_back == 7);
}

// The compact reader gives exactly the full reader's points, or leaves the file to it.
BOOST_AUTO_TEST_CASE(compact_off_reader) {
    auto same = [](const std::string& text) {
        auto fast = parse_off_fast(text, Numbers::Exact);
        BOOST_REQUIRE_MESSAGE(fast, text);
        ReadOptions exact;
        exact.numbers = Numbers::Exact;
        BOOST_TEST((q_points(*fast) == parse_mesh(text, MeshFormat::Off, "t", exact)));
    };
    same("OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
    same("OFF 4 4 6\n1.5 -2.25e1 +3E-2\n-0.001 7 100e-3\n1234567890123 0 0\n0 0 -1e3\n3 0 1 2\n");
    same("OFF\n4 0 0\n0.10 0.2 0.300\n-0 -0.0 5\n1e0 2E+1 3e-1\n9 9 9\n trailing text is not read\n");
    // Random decimals with random exponents.
    std::mt19937 g(3);
    std::uniform_int_distribution<long> m(-99999, 99999);
    std::uniform_int_distribution<int> e(-3, 3), f(0, 3);
    for (int rep = 0; rep < 50; ++rep) {
        std::string t = "OFF\n20 0 0\n";
        for (int i = 0; i < 60; ++i) {
            std::string s = std::to_string(m(g));
            const int fd = f(g);
            if (fd && s.size() > static_cast<size_t>(fd + 1)) s.insert(s.size() - static_cast<size_t>(fd), ".");
            const int x = e(g);
            if (x) s += "e" + std::to_string(x);
            t += s + (i % 3 == 2 ? "\n" : " ");
        }
        same(t);
    }
    // Left to the full reader: comments, fractions, too many digits, huge values, a bad header.
    for (const char* t :
         {"OFF\n4 0 0\n0 0 0 # here\n1 0 0\n0 1 0\n0 0 1\n", "OFF\n4 0 0\n1/2 0 0\n1 0 0\n0 1 0\n0 0 1\n",
          "OFF\n4 0 0\n1234567890123456789 0 0\n1 0 0\n0 1 0\n0 0 1\n", "OFF\n4 0 0\n1e30 0 0\n1 0 0\n0 1 0\n0 0 1\n",
          "OFF\n4 0 0\n1e-30 0 0\n1 0 0\n0 1 0\n0 0 1\n", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n",
          "OFF\n4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n", "OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0\n",
          "OFF\n4 0 0\n1. 0 0\n1 0 0\n0 1 0\n0 0 1\n", "OFF\n4 0 0\n.5 0 0\n1 0 0\n0 1 0\n0 0 1\n",
          "COFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"})
        BOOST_TEST(!parse_off_fast(t, Numbers::Exact), t);
}

// Under --numbers double or float32 the compact reader takes a decimal only when the reading keeps
// it as written (a dyadic decimal of few enough bits); any other is left to the full reader.
BOOST_AUTO_TEST_CASE(compact_off_reader_under_binary_readings) {
    const std::string dyadic = "OFF\n4 0 0\n0.5 -0.25 3\n1.125 0 -7\n0.375 2 1e2\n-12.5e-1 0 0\n";
    for (Numbers n : {Numbers::Double, Numbers::Float32}) {
        ReadOptions o;
        o.numbers = n;
        auto fast = parse_off_fast(dyadic, n);
        BOOST_REQUIRE(fast);
        BOOST_TEST((q_points(*fast) == parse_mesh(dyadic, MeshFormat::Off, "t", o)));
        // 0.1 is no double, no float: the full reader reads it.
        BOOST_TEST(!parse_off_fast("OFF\n4 0 0\n0.1 0 0\n1 0 0\n0 1 0\n0 0 1\n", n));
    }
    // 2^24 + 1 is a double but no float; 2^53 + 1 neither.
    const std::string big = "OFF\n4 0 0\n16777217 0 0\n1 0 0\n0 1 0\n0 0 1\n";
    BOOST_TEST(parse_off_fast(big, Numbers::Double).has_value());
    BOOST_TEST(!parse_off_fast(big, Numbers::Float32));
    // Random decimals with random exponents: the fast reader's points, when it reads them, are the
    // full reader's, and it reads a text exactly when every decimal is dyadic with at most 53 bits
    // (checked here on the rationals: a denominator a power of two and the odd part below 2^53).
    std::mt19937 g(5);
    std::uniform_int_distribution<long> m(-99999, 99999);
    std::uniform_int_distribution<int> e(-3, 3), f(0, 3);
    int taken = 0;
    for (int rep = 0; rep < 200; ++rep) {
        std::string t = "OFF\n4 0 0\n";
        for (int i = 0; i < 12; ++i) {
            std::string s = std::to_string(m(g));
            if (rep % 2) {  // any decimal
                const int fd = f(g), x = e(g);
                if (fd && s.size() > static_cast<size_t>(fd + 1)) s.insert(s.size() - static_cast<size_t>(fd), ".");
                if (x) s += "e" + std::to_string(x);
            } else {  // eighths: dyadic
                static const char* const eighths[] = {"", ".5", ".25", ".125", ".375"};
                s = std::to_string(m(g) % 1000) + eighths[f(g) + i % 2];
            }
            t += s + (i % 3 == 2 ? "\n" : " ");
        }
        ReadOptions exact;
        exact.numbers = Numbers::Exact;
        bool all_doubles = true;
        for (const Vec3q& v : parse_mesh(t, MeshFormat::Off, "t", exact))
            for (const Q& c : v) {
                Z d = c.get_den(), odd = abs(c.get_num());
                while (odd != 0 && mpz_even_p(odd.get_mpz_t())) odd /= 2;
                const bool pow2 = mpz_popcount(d.get_mpz_t()) == 1;
                all_doubles = all_doubles && pow2 && odd < (Z(1) << 53);
            }
        auto fast = parse_off_fast(t, Numbers::Double);
        BOOST_TEST(fast.has_value() == all_doubles, t);
        if (fast) {
            ++taken;
            ReadOptions dbl;
            BOOST_TEST((q_points(*fast) == parse_mesh(t, MeshFormat::Off, "t", dbl)));
        }
    }
    BOOST_TEST(taken > 20);  // the dyadic half is read fast
}

// The compact scene reader: the full reader's scene exactly, or the file left to it.
BOOST_AUTO_TEST_CASE(compact_scene_reader) {
    auto same = [](const std::string& text) {
        auto fast = parse_scene_fast(text.data(), text.size(), Numbers::Exact);
        BOOST_REQUIRE_MESSAGE(fast, text);
        ReadOptions exact;
        exact.numbers = Numbers::Exact;
        const ExactScene full = parse_scene_text(text, "t", ".", exact);
        const ExactScene back = full_scene(*fast);
        for (int i = 0; i < 2; ++i) {
            BOOST_TEST((back.P[i].points == full.P[i].points));
            BOOST_TEST((back.P[i].seed == full.P[i].seed));
            BOOST_TEST(back.P[i].seed_given == full.P[i].seed_given);
            BOOST_TEST((back.lo[i] == full.lo[i] && back.hi[i] == full.hi[i]));
        }
    };
    const std::string cube = "[[0,0,0],[2,0,0],[0,2,0],[2,2,0],[0,0,2],[2,0,2],[0,2,2],[2,2,2]]";
    same("{\"P1\": {\"vertices\": " + cube +
         "}, \"P2\": {\"vertices\": [[0,0,3],[2,0,3.5],[0,2e0,3],[2,2,3],[0,0,5],[2,0,5],[0,2,5],[2,2,5.25]]}, \"I1\": "
         "[0.5, 2.5], \"I2\": [1e-1, 3]}");
    same("\n{ \"I2\" : [0.5,2], \"P2\":{\"seed\":[1,1,4],\"vertices\":" + cube +
         "},\r\n\"I1\":[1,2],\t\"P1\":{\"vertices\":[[-0.001,0,0],[1,0,0],[0,1,0],[0,0,1]], \"seed\": [0.1, 0.1, 0.1]} "
         "}\n");
    // Left to the full reader (which accepts some and refuses the rest with its own message).
    for (const std::string& t :
         {"{\"P1\": {\"vertices\": " + cube + "}, \"P2\": {\"vertices\": " + cube +
              "}, \"I1\": [\"1/2\", 2], \"I2\": [1, 2]}",  // a string number
          "{\"P1\": {\"vertices\": " + cube + "}, \"P1\": {\"vertices\": " + cube +
              "}, \"I1\": [1, 2], \"I2\": [1, 2]}",  // duplicate key
          "{\"P1\": {\"vertices\": " + cube +
              "}, \"P2\": {\"vertices\": [[01,0,0],[1,0,0],[0,1,0],[0,0,1]]}, \"I1\": [1, 2], "
              "\"I2\": [1, 2]}",  // leading zero
          "{\"P1\": {\"vertices\": " + cube +
              "}, \"P2\": {\"off\": \"x.off\"}, \"I1\": [1, 2], \"I2\": [1, 2]}",  // a file
          "{\"P1\": {\"vertices\": " + cube + "}, \"P2\": {\"vertices\": " + cube +
              "}, \"I1\": [1, 2], \"I2\": [1, 2]} x",  // trailing text
          "{\"P1\": {\"vertices\": " + cube + "}, \"P2\": {\"vertices\": " + cube +
              "}, \"I1\": [2, 1], \"I2\": [1, 2]}",                                  // lo > hi
          "{\"P1\": {\"vertices\": " + cube + "}, \"I1\": [1, 2], \"I2\": [1, 2]}",  // P2 missing
          "{\"P1\": {\"vertices\": [[0,0,0],[1,0,0],[0,1,0]]}, \"P2\": {\"vertices\": " + cube +
              "}, \"I1\": [1, 2], \"I2\": [1, 2]}",  // 3 points
          "{\"P1\": {\"vertices\": " + cube + ", \"color\": 1}, \"P2\": {\"vertices\": " + cube +
              "}, \"I1\": [1, 2], \"I2\": [1, 2]}",  // unknown key
          "{\"P1\": {\"vertices\": " + cube + "}, \"P2\": {\"vertices\": " + cube +
              "}, \"I1\": [1, 2], \"I2\": [1, 2],}",  // trailing comma
          "{\"P1\": {\"vertices\": " + cube + "}, \"P2\": {\"vertices\": " + cube +
              "}, \"I1\": [+1, 2], \"I2\": [1, 2]}"})  // '+'
        BOOST_TEST(!parse_scene_fast(t.data(), t.size(), Numbers::Exact), t);
    // Without I2 its range is [1, 1], as the full reader has it.
    const std::string no_i2 =
        "{\"P1\": {\"vertices\": " + cube + "}, \"P2\": {\"vertices\": " + cube + "}, \"I1\": [1, 2]}";
    const auto cs = parse_scene_fast(no_i2.data(), no_i2.size(), Numbers::Exact);
    BOOST_TEST_REQUIRE(cs.has_value());
    BOOST_TEST(cs->lo[0] == Q(1));
    BOOST_TEST(cs->hi[0] == Q(2));
    BOOST_TEST(cs->lo[1] == Q(1));
    BOOST_TEST(cs->hi[1] == Q(1));
}

// Claims of every kind on a scene the walk takes, judged on the walk, build no hull model (the
// Gauss-map overlay and a line per Minkowski facet: quadratic on crossed prisms) and give the
// judgements the hull model gives. The claims are made from the hull model's exact answers (the
// other engine): right as made, and wrong where one number is moved off them. Both engines'
// certificates pass scalecert-check.
BOOST_AUTO_TEST_CASE(claims_on_the_walk_build_no_hull_model) {
    const ExactScene sc = test::crossed_prism_scene(100);
    const HullModel hm = build_model(sc);
    const TouchingCurve hc = build_curve(hm);
    const auto ex = [](const Q& q) { return to_exact_string(q); };
    const auto pt = [&](const Vec3q& v) { return Json::array({ex(v[0]), ex(v[1]), ex(v[2])}); };
    const auto f = [&](const Q& x) { return hc.env.value(hm.lines, x); };
    const ContactLine& last = hm.lines[hc.env.pieces.back().line];
    const Q zero = -last.intercept / last.slope;  // where f reaches 0 (the last piece goes on as one line)
    Json claims = Json::array();
    std::vector<bool> expect;
    auto add = [&](Json c, bool right) {
        claims.push_back(std::move(c));
        expect.push_back(right);
    };
    int switches = 0;
    for (const Q& x : {qc(1, 2), qc(3, 4), Q(zero * qc(1, 2)), Q(zero * qc(9, 10))}) {
        const Q y = f(x);
        BOOST_TEST(sgn(y) > 0);
        const Q over = y * qc(65, 64), under = y * qc(63, 64);
        add({{"kind", "verdict"}, {"rho1", ex(x)}, {"rho2", ex(y)}, {"verdict", "touching"}}, true);
        add({{"kind", "verdict"}, {"rho1", ex(x)}, {"rho2", ex(over)}, {"verdict", "separated"}}, false);
        add({{"kind", "curve_point"}, {"rho1", ex(x)}, {"rho2", ex(y)}}, true);
        add({{"kind", "curve_point"}, {"rho1", ex(x)}, {"rho2", ex(Q(y + qc(1, 1000)))}}, false);
        const ExactDistance meet = exact_distance(hm, x, over);
        BOOST_TEST(sgn(meet.squared) == 0);
        add({{"kind", "witness_point"}, {"rho1", ex(x)}, {"rho2", ex(over)}, {"point", pt(meet.p1)}}, true);
        add({{"kind", "witness_point"}, {"rho1", ex(x)}, {"rho2", ex(under)}, {"point", pt(meet.p1)}}, false);
        const ExactDistance apart = exact_distance(hm, x, under);
        BOOST_TEST(sgn(apart.squared) > 0);
        const double d = sqrt_minus_rn(apart.squared, Q(0));
        add({{"kind", "distance"},
             {"rho1", ex(x)},
             {"rho2", ex(under)},
             {"value", d},
             {"closest", Json::array({pt(apart.p1), pt(apart.p2)})}},
            true);
        add({{"kind", "distance"}, {"rho1", ex(x)}, {"rho2", ex(under)}, {"value", d * 1.01}}, false);
        const ExactDepth dep = exact_penetration_depth(hm, all_facet_normals(hm), x, over);
        add({{"kind", "penetration_depth"},
             {"rho1", ex(x)},
             {"rho2", ex(over)},
             {"value", sqrt_minus_rn(dep.squared, Q(0))},
             {"direction", pt(to_q(dep.direction))}},
            true);
        const Vec3z n = hm.lines[hc.env.pieces[hc.env.locate(x)].line].normal;
        add({{"kind", "separating_plane"}, {"rho1", ex(x)}, {"rho2", ex(under)}, {"normal", pt(to_q(n))}}, true);
        add({{"kind", "separating_plane"}, {"rho1", ex(x)}, {"rho2", ex(over)}, {"normal", pt(to_q(n))}}, false);
        // Beyond doubles: a point far outside both (by its x), and a normal nearly along x, along
        // which the prisms' x-ranges overlap (P1's x within ±10^6·ρ1 about 0, P2's about 12345).
        add({{"kind", "witness_point"},
             {"rho1", ex(x)},
             {"rho2", ex(over)},
             {"point", Json::array({"1e400", "0", "0"})}},
            false);
        add({{"kind", "separating_plane"},
             {"rho1", ex(x)},
             {"rho2", ex(under)},
             {"normal", Json::array({"1e400", "0", "1"})}},
            false);
    }
    // The curve from ρ1 = 1/2 to 9/10 of the way to ρ2 = 0, as the polyline of its breaks; a switch
    // point at every break with ρ2 > 0; and the growth distance.
    Q lo = qc(1, 2);
    const Q hi = zero * qc(9, 10);
    for (size_t k = 0; k + 1 < hc.env.pieces.size(); ++k)
        if (const Q x = *hc.env.pieces[k].to; sgn(x) > 0 && x < lo * 2)
            lo = std::min(lo, Q(x / 2));  // a break inside the range
    Json verts = Json::array({Json::array({ex(lo), ex(f(lo))})});
    for (size_t k = 0; k + 1 < hc.env.pieces.size(); ++k) {
        const Q x = *hc.env.pieces[k].to, y = f(x);
        if (sgn(x) <= 0 || sgn(y) <= 0) continue;
        const std::string label =
            contact_at(hm, hm.lines[hc.env.pieces[k].line], hm.lines[hc.env.pieces[k + 1].line], x, y).label;
        add({{"kind", "switch_point"}, {"rho1", ex(x)}, {"rho2", ex(y)}, {"contact", label}}, true);
        add({{"kind", "switch_point"}, {"rho1", ex(Q(x * qc(101, 100)))}, {"rho2", ex(y)}}, false);
        ++switches;
        if (x > lo && x < hi) verts.push_back(Json::array({ex(x), ex(y)}));
    }
    verts.push_back(Json::array({ex(hi), ex(f(hi))}));
    add({{"kind", "curve"}, {"vertices", verts}}, true);
    Json off = verts;
    off[1][1] = ex(Q(f(parse_exact(verts[1][0].get<std::string>())) + qc(1, 1000)));
    add({{"kind", "curve"}, {"vertices", off}}, false);
    add({{"kind", "growth_distance"}, {"value", ex(hc.growth.value)}}, true);
    add({{"kind", "growth_distance"}, {"value", ex(Q(hc.growth.value * 2))}}, false);
    BOOST_TEST(switches >= 1);
    BOOST_TEST(verts.size() >= 3u);

    const std::string doc = dump(Json{{"format", "scalecert-claims-1"}, {"claims", claims}});
    const ClaimOptions opt{Numbers::Double, qc(1, 1000000), true};
    const std::filesystem::path dir = test::scratch_dir("walk-claims");
    std::vector<bool> right[2];
    for (Engine e : {Engine::Scan, Engine::Hull}) {
        Session s(sc, "crossed", e);
        long wrong = 0;
        std::string cert;
        const Json rep = Json::parse(certify_fp(s.claim_models(), doc, "claims", opt, &wrong, nullptr, &cert));
        std::vector<bool>& r = right[e == Engine::Hull];
        for (const Json& c : rep.at("claims")) r.push_back(c.at("right").get<bool>());
        BOOST_TEST(r == expect, (e == Engine::Hull ? "hull" : "walk"));
        if (e == Engine::Scan) {
            BOOST_TEST(s.walked());
            BOOST_TEST(!s.hull_built());
        }
        const std::filesystem::path p = dir / (e == Engine::Hull ? "hull.json" : "walk.json");
        std::ofstream(p) << cert;
        BOOST_TEST(std::system((std::string(SCALECERT_CHECK_BIN) + " " + p.string() + " >/dev/null").c_str()) == 0);
    }
    // The same claims as lines ('RHO1 RHO2 VERDICT', 'curve', 'growth') build none either.
    Session s(sc, "crossed", Engine::Scan);
    long wrong = 0;
    std::string cert;
    const std::string lines = ex(lo) + " " + ex(f(lo)) + " touching\ncurve " + ex(lo) + " " + ex(f(lo)) + "\ngrowth " +
                              ex(hc.growth.value) + "\n";
    certify_fp(s.claim_models(), lines, "lines", ClaimOptions{Numbers::Double, Q(0), true}, &wrong, nullptr, &cert);
    BOOST_TEST(wrong == 0);
    BOOST_TEST(!s.hull_built());
    // A curve point past where the curve reaches 0 (ρ1 = 3 > 20/9 of the way there: wrong), whose
    // proof's window starts where the curve is <= 0 on the walk (the claims fuzz target's finding:
    // that end's witness lacked the seeds' weights, and the checker refused the certificate).
    const std::string past = "curve 3 2\n";
    certify_fp(s.claim_models(), past, "past", ClaimOptions{Numbers::Double, Q(0), true}, &wrong, nullptr, &cert);
    BOOST_TEST(wrong == 1);
    BOOST_TEST(sgn(f(Q(3))) <= 0);
    const std::filesystem::path pp = dir / "past.json";
    std::ofstream(pp) << cert;
    BOOST_TEST(std::system((std::string(SCALECERT_CHECK_BIN) + " " + pp.string() + " >/dev/null").c_str()) == 0);
    std::filesystem::remove_all(dir);
}
