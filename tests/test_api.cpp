// The public API (include/scalecert/scalecert.hpp) alone: values derived by hand.
#include <boost/test/unit_test.hpp>

#include <scalecert/scalecert.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <nlohmann/json.hpp>
#include <unistd.h>
#include <string>

using scalecert::Rational;
using R = Rational;

namespace {

std::vector<scalecert::Point> box(long x0, long y0, long z0, long x1, long y1, long z1) {
    std::vector<scalecert::Point> v;
    for (long x : {x0, x1})
        for (long y : {y0, y1})
            for (long z : {z0, z1}) v.push_back({R(x), R(y), R(z)});
    return v;
}

// The stacked cubes: [0,2]^3 below [0,2]^2 x [3,5], seeds the centres (1,1,1) and (1,1,4). The
// gap between the scaled cubes along z is (4 − 2ρ2/2·... ) : P1(ρ1) reaches z = 1 + ρ1, P2(ρ2)
// starts at z = 4 − ρ2, so they touch on ρ1 + ρ2 = 3, face to face (FF); ρ* = 3/2.
scalecert::Scene stacked(R lo = R(1, 2), R hi = R(5, 2)) {
    return scalecert::Scene(box(0, 0, 0, 2, 2, 2), box(0, 0, 3, 2, 2, 5), {lo, hi}, {lo, hi});
}

template <class F>
std::string error_of(F f) {
    try {
        f();
    } catch (const scalecert::InputError& e) {
        return e.what();
    }
    return "";
}

// Whether scalecert-check accepts the certificate `text` (written to a temporary file).
bool checker_accepts(const std::string& text) {
    static int n = 0;
    const std::string path =
        "/tmp/scalecert-test-api-" + std::to_string(::getpid()) + "-" + std::to_string(++n) + ".json";
    std::FILE* out = std::fopen(path.c_str(), "wb");
    if (!out) return false;
    std::fwrite(text.data(), 1, text.size(), out);
    std::fclose(out);
    const int st = std::system((std::string(SCALECERT_CHECK_BIN) + " " + path + " >/dev/null").c_str());
    std::remove(path.c_str());
    return st == 0;
}

}  // namespace

BOOST_AUTO_TEST_CASE(stacked_cubes_by_hand) {
    const scalecert::Scene s = stacked();
    BOOST_TEST(s.seed(0)[2] == R(1));
    BOOST_TEST(s.seed(1)[2] == R(4));
    const scalecert::Analysis a(s);
    const scalecert::Curve& c = a.curve();
    BOOST_TEST_REQUIRE(c.pieces.size() == 1u);
    BOOST_TEST(c.pieces[0].slope == R(-1));
    BOOST_TEST(c.pieces[0].intercept == R(3));
    BOOST_TEST(c.pieces[0].from == R(1, 2));
    BOOST_TEST(c.pieces[0].to == R(5, 2));
    BOOST_TEST((c.pieces[0].contact->kind == scalecert::ContactKind::FF));
    BOOST_TEST(c.pieces[0].contact->verts1.size() == 4u);  // the top face of P1
    BOOST_TEST(c.pieces[0].normal[2] > 0);
    BOOST_TEST(c.pieces[0].normal[0] == 0);
    BOOST_TEST(c.switches.empty());
    BOOST_TEST(c.growth.value == R(3, 2));
    BOOST_TEST(c.growth.in_rectangle);

    // Below the line: separated, the plane z = const between 1 + ρ1 and 4 − ρ2.
    scalecert::QueryResult q = a.query(R(1), R(3, 2));
    BOOST_TEST((q.verdict == scalecert::Verdict::Separated));
    BOOST_TEST_REQUIRE(q.plane.has_value());
    const R scale = q.plane->normal[2];  // the normal is (0, 0, k), k > 0
    BOOST_TEST(q.plane->c1 == scale * 2);
    BOOST_TEST(q.plane->c2 == scale * R(5, 2));
    BOOST_TEST(!q.common.has_value());
    // On it: touching, a common point at height 1 + ρ1.
    q = a.query(R(1, 2), R(5, 2));
    BOOST_TEST((q.verdict == scalecert::Verdict::Touching));
    BOOST_TEST_REQUIRE(q.common.has_value());
    BOOST_TEST(q.common->point[2] == R(3, 2));
    BOOST_TEST(q.plane->c1 == q.plane->c2);
    // Above: overlapping, with a common point at a pair on the ray below it.
    q = a.query(R(2), R(2));
    BOOST_TEST((q.verdict == scalecert::Verdict::Overlapping));
    BOOST_TEST_REQUIRE(q.common.has_value());
    BOOST_TEST(q.common->rho1 + q.common->rho2 == R(3));  // t·(2, 2) on ρ1 + ρ2 = 3
    BOOST_TEST(!q.plane.has_value());

    // Doubles at their exact values: 1.5 + 1.5 = 3 touches; the next double above overlaps.
    const std::vector<scalecert::Verdict> v =
        a.classify({1.0, 1.5, 1.5, 2.0}, {1.0, 1.5, std::nextafter(1.5, 2.0), 2.0}, 2);
    BOOST_TEST((v[0] == scalecert::Verdict::Separated));
    BOOST_TEST((v[1] == scalecert::Verdict::Touching));
    BOOST_TEST((v[2] == scalecert::Verdict::Overlapping));
    BOOST_TEST((v[3] == scalecert::Verdict::Overlapping));
}

BOOST_AUTO_TEST_CASE(claimed_planes_are_checked_exactly) {
    const scalecert::Analysis a(stacked());
    // At (1, 1): P1 reaches z = 2, P2 starts at z = 3.
    scalecert::PlaneCheck p = a.check_plane(R(1), R(1), {R(0), R(0), R(1, 3)});
    BOOST_TEST(p.separates);
    BOOST_TEST(p.c1 == R(2, 3));
    BOOST_TEST(p.c2 == R(1));
    BOOST_TEST(a.check_plane(R(1), R(1), {R(0), R(0), R(1)}, R(5, 2)).separates);
    BOOST_TEST(!a.check_plane(R(1), R(1), {R(0), R(0), R(1)}, R(3)).separates);  // touches P2
    BOOST_TEST(!a.check_plane(R(1), R(1), {R(0), R(0), R(-1)}).separates);       // wrong way round
    BOOST_TEST(!a.check_plane(R(1), R(1), {R(1), R(0), R(0)}).separates);        // side by side in x
    // x + z: P1's max is 2 + 2 = 4 at (2, y, 2); P2's min 0 + 3 = 3: overlap in that direction.
    p = a.check_plane(R(1), R(1), {R(1), R(0), R(1)});
    BOOST_TEST(p.c1 == R(4));
    BOOST_TEST(p.c2 == R(3));
    BOOST_TEST(!p.separates);
    BOOST_TEST(error_of([&] {
                   a.check_plane(R(1), R(1), {R(0), R(0), R(0)});
               }).find("normal is zero") != std::string::npos);
}

// Objects with a radius from code (CLAIMS.md, "Objects with a radius"): a capsule of radius 1/4
// on the z axis from −1 to 1 and a sphere of radius 1/2 at (2, 0, 0): the sphere's centre is 2
// from the axis, so the signed distance at (ρ1, ρ2) is 2 − ρ1/4 − ρ2/2: 5/4 at (1, 1), touching
// at (4, 2), and −1/4 at (4, 5/2).
BOOST_AUTO_TEST_CASE(objects_with_a_radius_from_code) {
    const scalecert::Scene s = scalecert::Scene::with_radii({{R(0), R(0), R(-1)}, {R(0), R(0), R(1)}},
                                                            {{R(2), R(0), R(0)}}, {R(1, 4), R(1, 2)});
    BOOST_TEST(s.radius(0) == R(1, 4));
    const scalecert::Analysis a(s);
    BOOST_TEST((a.verdict(R(1), R(1)) == scalecert::Verdict::Separated));
    BOOST_TEST((a.verdict(R(4), R(2)) == scalecert::Verdict::Touching));
    BOOST_TEST((a.verdict(R(4), R(5, 2)) == scalecert::Verdict::Overlapping));
    scalecert::Claim c;
    c.kind = scalecert::ClaimKind::SignedDistance;
    c.rho1 = R(4);
    c.rho2 = R(5, 2);
    c.value = R(-1, 4);
    const scalecert::Judgements j = a.certify({c}, {});
    BOOST_TEST(j.wrong == 0);
    BOOST_TEST(*j.items[0].exact_squared == R(4));  // the hulls': the centre 2 from the axis
    BOOST_TEST(*j.items[0].radius_sum == R(9, 4));
    BOOST_TEST(j.items[0].exact == -0.25);
    BOOST_TEST(error_of([&] { a.curve(); }).find("not built for objects with a radius") != std::string::npos);
    BOOST_TEST(error_of([&] {
                   scalecert::Scene::with_radii({{R(0), R(0), R(0)}}, {{R(2), R(0), R(0)}}, {R(-1), R(1)});
               }).find("P1: radius: a radius is >= 0") != std::string::npos);
}

// A sphere set from code (CLAIMS.md, "Parts with radii"): balls of radius 1/2 at (0, 0, 0) and
// (0, 0, 2) (seed (0, 0, 1)) against the box [3, 5] × [−1, 1] × [−1, 3] about (4, 0, 1). The
// box's y and z ranges hold the balls' centres at every scaling here, so along x each ball
// reaches ρ1/2 and the box starts at 4 − ρ2: 5/2 apart at (1, 1), touching at (2, 3).
BOOST_AUTO_TEST_CASE(sphere_sets_from_code) {
    std::vector<scalecert::Point> cube;
    for (int k = 0; k < 8; ++k) cube.push_back({R(k & 1 ? 5 : 3), R(k & 2 ? 1 : -1), R(k & 4 ? 3 : -1)});
    const scalecert::Scene s = scalecert::Scene::from_parts(
        {{{R(0), R(0), R(0)}}, {{R(0), R(0), R(2)}}}, {cube}, {}, {}, scalecert::Point{R(0), R(0), R(1)},
        scalecert::Point{R(4), R(0), R(1)}, {std::vector<scalecert::Rational>{R(1, 2), R(1, 2)}, {}});
    BOOST_TEST(s.part_radius(0, 1) == R(1, 2));
    BOOST_TEST(s.part_radius(1, 0) == R(0));
    const scalecert::Analysis a(s);
    BOOST_TEST((a.verdict(R(1), R(1)) == scalecert::Verdict::Separated));
    BOOST_TEST((a.verdict(R(2), R(3)) == scalecert::Verdict::Touching));
    scalecert::Claim d;
    d.kind = scalecert::ClaimKind::Distance;
    d.value = R(5, 2);
    scalecert::Claim sd;
    sd.kind = scalecert::ClaimKind::SignedDistance;
    sd.value = R(5, 2);
    sd.parts = std::array<int, 2>{1, 0};
    const scalecert::Judgements j = a.certify({d, sd}, {});
    BOOST_TEST(j.wrong == 0);
    sd.parts.reset();  // the objects' signed distance is not one of convex objects
    BOOST_TEST(error_of([&] { a.certify({sd}, {}); }).find("certify: claims[0].parts: missing") != std::string::npos);
    // Without radii, a signed distance on parts is refused in one line.
    const scalecert::Analysis plain(scalecert::Scene::from_parts({cube}, {box(0, 0, 6, 2, 2, 8)}, {}, {}));
    BOOST_TEST(error_of([&] { plain.certify({sd}, {}); }).find("claims[0].kind: signed_distance") != std::string::npos);
    BOOST_TEST(error_of([&] {
                   scalecert::Scene::from_parts({{{R(0), R(0), R(0)}}}, {cube}, {}, {}, {}, {},
                                                {std::vector<scalecert::Rational>{R(1), R(2)}, {}});
               }).find("2 radii for 1 parts") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(scenes_in_code_are_checked_like_scene_files) {
    BOOST_TEST(error_of([] { stacked(R(3), R(1, 2)); }) == "scene: I1: lo > hi");
    BOOST_TEST(error_of([] { stacked(R(0), R(1)); }) == "scene: I1: lo must be > 0 (got '0')");
    BOOST_TEST(error_of([] {
                   scalecert::Scene(box(0, 0, 0, 2, 2, 0), box(0, 0, 3, 2, 2, 5), {R(1), R(2)}, {R(1), R(2)});
               }).find("flat") != std::string::npos);
    BOOST_TEST(error_of([] {
                   scalecert::Scene(box(0, 0, 0, 2, 2, 2), box(0, 0, 3, 2, 2, 5), {R(1), R(2)}, {R(1), R(2)},
                                    scalecert::Point{R(2), R(1), R(1)});
               }).find("seed: not strictly inside") != std::string::npos);
    BOOST_TEST(
        error_of([] {
            scalecert::Scene(std::vector<scalecert::Point>(3), box(0, 0, 3, 2, 2, 5), {R(1), R(2)}, {R(1), R(2)});
        }) == "scene: P1: fewer than 4 vertices (3)");
    // A rational given in non-canonical form is the same number.
    scalecert::Scene s(box(0, 0, 0, 2, 2, 2), box(0, 0, 3, 2, 2, 5), {R(2, 4), R(5, 2)}, {R(1, 2), R(5, 2)});
    BOOST_TEST(s.range(0).lo.get_den() == 2);
}

BOOST_AUTO_TEST_CASE(doubles_are_exact_and_names_are_fixed) {
    BOOST_TEST(scalecert::exact(0.1) == R(3602879701896397, mpz_class(1) << 55));
    BOOST_TEST(scalecert::parse_rational("0.1") == R(1, 10));
    BOOST_TEST(scalecert::to_string(R(6, -4)) == "-3/2");
    BOOST_TEST(std::string(scalecert::name(scalecert::ContactKind::VE)) == "VE");
    BOOST_TEST((scalecert::feature1(scalecert::ContactKind::FE) == scalecert::Feature::Face));
    BOOST_TEST((scalecert::feature2(scalecert::ContactKind::FE) == scalecert::Feature::Edge));
    BOOST_TEST(std::string(scalecert::name(scalecert::Verdict::Touching)) == "touching");
    BOOST_TEST(std::string(scalecert::version()).find('.') != std::string::npos);
}

// The tetrahedron on the box (certificates/scenes/tetra_box_switch.json), loaded through the API:
// its JSON documents are the engine's, and the partition passes the independent checker.
BOOST_AUTO_TEST_CASE(loaded_scene_certificate_passes_the_checker) {
    const std::string dir = std::string(SCALECERT_SOURCE_DIR) + "/certificates/";
    const scalecert::Analysis a(scalecert::Scene::load(dir + "scenes/tetra_box_switch.json"));
    const std::string cert = a.partition_json();
    std::FILE* f = std::fopen((dir + "tetra_box_switch.partition.json").c_str(), "rb");
    BOOST_TEST_REQUIRE(f != nullptr);
    std::string bundled;
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) bundled.append(buf, n);
    std::fclose(f);
    BOOST_TEST(cert == bundled);        // the bundled certificate was written by the scalecert command
    BOOST_TEST(checker_accepts(cert));  // the independent checker accepts what the API wrote
    // By hand (test_hand_curves): the lowest vertex v = (2,0,2), about the seed (0,0,9/2), is at
    // (2ρ1, 0, 9/2 − 5ρ1/2); the box's top is at z = ρ2. Vertex on face: ρ2 = 9/2 − 5ρ1/2, until
    // x = 2ρ1 reaches the top's edge x = ρ2 at (1, 2), a (V,E) switch.
    const scalecert::Curve& c = a.curve();
    BOOST_TEST_REQUIRE(c.pieces.size() >= 2u);
    BOOST_TEST(c.pieces[0].slope == R(-5, 2));
    BOOST_TEST(c.pieces[0].intercept == R(9, 2));
    BOOST_TEST((c.pieces[0].contact->kind == scalecert::ContactKind::VF));
    BOOST_TEST_REQUIRE(c.switches.size() >= 1u);
    BOOST_TEST(c.switches[0].rho1 == R(1));
    BOOST_TEST(c.switches[0].rho2 == R(2));
    BOOST_TEST_REQUIRE(c.switches[0].contact.has_value());
    BOOST_TEST((c.switches[0].contact->kind == scalecert::ContactKind::VE));
}

// The same tetrahedron and box with 1,200 strictly interior points each (dyadic convex
// combinations, so the hulls are unchanged): 2,400 points, so the library builds the curve by the
// scan path, as the command does. The curve must be the small scene's (built by the hull path) and
// start with the hand-derived piece; queries (hull model, built on first use) agree.
BOOST_AUTO_TEST_CASE(claims_and_golden_data_through_the_public_api) {
    // Stacked cubes, by hand: touching on ρ1 + ρ2 = 3, growth distance 3/2.
    const scalecert::Analysis a(stacked());
    const scalecert::ClaimReport r =
        a.certify_fp("1 1 separated\n1.5 1.5 touching\n2 2 separated\ngrowth 1.5\ncurve 1 2\ncurve 1 2.5\n");
    BOOST_TEST(r.claims == 6);
    BOOST_TEST(r.wrong == 2);  // (2, 2) overlaps (2 + 2 > 3); the curve at ρ1 = 1 is 2, not 5/2
    BOOST_TEST(r.report.find("\"wrong\": 2") != std::string::npos);
    scalecert::ClaimOptions text;
    text.json = false;
    BOOST_TEST(a.certify_fp("growth 1.5\n", text).report ==
               "right  growth distance 1.5: exact 3/2 (~1.5), off by 0 (~0)\nclaims: 1, right: 1, wrong: 0\n");
    // A claim means the double the program held: the doubles 0.1 and 2.9 sum to just under 3
    // exactly, so (0.1, 2.9) is separated; read as decimals, 1/10 + 29/10 = 3 touches.
    BOOST_TEST((scalecert::exact(0.1) + scalecert::exact(2.9) < R(3)));
    BOOST_TEST(a.certify_fp("0.1 2.9 separated\n").wrong == 0);
    BOOST_TEST(a.certify_fp("0.1 2.9 touching\n").wrong == 1);
    scalecert::ClaimOptions decimals;
    decimals.numbers = scalecert::Numbers::Exact;
    BOOST_TEST(a.certify_fp("0.1 2.9 touching\n", decimals).wrong == 0);
    BOOST_TEST(a.certify_fp("1/10 29/10 touching\n").wrong == 0);  // a fraction is exact either way
    // In JSON, a number is the double and a string exact, whatever the option.
    const std::string json_claims = R"({"format": "scalecert-claims-1", "claims": [
        {"kind": "verdict", "rho1": 0.1, "rho2": 2.9, "verdict": "separated"},
        {"kind": "verdict", "rho1": "0.1", "rho2": "2.9", "verdict": "touching"}]})";
    BOOST_TEST(a.certify_fp(json_claims).wrong == 0);
    BOOST_TEST(a.certify_fp(json_claims, decimals).wrong == 1);  // 0.1 + 2.9 = 3 then: touching, not separated
    BOOST_CHECK_THROW(a.certify_fp("1 1 maybe\n"), scalecert::InputError);

    // Golden data: 7 values of ρ1 across [1/2, 5/2] (the curve ρ2 = 3 − ρ1 crosses the rectangle
    // from corner to corner) with no switch point, 25 pairs each (on the line, and 2^-k above,
    // below, right and left of it for 6 values of k); 13 where it enters and 13 where it leaves
    // (the pairs outside dropped); 4 corners. ρ1 = 1/2 + 2/8 = 3/4 has ρ2 = 9/4 on it.
    const scalecert::GoldenData g = a.golden();
    size_t lines = 0;
    for (char ch : g.csv) lines += ch == '\n';
    BOOST_TEST(lines == 1 + 7 * 25u + 2 * 13u + 4u);
    BOOST_TEST(g.csv.find("\n0.75,2.25,on,touching,touching,0,vertical,") != std::string::npos);
    // 2^-4 of f(3/4) = 9/4 above the curve they overlap by 9/64 = 0.140625 in z (the depth), and as
    // far below they are that far apart, along z.
    BOOST_TEST(
        g.csv.find("\n0.75,2.390625,above 2^-4,overlapping,depth,0.140625,vertical,,,,,,,0,0,1,,,\n0.75,2.109375,"
                   "below 2^-4,separated,distance,0.140625,vertical,") != std::string::npos);
    // Fewer pairs when asked: 1 vertical (ρ1 = 3/2) and one offset: 5 + 3 + 3 + 4.
    const scalecert::GoldenData few = a.golden({1, {8}});
    BOOST_TEST(nlohmann::json::parse(few.json)["queries"].size() == 15u);
    BOOST_TEST(few.rational_csv.find("\n3,2,3,2,vertical,on,touching,touching,0,1,") != std::string::npos);
    BOOST_CHECK_THROW(a.golden({1, {0}}), scalecert::InputError);
    BOOST_TEST(g.json.find("\"verdict\": \"touching\"") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(large_scene_takes_the_scan_path) {
    const std::string dir = std::string(SCALECERT_SOURCE_DIR) + "/certificates/";
    const scalecert::Scene small = scalecert::Scene::load(dir + "scenes/tetra_box_switch.json");
    std::vector<scalecert::Point> p[2] = {small.points(0), small.points(1)};
    unsigned s = 12345;
    auto next = [&s] { return (s = s * 1103515245u + 12345u) >> 16; };
    for (int i = 0; i < 2; ++i) {
        const std::vector<scalecert::Point> corners = p[i];
        for (int k = 0; k < 1200; ++k) {
            // Weights >= 1 out of 64·n: strictly inside the hull of the corners.
            std::vector<long> w(corners.size(), 1);
            long left = 64 * long(corners.size()) - long(corners.size());
            for (size_t j = 0; j + 1 < w.size(); ++j) {
                const long t = long(next() % (left + 1));
                w[j] += t;
                left -= t;
            }
            w.back() += left;
            scalecert::Point q{R(0), R(0), R(0)};
            for (size_t j = 0; j < corners.size(); ++j)
                for (int c = 0; c < 3; ++c) q[c] += corners[j][c] * R(w[j], 64 * long(corners.size()));
            for (int c = 0; c < 3; ++c) q[c].canonicalize();
            p[i].push_back(q);
        }
    }
    const scalecert::Scene large(p[0], p[1], small.range(0), small.range(1), small.seed(0), small.seed(1));
    const scalecert::Analysis a(large), b(small);
    BOOST_TEST(a.curve_json().find("\"engine\": \"scan\"") != std::string::npos);
    BOOST_TEST(b.curve_json().find("\"engine\": \"scan\"") == std::string::npos);
    const scalecert::Curve &ca = a.curve(), &cb = b.curve();
    BOOST_TEST_REQUIRE(ca.pieces.size() == cb.pieces.size());
    for (size_t k = 0; k < ca.pieces.size(); ++k) {
        BOOST_TEST(ca.pieces[k].from == cb.pieces[k].from);
        BOOST_TEST(ca.pieces[k].to == cb.pieces[k].to);
        BOOST_TEST(ca.pieces[k].slope == cb.pieces[k].slope);
        BOOST_TEST(ca.pieces[k].intercept == cb.pieces[k].intercept);
        BOOST_TEST((ca.pieces[k].contact->kind == cb.pieces[k].contact->kind));
        BOOST_TEST(ca.pieces[k].contact->verts1 == cb.pieces[k].contact->verts1);
        BOOST_TEST(ca.pieces[k].contact->verts2 == cb.pieces[k].contact->verts2);
    }
    BOOST_TEST_REQUIRE(ca.switches.size() == cb.switches.size());
    for (size_t k = 0; k < ca.switches.size(); ++k) {
        BOOST_TEST(ca.switches[k].rho1 == cb.switches[k].rho1);
        BOOST_TEST(ca.switches[k].rho2 == cb.switches[k].rho2);
    }
    BOOST_TEST(ca.growth.value == cb.growth.value);
    BOOST_TEST(ca.pieces[0].slope == R(-5, 2));  // by hand, as above
    BOOST_TEST(ca.pieces[0].intercept == R(9, 2));
    // Below, on and above the first piece at ρ1 = 3/5 (ρ2 = 9/2 − 3/2 = 3).
    BOOST_TEST((a.query(R(3, 5), R(2)).verdict == scalecert::Verdict::Separated));
    BOOST_TEST((a.query(R(3, 5), R(3)).verdict == scalecert::Verdict::Touching));
    BOOST_TEST((a.query(R(3, 5), R(4)).verdict == scalecert::Verdict::Overlapping));
}

BOOST_AUTO_TEST_CASE(the_public_header_names_no_internals) {
    // The API on one screen: nothing of the engine's namespace or headers leaks into it.
    std::ifstream in(std::string(SCALECERT_SOURCE_DIR) + "/include/scalecert/scalecert.hpp");
    BOOST_TEST_REQUIRE(in.good());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    BOOST_TEST(text.find("internal") == std::string::npos);
    BOOST_TEST(text.size() > 1000u);
}

// The typed claims API, against values derived by hand and a brute-force formula. Stacked cubes:
// P1(r1) = 1 + r1[−1, 1]^3 and P2(r2) = (1, 1, 4) + r2[−1, 1]^3 are axis-aligned boxes, so their
// distance is the norm of the per-axis gaps max(0, lo2 − hi1, lo1 − hi2), and when they overlap
// the depth is the smallest per-axis overlap min(hi1 − lo2, hi2 − lo1) (their difference is a box).
BOOST_AUTO_TEST_CASE(typed_claims_by_hand_and_by_brute_force) {
    using scalecert::Claim;
    using scalecert::ClaimKind;
    const scalecert::Analysis a(stacked());
    std::vector<Claim> claims(5);
    claims[0].kind = ClaimKind::Distance;  // at (1, 1/2): the gap 3.5 − 2 = 3/2 in z
    claims[0].rho1 = 1, claims[0].rho2 = R(1, 2), claims[0].value = R(3, 2);
    claims[0].closest = std::array<scalecert::Point, 2>{scalecert::Point{1, 1, 2}, scalecert::Point{1, 1, R(7, 2)}};
    claims[1] = claims[0];
    claims[1].closest = std::array<scalecert::Point, 2>{scalecert::Point{1, 1, R(21, 10)},
                                                        scalecert::Point{1, 1, R(7, 2)}};  // outside P1
    claims[2].kind = ClaimKind::PenetrationDepth;  // at (2, 2): overlap 1 in z, 4 in x and y
    claims[2].rho1 = claims[2].rho2 = 2, claims[2].value = scalecert::exact(1.0000001),
    claims[2].direction = scalecert::Point{0, 0, 1};
    claims[3].kind = ClaimKind::Verdict;
    claims[3].rho1 = claims[3].rho2 = R(3, 2), claims[3].verdict = scalecert::ClaimedVerdict::Touching;
    claims[4].kind = ClaimKind::WitnessPoint;
    claims[4].rho1 = claims[4].rho2 = R(3, 2), claims[4].point = {1, 1, R(5, 2)};
    scalecert::ClaimOptions opt;
    opt.certificate = true;
    const scalecert::Judgements j = a.certify(claims, opt);
    BOOST_TEST_REQUIRE(j.items.size() == 5u);
    BOOST_TEST(j.items[0].right);
    BOOST_TEST((*j.items[0].exact_squared == R(9, 4)));
    BOOST_TEST(j.items[0].exact == 1.5);
    BOOST_TEST(!j.items[1].right);
    BOOST_TEST(*j.items[1].value_right);      // the value is right,
    BOOST_TEST(!*j.items[1].closest_right);   // the closest points are not
    BOOST_TEST(!j.items[2].right);            // 1.0000001 is not 1 without a tolerance,
    BOOST_TEST(*j.items[2].direction_right);  // but the direction attains the depth
    BOOST_TEST(std::fabs(j.items[2].rel_error - 1e-7) < 1e-12);
    BOOST_TEST(j.items[3].right);
    BOOST_TEST((*j.items[3].exact_verdict == scalecert::Verdict::Touching));
    BOOST_TEST(j.items[4].right);
    BOOST_TEST(j.wrong == 2);
    BOOST_TEST(j.certificate.find("\"kind\": \"judgements\"") != std::string::npos);
    opt.tolerance = R(1, 1000000);
    opt.certificate = false;
    BOOST_TEST(a.certify({claims[2]}, opt).items[0].right);  // within 10^-6
    BOOST_TEST(a.certify({claims[2]}, opt).certificate.empty());
    // Intersecting (not separated): right at the touching pair (3/2, 3/2), wrong at (1, 1/2), where the gap is 3/2.
    Claim yes = claims[3];
    yes.verdict = scalecert::ClaimedVerdict::Intersecting;
    BOOST_TEST(a.certify({yes}).items[0].right);
    yes.rho1 = 1, yes.rho2 = R(1, 2);
    BOOST_TEST(!a.certify({yes}).items[0].right);

    // Brute force over a grid of pairs: the box formula against the engine's exact squares.
    std::vector<Claim> grid;
    std::vector<R> want;
    for (int i = 1; i <= 12; ++i)
        for (int k = 1; k <= 12; ++k) {
            const R r1(i, 4), r2(k, 4);
            R lo1[3], hi1[3], lo2[3], hi2[3];
            for (int c = 0; c < 3; ++c) {
                lo1[c] = 1 - r1, hi1[c] = 1 + r1;
                const R s2 = c == 2 ? R(4) : R(1);
                lo2[c] = s2 - r2, hi2[c] = s2 + r2;
            }
            R gap2 = 0, depth = -1;
            bool overlap = true;
            for (int c = 0; c < 3; ++c) {
                const R g = std::max({R(0), R(lo2[c] - hi1[c]), R(lo1[c] - hi2[c])});
                gap2 += g * g;
                const R o = std::min(R(hi1[c] - lo2[c]), R(hi2[c] - lo1[c]));
                overlap = overlap && o > 0;
                if (depth < 0 || o < depth) depth = o;
            }
            Claim c;
            c.rho1 = r1, c.rho2 = r2;
            c.kind = overlap ? ClaimKind::PenetrationDepth : ClaimKind::Distance;
            c.value = overlap ? depth : R(0);
            grid.push_back(c);
            want.push_back(overlap ? R(depth * depth) : gap2);
        }
    const scalecert::Judgements g = a.certify(grid);
    for (size_t i = 0; i < grid.size(); ++i)
        BOOST_TEST((g.items[i].exact_squared && *g.items[i].exact_squared == want[i]), i);
}

// The band of tests/test_compound.cpp: object 1 the parts [2,3] x [-1,1]^2 and [-3,-2] x [-1,1]^2
// about the origin (in neither), object 2 the box [4,5] x [-1,1]^2 about (9/2, 0, 0); I1 = [1, 4],
// I2 = [1, 3].
scalecert::Scene band_scene() {
    return scalecert::Scene::from_parts({box(2, -1, -1, 3, 1, 1), box(-3, -1, -1, -2, 1, 1)}, {box(4, -1, -1, 5, 1, 1)},
                                        {R(1), R(4)}, {R(1), R(3)}, scalecert::Point{R(0), R(0), R(0)},
                                        scalecert::Point{R(9, 2), R(0), R(0)});
}

BOOST_AUTO_TEST_CASE(a_region_of_parts_by_hand) {
    // The band of tests/test_compound.cpp through the public API: object 1 the parts
    // [2,3] x [-1,1]^2 and [-3,-2] x [-1,1]^2 about the origin (in neither), object 2 the box
    // [4,5] x [-1,1]^2 about (9/2, 0, 0). The right part spans [2ρ1, 3ρ1] in x, the box
    // [9/2 − ρ2/2, 9/2 + ρ2/2]: they meet iff 3ρ1 >= 9/2 − ρ2/2 and 2ρ1 <= 9/2 + ρ2/2. At ρ2 = 2:
    // from ρ1 = 7/6 to 11/4, then apart again as object 1 grows.
    const scalecert::Scene band = band_scene();
    BOOST_TEST(!band.convex());
    BOOST_TEST(band.part_count(0) == 2u);
    BOOST_TEST(band.part_count(1) == 1u);
    BOOST_TEST((band.part(0, 1)[0] == scalecert::Point{R(-3), R(-1), R(-1)}));
    BOOST_CHECK_THROW(band.part(1, 1), scalecert::InputError);
    const scalecert::Analysis r(band);
    BOOST_TEST(!r.convex());
    BOOST_TEST((r.verdict(R(1), R(2)) == scalecert::Verdict::Separated));
    BOOST_TEST((r.verdict(R(7, 6), R(2)) == scalecert::Verdict::Touching));
    BOOST_TEST((r.verdict(R(2), R(2)) == scalecert::Verdict::Overlapping));
    BOOST_TEST((r.verdict(R(11, 4), R(2)) == scalecert::Verdict::Touching));
    BOOST_TEST((r.verdict(R(3), R(2)) == scalecert::Verdict::Separated));
    const std::vector<scalecert::Verdict> v = r.classify({1.0, 2.0, 2.75, 3.0}, {2.0, 2.0, 2.0, 2.0}, 1);
    BOOST_TEST((v == std::vector<scalecert::Verdict>{scalecert::Verdict::Separated, scalecert::Verdict::Overlapping,
                                                     scalecert::Verdict::Touching, scalecert::Verdict::Separated}));
    // Outside I1 x I2 as well: at (5, 2) the right part spans [10, 15] in x, past the box.
    BOOST_TEST((r.verdict(R(5), R(2)) == scalecert::Verdict::Separated));
    // classify judges it alone, beside the pairs located on the grid.
    BOOST_TEST((r.classify({5.0, 2.0}, {2.0, 2.0}, 1) ==
                std::vector<scalecert::Verdict>{scalecert::Verdict::Separated, scalecert::Verdict::Overlapping}));
    BOOST_CHECK_THROW(r.classify({5.0}, {0.0}, 1), scalecert::InputError);  // not positive
    // query gives the verdict (no one plane or common point stands for the parts); check_plane
    // takes every part: at (1, 2) the plane x = 13/4 lies between the right part's face x = 3
    // (the left part is at x <= -2) and the box's face x = 7/2.
    const scalecert::QueryResult q = r.query(R(1), R(2));
    BOOST_TEST((q.verdict == scalecert::Verdict::Separated));
    BOOST_TEST((!q.plane && !q.common));
    const scalecert::PlaneCheck pc = r.check_plane(R(1), R(2), {R(1), R(0), R(0)}, R(13, 4));
    BOOST_TEST(pc.separates);
    BOOST_TEST(pc.c1 == R(3));
    BOOST_TEST(pc.c2 == R(7, 2));
    BOOST_TEST(!r.check_plane(R(2), R(2), {R(1), R(0), R(0)}).separates);  // overlapping at (2, 2)
    // What is defined for two convex objects only says what answers instead.
    for (const std::string& e : {error_of([&] { r.curve(); }), error_of([&] { r.curve_json(); })})
        BOOST_TEST(e.find("is defined for two convex objects; on objects made of parts, the region gives where they "
                          "meet, with its labelled boundary, switch points and growth set (C++ region_json(), Python "
                          "region(), `scalecert region`)") != std::string::npos,
                   e);
    BOOST_TEST(r.region_json().find("\"switch_points\": []") != std::string::npos);
    BOOST_TEST(r.partition_json().find("\"kind\": \"compound_partition\"") != std::string::npos);
    // Golden data (test_cli derives it by hand on the same band): 25 pairs around (23/8, 5/2) on the
    // boundary, the first on it, and the 4 corners.
    const scalecert::GoldenData gd = r.golden();
    const auto gj = nlohmann::json::parse(gd.json);
    BOOST_TEST(gj["queries"].size() == 29u);
    BOOST_TEST(gj["queries"][0]["rho2"] == "5/2");
    BOOST_TEST(gj["queries"][0]["verdict"] == "touching");
    BOOST_TEST(checker_accepts(r.partition_json()));
    // query_json on parts is the judgements certificate of the exact verdict, as scalecert query --json writes.
    const std::string qj = r.query_json(R(7, 6), R(2));
    BOOST_TEST(qj.find("\"verdict\": \"touching\"") != std::string::npos);
    BOOST_TEST(checker_accepts(qj));
    // The scene file of parts, and back.
    BOOST_TEST(scalecert::Scene::from_parts({band.part(0, 0), band.part(0, 1)}, {band.part(1, 0)}, band.range(0),
                                            band.range(1), band.seed(0), band.seed(1))
                   .json() == band.json());
    // A flat part: one line, InputError.
    BOOST_CHECK_THROW(
        scalecert::Analysis(scalecert::Scene::from_parts(
                                {{{R(0), R(0), R(0)}, {R(1), R(0), R(0)}, {R(0), R(1), R(0)}, {R(1), R(1), R(0)}}},
                                {box(4, -1, -1, 5, 1, 1)}, {R(1), R(4)}, {R(1), R(3)}))
            .verdict(R(1), R(1)),
        scalecert::InputError);
}

// Typed claims on objects made of parts, by hand, on the band above. At (1, 2) the right part
// spans x in [2, 3] and the box [7/2, 11/2]: the gap is 1/2 along x, between (3, y, z) and
// (7/2, y, z) for |y|, |z| <= 1; the left part, x in [-3, -2], is farther. At (2, 2) the right
// part spans [4, 6]: (5, 0, 0) lies in it and in the box.
BOOST_AUTO_TEST_CASE(typed_claims_on_parts_by_hand) {
    using scalecert::Claim;
    using scalecert::ClaimKind;
    using scalecert::Point;
    const scalecert::Analysis r(band_scene());
    std::vector<Claim> c(7);
    c[0].kind = ClaimKind::Distance, c[0].rho1 = 1, c[0].rho2 = 2, c[0].value = R(1, 2);
    c[0].closest = std::array<Point, 2>{Point{3, 1, 0}, Point{R(7, 2), 1, 0}};
    c[1] = c[0],
    c[1].closest = std::array<Point, 2>{Point{3, 1, 0}, Point{R(7, 2), 0, 0}};  // 1/2 apart in x, 1 in y: too far
    c[2].kind = ClaimKind::Verdict, c[2].rho1 = R(7, 6), c[2].rho2 = 2,
    c[2].verdict = scalecert::ClaimedVerdict::Touching;
    c[3].kind = ClaimKind::Verdict, c[3].rho1 = 3, c[3].rho2 = 2,
    c[3].verdict = scalecert::ClaimedVerdict::Intersecting;  // apart again
    c[4].kind = ClaimKind::WitnessPoint, c[4].rho1 = 2, c[4].rho2 = 2, c[4].point = {5, 0, 0};
    c[5].kind = ClaimKind::SeparatingPlane, c[5].rho1 = 1, c[5].rho2 = 2, c[5].normal = {1, 0, 0},
    c[5].offset = R(13, 4);
    c[6] = c[5], c[6].offset = R(4);  // beyond the box's near face at 7/2
    scalecert::ClaimOptions opt;
    opt.certificate = true;
    const scalecert::Judgements j = r.certify(c, opt);
    BOOST_TEST_REQUIRE(j.items.size() == 7u);
    BOOST_TEST(j.items[0].right);
    BOOST_TEST((*j.items[0].exact_squared == R(1, 4)));
    BOOST_TEST(!j.items[1].right);
    BOOST_TEST(*j.items[1].value_right);
    BOOST_TEST(!*j.items[1].closest_right);
    BOOST_TEST(j.items[2].right);
    BOOST_TEST(!j.items[3].right);
    BOOST_TEST((*j.items[3].exact_verdict == scalecert::Verdict::Separated));
    BOOST_TEST(j.items[4].right);
    BOOST_TEST(j.items[5].right);
    BOOST_TEST(!j.items[6].right);
    BOOST_TEST(j.wrong == 3);
    // The independent checker accepts the compound_judgements certificate.
    BOOST_TEST(j.certificate.find("\"kind\": \"compound_judgements\"") != std::string::npos);
    BOOST_TEST(checker_accepts(j.certificate));
    // A depth names no part pair: refused with one line.
    Claim d;
    d.kind = ClaimKind::PenetrationDepth, d.rho1 = 2, d.rho2 = 2, d.value = 1;
    BOOST_CHECK_THROW(r.certify({d}), scalecert::InputError);
    BOOST_TEST(r.certify({}).items.empty());  // an empty batch is judged
    // A claim with no answer (CLAIMS.md): wrong, with its reason, and the batch goes on.
    Claim nan = c[0];
    nan.no_answer = "value";
    Claim flat = c[5];
    flat.normal = {0, 0, 0};
    const scalecert::Judgements na = r.certify({nan, c[0], flat});
    BOOST_TEST(!na.items[0].right);
    BOOST_TEST(na.items[0].reason == "value: not a number");
    BOOST_TEST(na.items[1].right);
    BOOST_TEST(!na.items[2].right);
    BOOST_TEST(na.items[2].reason == "normal: the zero vector");
}

// Contacts: a penetration depth on objects made of parts names its part pair, and is judged as
// the depth of those two convex parts scaled about their objects' seeds.
// By hand on the band: at ρ1 = ρ2 = 2, part 0 of P1 is [4,6] x [-2,2]^2 and P2 is [7/2,11/2] x
// [-2,2]^2 (about (9/2,0,0)); moving P2 by 3/2 along −x separates them (along +x 5/2, along y or z
// 4): depth 3/2, direction (−1,0,0). Part 1, [-6,-4] x [-2,2]^2, is apart from P2.
// By brute force: parts that are boxes, where the depth of two meeting boxes is the least, over
// the axes, of how far one must move either way, min(A.hi − B.lo, B.hi − A.lo).
BOOST_AUTO_TEST_CASE(contacts_on_parts_by_hand_and_by_brute_force) {
    using scalecert::Claim;
    using scalecert::ClaimKind;
    const scalecert::Analysis r(band_scene());
    std::vector<Claim> c(4);
    c[0].kind = ClaimKind::PenetrationDepth, c[0].rho1 = 2, c[0].rho2 = 2, c[0].value = R(3, 2);
    c[0].parts = std::array<int, 2>{0, 0};
    c[0].direction = scalecert::Point{-1, 0, 0};
    c[1] = c[0], c[1].direction = scalecert::Point{1, 0, 0};                     // 5/2 along +x: wrong direction
    c[2] = c[0], c[2].parts = std::array<int, 2>{1, 0}, c[2].direction.reset();  // apart: no depth
    c[3] = c[0], c[3].value = R(5, 2), c[3].direction.reset();                   // the depth along +x
    scalecert::ClaimOptions opt;
    opt.certificate = true;
    const scalecert::Judgements j = r.certify(c, opt);
    BOOST_TEST(j.items[0].right);
    BOOST_TEST((*j.items[0].exact_squared == R(9, 4)));
    BOOST_TEST(!j.items[1].right);
    BOOST_TEST(*j.items[1].value_right);
    BOOST_TEST(!*j.items[1].direction_right);
    BOOST_TEST(!j.items[2].right);
    BOOST_TEST(!j.items[2].exact_squared);
    BOOST_TEST(!j.items[3].right);
    BOOST_TEST(j.wrong == 3);
    BOOST_TEST(checker_accepts(j.certificate));
    // A part number past the object's parts is refused in one line.
    Claim bad = c[0];
    bad.parts = std::array<int, 2>{0, 1};
    BOOST_CHECK_THROW(r.certify({bad}), scalecert::InputError);

    std::mt19937 g(35);
    std::uniform_int_distribution<long> at(-2, 2), side(2, 4), den(1, 4);
    int overlapping = 0, apart = 0;  // the brute force's cases, so that it tries both
    for (int t = 0; t < 12; ++t) {
        std::array<std::vector<std::array<long, 6>>, 2> boxes;
        std::array<std::vector<std::vector<scalecert::Point>>, 2> parts;
        for (int i = 0; i < 2; ++i)
            for (int k = 0; k < 2 + i; ++k) {
                const long x = at(g), y = at(g), z = at(g);
                boxes[i].push_back({x, y, z, x + side(g), y + side(g), z + side(g)});
                const auto& b = boxes[i].back();
                parts[i].push_back(box(b[0], b[1], b[2], b[3], b[4], b[5]));
            }
        const scalecert::Point s1{R(at(g)), R(at(g)), R(at(g))}, s2{R(at(g)), R(at(g)), R(at(g))};
        const scalecert::Analysis a(
            scalecert::Scene::from_parts(parts[0], parts[1], {R(1, 2), R(2)}, {R(1, 2), R(2)}, s1, s2));
        std::vector<Claim> cs;
        std::vector<std::optional<R>> want;
        for (int k = 0; k < 8; ++k) {
            R r1(den(g) + 1, den(g)), r2(den(g) + 1, den(g));
            r1.canonicalize(), r2.canonicalize();
            for (size_t p = 0; p < boxes[0].size(); ++p)
                for (size_t q = 0; q < boxes[1].size(); ++q) {
                    std::optional<R> depth;
                    R least = -1;
                    bool far = false;
                    for (int e = 0; e < 3; ++e) {
                        const R alo = s1[e] + r1 * (boxes[0][p][e] - s1[e]),
                                ahi = s1[e] + r1 * (boxes[0][p][e + 3] - s1[e]);
                        const R blo = s2[e] + r2 * (boxes[1][q][e] - s2[e]),
                                bhi = s2[e] + r2 * (boxes[1][q][e + 3] - s2[e]);
                        if (ahi < blo || bhi < alo) far = true;
                        const R m = std::min(R(ahi - blo), R(bhi - alo));
                        if (least < 0 || m < least) least = m;
                    }
                    if (!far) depth = least;
                    overlapping += depth && sgn(*depth) > 0;
                    apart += !depth;
                    Claim cl;
                    cl.kind = ClaimKind::PenetrationDepth, cl.rho1 = r1, cl.rho2 = r2, cl.value = depth ? *depth : R(0);
                    cl.parts = std::array<int, 2>{static_cast<int>(p), static_cast<int>(q)};
                    cs.push_back(cl);
                    want.push_back(depth);
                }
        }
        const scalecert::Judgements jj = a.certify(cs, opt);
        for (size_t i = 0; i < cs.size(); ++i) {
            BOOST_TEST(jj.items[i].right == want[i].has_value(), t << " " << i);
            if (want[i])
                BOOST_TEST((jj.items[i].exact_squared && *jj.items[i].exact_squared == *want[i] * *want[i]),
                           t << " " << i);
        }
        BOOST_TEST(checker_accepts(jj.certificate), t);
    }
    BOOST_TEST(overlapping > 50, overlapping);
    BOOST_TEST(apart > 50, apart);
}

// Claims at poses. By hand: the stacked cubes with P2 turned a quarter about the vertical line
// through (1, 1) (R = [[0,−1,0],[1,0,0],[0,0,1]], t = (2, 0, 0): P2 maps onto itself) answer as
// unposed: touching at (1, 2), 1 apart at (1, 1); lifted by 1 more (t = (2, 0, 1)) 2 apart at
// (1, 1) and separated at (1, 2). By brute force: random boxes at random poses of doubles
// (rotations by angles held as doubles, so R is not exactly orthogonal), each claim judged at its
// pose equals the same claim on a scene whose points were moved by the pose here, in rationals.
BOOST_AUTO_TEST_CASE(claims_at_poses_by_hand_and_by_brute_force) {
    using scalecert::Claim;
    using scalecert::ClaimKind;
    using scalecert::Point;
    using scalecert::Pose;
    const Pose quarter{{{R(0), R(-1), R(0), R(2)}, {R(1), R(0), R(0), R(0)}, {R(0), R(0), R(1), R(0)}}};
    Pose lifted = quarter;
    lifted[2][3] = 1;
    const scalecert::Analysis a(stacked());
    std::vector<Claim> c(4);
    c[0].kind = ClaimKind::Verdict, c[0].rho1 = 1, c[0].rho2 = 2, c[0].verdict = scalecert::ClaimedVerdict::Touching;
    c[0].pose2 = quarter;
    c[1].kind = ClaimKind::Distance, c[1].rho1 = 1, c[1].rho2 = 1, c[1].value = 1, c[1].pose2 = quarter;
    c[2] = c[1], c[2].value = 2, c[2].pose2 = lifted;
    c[3] = c[0], c[3].pose2 = lifted;
    scalecert::ClaimOptions opt;
    opt.certificate = true;
    const scalecert::Judgements j = a.certify(c, opt);
    BOOST_TEST(j.items[0].right);
    BOOST_TEST(j.items[1].right);
    BOOST_TEST(j.items[2].right);
    BOOST_TEST(!j.items[3].right);
    BOOST_TEST((*j.items[3].exact_verdict == scalecert::Verdict::Separated));
    BOOST_TEST(checker_accepts(j.certificate));
    Claim flat = c[0];
    flat.pose1 = Pose{};  // R = 0: singular
    BOOST_CHECK_THROW(a.certify({flat}), scalecert::InputError);

    std::mt19937 g(36);
    std::uniform_int_distribution<long> at(-2, 2), side(1, 3), den(1, 4);
    std::uniform_real_distribution<double> angle(0, 6.283);
    auto random_pose = [&] {
        const double u = angle(g), v = angle(g);
        // A turn about z by u, then about x by v, moved by a small translation: doubles.
        const double cz = std::cos(u), sz = std::sin(u), cx = std::cos(v), sx = std::sin(v);
        const double m[3][3] = {{cz, -sz, 0}, {cx * sz, cx * cz, -sx}, {sx * sz, sx * cz, cx}};
        Pose p;
        for (int r = 0; r < 3; ++r) {
            for (int k = 0; k < 3; ++k) p[r][k] = scalecert::exact(m[r][k]);
            p[r][3] = scalecert::exact(0.25 * static_cast<double>(at(g)));
        }
        return p;
    };
    auto moved = [](const Pose& p, const Point& x) {
        Point y;
        for (int r = 0; r < 3; ++r) y[r] = p[r][0] * x[0] + p[r][1] * x[1] + p[r][2] * x[2] + p[r][3];
        return y;
    };
    int kinds[3] = {0, 0, 0};  // the exact verdicts met, so that the brute force tries each
    for (int t = 0; t < 10; ++t) {
        std::vector<Point> P[2];
        for (int i = 0; i < 2; ++i) {
            const long x = at(g), y = at(g), z = at(g);
            P[i] = box(x, y, z, x + side(g), y + side(g), z + side(g));
        }
        // Seeds: the boxes' centres (the means), which a pose moves to the moved boxes' centres.
        const scalecert::Analysis base(scalecert::Scene(P[0], P[1], {R(1, 2), R(2)}, {R(1, 2), R(2)}));
        for (int k = 0; k < 3; ++k) {
            const Pose p1 = random_pose(), p2 = random_pose();
            std::vector<Point> Q[2];
            for (int i = 0; i < 2; ++i)
                for (const Point& x : P[i]) Q[i].push_back(moved(i ? p2 : p1, x));
            const scalecert::Analysis there(scalecert::Scene(Q[0], Q[1], {R(1, 2), R(2)}, {R(1, 2), R(2)}));
            R r1(den(g) + 1, den(g)), r2(den(g) + 1, den(g));
            r1.canonicalize(), r2.canonicalize();
            std::vector<Claim> cs(4);
            cs[0].kind = ClaimKind::Verdict, cs[0].verdict = scalecert::ClaimedVerdict::Touching;
            cs[1].kind = ClaimKind::Distance, cs[1].value = 1;
            cs[2].kind = ClaimKind::PenetrationDepth, cs[2].value = 1;
            cs[3].kind = ClaimKind::SeparatingPlane, cs[3].normal = {1, 1, 0};
            for (Claim& x : cs) x.rho1 = r1, x.rho2 = r2;
            const scalecert::Judgements want = there.certify(cs);
            for (Claim& x : cs) x.pose1 = p1, x.pose2 = p2;
            const scalecert::Judgements got = base.certify(cs, opt);
            for (size_t i = 0; i < cs.size(); ++i) {
                BOOST_TEST(got.items[i].right == want.items[i].right, t << " " << k << " " << i);
                BOOST_TEST((got.items[i].exact_squared == want.items[i].exact_squared), t << " " << k << " " << i);
            }
            BOOST_TEST((got.items[0].exact_verdict == want.items[0].exact_verdict), t << " " << k);
            ++kinds[static_cast<int>(*want.items[0].exact_verdict)];
            BOOST_TEST(checker_accepts(got.certificate), t << " " << k);
        }
    }
    BOOST_TEST(kinds[0] > 3, kinds[0]);  // separated
    BOOST_TEST(kinds[2] > 3, kinds[2]);  // overlapping
}

// Parts named by OBJ groups: tests/data/compound_band.obj has the groups `right` (the box
// [2,3] x [-1,1]^2) and `left` ([-3,-2] x [-1,1]^2), in that order; compound_band_groups.json is
// the band with P1 from it. Only the right part meets P2's box (a_region_of_parts_by_hand), so
// "right" labels P1's part wherever the region names a pair; P2, a convex object, has no name.
BOOST_AUTO_TEST_CASE(parts_named_by_obj_groups) {
    const std::string data = std::string(SCALECERT_SOURCE_DIR) + "/tests/data/";
    const scalecert::Scene s = scalecert::Scene::load(data + "compound_band_groups.json");
    BOOST_TEST(s.part_name(0, 0) == "right");
    BOOST_TEST(s.part_name(0, 1) == "left");
    BOOST_TEST(s.part_name(1, 0) == "");
    BOOST_TEST((s.part(0, 1)[0] == scalecert::Point{R(-3), R(-1), R(-1)}));
    BOOST_CHECK_THROW(s.part_name(0, 2), scalecert::InputError);
    BOOST_CHECK_THROW(s.part_name(2, 0), scalecert::InputError);
    BOOST_TEST(s.notes().empty());
    const auto region = nlohmann::json::parse(scalecert::Analysis(s).region_json());
    BOOST_TEST(region["pair_regions"].size() == 1u);
    BOOST_TEST(region["pair_regions"][0]["P1_part_name"] == "right");
    BOOST_TEST(!region["pair_regions"][0].contains("P2_part_name"));
    for (int k : {1, 3}) BOOST_TEST(region["boundary"][0]["edges"][k]["on"]["P1_part_name"] == "right");
    BOOST_TEST(region["growth_set"][0]["first_contact"]["P1_part_name"] == "right");
    // The scene file keeps the names, and read back gives the same file.
    const std::string json = s.json();
    BOOST_TEST(json.find("\"name\": \"left\"") != std::string::npos);
    const std::string path = "/tmp/scalecert-test-api-names-" + std::to_string(::getpid()) + ".json";
    std::FILE* out = std::fopen(path.c_str(), "wb");
    BOOST_TEST_REQUIRE(out != nullptr);
    std::fwrite(json.data(), 1, json.size(), out);
    std::fclose(out);
    BOOST_TEST(scalecert::Scene::load(path).json() == json);
    std::remove(path.c_str());
    // Unnamed parts (from_parts) have "" for a name, and their scene file no "name".
    const scalecert::Scene band = band_scene();
    BOOST_TEST(band.part_name(0, 1) == "");
    BOOST_TEST(band.json().find("\"name\"") == std::string::npos);
    // From meshes: with parts_from_groups the groups' names; without, one hull each and a note.
    const std::string obj = data + "compound_band.obj";
    const scalecert::Interval i{R(1), R(2)};
    const scalecert::Scene g = scalecert::Scene::from_meshes(obj, obj, i, i, true);
    BOOST_TEST(g.part_name(1, 0) == "right");
    BOOST_TEST(g.part_name(1, 1) == "left");
    BOOST_TEST(g.notes().empty());
    const scalecert::Scene h = scalecert::Scene::from_meshes(obj, obj, i, i);
    BOOST_TEST(h.convex());
    BOOST_TEST(h.part_name(0, 0) == "");
    const std::vector<std::string> notes = h.notes();
    BOOST_TEST_REQUIRE(notes.size() == 2u);
    BOOST_TEST(notes[0] == obj +
                               ": 2 groups with faces, read as one convex object (the hull of all its vertices); "
                               "--parts-from-groups (the scene key \"parts_from_groups\", from_meshes(..., "
                               "parts_from_groups=true)) reads a convex part per group");
}

namespace {
// Random claims of every typed kind near two objects in [-4, 4]^3: doubles, as a program writes them.
std::vector<scalecert::Claim> random_claims(size_t n, unsigned seed, bool depths) {
    using scalecert::Claim;
    using scalecert::ClaimKind;
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> rho(0.25, 3), coord(-4, 4), val(0, 3);
    auto x = [&](auto& d) { return scalecert::exact(d(g)); };
    auto pt = [&] { return scalecert::Point{x(coord), x(coord), x(coord)}; };
    std::vector<Claim> out(n);
    const int kinds = depths ? 6 : 4;
    for (size_t i = 0; i < n; ++i) {
        Claim& c = out[i];
        c.rho1 = x(rho), c.rho2 = x(rho);
        switch (static_cast<int>(i % kinds)) {
        case 0:
            c.kind = ClaimKind::Verdict;
            c.verdict = static_cast<scalecert::ClaimedVerdict>(g() % 5);
            break;
        case 1:
            c.kind = ClaimKind::SeparatingPlane;
            c.normal = pt();
            if (g() % 2) c.offset = x(coord);
            break;
        case 2:
            c.kind = ClaimKind::WitnessPoint;
            c.point = pt();
            break;
        case 3:
            c.kind = ClaimKind::Distance;
            c.value = x(val);
            if (g() % 2) c.closest = std::array<scalecert::Point, 2>{pt(), pt()};
            break;
        case 4:
            c.kind = ClaimKind::PenetrationDepth;
            c.value = x(val);
            if (g() % 2) c.direction = pt();
            break;
        default:
            c.kind = ClaimKind::SignedDistance;
            c.value = x(val) - x(val);
            c.bound = static_cast<scalecert::SignedBound>(g() % 3);
        }
    }
    return out;
}

std::string exact_text(const R& q) { return "\"" + q.get_str() + "\""; }
std::string exact_point(const scalecert::Point& p) {
    return "[" + exact_text(p[0]) + "," + exact_text(p[1]) + "," + exact_text(p[2]) + "]";
}
// The same claims as a scalecert-claims-1 file, every number an exact string.
std::string claims_file(const std::vector<scalecert::Claim>& claims) {
    using scalecert::ClaimKind;
    std::string s = "{\"format\": \"scalecert-claims-1\", \"claims\": [";
    for (size_t i = 0; i < claims.size(); ++i) {
        const scalecert::Claim& c = claims[i];
        s += i ? ",{" : "{";
        s += "\"rho1\":" + exact_text(c.rho1) + ",\"rho2\":" + exact_text(c.rho2) + ",";
        switch (c.kind) {
        case ClaimKind::Verdict: {
            const char* v[] = {"separated", "touching", "overlapping", "intersecting", "not_overlapping"};
            s += "\"kind\":\"verdict\",\"verdict\":\"" + std::string(v[static_cast<int>(c.verdict)]) + "\"";
            break;
        }
        case ClaimKind::SeparatingPlane:
            s += "\"kind\":\"separating_plane\",\"normal\":" + exact_point(c.normal);
            if (c.offset) s += ",\"offset\":" + exact_text(*c.offset);
            break;
        case ClaimKind::WitnessPoint: s += "\"kind\":\"witness_point\",\"point\":" + exact_point(c.point); break;
        case ClaimKind::Distance:
            s += "\"kind\":\"distance\",\"value\":" + exact_text(c.value);
            if (c.closest)
                s += ",\"closest\":[" + exact_point((*c.closest)[0]) + "," + exact_point((*c.closest)[1]) + "]";
            break;
        case ClaimKind::PenetrationDepth:
            s += "\"kind\":\"penetration_depth\",\"value\":" + exact_text(c.value);
            if (c.direction) s += ",\"direction\":" + exact_point(*c.direction);
            break;
        case ClaimKind::SignedDistance: {
            const char* b[] = {"value", "at_least", "below"};
            s += "\"kind\":\"signed_distance\",\"" + std::string(b[static_cast<int>(c.bound)]) +
                 "\":" + exact_text(c.value);
            break;
        }
        }
        s += "}";
    }
    return s + "]}";
}

// The typed judgements against the file's report, claim by claim: every part's verdict and the
// exact square. Returns how many were right.
size_t same_judgements(const scalecert::Judgements& typed, const std::string& report_json) {
    const nlohmann::json rep = nlohmann::json::parse(report_json);
    const nlohmann::json& list = rep["claims"];
    BOOST_TEST_REQUIRE(list.size() == typed.items.size());
    size_t right = 0, bad = 0;
    auto opt = [](const nlohmann::json& o, const char* k) {
        return o.contains(k) ? std::optional<bool>(o[k].get<bool>()) : std::nullopt;
    };
    for (size_t i = 0; i < list.size(); ++i) {
        const scalecert::Judgement& t = typed.items[i];
        const nlohmann::json& o = list[i];
        const bool same =
            t.right == o["right"].get<bool>() && t.value_right == opt(o, "value_right") &&
            t.closest_right == opt(o, "closest_right") && t.direction_right == opt(o, "direction_right") &&
            (t.exact_squared
                 ? o.contains("exact_squared") && o["exact_squared"].get<std::string>() == t.exact_squared->get_str()
                 : !o.contains("exact_squared"));
        if (!same && ++bad <= 5) BOOST_ERROR("claim " << i << " is judged differently: " << o.dump());
        right += t.right;
    }
    BOOST_TEST(rep["wrong"].get<long>() == typed.wrong);
    return right;
}
}  // namespace

// The typed API and certify-fp on a file judge 10,000 random claims of every kind alike, on two
// convex objects, with and without a tolerance; 2,000 more on objects made of parts.
// Typed signed distances, as the engines' adapters claim them (CLAIMS.md, "Signed distances": on
// the stacked cubes 3/2 apart at (1, 1/2), touching at (1, 2), overlapping by 1 at (2, 2)).
BOOST_AUTO_TEST_CASE(typed_signed_distances_by_hand) {
    using scalecert::Claim;
    using scalecert::SignedBound;
    const scalecert::Analysis a(stacked());
    auto sd = [](R r1, R r2, R v, SignedBound b = SignedBound::Value) {
        Claim c;
        c.kind = scalecert::ClaimKind::SignedDistance;
        c.rho1 = r1, c.rho2 = r2, c.value = v, c.bound = b;
        return c;
    };
    const std::vector<Claim> claims{sd(1, R(1, 2), R(3, 2)),
                                    sd(2, 2, -1),
                                    sd(2, 2, 1),
                                    sd(1, R(1, 2), R(3, 2), SignedBound::AtLeast),
                                    sd(1, R(1, 2), R(3, 2), SignedBound::Below),
                                    sd(2, 2, 0, SignedBound::Below),
                                    sd(1, 2, 0, SignedBound::Below),
                                    sd(2, 2, R(-11, 10))};
    const scalecert::Judgements j = a.certify(claims);
    BOOST_TEST_REQUIRE(j.items.size() == claims.size());
    const bool expected[] = {true, true, false, true, false, true, false, false};
    for (size_t i = 0; i < claims.size(); ++i) BOOST_TEST(j.items[i].right == expected[i], "claim " << i);
    BOOST_TEST(j.items[0].exact == 1.5);
    BOOST_TEST((*j.items[1].exact_squared == 1));
    BOOST_TEST(j.items[1].exact == -1.0);  // signed
    BOOST_TEST((*j.items[1].exact_verdict == scalecert::Verdict::Overlapping));
    BOOST_TEST(j.items[2].rel_error == 2.0);  // |1 − (−1)| / 1
    BOOST_TEST(std::fabs(j.items[7].rel_error - 0.1) < 1e-15);
    BOOST_TEST((*j.items[6].exact_verdict == scalecert::Verdict::Touching));
    BOOST_TEST(j.items[6].exact == 0.0);
    scalecert::ClaimOptions tol;
    tol.tolerance = R(1, 10);
    BOOST_TEST(a.certify({claims[7]}, tol).items[0].right);  // −1.1 within a tenth of −1
}

BOOST_AUTO_TEST_CASE(typed_and_file_claims_judge_alike) {
    std::vector<scalecert::Point> p1, p2;
    std::mt19937_64 g(7);
    std::uniform_int_distribution<int> u(-30, 30);
    for (int i = 0; i < 24; ++i) p1.push_back({R(u(g), 10), R(u(g), 10), R(u(g), 10)});
    for (int i = 0; i < 24; ++i) p2.push_back({R(u(g), 10) + 2, R(u(g), 10), R(u(g), 10) + 1});
    const scalecert::Analysis a(scalecert::Scene(p1, p2, {R(1, 2), R(2)}, {R(1, 2), R(2)}));
    for (const R& tol : {R(0), R(1, 3)}) {
        const std::vector<scalecert::Claim> claims = random_claims(5000, 11 + tol.get_den().get_ui(), true);
        scalecert::ClaimOptions opt;
        opt.tolerance = tol;
        const scalecert::Judgements typed = a.certify(claims, opt);
        const size_t right = same_judgements(typed, a.certify_fp(claims_file(claims), opt).report);
        BOOST_TEST(right > 0u);  // both outcomes occur
        BOOST_TEST(right < claims.size());
    }
    const scalecert::Analysis r(band_scene());
    const std::vector<scalecert::Claim> claims = random_claims(2000, 5, false);
    const scalecert::Judgements typed = r.certify(claims);
    const size_t right = same_judgements(typed, r.certify_fp(claims_file(claims)).report);
    BOOST_TEST(right > 0u);
    BOOST_TEST(right < claims.size());
}

// A family's golden data through the public API: what the family run writes for a scene is what
// an Analysis of that scene's written copy gives (the same queries and CSV), and the faults are
// refused before anything is written.
BOOST_AUTO_TEST_CASE(family_golden_data_through_the_public_api) {
    const std::vector<std::string> f = scalecert::families();
    BOOST_TEST((std::find(f.begin(), f.end(), "random") != f.end()));
    char tmpl[] = "/tmp/scalecert_api_golden_XXXXXX";
    const std::string dir = std::string(mkdtemp(tmpl)) + "/g";
    BOOST_CHECK_THROW(scalecert::write_golden("bogus", 1, 5, Rational(1, 1024), dir), scalecert::InputError);
    BOOST_CHECK_THROW(scalecert::write_golden("random", 0, 5, Rational(1, 1024), dir), scalecert::InputError);
    BOOST_CHECK_THROW(scalecert::write_golden("random", 1, 5, Rational(0), dir), scalecert::InputError);
    BOOST_TEST(access(dir.c_str(), F_OK) != 0);  // nothing made
    scalecert::write_golden("random", 1, 5, Rational(1, 1024), dir);
    auto read = [](const std::string& p) {
        std::ifstream in(p);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    const scalecert::GoldenData g = scalecert::Analysis(scalecert::Scene::load(dir + "/random-0.scene.json")).golden();
    const nlohmann::json written = nlohmann::json::parse(read(dir + "/random-0.golden.json"));
    BOOST_TEST(written["family"] == "random");
    BOOST_TEST(written["queries"].size() >= 13u);
    BOOST_TEST(written["queries"] == nlohmann::json::parse(g.json)["queries"]);
    BOOST_TEST(read(dir + "/random-0.golden.csv") == g.csv);
    std::filesystem::remove_all(std::filesystem::path(dir).parent_path());
}

// Scene::from_meshes on two large OFF files of integers reads them straight into machine integers,
// as the command does, with no exact form until one is asked for. Against the same points given
// exactly (the Scene constructor), everything answers alike: the scene file, seeds, the curve,
// queries with their evidence, the partition and golden data. 1,200 points each on spheres of
// radius 10^6 (the walk answers from 2,000 points in all).
BOOST_AUTO_TEST_CASE(large_off_meshes_read_as_integers_answer_as_the_exact_scene) {
    std::mt19937 g(77);
    std::normal_distribution<double> N(0, 1);
    std::vector<scalecert::Point> pts[2];
    std::string paths[2];
    for (int i = 0; i < 2; ++i) {
        paths[i] = "/tmp/scalecert-test-api-off-" + std::to_string(::getpid()) + "-" + std::to_string(i) + ".off";
        std::ofstream o(paths[i]);
        o << "OFF\n1200 0 0\n";
        for (int k = 0; k < 1200; ++k) {
            const double x = N(g), y = N(g), z = N(g), l = std::sqrt(x * x + y * y + z * z);
            const long c[3] = {std::lround(1e6 * x / l) + (i ? 2500000 : 0), std::lround(1e6 * y / l),
                               std::lround(1e6 * z / l)};
            o << c[0] << ' ' << c[1] << ' ' << c[2] << '\n';
            pts[i].push_back({R(c[0]), R(c[1]), R(c[2])});
        }
    }
    const scalecert::Interval I{R(1, 2), R(2)};
    const scalecert::Scene a = scalecert::Scene::from_meshes(paths[0], paths[1], I, I);
    const scalecert::Scene b(pts[0], pts[1], I, I);
    const scalecert::Analysis aa(a), ab(b);
    BOOST_TEST(aa.curve_json() == ab.curve_json());
    for (const auto& [r1, r2] : std::vector<std::pair<R, R>>{{R(1), R(1)}, {R(2), R(2)}, {R(1, 2), R(3, 2)}}) {
        const scalecert::QueryResult qa = aa.query(r1, r2), qb = ab.query(r1, r2);
        BOOST_TEST((qa.verdict == qb.verdict));
        BOOST_TEST(bool(qa.plane) == bool(qb.plane));
        if (qa.plane && qb.plane)
            BOOST_TEST((qa.plane->normal == qb.plane->normal && qa.plane->offset == qb.plane->offset));
    }
    BOOST_TEST(aa.partition_json() == ab.partition_json());
    // The exact form, made when asked for: the same points, seeds (the means) and scene file.
    for (int i = 0; i < 2; ++i) {
        BOOST_TEST((a.points(i) == pts[i]));
        BOOST_TEST((a.seed(i) == b.seed(i)));
    }
    BOOST_TEST(a.json() == b.json());
    const scalecert::GoldenData ga = aa.golden(), gb = ab.golden();
    BOOST_TEST(ga.json == gb.json);
    BOOST_TEST(ga.csv == gb.csv);
    BOOST_TEST(ga.rational_csv == gb.rational_csv);
    for (const std::string& p : paths) std::remove(p.c_str());
}

// One rule for numbers: a mesh's decimal is the double a program reads from it by default, the
// float with Numbers::Float32, and the decimal as written with Numbers::Exact; the scene says how
// many decimals were not read as written.
BOOST_AUTO_TEST_CASE(mesh_and_scene_numbers_are_what_the_program_holds) {
    using scalecert::Numbers;
    const std::string dir = "/tmp/scalecert-test-api-numbers-" + std::to_string(::getpid());
    std::filesystem::create_directories(dir);
    // A tetrahedron with one vertex at x = 0.1 (no double, no float) and a cube.
    {
        std::ofstream(dir + "/t.off") << "OFF\n4 0 0\n0.1 0 0\n1 0 0\n0 1 0\n0 0 1\n";
        std::ofstream(dir + "/c.off") << "OFF\n8 0 0\n5 0 0\n6 0 0\n5 1 0\n6 1 0\n5 0 1\n6 0 1\n5 1 1\n6 1 1\n";
    }
    const scalecert::Interval I{R(1, 2), R(2)};
    const R tenth_double = scalecert::exact(0.1), tenth_float(R(13421773) / R(mpz_class(1) << 27));
    const std::pair<Numbers, R> cases[] = {
        {Numbers::Double, tenth_double}, {Numbers::Float32, tenth_float}, {Numbers::Exact, R(1, 10)}};
    for (const auto& [numbers, x] : cases) {
        const scalecert::Scene s = scalecert::Scene::from_meshes(dir + "/t.off", dir + "/c.off", I, I, false, numbers);
        BOOST_TEST((s.points(0)[0][0] == x));
        const std::vector<std::string> notes = s.notes();
        // One decimal (0.1) is not read as written, except by Exact.
        BOOST_TEST(notes.size() == (numbers == Numbers::Exact ? 0u : 1u));
        if (!notes.empty()) BOOST_TEST(notes[0].rfind("1 number written as decimals is not a", 0) == 0, notes[0]);
    }
    // A scene file: JSON numbers the same way, JSON strings exact always.
    std::ofstream(dir + "/s.json") << R"({"P1": {"vertices": [[0.1,0,0],["0.1",1,0],[0,0,1],[1,1,1]]},
        "P2": {"vertices": [[5,0,0],[6,0,0],[5,1,0],[5,0,1]]}, "I1": [0.5, 2], "I2": ["0.5", 2]})";
    for (const auto& [numbers, x] : cases) {
        const scalecert::Scene s = scalecert::Scene::load(dir + "/s.json", numbers);
        BOOST_TEST((s.points(0)[0][0] == x));
        BOOST_TEST((s.points(0)[1][0] == R(1, 10)));
        BOOST_TEST((s.range(0).lo == R(1, 2)));
    }
    std::filesystem::remove_all(dir);
}

// Scene::from_meshes at poses: the tall box [0,2]^2 x [3,7] turned a quarter about y and moved by
// (−3, 0, 5) is [0,4] x [0,2] x [3,5] (test_cli derives it): touching the cube [0,2]^3 on
// ρ1 + ρ2 = 3 instead of ρ1 + 2ρ2 = 4.
BOOST_AUTO_TEST_CASE(meshes_at_poses) {
    const std::string dir = "/tmp/scalecert-test-api-poses-" + std::to_string(::getpid());
    std::filesystem::create_directories(dir);
    std::ofstream(dir + "/cube.obj") << "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 2 2 0\nv 0 0 2\nv 2 0 2\nv 0 2 2\nv 2 2 2\n";
    std::ofstream(dir + "/tall.obj") << "v 0 0 3\nv 2 0 3\nv 0 2 3\nv 2 2 3\nv 0 0 7\nv 2 0 7\nv 0 2 7\nv 2 2 7\n";
    const scalecert::Interval I{R(1, 2), R(2)};
    const scalecert::Pose quarter = {{{R(0), R(0), R(1), R(-3)}, {R(0), R(1), R(0), R(0)}, {R(-1), R(0), R(0), R(5)}}};
    const scalecert::Scene plain = scalecert::Scene::from_meshes(dir + "/cube.obj", dir + "/tall.obj", I, I);
    const scalecert::Scene posed = scalecert::Scene::from_meshes(dir + "/cube.obj", dir + "/tall.obj", I, I, false,
                                                                 scalecert::Numbers::Double, {std::nullopt, quarter});
    BOOST_TEST((scalecert::Analysis(plain).verdict(R(1), R(3, 2)) == scalecert::Verdict::Touching));
    BOOST_TEST((scalecert::Analysis(posed).verdict(R(1), R(3, 2)) == scalecert::Verdict::Separated));
    BOOST_TEST((scalecert::Analysis(posed).verdict(R(1), R(2)) == scalecert::Verdict::Touching));
    BOOST_TEST((posed.seed(1) == scalecert::Point{R(2), R(1), R(4)}));  // the mean of the moved points
    // A seed given in the mesh's frame moves with it: (1/2, 1, 5) inside the tall box goes to
    // (2, 1, 9/2) inside the moved box [0,4] x [0,2] x [3,5], so P2(ρ2) reaches down to
    // z = 9/2 − 3ρ2/2 and meets P1's top 1 + ρ1 on 2ρ1 + 3ρ2 = 7: touching at (1/2, 2), apart at
    // (1, 1). (About the default seed (2, 1, 4) they touch on ρ1 + ρ2 = 3: apart at (1/2, 2).)
    const scalecert::Scene seeded =
        scalecert::Scene::from_meshes(dir + "/cube.obj", dir + "/tall.obj", I, I, false, scalecert::Numbers::Double,
                                      {std::nullopt, quarter}, {std::nullopt, scalecert::Point{R(1, 2), R(1), R(5)}});
    BOOST_TEST((seeded.seed(1) == scalecert::Point{R(2), R(1), R(9, 2)}));
    BOOST_TEST((seeded.seed(0) == scalecert::Point{R(1), R(1), R(1)}));
    BOOST_TEST((scalecert::Analysis(seeded).verdict(R(1, 2), R(2)) == scalecert::Verdict::Touching));
    BOOST_TEST((scalecert::Analysis(seeded).verdict(R(1), R(1)) == scalecert::Verdict::Separated));
    BOOST_TEST((scalecert::Analysis(posed).verdict(R(1, 2), R(2)) == scalecert::Verdict::Separated));
    // Unposed, the seed is where it is given: about (1, 1, 7/2) P2(ρ2) spans z from 7/2 − ρ2/2 and
    // meets P1 = [1 − ρ1, 1 + ρ1]^3 on 2ρ1 + ρ2 = 5: touching at (3/2, 2), apart at (3/2, 1). (About
    // the default seed (1, 1, 5), on ρ1 + 2ρ2 = 4: overlapping at (3/2, 2).)
    const scalecert::Scene low =
        scalecert::Scene::from_meshes(dir + "/cube.obj", dir + "/tall.obj", I, I, false, scalecert::Numbers::Double, {},
                                      {std::nullopt, scalecert::Point{R(1), R(1), R(7, 2)}});
    BOOST_TEST((scalecert::Analysis(low).verdict(R(3, 2), R(2)) == scalecert::Verdict::Touching));
    BOOST_TEST((scalecert::Analysis(low).verdict(R(3, 2), R(1)) == scalecert::Verdict::Separated));
    BOOST_TEST((scalecert::Analysis(plain).verdict(R(3, 2), R(2)) == scalecert::Verdict::Overlapping));
    // A singular R is refused in one line.
    scalecert::Pose flat = quarter;
    flat[2] = {R(0), R(0), R(0), R(5)};
    BOOST_CHECK_EXCEPTION(scalecert::Scene::from_meshes(dir + "/cube.obj", dir + "/tall.obj", I, I, false,
                                                        scalecert::Numbers::Double, {flat, std::nullopt}),
                          scalecert::InputError, [](const scalecert::InputError& e) {
                              return std::string(e.what()).find("pose of P1: its 3x3 part R is singular") !=
                                     std::string::npos;
                          });
    std::filesystem::remove_all(dir);
}
