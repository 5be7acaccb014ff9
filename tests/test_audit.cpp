// Golden data, certify-fp, and a small audit and stability sweep.
#define BOOST_TEST_MODULE audit
#include <boost/test/unit_test.hpp>

#include "baselines/audit.hpp"
#include "certify/claims.hpp"
#include "certify/classify.hpp"
#include "files.hpp"
#include "support.hpp"

#include <filesystem>
#include <map>
#include <set>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace scalecert::internal;

using test::slurp;

BOOST_AUTO_TEST_CASE(certify_fp_marks_hand_derived_claims) {
    // Stacked cubes: the touching line is ρ1 + ρ2 = 3 and ρ* = 3/2 (test_hand_curves).
    HullModel m = build_model(load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json"));
    TouchingCurve c = build_curve(m);
    long wrong = -1;
    std::string r = certify_fp(m, c,
                               "1 2 touching\n1 1.99 separated\n1 2.01 separated\n1 2.01 intersecting\n"
                               "curve 1 2\ncurve 1 2.000001\ngrowth 3/2\ngrowth 1.5000001\n",
                               "claims", false, false, &wrong);
    BOOST_TEST(wrong == 3);  // (1, 2.01) is overlapping; the curve is at 2; ρ* is 3/2 exactly
    BOOST_TEST(r.find("claims: 8, right: 5, wrong: 3") != std::string::npos);
    BOOST_CHECK_THROW(certify_fp(m, c, "1 2 maybe\n", "claims", false, false, &wrong), InputError);
    BOOST_CHECK_THROW(certify_fp(m, c, "-1 2 touching\n", "claims", false, false, &wrong), InputError);
}

BOOST_AUTO_TEST_CASE(golden_data_is_deterministic_and_exact) {
    fs::path a = test::scratch_dir("golden-a"), b = test::scratch_dir("golden-b");
    for (const std::string& fam : family_names()) {
        write_golden(fam, 1, 9, Q(1, 1 << 20), a.string());
        write_golden(fam, 1, 9, Q(1, 1 << 20), b.string());
        for (const char* ext : {".scene.json", ".golden.json", ".golden.csv"}) {
            std::string f = fam + "-0" + ext;
            BOOST_TEST(slurp(a / f) == slurp(b / f), f);
        }
        // Every golden verdict agrees with the brute-force classifier on the stored scene.
        ExactScene sc = load_scene((a / (fam + "-0.scene.json")).string());
        if (sc.P[0].points.size() > 20) continue;  // the brute force is quartic; near-spheres skip it
        test::Brute brute(sc);
        auto j = nlohmann::json::parse(slurp(a / (fam + "-0.golden.json")));
        int checked = 0;
        for (const auto& q : j["queries"]) {
            int want = q["verdict"] == "separated" ? 1 : q["verdict"] == "touching" ? 0 : -1;
            BOOST_TEST(brute.classify(sc, parse_exact(q["rho1"]), parse_exact(q["rho2"])) == want);
            if (q["where"] == "on") BOOST_TEST(q["verdict"] == "touching");
            ++checked;
        }
        BOOST_TEST(checked > 10);
    }
    fs::remove_all(a);
    fs::remove_all(b);
}

BOOST_AUTO_TEST_CASE(small_audit_and_stability_sweep) {
    // Every method gives a row per ε (and the grid two per resolution); the exact engine's row
    // finds every junction.
    std::vector<AuditRow> rows;
    for (int k : {4, 16, 30}) {
        Rng g(3);
        Q eps(1, Z(1) << k);
        auto r = audit_scene("nearly-equal-slopes", make_family_scene("nearly-equal-slopes", eps, g), eps,
                             {"libccd-gjk", "libccd-mpr", "double-envelope", "grid"}, {16, 64});
        rows.insert(rows.end(), r.begin(), r.end());
    }
    int query_rows = 0, curve_rows = 0;
    for (const AuditRow& r : rows) {
        if (r.has_curve) {
            ++curve_rows;
            if (r.method == "scalecert (exact)") BOOST_TEST(r.junctions_missed == 0);
            // The Appendix's equations put a junction they find at the exact switch up to rounding,
            // which the slope difference (about ε) amplifies: a tight bound only for ε = 2^-4.
            if (r.method.rfind("grid+analytical", 0) == 0 && r.eps == Q(1, 16) && r.exact_junctions > r.junctions_missed)
                BOOST_TEST(r.max_junction_error < 1e-9);
        } else {
            ++query_rows;
            BOOST_TEST(r.queries > 200);
            BOOST_TEST(r.false_separated + r.false_overlapping <= r.queries);
        }
    }
    BOOST_TEST(query_rows == 9);
    BOOST_TEST(curve_rows == 15);  // per ε: the exact row, and per resolution bisection and analytical
    std::string csv = audit_csv(rows);
    BOOST_TEST(std::count(csv.begin(), csv.end(), '\n') == static_cast<long>(rows.size()) + 1);
}

BOOST_AUTO_TEST_CASE(baselines_agree_away_from_the_curve) {
    // A small audit: away from the curve (|ρ2 − f(ρ1)| > 1/10) every baseline (libccd GJK and MPR,
    // FCL with either GJK, Bullet, the paper's triangle test, plain doubles) must agree with the
    // exact verdict; this checks their wiring, not their precision.
    HullModel m = build_model(load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/fig5_vf_ve_ee.json"));
    TouchingCurve c = build_curve(m);
    fp::FpScene f = fp::to_fp(m.scene);
    std::vector<std::unique_ptr<fp::Method>> methods;
    methods.push_back(fp::make_libccd_gjk(f));
    methods.push_back(fp::make_libccd_mpr(f));
    methods.push_back(fp::make_double_envelope(m, f));
    methods.push_back(fp::make_fcl(m, f, true));
    methods.push_back(fp::make_fcl(m, f, false));
    methods.push_back(fp::make_bullet(f));
    methods.push_back(fp::make_paper_tritri(m, f));
    int checked = 0;
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 40; ++j) {
            Q r1 = Q(4, 5) + Q(11, 200) * i, r2 = Q(4, 5) + Q(11, 200) * j;
            Q f1 = c.env.value(m.lines, r1);
            if (abs(r2 - f1) < Q(1, 10)) continue;
            int e = r2 < f1 ? 1 : -1;
            for (const auto& meth : methods) BOOST_TEST(meth->classify(r1.get_d(), r2.get_d()) == e, meth->name());
            ++checked;
        }
    BOOST_TEST(checked > 1000);
}

// ---- campaigns (issue 12): hashes, shard plans, and per-scene seeds -----------------------------
#include "campaign/campaign.hpp"
#include "geometry/measures.hpp"

BOOST_AUTO_TEST_CASE(sha256_known_answers) {
    // FIPS 180-4's examples: one block, the empty message, and a message that spills into a second block.
    BOOST_TEST(sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    BOOST_TEST(sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    BOOST_TEST(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
               "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    BOOST_TEST(sha256_hex(std::string(1000000, 'a')) == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

BOOST_AUTO_TEST_CASE(shard_plans_cover_every_scene_once) {
    CampaignArgs a;
    a.scenes = {"x.json", "y.json"};
    a.family = "random";
    a.sweep_from = 3;
    a.sweep_to = 5;
    a.count = 10;
    a.shard_size = 4;
    const std::vector<Shard> p = plan(a);
    BOOST_TEST(p.size() == 2u + 3u * 3u);  // two files, then 3 values of k × ceil(10/4) ranges
    std::map<std::pair<int, int>, int> seen;
    for (size_t i = 0; i < p.size(); ++i) {
        BOOST_TEST(p[i].index == static_cast<int>(i));
        if (p[i].scene_file >= 0) continue;
        for (int s = p[i].first; s < p[i].last; ++s) ++seen[{p[i].k, s}];
    }
    BOOST_TEST(seen.size() == 30u);
    for (const auto& [key, n] : seen) BOOST_TEST(n == 1);
    // A scene's seed depends on the run's seed, k and its index only (not on the shard size).
    std::set<std::uint64_t> seeds;
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 100; ++i) seeds.insert(scene_seed(7, k, i));
    BOOST_TEST(seeds.size() == 300u);
    BOOST_TEST(scene_seed(7, 1, 2) != scene_seed(8, 1, 2));
}

// ---- JSON claims (issue 11): every kind, against values worked out by hand ----------------------
namespace {

struct Claims {
    HullModel m;
    TouchingCurve c;
    explicit Claims(const ExactScene& s) : m(build_model(s)), c(build_curve(m)) {}
    explicit Claims(const std::string& bundled)
        : Claims(load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/" + bundled + ".json")) {}
    // The report of one claim (JSON), and whether it was right. These cases read decimals exactly
    // (exact_decimals) unless binary_doubles.
    nlohmann::json one(const std::string& claim, const std::string& tolerance = "0", bool binary_doubles = false) {
        long wrong = -1;
        const std::string r = certify_fp(m, c, "{\"format\": \"scalecert-claims-1\", \"claims\": [" + claim + "]}", "c.json",
                                         ClaimOptions{!binary_doubles, parse_exact(tolerance), true}, &wrong);
        auto j = nlohmann::json::parse(r)["claims"][0];
        BOOST_TEST(wrong == (j["right"].get<bool>() ? 0 : 1));
        return j;
    }
    bool right(const std::string& claim, const std::string& tolerance = "0", bool binary_doubles = false) {
        return one(claim, tolerance, binary_doubles)["right"].get<bool>();
    }
};

std::vector<Vec3q> cube(long x0, long y0, long z0, long side) {
    std::vector<Vec3q> v;
    for (long x : {x0, x0 + side})
        for (long y : {y0, y0 + side})
            for (long z : {z0, z0 + side}) v.push_back({Q(x), Q(y), Q(z)});
    return v;
}

}  // namespace

BOOST_AUTO_TEST_CASE(curve_claim_rules) {
    // CLAIMS.md, "Curve claims", rule by rule. The tetrahedron on the box (test_hand_curves) with
    // I1 narrowed to [1/2, 3/4]: the exact curve is (V,F) ρ2 = 9/2 − 5ρ1/2 for 0 < ρ1 ≤ 1 and (E,E)
    // ρ2 = (18 − 4ρ1)/7 on [1, 27/13], so its switch point (1, 2) now lies outside I1.
    ExactScene sc = load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/tetra_box_switch.json");
    sc.hi[0] = Q(3, 4);
    Claims k(sc);
    auto refused = [&](const std::string& claim) {
        try {
            k.one(claim);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    // Rule 2 outside I1: the chord from (1/2, 13/4) to (3/2, 12/7) is exact at both ends, but at the
    // switch point it gives 13/4 + (12/7 − 13/4)/2 = 139/56 where f(1) = 2: off by 27/56.
    auto j = k.one(R"({"kind": "curve", "vertices": [["1/2", "13/4"], ["3/2", "12/7"]], "switch_points": []})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["max_vertical_error"] == "27/56");
    BOOST_TEST(j["max_vertical_error_at_rho1"] == "1");
    BOOST_TEST(j["switch_points_missed"] == nlohmann::json::parse(R"([["1", "2"]])"));
    // The exact curve outside I1, with its labels, is right (its switch point is no longer "extra").
    BOOST_TEST(k.right(R"({"kind": "curve", "pieces": [
        {"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2", "contact": "VF"},
        {"rho1": [1, "3/2"], "slope": "-4/7", "intercept": "18/7", "contact": "EE"}]})"));
    BOOST_TEST(k.right(R"({"kind": "switch_point", "rho1": 1, "rho2": 2, "contact": "VE"})"));
    // Curve points: f(1/2) = 9/2 − 5/4 = 13/4, f(3/2) = (18 − 6)/7 = 12/7; the double nearest
    // 12/7 is right within 1e-15 but not exactly.
    BOOST_TEST(k.right(R"({"kind": "curve_point", "rho1": "1/2", "rho2": "13/4"})"));
    BOOST_TEST(k.right(R"({"kind": "curve_point", "rho1": "3/2", "rho2": "12/7"})"));
    BOOST_TEST(!k.right(R"({"kind": "curve_point", "rho1": "3/2", "rho2": 1.7142857142857142})"));
    BOOST_TEST(k.right(R"({"kind": "curve_point", "rho1": "3/2", "rho2": 1.7142857142857142})", "1e-15"));
    BOOST_TEST(!k.right(R"({"kind": "curve_point", "rho1": 1, "rho2": "2.001"})", "1e-4"));
    // Rule 3 at the ends: a range ending at the switch point may list it or not; listed with the
    // wrong ρ2 it is misplaced. Starting there, likewise.
    const std::string first = R"({"kind": "curve", "pieces": [{"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2"}])";
    BOOST_TEST(k.right(first + "}"));
    BOOST_TEST(k.right(first + R"(, "switch_points": [[1, 2]]})"));
    j = k.one(first + R"(, "switch_points": [[1, 999]]})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["switch_points_misplaced"].size() == 1u);
    BOOST_TEST(j["switch_points_misplaced"][0]["claimed_rho2"] == "999");
    BOOST_TEST(k.right(R"({"kind": "curve", "vertices": [[1, 2], ["3/2", "12/7"]], "switch_points": [[1, 2]]})"));
    // Rule 3 inside: the switch point's ρ2 is compared too, between pieces and as a claim.
    j = k.one(R"({"kind": "curve", "pieces": [
        {"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2"},
        {"rho1": [1, "3/2"], "slope": "-4/7", "intercept": "18/7"}], "switch_points": [[1, 999]]})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["switch_points_misplaced"].size() == 1u);
    BOOST_TEST(!k.right(R"({"kind": "switch_point", "rho1": 1, "rho2": 999})"));
    BOOST_TEST(k.right(R"({"kind": "switch_point", "rho1": 1, "rho2": "2.0000001"})", "1e-7"));
    BOOST_TEST(!k.right(R"({"kind": "switch_point", "rho1": 1, "rho2": "2.0000003"})", "1e-7"));
    // Scalings <= 0 are refused in every form, and so are switch points outside the range and
    // pieces with gaps between them.
    BOOST_TEST(refused(R"({"kind": "curve", "vertices": [[0, "9/2"], [1, 2]]})").find("scalings must be > 0") != std::string::npos);
    BOOST_TEST(refused(R"({"kind": "curve", "vertices": [[1, 2], [2, 0]]})").find("scalings must be > 0") != std::string::npos);
    // The message names the scaling at fault, with its value.
    BOOST_TEST(refused(R"({"kind": "verdict", "rho1": 1, "rho2": -1, "verdict": "separated"})").find("rho2: scalings must be > 0 (got -1)") !=
               std::string::npos);
    BOOST_TEST(refused(R"({"kind": "distance", "rho1": 0, "rho2": 1, "value": 1})").find("rho1: scalings must be > 0 (got 0)") !=
               std::string::npos);
    BOOST_TEST(refused(R"({"kind": "curve", "pieces": [{"rho1": [1, 5], "slope": "-4/7", "intercept": "18/7"}]})")
                   .find("rho2 <= 0") != std::string::npos);  // (18 − 20)/7 < 0 at ρ1 = 5
    BOOST_TEST(refused(R"({"kind": "curve", "vertices": [[1, 2], ["3/2", "12/7"]], "switch_points": [[-1, 2]]})") != "accepted");
    BOOST_TEST(refused(R"({"kind": "curve", "vertices": [[1, 2], ["3/2", "12/7"]], "switch_points": [[2, "10/7"]]})")
                   .find("outside the claimed range") != std::string::npos);
    BOOST_TEST(refused(R"({"kind": "curve", "pieces": [
        {"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2"},
        {"rho1": ["11/10", "3/2"], "slope": "-4/7", "intercept": "18/7"}]})").find("start where") != std::string::npos);
    BOOST_TEST(refused(R"({"kind": "switch_point", "rho1": 1, "rho2": -2})") != "accepted");
    BOOST_TEST(refused(R"({"kind": "growth_distance", "value": "-18/11"})").find(">= 0") != std::string::npos);
    long wrong = -1;
    for (const char* line : {"curve 1 0\n", "curve 0 9/2\n", "curve 1 -2\n", "growth -1\n"})
        BOOST_CHECK_THROW(certify_fp(k.m, k.c, line, "c.txt", ClaimOptions{true, Q(0), false}, &wrong), InputError);
    BOOST_TEST(certify_fp(k.m, k.c, "curve 1 2\ncurve 3/2 12/7\n", "c.txt", ClaimOptions{true, Q(0), false}, &wrong).find("wrong: 0") !=
               std::string::npos);
    // Rule 4 at a switch point: the chord over [1/2, 3/2] (within a tolerance of 1/2 of the curve)
    // has its midpoint at the switch point (1, 2), whose contact is VE (the hostile review: EE,
    // the next piece's, was judged right there and VE wrong).
    const std::string chord = R"({"kind": "curve", "pieces": [{"rho1": ["1/2", "3/2"], "slope": "-43/28", "intercept": "225/56", "contact": ")";
    BOOST_TEST(k.right(chord + R"(VE"}], "switch_points": [[1, 2]]})", "1/2"));
    j = k.one(chord + R"(EE"}], "switch_points": [[1, 2]]})", "1/2");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["wrong_contacts"][0]["exact"] == "VE");
    // Rule 1: the stacked cubes' curve ρ2 = 3 − ρ1 (one (F,F) line for every ρ1 > 0) reaches 0 at
    // ρ1 = 3. A claim that stays above 0 up to ρ1 = 4 is wrong, however large the tolerance.
    Claims cubes("stacked_cubes");
    j = cubes.one(R"({"kind": "curve", "vertices": [[1, 2], [4, "1/1000"]]})", "1000");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(!j["exact_rho2_positive_over_range"].get<bool>());
    BOOST_TEST(cubes.right(R"({"kind": "curve", "vertices": [[1, 2], ["5/2", "1/2"]], "switch_points": []})"));
}

BOOST_AUTO_TEST_CASE(claimed_planes_must_separate_exactly) {
    // Stacked cubes at (1, 1): P1 = [0,2]^3 reaches z = 2, P2 = [0,2]^2 x [3,5] starts at z = 3.
    Claims k("stacked_cubes");
    BOOST_TEST(k.right(R"({"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0, 0, 1], "offset": 2.5})"));
    // The plane z = 2 − 10^-17 leaves P1's top vertices on the wrong side by 10^-17.
    auto j = k.one(R"({"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0, 0, 1], "offset": "1.99999999999999999"})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["offset_minus_P1"] == "-1/100000000000000000");
    // A correct plane with rounded coefficients (the doubles nearest 0.1, 1e-3 and 2.6): still
    // strictly between P1 (max 0.1·2 + 0.002 + 2 ≈ 2.202) and P2 (min 3).
    BOOST_TEST(k.right(R"({"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0.1, 0.001, 1], "offset": 2.6})", "0", true));
    // At a touching pair no plane separates strictly, and the normal's direction matters.
    BOOST_TEST(!k.right(R"({"kind": "separating_plane", "rho1": 1.5, "rho2": 1.5, "normal": [0, 0, 1]})"));
    BOOST_TEST(!k.right(R"({"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0, 0, -1]})"));
    // A witness point: (1, 1, 5/2) is in both at (3/2, 3/2); 2.5 + 10^-17 is above P1(3/2).
    BOOST_TEST(k.right(R"({"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [1, 1, 2.5]})"));
    j = k.one(R"({"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [1, 1, "2.50000000000000001"]})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(!j["in_P1"].get<bool>());
    BOOST_TEST(j["in_P2"].get<bool>());
}

BOOST_AUTO_TEST_CASE(distances_and_depths_by_hand) {
    // Unit-side... side-2 cubes [0,2]^3 and [3,5] x [0,2] x [3,5], seeds at their centres: at (1, 1)
    // they are 1 apart in x and 1 apart in z, and overlap in y: the closest features are two edges,
    // the squared distance 1 + 1 = 2, attained from (2, y, 2) to (3, y, 3).
    ExactScene s;
    s.P[0].points = cube(0, 0, 0, 2);
    s.P[1].points = cube(3, 0, 3, 2);
    s.lo[0] = s.lo[1] = Q(1, 2);
    s.hi[0] = s.hi[1] = Q(3);
    finish_scene(s, "diagonal cubes");
    Claims k(s);
    const ExactDistance d = exact_distance(k.m, Q(1), Q(1));
    BOOST_TEST(d.squared == Q(2));
    BOOST_TEST(d.p1[0] == Q(2));
    BOOST_TEST(d.p1[2] == Q(2));
    BOOST_TEST(d.p2[0] == Q(3));
    BOOST_TEST(d.p2[2] == Q(3));
    // At (1, 1/2): P2(1/2) = [3.5, 4.5] x [0.5, 1.5] x [3.5, 4.5]: gaps 1.5 and 1.5, squared 9/2.
    BOOST_TEST(exact_distance(k.m, Q(1), Q(1, 2)).squared == Q(9, 2));
    // sqrt(2) as a double is not the distance; within 10^-15 it is.
    auto j = k.one(R"({"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.4142135623730951})", "0", true);
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["exact_squared"] == "2");
    const double err = j["abs_error_double"].get<double>();
    BOOST_TEST((err > 0 && err < 2.3e-16));  // |fl(√2) − √2| < ulp(√2)/2 = 1.1e-16
    BOOST_TEST(k.right(R"({"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.4142135623730951})", "1e-15", true));
    BOOST_TEST(k.right(R"({"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.4142135623730951,
                           "closest": [[2, 1, 2], [3, 1, 3]]})", "1e-15", true));
    BOOST_TEST(!k.right(R"({"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.4142135623730951,
                            "closest": [[2, 1, 2], [3, 1, 4]]})", "1e-15", true));  // |(1,0,2)|² = 5
    // Meeting bodies have distance 0: at (2, 2) P1(2) = [-1,3]^3 and P2(2) = [2,6] x [-1,3] x [2,6].
    BOOST_TEST(exact_distance(k.m, Q(2), Q(2)).squared == Q(0));

    // Penetration depth, stacked cubes at (2, 5/2): P1(2) = [-1,3]^3, P2(5/2) = [-1.5,3.5]^2 x
    // [1.5, 6.5]. Separating along z needs 3 − 1.5 = 3/2; along x, 3 + 1.5 = 9/2; so the depth is
    // 3/2 (squared 9/4) along (0,0,1), and 9/2 along (1,0,0).
    Claims st("stacked_cubes");
    const ExactDepth e = exact_penetration_depth(st.m, all_facet_normals(st.m), Q(2), Q(5, 2));
    BOOST_TEST(e.squared == Q(9, 4));
    BOOST_TEST((e.direction == Vec3z{Z(0), Z(0), Z(1)}));
    BOOST_TEST(directional_depth_squared(st.m, {Q(1), Q(0), Q(0)}, Q(2), Q(5, 2)) == Q(81, 4));
    BOOST_TEST(st.right(R"({"kind": "penetration_depth", "rho1": 2, "rho2": 2.5, "value": 1.5, "direction": [0, 0, 1]})"));
    j = st.one(R"({"kind": "penetration_depth", "rho1": 2, "rho2": 2.5, "value": 1.5, "direction": [1, 0, 0]})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(!j["direction_right"].get<bool>());
    BOOST_TEST(!st.right(R"({"kind": "penetration_depth", "rho1": 2, "rho2": 2.5, "value": 1.4})"));
    BOOST_TEST(!st.right(R"({"kind": "penetration_depth", "rho1": 1, "rho2": 1, "value": 0})"));  // separated
    // Touching: depth 0.
    BOOST_TEST(st.right(R"({"kind": "penetration_depth", "rho1": 1.5, "rho2": 1.5, "value": 0})"));
}

BOOST_AUTO_TEST_CASE(claimed_curves_switches_and_labels) {
    // The tetrahedron on the box (test_hand_curves): (V,F) ρ2 = 9/2 − 5ρ1/2 on [1/2, 1], then
    // (E,E) ρ2 = (18 − 4ρ1)/7, switching at (1, 2) with a (V,E) contact; ρ* = 18/11.
    Claims k("tetra_box_switch");
    const std::string exact_pieces = R"({"kind": "curve", "pieces": [
        {"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2", "contact": "VF"},
        {"rho1": [1, 2], "slope": "-4/7", "intercept": "18/7", "contact": "EE"}]})";
    BOOST_TEST(k.right(exact_pieces));
    // A wrong label on the second piece.
    auto j = k.one(R"({"kind": "curve", "pieces": [
        {"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2", "contact": "VF"},
        {"rho1": [1, 2], "slope": "-4/7", "intercept": "18/7", "contact": "FE"}]})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["wrong_contacts"].size() == 1u);
    BOOST_TEST(j["wrong_contacts"][0]["exact"] == "EE");
    // The switch moved to ρ1 = 101/100: misplaced, and the curve is off there.
    j = k.one(R"({"kind": "curve", "pieces": [
        {"rho1": ["1/2", "101/100"], "slope": "-5/2", "intercept": "9/2"},
        {"rho1": ["101/100", 2], "slope": "-4/7", "intercept": "18/7"}]})");
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["switch_points_misplaced"].size() == 1u);
    BOOST_TEST(j["switch_points_misplaced"][0]["claimed_rho1"] == "101/100");
    // At 101/100 the claimed first piece gives 9/2 − 5/2 · 101/100 = 79/40, and the exact (E,E)
    // line (18 − 404/100)/7 = 349/175: error 79/40 − 349/175 = (2765 − 2792)/1400 = −27/1400.
    BOOST_TEST(j["max_vertical_error"] == "27/1400");
    BOOST_TEST(j["max_vertical_error_at_rho1"] == "101/100");
    // A polyline that skips the switch: from (1/2, 13/4) to (2, 10/7), at ρ1 = 1 it gives
    // 13/4 + (10/7 − 13/4)/3 = 37/14 where the curve is 2: error 9/14, and the switch is missed.
    j = k.one(R"({"kind": "curve", "vertices": [["1/2", "13/4"], [2, "10/7"]]})");
    BOOST_TEST(j["max_vertical_error"] == "9/14");
    BOOST_TEST(j["max_vertical_error_at_rho1"] == "1");
    BOOST_TEST(j["switch_points_missed"].size() == 1u);
    BOOST_TEST(k.right(R"({"kind": "curve", "vertices": [["1/2", "13/4"], [1, 2], [2, "10/7"]], "switch_points": [[1, 2]]})"));
    BOOST_TEST(k.right(R"({"kind": "curve", "vertices": [["1/2", "13/4"], [1, 2], [2, "10/7"]]})"));  // its bend is the switch
    // The paper's grid (libccd GJK at 8 × 8 nodes, bisection) as a sampled curve that claims no
    // switch point: the (V,E) switch at ρ1 = 1 is reported missing, and the samples are off.
    {
        const fp::FpScene f = fp::to_fp(k.m.scene);
        const fp::GridCurve g = fp::grid_search(*fp::make_libccd_gjk(f), f, 8, 20, 3);
        std::string vs;
        for (size_t i = 0; i < g.rho1.size(); ++i) {
            char b[80];
            std::snprintf(b, sizeof b, "%s[%.17g, %.17g]", i ? ", " : "", g.rho1[i], g.rho2[i]);
            vs += b;
        }
        j = k.one(R"({"kind": "curve", "vertices": [)" + vs + R"(], "switch_points": []})", "0", true);
        BOOST_TEST(!j["right"].get<bool>());
        BOOST_TEST(j["switch_points_missed"] == nlohmann::json::parse(R"([["1", "2"]])"));
        BOOST_TEST(parse_exact(j["max_vertical_error"].get<std::string>()) > 0);
    }
    // An extra switch point.
    j = k.one(R"({"kind": "curve", "vertices": [["1/2", "13/4"], [1, 2], [2, "10/7"]], "switch_points": [[1, 2], ["3/2", "12/7"]]})");
    BOOST_TEST(j["switch_points_extra"].size() == 1u);
    // Switch points and the growth distance, exact or within a tolerance.
    BOOST_TEST(k.right(R"({"kind": "switch_point", "rho1": 1, "rho2": 2, "contact": "VE"})"));
    // Curve points: f(1/2) = 9/2 − 5/4 = 13/4, f(3/2) = (18 − 6)/7 = 12/7; the double nearest
    // 12/7 is right within 1e-15 but not exactly.
    BOOST_TEST(k.right(R"({"kind": "curve_point", "rho1": "1/2", "rho2": "13/4"})"));
    BOOST_TEST(k.right(R"({"kind": "curve_point", "rho1": "3/2", "rho2": "12/7"})"));
    BOOST_TEST(!k.right(R"({"kind": "curve_point", "rho1": "3/2", "rho2": 1.7142857142857142})"));
    BOOST_TEST(k.right(R"({"kind": "curve_point", "rho1": "3/2", "rho2": 1.7142857142857142})", "1e-15"));
    BOOST_TEST(!k.right(R"({"kind": "curve_point", "rho1": 1, "rho2": "2.001"})", "1e-4"));
    BOOST_TEST(!k.right(R"({"kind": "switch_point", "rho1": 1, "rho2": 2, "contact": "VV"})"));
    BOOST_TEST(!k.right(R"({"kind": "switch_point", "rho1": "1.0000001", "rho2": 2})"));
    BOOST_TEST(k.right(R"({"kind": "switch_point", "rho1": "1.0000001", "rho2": 2})", "1e-6"));
    BOOST_TEST(k.right(R"({"kind": "growth_distance", "value": "18/11"})"));
    j = k.one(R"({"kind": "growth_distance", "value": 1.6363636363636365})", "0", true);
    BOOST_TEST(!j["right"].get<bool>());
    BOOST_TEST(j["exact"] == "18/11");
    BOOST_TEST(k.right(R"({"kind": "growth_distance", "value": 1.6363636363636365})", "1e-15", true));
}

BOOST_AUTO_TEST_CASE(malformed_claims_get_one_line) {
    Claims k("stacked_cubes");
    auto err = [&](const std::string& text) {
        long wrong = 0;
        try {
            certify_fp(k.m, k.c, text, "c.json", ClaimOptions{true, Q(0), false}, &wrong);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    BOOST_TEST(err(R"({"format": "scalecert-claims-1", "claims": [{"kind": "area"}]})").find("claims[0].kind: unknown kind 'area'") != std::string::npos);
    BOOST_TEST(err(R"({"format": "scalecert-claims-1", "claims": [{"kind": "distance", "rho1": 1, "rho2": 1}]})") == "c.json: claims[0].value: missing");
    BOOST_TEST(err(R"({"format": "scalecert-claims-1", "claims": [{"kind": "growth_distance", "value": 1, "valu": 2}]})") == "c.json: claims[0].valu: unknown field");
    BOOST_TEST(err(R"({"format": "scalecert-claims-2", "claims": []})").find("format") != std::string::npos);
    BOOST_TEST(err(R"({"format": "scalecert-claims-1", "claims": [], "claims": []})").find("duplicate") != std::string::npos);
    BOOST_TEST(err(R"({"format": "scalecert-claims-1", "claims": [{"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0, 0, 0]}]})").find("normal") != std::string::npos);
    BOOST_TEST(err(R"({"format": "scalecert-claims-1", "claims": [{"kind": "verdict", "rho1": 0, "rho2": 1, "verdict": "separated"}]})").find("> 0") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(baseline_measures_follow_one_convention) {
    // Stacked cubes (test_hand_curves): at (2, 5/2) the depth is 3/2 along (0,0,1), P1 towards P2
    // (distances_and_depths_by_hand); at (1, 1/2) the distance is 3/2 (P1's top z = 2, P2(1/2)'s
    // bottom z = 3.5). Each adapter reports its library's values in that convention: libccd's
    // direction moves P2, FCL's normal points from P1 to P2, Bullet's is negated.
    ExactScene s = load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json");
    HullModel m = build_model(s);
    fp::FpScene f = fp::to_fp(s);
    for (const char* name : {"libccd-gjk", "libccd-mpr", "fcl-gjk-libccd", "fcl-gjk-indep", "bullet-gjk-epa"}) {
        auto mm = fp::make_method(name, m, f);
        auto d = mm->measure(2, 2.5, false);
        BOOST_TEST_REQUIRE(d.has_value(), name);
        BOOST_TEST(d->depth);
        // FCL's own GJK returns the depth negated: the audit reports that as a relative error of 2.
        BOOST_TEST(std::fabs(std::fabs(d->value) - 1.5) < 1e-12, name << " depth " << d->value);
        BOOST_TEST_REQUIRE(d->direction.has_value(), name);
        BOOST_TEST((*d->direction)[2] > 0.999, name);
        auto e = mm->measure(1, 0.5, true);
        if (std::string(name).rfind("libccd", 0) == 0) {
            BOOST_TEST(!e.has_value(), name);  // libccd has no distance query
            continue;
        }
        BOOST_TEST_REQUIRE(e.has_value(), name);
        BOOST_TEST(std::fabs(e->value - 1.5) < 1e-6, name << " distance " << e->value);
    }
    // The audit row's counts: every right verdict with a measure is compared with the exact value.
    const std::vector<AuditRow> rows = audit_scene("cubes", s, Q(0), {"fcl-gjk-libccd"}, {});
    BOOST_TEST(rows[0].distances > 50);
    BOOST_TEST(rows[0].depths > 50);
    // --no-measures: the same verdict counts, no distances or depths compared.
    const std::vector<AuditRow> v = audit_scene("cubes", s, Q(0), {"fcl-gjk-libccd"}, {}, false, false);
    BOOST_TEST(v[0].distances == 0);
    BOOST_TEST(v[0].depths == 0);
    BOOST_TEST(v[0].false_separated == rows[0].false_separated);
    BOOST_TEST(v[0].false_overlapping == rows[0].false_overlapping);
}

BOOST_AUTO_TEST_CASE(wrong_verdicts_by_distance_from_the_curve) {
    // Stacked cubes: f(ρ1) = 3 − ρ1 > 0 on all 15 verticals of [1/2, 5/2], so each k has 30 pairs,
    // each either scored or, when rounding to doubles lands exactly on the curve, touching.
    ExactScene s = load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json");
    const std::vector<AuditRow> rows = audit_scene("cubes", s, Q(0), {"libccd-gjk", "double-envelope"}, {}, true);
    for (const AuditRow& r : rows) {
        if (r.has_curve) continue;
        BOOST_TEST_REQUIRE(r.by_distance.size() == 13u);
        for (const AuditRow::ByDistance& b : r.by_distance) {
            BOOST_TEST(b.pairs + b.touching == 30);
            BOOST_TEST(b.wrong <= b.pairs);
        }
        // At 2^-4 of the curve (a sixteenth of ρ2 ≥ 1/2: at least 1/32 away) every method is right.
        BOOST_TEST(r.by_distance[0].wrong == 0, r.method);
    }
    // Without the option, nothing is added.
    BOOST_TEST(audit_scene("cubes", s, Q(0), {"libccd-gjk"}, {})[0].by_distance.empty());
}

BOOST_AUTO_TEST_CASE(rows_with_nan_survive_the_shard_round_trip) {
    // The paper's grid at n = 16 on the thin boxes of FCL issue #399 never crosses ρ1 = ρ2, so its
    // growth error is NaN. Rows pass through shard text (JSON, which has no NaN) on their way to the
    // outputs; that once threw "type must be number, but is null".
    CampaignArgs a;
    a.auditor = baseline_auditor();
    a.scenes = {std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/reported_fcl399_thin_boxes.json"};
    a.methods = {"grid"};
    a.grid = {16};
    a.no_timing = true;
    const fs::path dir = test::scratch_dir("nan-rows");
    a.out = (dir / "a.json").string();
    a.csv = (dir / "a.csv").string();
    BOOST_TEST(run_campaign(a) == 3);  // the exact engine's row and the grid's two
    const std::string csv = slurp(dir / "a.csv");
    BOOST_TEST(csv.find(",16,,nan,") != std::string::npos, csv);
    // The same rows straight from audit_scene, written without the round trip.
    const std::vector<AuditRow> rows = audit_scene(a.scenes[0], load_scene(a.scenes[0]), Q(0), a.methods, a.grid);
    BOOST_TEST(audit_csv(rows, false) == csv);
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(campaigns_are_keyed_by_the_contents_of_their_inputs) {
    // The run's identity and each scene shard record [path, SHA-256] of every file read: the scene
    // and the mesh it names. A shard computed from other contents than the run's is found stale.
    const fs::path dir = test::scratch_dir("content-keys");
    const std::string mesh = (dir / "t.obj").string(), sc = (dir / "s.json").string();
    const std::string obj = "v 2 0 2\nv -2 2 5\nv -1 -2 6\nv 2 0 7\n";
    std::ofstream(mesh, std::ios::binary) << obj;
    const std::string scene_text = "{\"P1\": {\"mesh\": \"t.obj\"}, \"P2\": {\"vertices\": [[-1,-1,-1],[1,-1,-1],[-1,1,-1],[1,1,-1],"
                                   "[-1,-1,1],[1,-1,1],[-1,1,1],[1,1,1]]}, \"I1\": [0.5, 2], \"I2\": [1, 4]}";
    std::ofstream(sc, std::ios::binary) << scene_text;
    CampaignArgs a;
    a.auditor = baseline_auditor();
    a.scenes = {sc};
    a.methods = {"libccd-gjk"};
    const Json inputs = campaign_inputs(a);
    BOOST_TEST(inputs.dump() == Json::array({Json::array({sc, sha256_hex(scene_text)}), Json::array({mesh, sha256_hex(obj)})}).dump());
    BOOST_TEST(campaign_identity(a, inputs).find(sha256_hex(obj)) != std::string::npos);
    const std::string shard = run_shard(a, plan(a)[0]);
    BOOST_TEST(Json::parse(shard).at("inputs") == inputs);
    BOOST_TEST(stale_input(inputs, shard).empty());
    // The mesh changes: the inputs now differ, and the old shard is stale, naming the mesh.
    std::ofstream(mesh, std::ios::binary | std::ios::app) << "v 0 0 9\n";
    const Json changed = campaign_inputs(a);
    BOOST_TEST(campaign_identity(a, changed) != campaign_identity(a, inputs));
    BOOST_TEST(stale_input(changed, shard) == mesh);
    // Golden and family runs read no files; standard input cannot be checked again, so is refused.
    CampaignArgs f;
    f.family = "random";
    BOOST_TEST(campaign_inputs(f).empty());
    a.scenes = {"-"};
    BOOST_CHECK_THROW(campaign_inputs(a), InputError);
    fs::remove_all(dir);
}
