// Compound partitions (checker/compound_partition.cpp): every mutation of the engine's
// certificates is rejected, or the engine, re-run, finds the file's region; forgeries by hand; a
// fence of many normals over huge corners meets the work limit.
#include "checker_tests.hpp"

#include <chrono>

BOOST_AUTO_TEST_SUITE(checker_compound_partition)

BOOST_AUTO_TEST_CASE(compound_partitions_are_valid_and_tampering_is_rejected) {
    // Every mutation of three compound certificates is rejected, or the checker accepts it and the
    // engine, re-run on the changed file's scene, finds exactly the file's pair polygons and
    // growth set (so the accepted file is still true).
    mutate_and_report(compound_certificate(data("compound_band.json"), "band"), "compound band", false, false, true);
    mutate_and_report(compound_certificate(data("compound_u_peg.json"), "u_peg"), "compound U and peg", false, false,
                      true);
    const OJ mixed = compound_certificate(mixed_compound(), "mixed");
    bool block = false, apart = false;
    for (const OJ& e : mixed["pairs"]) {
        block = block || e["P1_parts"][0] != e["P1_parts"][1] || e["P2_parts"][0] != e["P2_parts"][1];
        apart = apart ||
                (e["vertices"].empty() && e["P1_parts"][0] == e["P1_parts"][1] && e["P2_parts"][0] == e["P2_parts"][1]);
    }
    BOOST_TEST(block);  // pruned pairs merged into a block
    mutate_and_report(mixed, "compound mixed", false, false, true);
}

BOOST_AUTO_TEST_CASE(compound_forgeries_are_rejected) {
    // The U and peg (test_compound derives it by hand): pairs[0] is the bottom (cut by +z to
    // rho1 + 3 rho2 >= 6), pairs[1] and [2] the walls (cut by +x, -x to rho2 >= 2 rho1).
    const OJ u = compound_certificate(data("compound_u_peg.json"), "u_peg_forged");
    BOOST_TEST(check_json(u) == 0);
    {  // the bottom's fence dropped and its polygon claimed to be the whole rectangle: no witness at (1/2, 1/2)
        OJ f = u;
        f["pairs"][0]["normals"] = OJ::array();
        f["pairs"][0]["vertices"] = OJ::parse(R"([["1/2", "1/2"], ["2", "1/2"], ["2", "3"], ["1/2", "3"]])");
        f["pairs"][0]["vertices_double"] = OJ::parse("[[0.5, 0.5], [2.0, 0.5], [2.0, 3.0], [0.5, 3.0]]");
        OJ w = f["pairs"][0]["witnesses"];
        f["pairs"][0]["witnesses"] = OJ::array({w[0], w[0], w[1], w[2]});
        BOOST_TEST(check_json(f) == 1);
    }
    {  // a wall claimed apart: its polygon left out (the fence cuts the rectangle to a triangle)
        OJ f = u;
        f["pairs"][1]["vertices"] = OJ::array();
        f["pairs"][1]["vertices_double"] = OJ::array();
        f["pairs"][1]["witnesses"] = OJ::array();
        BOOST_TEST(check_json(f) == 1);
    }
    {  // both walls as one block: the +x support over both walls is 3 rho1, and the block meets
        OJ f = u;
        f["pairs"][1]["P1_parts"] = OJ::parse("[1, 2]");
        f["pairs"].erase(2);
        BOOST_TEST(check_json(f) == 1);
        f["pairs"][1]["vertices"] = OJ::array();
        f["pairs"][1]["vertices_double"] = OJ::array();
        f["pairs"][1]["witnesses"] = OJ::array();
        BOOST_TEST(check_json(f) == 1);
    }
    {  // a pair left out, or covered twice
        OJ f = u;
        f["pairs"].erase(2);
        BOOST_TEST(check_json(f) == 1);
        OJ g = u;
        g["pairs"].push_back(u["pairs"][2]);
        BOOST_TEST(check_json(g) == 1);
    }
    {  // a witness of the wall indexed into the bottom's vertices (index 7 of the bottom is (3, 1, 1))
        OJ f = u;
        f["pairs"][1]["witnesses"][0]["P1"] = OJ::parse(R"([[8, "1"]])");
        BOOST_TEST(check_json(f) == 1);
    }
    {  // the growth set moved or its first contact changed
        OJ f = u;
        f["growth_set"][0]["first_contact"]["P1_part"] = 1;
        BOOST_TEST(check_json(f) == 1);
        OJ g = u;
        g["growth_set"] = OJ::array();
        BOOST_TEST(check_json(g) == 1);
    }
    {  // the peg's seed moved: every recomputed line moves, and the listed polygons no longer match
        OJ f = u;
        f["scene"]["P2"]["seed"] = OJ::parse(R"(["0", "0", "4"])");
        BOOST_TEST(check_json(f) == 1);
    }
}

BOOST_AUTO_TEST_CASE(a_compound_fence_of_many_normals_over_huge_corners_meets_the_work_limit) {
    // One pair apart in the rectangle, cut first by two normals with 16,000-bit entries (the
    // polygon gets corners of twice that size), then by 40,000 copies of (-1, 0, 0), whose
    // half-plane holds everywhere, then emptied by (0, 1, 0). The certificate is true; checking it
    // re-evaluates the huge corners 40,000 times (97 s if counted by the small first corner only).
    // Counted by the largest corner, it is refused at once (exit 2).
    auto box = [](long x0, long x1, long y0, long y1, long z0, long z1, long dx, long dy, long dz, bool half) {
        std::string t = "[";
        for (long x : {x0, x1})
            for (long y : {y0, y1})
                for (long z : {z0, z1}) {
                    // P2's seed (-9/2, 100, -3): its x coordinates are halves
                    const std::string xs = half ? std::to_string(2 * (x + dx) - 9) + "/2" : std::to_string(x + dx);
                    t += (t.size() > 1 ? "," : "") + std::string("[\"") + xs + "\",\"" + std::to_string(y + dy) +
                         "\",\"" + std::to_string(z + dz) + "\"]";
                }
        return t + "]";
    };
    const mpz_class K = (mpz_class(1) << 16000) - 1, K2 = (mpz_class(1) << 16000) - 3;
    std::string normals = "[[\"" + K.get_str() + "\",\"1\",\"0\"],[\"1\",\"0\",\"" + K2.get_str() + "\"]";
    for (int k = 0; k < 40000; ++k) normals += ",[\"-1\",\"0\",\"0\"]";
    normals += ",[\"0\",\"1\",\"0\"]]";
    const std::string text =
        R"({"format":"scalecert-2","kind":"compound_partition",)"
        R"("pairs":[{"P1_parts":[0,0],"P2_parts":[0,0],"normals":)" +
        normals +
        R"(,"vertices":[],"vertices_double":[],"witnesses":[]}],"growth_set":[],"scene":{"P1":{"parts":[{"vertices":)" +
        box(-3, -1, -1, 1, -3, -1, 0, 0, 0, false) + R"(}],"seed":["0","0","0"]},"P2":{"parts":[{"vertices":)" +
        box(2, 3, -1, 1, 1, 3, 0, 100, -3, true) + R"(}],"seed":["-9/2","100","-3"]},"I1":["1","2"],"I2":["1","2"]}})";
    std::string msg;
    const auto t0 = std::chrono::steady_clock::now();
    BOOST_TEST(scalecert_check::check_text(text, msg) == 2, msg);
    BOOST_TEST(msg.find("work limit") != std::string::npos, msg);
    BOOST_TEST(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() <
               30.0);  // not the 97 s it took
}

BOOST_AUTO_TEST_SUITE_END()
