// Judgements files on objects with a radius (checker/rounded.cpp; CLAIMS.md, "Objects with a
// radius"): certify-fp's judgements on spheres, capsules, a rounded box and a sphere beside a plain
// box, derived by hand, at pairs and at poses, exactly and within tolerances, pass; every mutation is
// rejected or judged alike by the engine; and the tampered files FORMAT.md names are rejected.
#include "checker_tests.hpp"

#include "../../checker/judging.hpp"

BOOST_AUTO_TEST_SUITE(checker_rounded)

namespace rounded_tests {
// certify-fp's judgements file for `claims` on the scene `scene` (JSON text), checked valid.
OJ certificate(const std::string& scene, const std::string& claims, const std::string& name,
               const std::string& options = "") {
    const fs::path sp = tmpdir() / (name + ".scene.json"), cp = tmpdir() / (name + ".claims.json"),
                   out = tmpdir() / (name + ".cert.json");
    { std::ofstream(sp) << scene; }
    { std::ofstream(cp) << R"({"format": "scalecert-claims-1", "claims": [)" << claims << "]}"; }
    const int st = engine("certify-fp " + sp.string() + " " + cp.string() + " --certificate " + out.string() + options);
    BOOST_TEST_REQUIRE((st == 0 || st == 1), name);
    BOOST_TEST_REQUIRE(check_file(out) == 0, name);
    return load(out);
}
// The judgements' `right`, in order.
std::vector<bool> rights(const OJ& j) {
    std::vector<bool> r;
    for (const OJ& e : j["judgements"]) r.push_back(e["right"].get<bool>());
    return r;
}
std::string bits(const std::vector<bool>& v) {
    std::string t;
    for (bool b : v) t += b ? '1' : '0';
    return t;
}
// The checker's status and message on j.
std::pair<int, std::string> checked(const OJ& j) {
    std::string msg;
    const int st = scalecert_check::check_text(j.dump(1), msg);
    return {st, msg};
}
// j is rejected as invalid, with a message holding `why`.
void rejected(const OJ& j, const std::string& why, const std::string& what) {
    const auto [st, msg] = checked(j);
    BOOST_TEST(st == 1, what << ": " << msg);
    BOOST_TEST(msg.find(why) != std::string::npos, what << ": " << msg);
}

// P1 a sphere of radius 1 at the origin, P2 one of radius 2 at (5, 0, 0) (examples/spheres.json):
// R = ρ1 + 2ρ2 against D = 5.
const char* kSpheres = R"({"P1": {"sphere": 1},
 "P2": {"sphere": 2, "pose": [[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0]]}, "I1": [1, 2], "I2": [1, 2]})";
const char* kSphereClaims = R"(
 {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "touching"},
 {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated"},
 {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "overlapping"},
 {"kind": "distance", "rho1": 1, "rho2": 1, "value": 2, "closest": [[1, 0, 0], [3, 0, 0]]},
 {"kind": "distance", "rho1": 1, "rho2": 1, "value": 5},
 {"kind": "signed_distance", "rho1": 2, "rho2": 2, "value": -1},
 {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": 1, "direction": [1, 0, 0]},
 {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": 1, "direction": [1, 1, 0]},
 {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [1, 1, 0], "offset": 2},
 {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [1, 1, 0], "offset": 2.2},
 {"kind": "witness_point", "rho1": 2, "rho2": 2, "point": [1.5, 0, 0]},
 {"kind": "witness_point", "rho1": 1, "rho2": 1, "point": [1.1, 0, 0]},
 {"kind": "signed_distance", "rho1": 1, "rho2": 2, "value": 0},
 {"kind": "signed_distance", "rho1": 1, "rho2": 1, "at_least": 2},
 {"kind": "signed_distance", "rho1": 1, "rho2": 1, "below": 2},
 {"kind": "distance", "rho1": 2, "rho2": 2, "value": 0},
 {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "not_overlapping"},
 {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "intersecting"})";
// By hand: touching at (1, 2) (R = 5), apart by 5 − 3 = 2 at (1, 1), 1 deep at (2, 2); along
// (1, 1, 0) the balls part after −5/√2 + 6 ≈ 2.46 > 1; the plane x + y = 2 lies between √2 and
// 5 − 2√2 ≈ 2.17, x + y = 2.2 does not; (1.5, 0, 0) is in both at (2, 2) (1.5 <= 2, 3.5 <= 4),
// (1.1, 0, 0) in neither at (1, 1).
const std::vector<bool> kSphereRight = {true,  true, true,  true, false, true,  true, false, true,
                                        false, true, false, true, true,  false, true, true,  true};
}  // namespace rounded_tests
using namespace rounded_tests;

BOOST_AUTO_TEST_CASE(spheres_are_valid_and_tampering_is_rejected) {
    const OJ j = certificate(kSpheres, kSphereClaims, "spheres");
    BOOST_TEST(bits(rights(j)) == bits(kSphereRight));
    BOOST_TEST(j["scene"]["P1"]["radius"] == "1");
    BOOST_TEST(j["scene"]["P2"]["radius"] == "2");
    BOOST_TEST(j["seed_interior"]["P1"] == OJ::parse(R"({"within": [[0, "1"]]})"));
    // Apart hulls are proved by their distance (25), the closest points within the radii.
    BOOST_TEST(j["judgements"][0]["proof"]["distance"]["squared"] == "25");
    BOOST_TEST(j["judgements"][3]["proof"]["closest"]["P1"].contains("within"));
    BOOST_TEST(j["judgements"][11]["proof"]["P1"].contains("out"));
    mutate_and_report(j, "judgements on objects with a radius (spheres)", false, true);

    // A radius changed: P2's 2 made 3 touches at (1, 1) and overlaps at (1, 2).
    OJ f = j;
    f["scene"]["P2"]["radius"] = "3";
    rejected(f, ".right must be the judgement the rules give", "P2's radius 3");
    f = j;
    f["scene"]["P1"]["radius"] = "-1";
    rejected(f, "scene.P1.radius is >= 0", "a negative radius");
    f = j;
    f["scene"]["P1"]["radius"] = "0";  // a sphere without its radius: one point
    rejected(f, "scene.P1 has at least 4 vertices", "a point of radius 0");
    f = j;
    f["scene"]["P1"]["radius"] = "0", f["scene"]["P2"]["radius"] = "0";
    rejected(f, "scene.P1 has at least 4 vertices", "both radii 0");
    f = j;
    f["scene"]["P2"].erase("radius");
    rejected(f, "scene.P2.radius is present", "one object without its radius");
    // A `right` flipped.
    for (size_t k = 0; k < kSphereRight.size(); ++k) {
        f = j;
        f["judgements"][k]["right"] = !kSphereRight[k];
        rejected(f, "judgements[" + std::to_string(k) + "].right must be", "right flipped");
    }
    // A within membership whose point lies farther than ρr from its hull point: the closest point
    // (1, 0, 0) moved to (1.5, 0, 0), 3/2 from the centre of P1(1).
    f = j;
    f["judgements"][3]["claim"]["closest"][0][0] = "3/2";
    rejected(f, "closest.P1.within combines to a point within rho·radius of the point", "within too far");
    // An out normal that does not clear ρr: the witness (1.1, 0, 0) moved to (0.9, 0, 0), inside P1(1).
    f = j;
    f["judgements"][11]["claim"]["point"][0] = "9/10";
    rejected(f, "P1.out: the point lies more than rho·radius beyond", "out not clearing the radius");
    // The seed moved onto P1's sphere: |s − p| = r, not strictly inside.
    f = j;
    f["scene"]["P1"]["seed"] = OJ::parse(R"(["1", "0", "0"])");
    rejected(f, "seed_interior.P1.within combines to a point nearer the seed than the radius", "seed on the sphere");
    // A separating normal of the hulls in place of their distance proof: it shows them apart, not how far.
    f = j;
    f["judgements"][1]["proof"] = OJ::parse(R"({"depth": {"separated": ["1", "0", "0"]}})");
    rejected(f, "hulls apart take a distance proof", "depth {separated} in place of a distance");
    // Kinds of the curve are not judged on such a scene.
    for (const char* claim : {R"({"kind": "curve_point", "rho1": "1", "rho2": "2"})",
                              R"({"kind": "switch_point", "rho1": "1", "rho2": "2"})",
                              R"({"kind": "curve", "vertices": [["1", "2"], ["2", "3/2"]]})"}) {
        f = j;
        f["judgements"].push_back(
            OJ{{"index", 99}, {"claim", OJ::parse(claim)}, {"right", false}, {"proof", OJ::object()}});
        rejected(f, "kind is a kind of this file's claims", claim);
    }
    // The radius is a judgements file's field only: a query answer or a partition carrying one is refused.
    OJ q = bundled("stacked_cubes");
    q["scene"]["P1"]["radius"] = "1";
    BOOST_TEST(checked(q).first == 1);
}

// Growth distances (CLAIMS.md, "Objects with a radius"): a sphere of radius 1/2 centred at
// (2, 2, 0) beside the box [−1, 1]³ touches it at ρ* = (16 − 4√2)/7 (the edge region: √2·(2 − ρ) =
// ρ/2); two unit spheres 4 apart at ρ* = 2. The proof: ρ* as {a, b, c}, weights in Q(√2) of the
// nearest point of K on each object's vertices; every tamper of a, b, c, the sign, the feature and
// the weights is rejected.
BOOST_AUTO_TEST_CASE(growth_distances_are_checked_and_tampering_is_rejected) {
    char near[40];
    std::snprintf(near, sizeof near, "%.17g", (16 - 4 * std::sqrt(2.0)) / 7);
    const std::string claims = std::string(R"({"kind": "growth_distance", "value": )") + near + R"(},
     {"kind": "growth_distance", "value": 1.48},
     {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated"})";
    const std::string scene = R"({"P1": {"box": [1, 1, 1]},
      "P2": {"sphere": "1/2", "pose": [[1,0,0,2],[0,1,0,2],[0,0,1,0]]}, "I1": [1, 2], "I2": [1, 2]})";
    const OJ exact = certificate(scene, claims, "growth_edge_exact");
    BOOST_TEST(bits(rights(exact)) == "001");  // no rational is ρ*
    const OJ j = certificate(scene, claims, "growth_edge", " --tolerance 1e-15");
    BOOST_TEST(bits(rights(j)) == "101");
    const OJ& pr = j["judgements"][0]["proof"];
    BOOST_TEST(pr["value"] == OJ::parse(R"({"a": "16/7", "b": "-4/7", "c": "2"})"));
    BOOST_TEST(pr["P1"].size() == 2u);  // an edge of the box
    BOOST_TEST(pr["P2"].size() == 1u);  // the sphere's centre
    mutate_and_report(j, "judgements on objects with a radius (growth distance)", false, true);

    OJ f;
    auto tamper = [&](const char* key, const char* value, const std::string& why) {
        f = j;
        f["judgements"][0]["proof"]["value"][key] = value;
        rejected(f, why, std::string("value.") + key + " = " + value);
    };
    tamper("a", "17/7", "is (r1 + r2)²");
    tamper("b", "-5/7", "is (r1 + r2)²");
    // The other sign, (16 + 4√2)/7: its t is the conjugate root of the same quadratic, so |n|² holds,
    // and the plane through q normal to n cuts the box.
    tamper("b", "4/7", "lies beyond n·q1 along n");
    tamper("c", "3", "is (r1 + r2)²");
    tamper("c", "4", "value.c is not a perfect square");
    tamper("c", "0", "b and c are 0 together");
    f = j;
    f["judgements"][0]["proof"]["value"] = OJ::parse(R"({"a": "0", "b": "0", "c": "0"})");
    rejected(f, "value is 0 only where the seeds coincide", "rho* = 0");
    f = j;
    f["judgements"][0]["proof"]["value"] = OJ::parse(R"({"a": "-16/7", "b": "4/7", "c": "2"})");
    rejected(f, "value is > 0", "rho* < 0");
    // The feature: another vertex of the box in place of one of the edge's.
    f = j;
    OJ& w0 = f["judgements"][0]["proof"]["P1"][0][0];
    w0 = (w0.get<int>() + 1) % 8 == f["judgements"][0]["proof"]["P1"][1][0].get<int>() ? (w0.get<int>() + 2) % 8
                                                                                       : (w0.get<int>() + 1) % 8;
    rejected(f, "is (r1 + r2)²", "another vertex");
    // A weight below 0, weights not summing to 1, a vertex named twice.
    f = j;
    f["judgements"][0]["proof"]["P1"][0][1] = "-1";
    rejected(f, "is a weight >= 0", "a negative weight");
    f = j;
    f["judgements"][0]["proof"]["P2"][0][1] = "1/2";
    rejected(f, "the weights sum to 1", "weights summing to 1/2");
    f = j;
    f["judgements"][0]["proof"]["P1"][1][0] = f["judgements"][0]["proof"]["P1"][0][0];
    rejected(f, "is named once", "a vertex twice");
    // The scene's radius changed: the same proof no longer reaches r1 + r2.
    f = j;
    f["scene"]["P2"]["radius"] = "1";
    rejected(f, "is (r1 + r2)²", "radius 1");
    // `right` flipped.
    f = j;
    f["judgements"][1]["right"] = true;
    rejected(f, "judgements[1].right must be", "right flipped");

    // Two unit spheres 4 apart: ρ* = 2, rational.
    const OJ two =
        certificate(R"({"P1": {"sphere": 1}, "P2": {"sphere": 1, "pose": [[1,0,0,4],[0,1,0,0],[0,0,1,0]]}})",
                    R"({"kind": "growth_distance", "value": 2}, {"kind": "growth_distance", "value": 2.0000001})",
                    "growth_spheres");
    BOOST_TEST(bits(rights(two)) == "10");
    BOOST_TEST(two["judgements"][0]["proof"]["value"] == OJ::parse(R"({"a": "2", "b": "0", "c": "0"})"));
    mutate_and_report(two, "judgements on objects with a radius (growth of spheres)", false, true);
}

BOOST_AUTO_TEST_CASE(capsules_parallel_skew_and_crossing_by_hand) {
    // Capsules along z, half-length 1, radius 1/4, about their centres: P2 moved to x = 1
    // (parallel), turned onto x and moved to y = 2 (skew), or turned onto x at the origin (crossing).
    auto scene = [](const std::string& pose) {
        return R"({"P1": {"capsule": {"radius": "1/4", "half_length": 1}},
          "P2": {"capsule": {"radius": "1/4", "half_length": 1}, "pose": )" +
               pose + R"(}, "I1": [1, 2], "I2": [1, 2]})";
    };
    // Parallel: the axes 1 apart at every scaling, R = (ρ1 + ρ2)/4: 1/2 apart at (1, 1), touching
    // at (2, 2), 1/2 deep at (3, 3) along x (the hulls' extent −1 along x, plus R = 3/2), not along
    // y (0 + 3/2); the plane x = 1/2 between 1/4 and 3/4, x = 1/5 not.
    const OJ par = certificate(scene("[[1,0,0,1],[0,1,0,0],[0,0,1,0]]"), R"(
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 0.5, "closest": [[0.25, 0, 0], [0.75, 0, 0]]},
     {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "touching"},
     {"kind": "penetration_depth", "rho1": 3, "rho2": 3, "value": 0.5, "direction": [1, 0, 0]},
     {"kind": "penetration_depth", "rho1": 3, "rho2": 3, "value": 0.5, "direction": [0, 1, 0]},
     {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [1, 0, 0], "offset": 0.5},
     {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [1, 0, 0], "offset": 0.2},
     {"kind": "witness_point", "rho1": 2, "rho2": 2, "point": [0.5, 0, 1.5]})",
                               "capsules_parallel");
    BOOST_TEST(bits(rights(par)) == "1110101");
    mutate_and_report(par, "judgements on objects with a radius (parallel capsules)", false, true);
    // Skew: the axes 2 apart: 3/2 at (1, 1), touching at (4, 4).
    const OJ skew = certificate(scene("[[0,0,1,0],[0,1,0,2],[-1,0,0,0]]"), R"(
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.5},
     {"kind": "signed_distance", "rho1": 1, "rho2": 1, "value": 1.5},
     {"kind": "verdict", "rho1": 4, "rho2": 4, "verdict": "touching"},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 2})",
                                "capsules_skew");
    BOOST_TEST(bits(rights(skew)) == "1110");
    // Crossing at the origin: the hulls (two crossing segments, a flat difference) touch, so the
    // depth is R = 1/2: right along y (the hulls' extent 0), wrong along x, where they part only
    // after 1 + 1/2.
    const OJ cross = certificate(scene("[[0,0,1,0],[0,1,0,0],[-1,0,0,0]]"), R"(
     {"kind": "penetration_depth", "rho1": 1, "rho2": 1, "value": 0.5, "direction": [0, 1, 0]},
     {"kind": "penetration_depth", "rho1": 1, "rho2": 1, "value": 0.5, "direction": [1, 0, 0]},
     {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "overlapping"},
     {"kind": "signed_distance", "rho1": 1, "rho2": 1, "value": -0.5},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 0})",
                                 "capsules_crossing");
    BOOST_TEST(bits(rights(cross)) == "10111");
    BOOST_TEST(cross["judgements"][0]["proof"]["depth"]["squared"] == "0");
    BOOST_TEST(cross["judgements"][0]["proof"]["depth"].contains("common"));
    mutate_and_report(cross, "judgements on objects with a radius (crossing capsules)", false, true);
    // Touching hulls whose direction is not a normal of their flat difference prove nothing.
    OJ f = cross;
    f["judgements"][0]["proof"]["depth"]["direction"] = OJ::parse(R"(["1", "0", "0"])");
    rejected(f, "the plane supports both bodies", "a touching direction that does not support");
    // A flat object with radius 0: a capsule's segment is no polyhedron.
    f = cross;
    f["scene"]["P2"]["radius"] = "0";
    rejected(f, "scene.P2 has at least 4 vertices", "a segment of radius 0");
}

BOOST_AUTO_TEST_CASE(a_flat_object_needs_a_radius) {
    // A square of side 2 with radius 1/2 (a rounded plate) under a rounded cube: the plate reaches
    // z = ρ1/2, the cube starts at 3 − 5ρ2/4 (1.25 apart at (1, 1), overlapping at (2, 2)); the
    // plate's seed is in its interior only thanks to the radius. Made radius 0 with a polyhedron's seed weights (the
    // square's four corners, which combine to its centre), the weights span 2 dimensions: refused.
    const OJ j = certificate(R"({"P1": {"vertices": [[-1,-1,0],[1,-1,0],[1,1,0],[-1,1,0]], "radius": "1/2"},
      "P2": {"box": [1, 1, 1], "radius": "1/4", "pose": [[1,0,0,0],[0,1,0,0],[0,0,1,3]]}, "I1": [1, 2], "I2": [1, 2]})",
                             R"({"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.25},
                                {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "overlapping"})",
                             "plate");
    BOOST_TEST(bits(rights(j)) == "11");
    OJ f = j;
    f["scene"]["P1"]["radius"] = "0";
    f["seed_interior"]["P1"] = OJ::parse(R"([[0, "1/4"], [1, "1/4"], [2, "1/4"], [3, "1/4"]])");
    rejected(f, "seed_interior.P1 uses vertices spanning 3 dimensions", "a flat object of radius 0");
    // The plate's seed in a polyhedron's form is refused.
    f = j;
    f["seed_interior"]["P1"] = OJ::parse(R"([[0, "1"]])");
    rejected(f, "seed_interior.P1 is an object", "a rounded object's seed as weights");
}

BOOST_AUTO_TEST_CASE(a_rounded_box_on_a_box_at_pairs_and_at_poses) {
    // {"box": [1, 1, 1], "radius": "1/2"} under the box [−1, 1]² × [3/2, 7/2]: P1(ρ1) reaches
    // z = 3ρ1/2, P2(ρ2) starts at z = 5/2 − ρ2. They touch at (1, 1), are 1/2 apart at (1, 1/2),
    // and at (2, 1) the hulls overlap by 1/2 along z (an EPA surface), the objects by 3/2; along x
    // they part only after 3 + 1. Then the same with both objects at one pose A (a quarter turn
    // about x, then (1, 2, 3)): every value unchanged, the direction z turned to A·z = (0, −1, 0).
    const std::string A = "[[1,0,0,1],[0,0,-1,2],[0,1,0,3]]", at = R"(, "pose1": )" + A + R"(, "pose2": )" + A;
    const OJ j = certificate(R"({"P1": {"box": [1, 1, 1], "radius": "1/2"},
      "P2": {"box": [1, 1, 1], "pose": [[1,0,0,0],[0,1,0,0],[0,0,1,"5/2"]]}, "I1": [1, 2], "I2": [1, 2]})",
                             R"(
     {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "touching"},
     {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 0.5, "closest": [[0, 0, 1.5], [0, 0, 2]]},
     {"kind": "penetration_depth", "rho1": 2, "rho2": 1, "value": 1.5, "direction": [0, 0, 1]},
     {"kind": "penetration_depth", "rho1": 2, "rho2": 1, "value": 1.5, "direction": [1, 0, 0]},
     {"kind": "signed_distance", "rho1": 1, "rho2": 0.5, "value": 0.5},
     {"kind": "separating_plane", "rho1": 1, "rho2": 0.5, "normal": [0, 0, 1], "offset": 1.75},
     {"kind": "witness_point", "rho1": 2, "rho2": 1, "point": [0, 0, 2.5]},
     {"kind": "signed_distance", "rho1": 2, "rho2": 1, "value": -1.5},
     {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "touching")" +
                                 at + R"(},
     {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 0.5)" +
                                 at + R"(},
     {"kind": "penetration_depth", "rho1": 2, "rho2": 1, "value": 1.5, "direction": [0, -1, 0])" +
                                 at + R"(},
     {"kind": "penetration_depth", "rho1": 2, "rho2": 1, "value": 1.5, "direction": [0, 0, 1])" +
                                 at + R"(},
     {"kind": "signed_distance", "rho1": 2, "rho2": 1, "value": -1.5)" +
                                 at + R"(},
     {"kind": "separating_plane", "rho1": 1, "rho2": 0.5, "normal": [0, -1, 0], "offset": -0.25)" +
                                 at + R"(})",
                             "rounded_box");
    BOOST_TEST(bits(rights(j)) == "11101111111011");
    BOOST_TEST(j["judgements"][2]["proof"]["depth"].contains("triangles"));  // the hulls overlap
    BOOST_TEST(j["judgements"][2]["proof"]["depth"]["squared"] == "1/4");
    mutate_and_report(j, "judgements on objects with a radius (rounded box on a box, at poses)", false, true);
    // The radius made 1: P1 reaches z = 2 at (1, 1), past P2's start at 3/2.
    OJ f = j;
    f["scene"]["P1"]["radius"] = "1";
    rejected(f, ".right must be the judgement the rules give", "the rounded box's radius 1");
    // A pose's translation tampered moves P2 one deeper along the depth's direction (0, −1, 0):
    // the hulls' proved depth no longer holds there.
    f = j;
    f["judgements"][10]["claim"]["pose2"][1][3] = "1";
    rejected(f, "judgements[10].proof.depth.direction: the depth along it is sqrt(squared)", "a pose moved");
}

BOOST_AUTO_TEST_CASE(a_sphere_beside_a_plain_box_exactly_and_within_tolerances) {
    // A sphere of radius 1/2 against the box [−1, 1]³ (radius 0: a plain polyhedron): centred at
    // (3, 0, 0) the distance is 3/2; moved to (2, 2, 0) (an edge's region) √2 − 1/2, right as the
    // double nearest it within a relative 2^-50 and wrong without (no rational is it), wrong 10^-9
    // off; at (2, 2, 2) (a vertex's) √3 − 1/2. Grown about its centre it touches the face at
    // ρ2 = 4 and is 1 deep at ρ2 = 6, along x.
    const std::string edge = R"(, "pose2": [[1,0,0,-1],[0,1,0,2],[0,0,1,0]])",
                      vertex = R"(, "pose2": [[1,0,0,-1],[0,1,0,2],[0,0,1,2]])";
    const std::string scene = R"({"P1": {"box": [1, 1, 1]},
      "P2": {"sphere": "1/2", "pose": [[1,0,0,3],[0,1,0,0],[0,0,1,0]]}, "I1": [1, 2], "I2": [1, 2]})";
    const std::string claims = R"(
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.5, "closest": [[1, 0, 0], [2.5, 0, 0]]},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 0.9142135623730951)" +
                               edge + R"(},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": "914213563373095/1000000000000000")" +
                               edge + R"(},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.2320508075688772)" +
                               vertex + R"(},
     {"kind": "signed_distance", "rho1": 1, "rho2": 1, "value": 0.9142135623730951)" +
                               edge + R"(},
     {"kind": "verdict", "rho1": 1, "rho2": 4, "verdict": "touching"},
     {"kind": "penetration_depth", "rho1": 1, "rho2": 6, "value": 1, "direction": [1, 0, 0]},
     {"kind": "witness_point", "rho1": 1, "rho2": 4, "point": [1, 0, 0]},
     {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [1, 0, 0], "offset": 2},
     {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [1, 1, 0], "offset": 2.2)" +
                               edge + R"(})";
    // (The plane x + y = 2.2 at the edge pose: the box reaches 2, the sphere starts at 4 − √2/2 ≈ 3.29.)
    const OJ exact = certificate(scene, claims, "sphere_box");
    BOOST_TEST(bits(rights(exact)) == "1000011111");
    BOOST_TEST(exact["seed_interior"]["P1"].is_array());  // the box's seed: a polyhedron's weights
    BOOST_TEST(exact["seed_interior"]["P2"].contains("within"));
    OJ f = exact;  // the box's seed in the rounded form is refused
    f["seed_interior"]["P1"] = OJ::parse(R"({"within": [[0, "1"]]})");
    rejected(f, "seed_interior.P1 is a nonempty list of weights", "a polyhedron's seed as within");
    const OJ tol = certificate(scene, claims, "sphere_box_tol", " --tolerance 1/1125899906842624");
    BOOST_TEST(bits(rights(tol)) == "1101111111");
    mutate_and_report(tol, "judgements on objects with a radius (a sphere beside a box, relative tolerance)", false,
                      true);
    // The tolerance made 0, the edge distances are wrong.
    f = tol;
    f["tolerance"] = "0";
    rejected(f, "judgements[1].right must be", "the tolerance removed");
}

BOOST_AUTO_TEST_CASE(concentric_spheres_have_flat_touching_hulls) {
    // Two spheres about one centre: the hulls are one point each, their difference the origin, so
    // they touch (a direction normal to the flat difference, and the common point), and the depth
    // is R = ρ1 + 2ρ2 along every direction.
    const OJ j = certificate(R"({"P1": {"sphere": 1}, "P2": {"sphere": 2}, "I1": [1, 2], "I2": [1, 2]})", R"(
     {"kind": "penetration_depth", "rho1": 1, "rho2": 1, "value": 3, "direction": [1, 2, 3]},
     {"kind": "signed_distance", "rho1": 1, "rho2": 1, "value": -3},
     {"kind": "penetration_depth", "rho1": 1, "rho2": 1, "value": 2},
     {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "overlapping"})",
                             "concentric");
    BOOST_TEST(bits(rights(j)) == "1101");
    BOOST_TEST(j["judgements"][0]["proof"]["depth"]["squared"] == "0");
    mutate_and_report(j, "judgements on objects with a radius (concentric spheres)", false, true);
    // A distance proof of hulls that meet (squared 0) is true, but says nothing of their depth.
    OJ f = j;
    f["judgements"][1]["proof"] = OJ::parse(R"({"distance": {"squared": "0", "P1": [[0, "1"]], "P2": [[0, "1"]]}})");
    rejected(f, "distance proves the hulls apart (squared > 0)", "a distance proof of 0");
}

BOOST_AUTO_TEST_CASE(absolute_tolerance_on_objects_with_a_radius) {
    // The spheres above at LEN = 10^-9 (every number an exact string): at (1, 1) the closest point
    // (1 + 5·10^-10, 0, 0) lies 5·10^-10 out of P1 (near), and at the touching pair (1, 2) the
    // witness (1 + 5·10^-10, 0, 0) too; (1 + 2·10^-9, 0, 0) is 2·10^-9 out (out must clear
    // 1 + 10^-9); the plane x = 1 between the touching spheres is right within LEN, and a distance
    // of 2 + 10^-9 at (1, 1); 2 + 2·10^-9 is not.
    const std::string claims = R"(
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 2, "closest": [["2000000001/2000000000", 0, 0], [3, 0, 0]]},
     {"kind": "witness_point", "rho1": 1, "rho2": 2, "point": ["2000000001/2000000000", 0, 0]},
     {"kind": "witness_point", "rho1": 1, "rho2": 2, "point": ["500000001/500000000", 0, 0]},
     {"kind": "separating_plane", "rho1": 1, "rho2": 2, "normal": [1, 0, 0], "offset": 1},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": "2000000001/1000000000"},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": "1000000001/500000000"},
     {"kind": "signed_distance", "rho1": 1, "rho2": 2, "value": "-1/1000000000"})";
    const OJ exact = certificate(kSpheres, claims, "spheres_exact");
    BOOST_TEST(bits(rights(exact)) == "0000000");
    const OJ j = certificate(kSpheres, claims, "spheres_abs", " --abs-tolerance 1e-9");
    BOOST_TEST(bits(rights(j)) == "1101101");
    BOOST_TEST(j["abs_tolerance"] == "1/1000000000");
    BOOST_TEST(j["judgements"][0]["proof"]["closest"]["P1"].contains("near"));
    BOOST_TEST(j["judgements"][2]["proof"]["P1"].contains("out"));
    mutate_and_report(j, "judgements on objects with a radius (absolute tolerance)", false, true);
    // Without the tolerance the near proofs are refused; an out at 10^-9 no longer clears it at 10^-8.
    OJ f = j;
    f.erase("abs_tolerance");
    rejected(f, "closest.P1 is {\"within\": weights} or {\"out\": normal}", "near without abs_tolerance");
    f = j;
    f["abs_tolerance"] = "1/100000000";
    rejected(f, "P1.out: the point lies more than rho·radius + abs_tolerance beyond", "out within a larger LEN");
}

// Parts with radii (CLAIMS.md, "Parts with radii"): spheres of radius 1 at 0 and 1/2 at (3, 0, 0)
// (seed 0) against the box [5, 7] × [−1, 1]² about (6, 0, 0) (examples/sphere_set.json). Along x
// the second sphere reaches 7ρ1/2 and the box starts at 6 − ρ2: touching at (10/7, 1), 3/2 apart
// at (1, 1) (the first sphere 4), the second sphere 1 deep in the box at (2, 1) (depth 2).
BOOST_AUTO_TEST_CASE(parts_with_radii_are_checked_and_tampering_is_rejected) {
    const char* scene = R"({"P1": {"spheres": {"centres": [[0, 0, 0], [3, 0, 0]], "radii": [1, "1/2"]},
        "seed": [0, 0, 0]}, "P2": {"box": [1, 1, 1], "pose": [[1, 0, 0, 6], [0, 1, 0, 0], [0, 0, 1, 0]]},
        "I1": [1, 2], "I2": [1, 2]})";
    const char* claims = R"(
 {"kind": "verdict", "rho1": "10/7", "rho2": 1, "verdict": "touching"},
 {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated"},
 {"kind": "verdict", "rho1": 2, "rho2": 1, "verdict": "separated"},
 {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1.5, "closest": [[3.5, 0, 0], [5, 0, 0]]},
 {"kind": "distance", "rho1": 1, "rho2": 1, "value": 4},
 {"kind": "distance", "rho1": 2, "rho2": 1, "value": 0},
 {"kind": "witness_point", "rho1": 2, "rho2": 1, "point": [5, 0, 0]},
 {"kind": "witness_point", "rho1": 1, "rho2": 1, "point": [5, 0, 0]},
 {"kind": "signed_distance", "rho1": 1, "rho2": 1, "parts": [0, 0], "value": 4},
 {"kind": "penetration_depth", "rho1": 2, "rho2": 1, "parts": [1, 0], "value": 2},
 {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [1, 1, 0]},
 {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [1, 2, 0]},
 {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated",
  "pose2": [[0, 1, 0, 6], [-1, 0, 0, 0], [0, 0, 1, 0]]})";
    const OJ j = certificate(scene, claims, "sphere_set");
    BOOST_TEST(j["kind"] == "compound_judgements");
    BOOST_TEST(bits(rights(j)) == "1101011011101");
    BOOST_TEST(j["scene"]["P1"]["parts"][1]["radius"] == "1/2");
    mutate_and_report(j, "judgements on parts with radii", false, true, true);
    OJ f = j;
    // The second sphere's radius 1/2 made 1: it overlaps the box at (10/7, 1).
    f["scene"]["P1"]["parts"][1]["radius"] = "1";
    rejected(f, "judgements[0].proof.pairs[0]: the pair does not overlap", "a part's radius changed");
    f = j;
    f["scene"]["P1"]["parts"][1].erase("radius");
    rejected(f, "has a radius (every part has one when any has)", "one part without its radius");
    // The touching verdict's pairs without its touching pair (1, 0): none touches; and said
    // separated, that pair, left out, is not apart by its boxes (they touch at x = 5).
    f = j;
    f["judgements"][0]["proof"]["pairs"] = OJ::array();
    rejected(f, "judgements[0].proof.pairs has a touching pair", "the touching pair left out");
    f["judgements"][0]["proof"]["verdict"] = "separated";
    f["judgements"][0]["right"] = false;
    rejected(f, "parts 1 and 0, not listed, have widened boxes apart", "a meeting pair left out");
    // The distance's nearest pair swapped for the first sphere (4 apart): the second, not listed
    // and its boxes 3/2 apart, is nearer.
    f = j;
    f["judgements"][3]["proof"]["pair"] = OJ::array({0, 0});
    f["judgements"][3]["proof"]["hulls"] = j["judgements"][8]["proof"];
    rejected(f, "not listed, have widened boxes at least the distance apart", "the nearest pair swapped");
    // A witness said to be in part 0 (the first sphere, 5 from it at ρ1 = 2... 2 units of radius).
    f = j;
    f["judgements"][6]["proof"]["P1"]["part"] = 0;
    rejected(f, "within combines to a point within rho·radius of the point", "a witness in the wrong part");
    for (size_t k = 0; k < 13; ++k) {
        f = j;
        f["judgements"][k]["right"] = !j["judgements"][k]["right"].get<bool>();
        rejected(f, "judgements[" + std::to_string(k) + "].right must be", "right flipped");
    }
}

// Two parts of radius 0 (R = 0) sharing a face touch, as plain polytopes do (the second hostile
// review's forgery): the cube [0, 1]³ (beside a ball of radius 1 at (−5, 0, 0)) against the cube
// [1, 2] × [0, 1]² at (1, 1). The engine's certificate passes; the verdict said overlapping, with
// the touching pair as its proof, is rejected.
BOOST_AUTO_TEST_CASE(parts_of_radius_zero_touch) {
    const char* placed = R"({"P1": {"parts": [
        {"vertices": [[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1]], "radius": 0},
        {"vertices": [[-5,0,0]], "radius": 1}], "seed": [0, 0, 0]},
      "P2": {"parts": [{"vertices": [[1,0,0],[2,0,0],[1,1,0],[2,1,0],[1,0,1],[2,0,1],[1,1,1],[2,1,1]]}],
             "seed": [2, 0, 0]}})";
    const OJ j =
        certificate(placed, R"({"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "touching"})", "radius_zero_touch");
    BOOST_TEST(bits(rights(j)) == "1");
    BOOST_TEST(j["judgements"][0]["proof"]["verdict"] == "touching");
    OJ f = j;
    f["judgements"][0]["claim"]["verdict"] = "overlapping";
    f["judgements"][0]["proof"]["verdict"] = "overlapping";
    rejected(f, "judgements[0].proof.pairs[0]: the pair overlaps", "touching parts of radius 0 said to overlap");
}

// Random sphere sets against sphere sets and a rounded box, claims at pairs and at poses: every
// certificate the engine writes passes the checker (certificate() requires it).
BOOST_AUTO_TEST_CASE(random_sphere_sets_certify) {
    std::mt19937_64 g(61);
    std::uniform_int_distribution<int> c(-12, 12), r(1, 6), n(1, 6), rho(2, 8);
    auto q = [](long p, long d) { return "\"" + std::to_string(p) + "/" + std::to_string(d) + "\""; };
    for (int t = 0; t < 12; ++t) {
        auto spheres = [&](int shift) {
            std::string cs, rs;
            const int m = n(g);
            for (int k = 0; k < m; ++k) {
                cs +=
                    std::string(k ? ", " : "") + "[" + q(c(g) + shift, 4) + ", " + q(c(g), 4) + ", " + q(c(g), 4) + "]";
                rs += std::string(k ? ", " : "") + q(r(g), 4);
            }
            return R"({"spheres": {"centres": [)" + cs + R"(], "radii": [)" + rs + "]}}";
        };
        const std::string other =
            t % 2 ? spheres(12)
                  : R"({"box": [1, 2, 1], "radius": "1/4", "pose": [[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0]]})";
        const std::string scene = R"({"P1": )" + spheres(0) + R"(, "P2": )" + other + "}";
        std::string claims;
        for (int k = 0; k < 4; ++k) {
            const std::string at = R"("rho1": )" + q(rho(g), 4) + R"(, "rho2": )" + q(rho(g), 4);
            const std::string pose =
                k % 2 ? R"(, "pose2": [[0, -1, 0, )" + q(c(g), 8) + R"(], [1, 0, 0, 0], [0, 0, 1, 0]])" : "";
            claims += std::string(k ? ", " : "") + R"({"kind": "verdict", )" + at + R"(, "verdict": "separated")" +
                      pose + R"(}, {"kind": "distance", )" + at + R"(, "value": 1)" + pose + "}";
        }
        certificate(scene, claims, "random_set_" + std::to_string(t));
    }
}

BOOST_AUTO_TEST_CASE(signs_of_sums_of_roots_are_exact) {
    // a + b√A + c√E against exact values where A and E are squares (the roots rational), over
    // random small rationals, and by hand where they are not.
    namespace s = scalecert_check;
    std::mt19937_64 g(7);
    for (int t = 0; t < 20000; ++t) {
        const CQ a = rq(g, 6, 3), b = rq(g, 4, 2), c = rq(g, 4, 2), p = rq(g, 5, 3), q = rq(g, 5, 3);
        const CQ pa = abs(p), qa = abs(q), exact = a + b * pa + c * qa;
        BOOST_TEST_REQUIRE(s::sign_two_roots(a, b, p * p, c, q * q) == sgn(exact),
                           a << " " << b << " " << p << " " << c << " " << q);
    }
    BOOST_TEST(s::sign_two_roots(-3, 1, 2, 1, 3) == 1);               // √2 + √3 ≈ 3.146
    BOOST_TEST(s::sign_two_roots(cq(-63, 20), 1, 2, 1, 3) == -1);     // < 3.15
    BOOST_TEST(s::sign_two_roots(0, 1, 8, -2, 2) == 0);               // √8 = 2√2
    BOOST_TEST(s::sign_two_roots(cq(1, 1000000), 1, 2, -1, 2) == 1);  // 10^-6 + √2 − √2
    BOOST_TEST(s::sign_two_roots(1, -1, 2, 1, cq(3, 2)) == 1);        // 1 − 1.414 + 1.225
    BOOST_TEST(s::sign_two_roots(0, 1, 0, -1, 0) == 0);

    // close_value: |c − x| <= abs + tol·|x| for x = s√E + k, against the rational x where E is a
    // square.
    s::Context cx;
    for (int t = 0; t < 20000; ++t) {
        const s::Rules R{abs(rq(g, 2, 4)), t % 3 ? abs(rq(g, 1, 8)) : CQ(0)};
        const int sg = static_cast<int>(g() % 3) - 1;
        const CQ c = rq(g, 6, 4), k = rq(g, 6, 4), e = abs(rq(g, 4, 2)), x = sg * e + k;
        const bool direct = abs(c - x) <= R.abs + R.tol * abs(x);
        BOOST_TEST_REQUIRE(R.close_value(cx, c, sg, e * e, k) == direct, c << " " << sg << " " << e << " " << k);
    }
}

BOOST_AUTO_TEST_SUITE_END()
