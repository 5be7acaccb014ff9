// Compound judgements files (checker/compound_judgements.cpp): certify-fp's judgements on objects
// made of parts, at poses and over grids of parts, pass; every mutation is rejected or judged alike
// by the engine; forgeries by hand.
#include "checker_tests.hpp"

#include <random>

BOOST_AUTO_TEST_SUITE(checker_compound_judgements)

namespace {
// The band's claims (test_compound derives each by hand): a verdict of each kind, distances apart
// and meeting with closest points, planes and witness points in and out.
const char* kBandClaims = R"({"format": "scalecert-claims-1", "claims": [
 {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "separated"},
 {"kind": "verdict", "rho1": 1, "rho2": 3, "verdict": "touching"},
 {"kind": "verdict", "rho1": 1.5, "rho2": 2, "verdict": "overlapping"},
 {"kind": "verdict", "rho1": 3, "rho2": 2, "verdict": "intersecting"},
 {"kind": "distance", "rho1": 1, "rho2": 2, "value": 0.5, "closest": [[3, 0, 0], [3.5, 0, 0]]},
 {"kind": "distance", "rho1": 3, "rho2": 2, "value": 0.5},
 {"kind": "distance", "rho1": 1.5, "rho2": 2, "value": 0, "closest": [[4, 0, 0], [4, 0, 0]]},
 {"kind": "separating_plane", "rho1": 1, "rho2": 2, "normal": [1, 0, 0], "offset": 3.25},
 {"kind": "separating_plane", "rho1": 3, "rho2": 2, "normal": [1, 0, 0]},
 {"kind": "witness_point", "rho1": 1.5, "rho2": 2, "point": [4, 0, 0]},
 {"kind": "witness_point", "rho1": 1.5, "rho2": 2, "point": [-4, 0, 0]}
]})";
}  // namespace

BOOST_AUTO_TEST_CASE(compound_judgements_are_valid_and_tampering_is_rejected) {
    // Every mutation is rejected, or the checker accepts it and the engine, re-run on the changed
    // file's scene, claims and tolerance, gives every judgement the file states.
    const OJ band = compound_judgements(data("compound_band.json"), kBandClaims, "band");
    BOOST_TEST(band["kind"] == "compound_judgements");
    const std::vector<bool> right = {true, true, true, false, true, true, true, true, false, true, false};
    BOOST_TEST_REQUIRE(band["judgements"].size() == right.size());
    for (size_t k = 0; k < right.size(); ++k) BOOST_TEST(band["judgements"][k]["right"] == right[k], k);
    mutate_and_report(band, "compound judgements (band)", false, true);
    // The mixed compound: blocks of far parts, several pairs apart by their own normals.
    const std::string mixed_claims = R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated"},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1},
     {"kind": "verdict", "rho1": "5/2", "rho2": "5/2", "verdict": "overlapping"},
     {"kind": "distance", "rho1": "1/2", "rho2": "1/2", "value": 3}
    ]})";
    const OJ mixed = compound_judgements(mixed_compound(), mixed_claims, "mixed");
    mutate_and_report(
        mixed, "compound judgements (mixed)", false,
        true);  // Contacts on the U and peg (the U's bottom [-3,3] x [-1,1] x [0,1], arms [-3,-2] and [2,3] in x
    // up to z = 4, about (0,0,1/2); the peg [-1,1] x [-1/2,1/2] x [2,5] about (0,0,7/2)). At (1, 2)
    // the peg is [-2,2] x [-1,1] x [1/2,13/2]: it sinks 1/2 into the bottom (along +z; along y it
    // would move 2, along x 5) and touches each arm (depth 0); at (3/2, 2) the arms have moved out
    // to |x| >= 3 (apart) and the bottom reaches z = 5/4 (depth 3/4).
    const OJ contacts = compound_judgements(data("compound_u_peg.json"), R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "penetration_depth", "rho1": 1, "rho2": 2, "parts": [0, 0], "value": 0.5, "direction": [0, 0, 1]},
     {"kind": "penetration_depth", "rho1": 1, "rho2": 2, "parts": [0, 0], "value": 0.5, "direction": [1, 0, 0]},
     {"kind": "penetration_depth", "rho1": 1, "rho2": 2, "parts": [1, 0], "value": 0},
     {"kind": "penetration_depth", "rho1": 1.5, "rho2": 2, "parts": [2, 0], "value": 0},
     {"kind": "penetration_depth", "rho1": 1.5, "rho2": 2, "parts": [0, 0], "value": 0.75}
    ]})",
                                            "u_peg_contacts");
    const std::vector<bool> contact_right = {true, false, true, false, true};
    for (size_t k = 0; k < contact_right.size(); ++k)
        BOOST_TEST(contacts["judgements"][k]["right"] == contact_right[k], k);
    BOOST_TEST(contacts["judgements"][0]["proof"]["squared"] == "1/4");
    BOOST_TEST(contacts["judgements"][4]["proof"]["squared"] == "9/16");
    mutate_and_report(contacts, "compound judgements (contacts)", false, true);
}

BOOST_AUTO_TEST_CASE(compound_judgements_at_poses_are_valid_and_tampering_is_rejected) {
    // The U and peg (CLAIMS.md's contact example) with the peg lifted by 10: at (1, 2) the peg is
    // [-2,2] x [-1,1] x [21/2, 33/2], separated, 13/2 above the arms' tops (z = 4; x meets at ±2);
    // lowered by 1/4, it sinks 3/4 into the bottom (z up to 1); turned a quarter about z it still
    // holds (0, 0, 3/4), as the bottom does.
    const std::string up = "[[1,0,0,0],[0,1,0,0],[0,0,1,10]]", down = "[[1,0,0,0],[0,1,0,0],[0,0,1,-0.25]]";
    const OJ j = compound_judgements(data("compound_u_peg.json"),
                                     R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "separated", "pose2": )" +
                                         up + R"(},
     {"kind": "distance", "rho1": 1, "rho2": 2, "value": 6.5, "pose2": )" +
                                         up + R"(},
     {"kind": "penetration_depth", "rho1": 1, "rho2": 2, "parts": [0, 0], "value": 0.75, "pose2": )" +
                                         down + R"(},
     {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "touching", "pose2": )" +
                                         up + R"(},
     {"kind": "witness_point", "rho1": 1, "rho2": 2, "point": [0, 0, 0.75], "pose2": [[0,-1,0,0],[1,0,0,0],[0,0,1,0]]}
    ]})",
                                     "u_peg_posed");
    const std::vector<bool> right = {true, true, true, false, true};
    BOOST_TEST_REQUIRE(j["judgements"].size() == right.size());
    for (size_t k = 0; k < right.size(); ++k) BOOST_TEST(j["judgements"][k]["right"] == right[k], k);
    mutate_and_report(j, "compound judgements at poses", false, true);
}

BOOST_AUTO_TEST_CASE(compound_distances_over_grids_are_valid) {
    // Two grids of 4 x 4 random parts side by side: a distance's lower bound has blocks of boxes
    // apart, pairs apart along the slab of their double GJK direction and pairs apart by their own
    // closest points; a partition and verdicts too. Each certificate is valid.
    std::mt19937 g(77);
    std::uniform_int_distribution<int> u(-2, 2), h(0, 3);
    std::string text = "{";
    for (int i = 0; i < 2; ++i) {
        text += std::string(i ? ", " : "") + "\"P" + std::to_string(i + 1) + "\": {\"parts\": [";
        for (int p = 0; p < 16; ++p) {
            const int cx = (i ? 20 : 0) + (p % 4) * 4, cy = (p / 4) * 4 + (i ? 2 : 0), cz = h(g);
            text += std::string(p ? ", " : "") + "{\"vertices\": [";
            for (int q = 0; q < 8; ++q)
                text += std::string(q ? ", " : "") + "[" + std::to_string(cx + u(g)) + ", " +
                        std::to_string(cy + u(g)) + ", " + std::to_string(cz + u(g)) + "]";
            text += "]}";
        }
        text += std::string("], \"seed\": [") + (i ? "26, 8" : "6, 6") + ", 1]}";
    }
    text += R"(, "I1": ["1/2", 2], "I2": ["1/2", 2]})";
    const fs::path scene = tmpdir() / "grids.json";
    std::ofstream(scene) << text;
    const OJ j = compound_judgements(scene, R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1},
     {"kind": "distance", "rho1": 1.125, "rho2": 1, "value": 1},
     {"kind": "distance", "rho1": 1, "rho2": 1.125, "value": 1},
     {"kind": "distance", "rho1": 0.75, "rho2": 0.625, "value": 1},
     {"kind": "verdict", "rho1": 1.5, "rho2": 1.5, "verdict": "separated"},
     {"kind": "separating_plane", "rho1": 0.5, "rho2": 0.5, "normal": [1, 0.25, 0]},
     {"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [10, 6, 1]}
    ]})",
                                     "grids");
    long apart = 0;
    for (const auto& k : j["judgements"])
        if (k["proof"].contains("apart")) apart += static_cast<long>(k["proof"]["apart"].size());
    BOOST_TEST(apart > 3);
    const fs::path part = tmpdir() / "grids.partition.json";
    BOOST_REQUIRE(engine("partition " + scene.string() + " --out " + part.string()) == 0);
    BOOST_TEST(check_file(part) == 0);
}

BOOST_AUTO_TEST_CASE(compound_judgement_forgeries_are_rejected) {
    const OJ band = compound_judgements(data("compound_band.json"), kBandClaims, "band_forged");
    auto rejected = [](const OJ& j) { return check_json(j) == 1; };
    // A touching point called overlapping, its common point (on a face) offered as an interior one.
    {
        OJ f = band;
        OJ& e = f["judgements"][1];
        e["claim"]["verdict"] = "overlapping";
        const OJ w = e["proof"]["witness"];
        e["proof"] = OJ{{"verdict", "overlapping"}, {"pair", e["proof"]["pair"]}, {"interior", w}};
        BOOST_TEST(rejected(f));
    }
    // The same touching point called separated, with its weak blocks.
    {
        OJ f = band;
        OJ& e = f["judgements"][1];
        e["claim"]["verdict"] = "separated";
        e["proof"].erase("pair");
        e["proof"].erase("witness");
        e["proof"]["verdict"] = "separated";
        BOOST_TEST(rejected(f));
    }
    // At (3, 2) the objects are separated but no plane separates them: a block of both parts
    // under one normal is refused, whichever axis it takes.
    for (const char* n : {"1", "-1"}) {
        OJ f = band;
        OJ& e = f["judgements"][3];
        e["claim"]["verdict"] = "separated";
        e["right"] = true;
        e["proof"]["blocks"] = OJ::parse(std::string(R"([{"P1_parts": [0, 1], "P2_parts": [0, 0], "normal": [")") + n +
                                         R"(", "0", "0"]}])");
        BOOST_TEST(rejected(f), n);
    }
    // A distance below the exact one: the two points are farther apart, or the lower bound fails.
    {
        OJ f = band;
        OJ& e = f["judgements"][5];
        e["proof"]["squared"] = "1/5";
        BOOST_TEST(rejected(f));
    }
    // A block that skips a pair, and one that covers a pair twice.
    {
        OJ f = band;
        f["judgements"][0]["proof"]["blocks"][0]["P1_parts"] = OJ::array({0, 0});
        BOOST_TEST(rejected(f));
        OJ g = band;
        OJ& b = g["judgements"][1]["proof"]["blocks"];
        b[1]["P1_parts"] = OJ::array({0, 1});
        BOOST_TEST(rejected(g));
    }
    // A proof without its verdict or its squared distance: rejected, never read (the mutation test
    // crashed the checker here before it looked the keys up first).
    {
        OJ f = band;
        f["judgements"][0]["proof"].erase("verdict");
        BOOST_TEST(rejected(f));
        OJ g = band;
        g["judgements"][4]["proof"].erase("squared");
        BOOST_TEST(rejected(g));
    }
    // A witness point outside P2 shown "in" a part it is not in, and "out" with too few normals.
    {
        OJ f = band;
        OJ& e = f["judgements"][10];
        e["proof"]["P2"] = OJ{{"part", 0}, {"in", OJ::parse(R"([[0, "1"]])")}};
        BOOST_TEST(rejected(f));
        OJ g = band;
        g["judgements"][9]["proof"]["P2"] = OJ{{"out", OJ::array()}};
        BOOST_TEST(rejected(g));
    }
}

BOOST_AUTO_TEST_CASE(fresh_compound_judgements_for_random_scenes_are_valid) {
    // Random compounds of two to four parts a side (4 to 8 points each in a cube of side 4 at
    // random offsets; seeds anywhere), claims of the four kinds at eight scaling pairs each: every
    // certificate the engine writes passes the checker.
    std::mt19937 g(4242);
    std::uniform_int_distribution<int> c(-2, 2), off(-4, 4), np(4, 8), nparts(2, 4), q(4, 100);
    int files = 0, verdicts[3] = {0, 0, 0};
    for (int t = 0; t < 8; ++t) {
        OJ scene{{"I1", {"1/4", "3"}}, {"I2", {"1/4", "3"}}};
        for (int i = 0; i < 2; ++i) {
            OJ parts = OJ::array();
            for (int k = nparts(g); k > 0; --k) {
                const int ox = off(g) + 3 * i, oy = off(g);
                OJ v = OJ::array();
                for (int p = np(g); p > 0; --p) v.push_back({c(g) + ox, c(g) + oy, c(g)});
                v.push_back({ox - 2, oy - 2, -2});  // a tetrahedron's corners keep every part solid
                v.push_back({ox + 2, oy - 2, -2});
                v.push_back({ox - 2, oy + 2, -2});
                v.push_back({ox - 2, oy - 2, 2});
                parts.push_back({{"vertices", v}});
            }
            scene[i ? "P2" : "P1"] = {{"parts", parts}, {"seed", {off(g) + 3 * i, off(g), 0}}};
        }
        const fs::path sp = tmpdir() / "random_compound.json";
        save(scene, sp);
        OJ claims = OJ::array();
        for (int k = 0; k < 8; ++k) {
            const std::string a = std::to_string(q(g)) + "/40", b = std::to_string(q(g)) + "/40";
            claims.push_back({{"kind", "verdict"}, {"rho1", a}, {"rho2", b}, {"verdict", "touching"}});
            claims.push_back({{"kind", "distance"},
                              {"rho1", a},
                              {"rho2", b},
                              {"value", "1"},
                              {"closest", {{"1", "0", "0"}, {"2", "1", "0"}}}});
            claims.push_back({{"kind", "separating_plane"}, {"rho1", a}, {"rho2", b}, {"normal", {"1", "0", "0"}}});
            claims.push_back({{"kind", "witness_point"}, {"rho1", a}, {"rho2", b}, {"point", {"1", "1", "0"}}});
        }
        const OJ j =
            compound_judgements(sp, OJ{{"format", "scalecert-claims-1"}, {"claims", claims}}.dump(), "random_compound");
        for (const OJ& e : j["judgements"])
            if (e["claim"]["kind"] == "verdict") {
                const std::string v = e["proof"]["verdict"];
                ++verdicts[v == "separated" ? 0 : v == "touching" ? 1 : 2];
            }
        ++files;
    }
    std::cout << "fresh compound judgements: " << files << " files, verdicts " << verdicts[0] << " separated, "
              << verdicts[1] << " touching, " << verdicts[2] << " overlapping\n";
    BOOST_TEST(verdicts[0] > 0);
    BOOST_TEST(verdicts[2] > 0);
}

BOOST_AUTO_TEST_SUITE_END()
