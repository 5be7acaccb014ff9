// Partition files (checker/partition.cpp): the bundled and the engine's fresh partitions pass,
// every mutation of them is rejected or still true, and the overlap region built from the pieces
// equals the rectangle clipped by every line.
#include "checker_tests.hpp"
#include "../support.hpp"

#include "../../checker/formats.hpp"
#include "../../checker/scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>

BOOST_AUTO_TEST_SUITE(checker_partition)

BOOST_AUTO_TEST_CASE(bundled_certificates_are_valid) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(fs::path(SCALECERT_SOURCE_DIR) / "certificates"))
        if (e.path().string().size() > 15 &&
            e.path().string().rfind(".partition.json") == e.path().string().size() - 15) {
            BOOST_TEST(check_file(e.path()) == 0, e.path());
            ++n;
        }
    BOOST_TEST(n >= 4);
}

BOOST_AUTO_TEST_CASE(tampered_partitions_are_rejected) {
    for (const char* name : {"stacked_cubes", "tetra_box_switch", "fig5_vf_ve_ee", "roof_nearly_equal_slopes"}) {
        fs::path p = fs::path(SCALECERT_SOURCE_DIR) / "certificates" / (std::string(name) + ".partition.json");
        mutate_and_report(load(p), name, false);
    }
}

namespace {
// A scene file with crossed n-gon prisms (scalecert-bench's family) or two near-spheres of n points.
fs::path write_off(const std::string& name, const std::vector<std::array<long, 3>>& pts) {
    const fs::path p = tmpdir() / name;
    std::ofstream o(p);
    o << "OFF\n" << pts.size() << " 0 0\n";
    for (const auto& v : pts) o << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
    return p;
}
std::string crossed_prisms(int n) {
    const auto P = test::crossed_prisms(n);
    const std::string tag = "prism" + std::to_string(n);
    return "--p1 " + write_off(tag + "a.off", P[0]).string() + " --p2 " + write_off(tag + "b.off", P[1]).string() +
           " --i1 1/2,2 --i2 1/2,2";
}
std::string near_spheres(int n) {
    std::mt19937 g(7);
    std::normal_distribution<double> N(0, 1);
    std::vector<std::array<long, 3>> pts[2];
    const long R = 1000000;
    for (int i = 0; i < 2; ++i)
        for (int k = 0; k < n; ++k) {
            const double x = N(g), y = N(g), z = N(g), l = std::sqrt(x * x + y * y + z * z);
            pts[i].push_back(
                {std::lround(R * x / l) + 3 * R * i, std::lround(R * y / l) + R / 10 * i, std::lround(R * z / l)});
        }
    const std::string tag = "sphere" + std::to_string(n);
    return "--p1 " + write_off(tag + "a.off", pts[0]).string() + " --p2 " + write_off(tag + "b.off", pts[1]).string() +
           " --i1 1/2,2 --i2 1/2,2";
}
OJ run_json(const std::string& args) {
    const fs::path out = tmpdir() / "walk.json";
    fs::remove(out);
    BOOST_TEST_REQUIRE(engine(args + " --out " + out.string()) == 0, args);
    return load(out);
}
}  // namespace

BOOST_AUTO_TEST_CASE(the_walks_partitions_and_query_answers_pass_the_checker) {
    // The walk (no hull) writes partitions and query answers from its support sets: witnesses
    // over the features it walked, seed weights over a few extreme points, and overlap witnesses
    // lifted from the curve point below (query.hpp, lift_witness). Each must pass the checker, give
    // the hull path's regions and verdicts, and hold the same scene.
    const std::string boxes =
        (fs::path(SCALECERT_SOURCE_DIR) / "tests/data/boxes_curve_goes_on_below_zero.json").string();
    const std::string cubes_below =
        (fs::path(SCALECERT_SOURCE_DIR) / "tests/data/cubes_side_by_side_curve_below_zero.json").string();
    for (const std::string& scene : {boxes, cubes_below, crossed_prisms(8), crossed_prisms(40), near_spheres(300)}) {
        const OJ w = run_json("partition " + scene + " --engine scan");
        const OJ h = run_json("partition " + scene + " --engine hull");
        BOOST_TEST_REQUIRE(w["model"]["engine"] == "scan", scene);
        BOOST_TEST(verdict_of(w) == 0, scene);
        BOOST_TEST(w["scene"] == h["scene"]);
        BOOST_TEST(w["pieces"].size() == h["pieces"].size());
        BOOST_TEST(w["regions"]["overlap"]["vertices"] == h["regions"]["overlap"]["vertices"]);
        BOOST_TEST(w["growth_distance"] == h["growth_distance"]);
        // Queries: on the curve at each overlap vertex and piece end, 1/1000 below and above, and
        // far above (the ray from the origin may meet the curve left of the walk: the hull answers).
        std::vector<std::array<mpq_class, 2>> pairs;
        for (const auto& v : w["regions"]["overlap"]["vertices"])
            pairs.push_back({mpq_class(v[0].get<std::string>()), mpq_class(v[1].get<std::string>())});
        for (const auto& e : w["curve_ends"]) {
            const mpq_class x(e["rho1"].get<std::string>()), y(e["rho2"].get<std::string>());
            for (const mpq_class& dy : {mpq_class(0), mpq_class(-1, 1000), mpq_class(1, 1000)})
                if (sgn(y + dy) > 0) pairs.push_back({x, y + dy});
        }
        pairs.push_back({mpq_class(1, 2), mpq_class(1000)});
        for (const auto& [x, y] : pairs) {
            const std::string q = "query " + scene + " " + x.get_str() + " " + y.get_str() + " --json --engine ";
            const OJ a = run_json(q + "scan"), b = run_json(q + "hull");
            BOOST_TEST(verdict_of(a) == 0, q);
            BOOST_TEST(a["verdict"] == b["verdict"], q);
        }
    }
    // By hand (test_hand_curves): the curve 3 − ρ1 reaches 0 at ρ1 = 3, where P2's seed (3, 1, 0)
    // lies on P1(3). The overlap vertices (6, 1) and (6, 2) lie above the curve's negative part:
    // their witnesses are that seed, lifted.
    const OJ w = run_json("partition " + boxes + " --engine scan");
    const OJ& ov = w["regions"]["overlap"];
    BOOST_TEST_REQUIRE(ov["vertices"].size() == 4u);
    BOOST_TEST((ov["vertices"][0] == OJ::array({"2", "1"})));
    for (int k : {1, 2}) {
        BOOST_TEST(ov["vertices"][k][0] == "6");
        BOOST_TEST((ov["witnesses"][k]["point"] == OJ::array({"3", "1", "0"})));
    }
    // The walk's certificate under the structural mutations.
    mutate_and_report(w, "walk partition (boxes)", false);
}

BOOST_AUTO_TEST_CASE(a_single_rho1_at_a_switch_point_is_refused_by_partition) {
    // I1 = [18/13, 18/13], the switch point of the tetrahedron-on-box scene
    // (tests/data/tetra_on_box_curve_below_I2.json, derived there): a piece of no length has no
    // contact of its own; the engine refuses the range (exit 2), it does not stop with exit 3.
    OJ sc = load(fs::path(SCALECERT_SOURCE_DIR) / "tests/data/tetra_on_box_curve_below_I2.json");
    sc["I1"] = OJ::array({"18/13", "18/13"});
    const fs::path p = tmpdir() / "single_rho1_at_switch.json";
    save(sc, p);
    for (const char* e : {"hull", "scan"})
        BOOST_TEST(engine("partition " + p.string() + " --engine " + e + " --out " + (tmpdir() / "x.json").string()) ==
                   2);
    BOOST_TEST(engine("curve " + p.string() + " --out " + (tmpdir() / "x.json").string()) == 0);
    sc["I1"] = OJ::array({"18/13", "2"});  // a range from the switch point on: fine
    save(sc, p);
    BOOST_TEST(engine("partition " + p.string() + " --out " + (tmpdir() / "x.json").string()) == 0);
    BOOST_TEST(check_file(tmpdir() / "x.json") == 0);
}

BOOST_AUTO_TEST_CASE(overlap_region_equals_the_clip_by_every_line) {
    // Random convex, decreasing piecewise-linear curves over I1 (slopes increasing, neighbouring
    // lines meeting at the breakpoints) and random I2, including I2 ends through breakpoints, the
    // curve through a corner, rectangles without area, one piece and many: the region built from
    // the pieces equals the rectangle clipped by every line (the earlier O(K^2) method).
    std::mt19937_64 g(11);
    int cases = 0, empty = 0, points = 0, polygons = 0;
    for (int t = 0; t < 3000; ++t) {
        const size_t K = 1 + g() % (t % 10 == 0 ? 40 : 6);
        sc_::Scene sc;
        sc.lo[0] = cq(static_cast<long>(1 + g() % 4), static_cast<long>(1 + g() % 3));
        sc.hi[0] = t % 50 == 0 && K == 1
                       ? sc.lo[0]
                       : CQ(sc.lo[0] + cq(static_cast<long>(1 + g() % 9), static_cast<long>(1 + g() % 4)));
        std::vector<CQ> x{sc.lo[0]}, a;
        for (size_t k = 1; k < K; ++k)
            x.push_back(x.back() + cq(static_cast<long>(1 + g() % 5), static_cast<long>(1 + g() % 7)));
        const CQ stretch = (sc.hi[0] - sc.lo[0]) / (x.back() + 1 - sc.lo[0]);
        for (CQ& v : x) v = sc.lo[0] + (v - sc.lo[0]) * stretch;
        x.push_back(sc.hi[0]);
        for (size_t k = 0; k < K; ++k)
            a.push_back(-cq(static_cast<long>(1 + g() % 40), static_cast<long>(1 + g() % 5)));
        std::sort(a.begin(), a.end());
        a.erase(std::unique(a.begin(), a.end()), a.end());
        while (a.size() < K) a.push_back(a.back() / 2);  // still increasing and negative
        std::vector<sc_::Line> lines;
        std::vector<std::array<CQ, 2>> ranges;
        CQ y = rq(g, 20, 3) + 10;
        for (size_t k = 0; k < K; ++k) {
            lines.push_back({a[k], y - a[k] * x[k]});
            ranges.push_back({x[k], x[k + 1]});
            y = lines.back().at(x[k + 1]);
        }
        std::vector<CQ> ys;  // values the curve takes at breakpoints, and around them
        for (size_t k = 0; k <= K; ++k) ys.push_back(k < K ? lines[k].at(x[k]) : lines[K - 1].at(x[K]));
        auto pick = [&]() { return g() % 3 == 0 ? ys[g() % ys.size()] : ys[g() % ys.size()] + rq(g, 6, 4); };
        CQ lo2 = pick(), hi2 = pick();
        if (hi2 < lo2) std::swap(lo2, hi2);
        if (g() % 25 == 0) hi2 = lo2;
        if (sgn(lo2) <= 0) {
            hi2 += 1 - lo2;
            lo2 = 1;
        }
        sc.lo[1] = lo2;
        sc.hi[1] = hi2;
        const std::vector<sc_::P2> rect =
            sc_::normalize({{sc.lo[0], sc.lo[1]}, {sc.hi[0], sc.lo[1]}, {sc.hi[0], sc.hi[1]}, {sc.lo[0], sc.hi[1]}});
        BOOST_TEST(
            (rect ==
             ref_normalize({{sc.lo[0], sc.lo[1]}, {sc.hi[0], sc.lo[1]}, {sc.hi[0], sc.hi[1]}, {sc.lo[0], sc.hi[1]}})));
        std::vector<sc_::P2> want = rect;
        for (const sc_::Line& L : lines)
            if (!want.empty()) want = ref_clip(want, L, true);
        const std::vector<sc_::P2> got = sc_::overlap_region(sc, rect, lines, ranges);
        BOOST_TEST((got == want), "case " << t << ": " << got.size() << " vertices against " << want.size());
        ++cases;
        (want.empty() ? empty : want.size() < 3 ? points : polygons)++;
    }
    std::cout << "overlap regions compared: " << cases << " (" << empty << " empty, " << points
              << " of one or two points, " << polygons << " polygons)\n";
    BOOST_TEST(empty > 20);
    BOOST_TEST(points > 20);
    BOOST_TEST(polygons > 1000);
}

BOOST_AUTO_TEST_SUITE_END()
