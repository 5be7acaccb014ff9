// Objects made of parts (checker/parts.*): the part limit, each part over its own common
// denominator, and a pose whose denominators cancel its vertices' factors.
#include "checker_tests.hpp"

BOOST_AUTO_TEST_SUITE(checker_parts)

BOOST_AUTO_TEST_CASE(compound_partitions_beyond_the_part_limit_are_unreadable) {
    // 10,001 parts: refused before the pair bitmap (10^8 bits at the limit) is made.
    std::string parts;
    for (int k = 0; k <= 10000; ++k)
        parts += std::string(k ? "," : "") +
                 R"({"vertices": [["0", "0", "0"], ["1", "0", "0"], ["0", "1", "0"], ["0", "0", "1"]]})";
    const std::string text =
        R"({"format": "scalecert-2", "kind": "compound_partition", "pairs": [], "growth_set": [], )"
        R"("scene": {"P1": {"parts": [)" +
        parts +
        R"(], "seed": ["0", "0", "0"]}, "P2": {"parts": [{"vertices": [["1", "0", "0"], ["2", "0", "0"], ["1", )"
        R"("1", "0"], ["1", "0", "1"]]}], "seed": ["1", "0", "0"]}, "I1": ["1", "2"], "I2": ["1", "2"]}})";
    std::string msg;
    BOOST_TEST(scalecert_check::check_text(text, msg) == 2);
    BOOST_TEST(msg.find("more than 10000 parts") != std::string::npos, msg);
}

namespace {
// Three lanes of unit cubes a side, lane k at y in [3k, 3k + 1], z in [0, 1]: P1's part k at x in
// [e_k, 1 + e_k], P2's at x in [2 + d_k, 3 + d_k], with e_k = 1/a_k^m, d_k = 1/b_k^m of 6,500 to
// 7,000 bits each, so that each object's parts' denominators together pass 16,384 bits (about
// 20,000) and each part's stays under it. Seeds (1/2, 7/2, 1/2) and (5/2, 7/2, 1/2): on the
// diagonal ρ1 = ρ2 = ρ a lane's two cubes have one y and z range, and lanes k and j != k lie
// ρ (3|k − j| − 1) apart in y. Lane k's gap along x is 2 − ρ1 (1/2 + e_k) − ρ2 (1/2 − d_k).
using Q = mpq_class;
const int kLaneP1[3][2] = {{7, 2400}, {3, 4400}, {11, 1900}}, kLaneP2[3][2] = {{13, 1800}, {17, 1600}, {19, 1550}};
Q lane_eps(const int (&base)[3][2], int k) {
    mpz_class q;
    mpz_ui_pow_ui(q.get_mpz_t(), static_cast<unsigned long>(base[k][0]), static_cast<unsigned long>(base[k][1]));
    return Q(mpz_class(1), q);
}
std::string qs(const Q& q) { return q.get_str(); }
fs::path lanes_compound() {
    OJ scene{{"I1", {"1", "3"}}, {"I2", {"1", "3"}}};
    for (int i = 0; i < 2; ++i) {
        OJ parts = OJ::array();
        for (int k = 0; k < 3; ++k) {
            const Q x0 = i ? 2 + lane_eps(kLaneP2, k) : lane_eps(kLaneP1, k);
            OJ v = OJ::array();
            for (int c = 0; c < 8; ++c)
                v.push_back({qs(x0 + (c & 1)), std::to_string(3 * k + (c >> 1 & 1)), std::to_string(c >> 2 & 1)});
            parts.push_back({{"vertices", v}});
        }
        scene[i ? "P2" : "P1"] = {{"parts", parts}, {"seed", {i ? "5/2" : "1/2", "7/2", "1/2"}}};
    }
    const fs::path p = tmpdir() / "lanes_compound.json";
    save(scene, p);
    return p;
}
}  // namespace

BOOST_AUTO_TEST_CASE(parts_are_checked_over_their_own_denominators) {
    // Each object's parts' vertex denominators together pass 16,384 bits: the checker takes them,
    // each part over its own common denominator.
    mpz_class all[2] = {1, 1};
    for (int k = 0; k < 3; ++k) {
        for (int i = 0; i < 2; ++i) {
            const mpz_class d = lane_eps(i ? kLaneP2 : kLaneP1, k).get_den();
            BOOST_TEST(mpz_sizeinbase(d.get_mpz_t(), 2) < 16384);
            mpz_lcm(all[i].get_mpz_t(), all[i].get_mpz_t(), d.get_mpz_t());
        }
    }
    BOOST_TEST(mpz_sizeinbase(all[0].get_mpz_t(), 2) > 16384);
    BOOST_TEST(mpz_sizeinbase(all[1].get_mpz_t(), 2) > 16384);
    const fs::path sp = lanes_compound();
    const OJ cert = compound_certificate(sp, "lanes");
    // On the diagonal lane k meets from t_k = 2 / (1 + e_k − d_k) on (its gap closes) to 3; the
    // growth set is [min t_k, 3], first met by the lane of the largest e_k − d_k.
    int first = 0;
    Q t = 3;
    for (int k = 0; k < 3; ++k) {
        const Q tk = 2 / (1 + lane_eps(kLaneP1, k) - lane_eps(kLaneP2, k));
        if (tk < t) t = tk, first = k;
    }
    BOOST_TEST_REQUIRE(cert["growth_set"].size() == 1u);
    BOOST_TEST(Q(cert["growth_set"][0]["from"].get<std::string>()) == t);
    BOOST_TEST(cert["growth_set"][0]["to"] == "3");
    BOOST_TEST(cert["growth_set"][0]["first_contact"]["P1_part"] == first);
    BOOST_TEST(cert["growth_set"][0]["first_contact"]["P2_part"] == first);
    {  // a witness of a meeting pair moved by one in its part's denominator: refused
        OJ f = cert;
        bool changed = false;
        for (OJ& e : f["pairs"])
            if (!changed && !e["witnesses"].empty()) {
                Q x(e["witnesses"][0]["point"][0].get<std::string>());
                x += lane_eps(kLaneP1, e["P1_parts"][0].get<int>());
                e["witnesses"][0]["point"][0] = x.get_str();
                changed = true;
            }
        BOOST_TEST_REQUIRE(changed);
        BOOST_TEST(check_json(f) == 1);
    }
    {  // a part past 16,384 bits on its own: unreadable, the part named
        OJ f = cert;
        f["scene"]["P2"]["parts"][1]["vertices"].push_back(
            OJ::array({"5/2", "7/2", "1/" + mpz_class(mpz_class(1) << 16384).get_str()}));
        std::string msg;
        BOOST_TEST(scalecert_check::check_text(f.dump(1), msg) == 2);
        BOOST_TEST(msg.find("scene.P2.parts[1]'s vertex coordinates has more than 16384 bits") != std::string::npos,
                   msg);
    }
    // Claims on the same objects. At (1, 1) lane k's gap is 1 − e_k + d_k and the lanes lie 2
    // apart in y: the distance is 1 − max (e_k − d_k), so the claim 1 is wrong. At (3, 3) the
    // first lane's cubes overlap by 1 + 3 (e − d) along x and by 3 along y and z: that is its depth
    // (the claim 1 is wrong). At a pose moving P2 by 10 along x the objects are apart at (1, 1).
    const std::string p = std::to_string(first);
    const OJ j = compound_judgements(sp,
                                     R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated"},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1},
     {"kind": "penetration_depth", "rho1": 3, "rho2": 3, "parts": [)" +
                                         p + ", " + p + R"(], "value": 1},
     {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated",
      "pose2": [[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0]]}
    ]})",
                                     "lanes");
    const Q g = lane_eps(kLaneP1, first) - lane_eps(kLaneP2, first);
    const std::vector<bool> right = {true, false, false, true};
    BOOST_TEST_REQUIRE(j["judgements"].size() == right.size());
    for (size_t k = 0; k < right.size(); ++k) BOOST_TEST(j["judgements"][k]["right"] == right[k], k);
    BOOST_TEST(Q(j["judgements"][1]["proof"]["squared"].get<std::string>()) == (1 - g) * (1 - g));
    BOOST_TEST(Q(j["judgements"][2]["proof"]["squared"].get<std::string>()) == (1 + 3 * g) * (1 + 3 * g));
    {  // the distance's proof claiming the square of 1: refused
        OJ f = j;
        f["judgements"][1]["proof"]["squared"] = "1";
        BOOST_TEST(check_json(f) == 1);
    }
}

BOOST_AUTO_TEST_CASE(a_pose_whose_denominators_cancel_the_vertices_factors_is_checked) {
    // P1 the box [0, 3^4417] x [0, 5^3015] x [0, 7^2493] (about 7,000 bits a side), pose1 the
    // diagonal matrix of their inverses: the moved box is the unit cube, integers, though the
    // pose's denominators together have about 21,000 bits. P2 the unit cube at x in [2, 3]; seeds
    // the centres. At (1, 1) the cubes are 1 apart along x: separated, at distance 1.
    mpz_class e[3];
    mpz_ui_pow_ui(e[0].get_mpz_t(), 3, 4417);
    mpz_ui_pow_ui(e[1].get_mpz_t(), 5, 3015);
    mpz_ui_pow_ui(e[2].get_mpz_t(), 7, 2493);
    mpz_class L = e[0] * e[1] * e[2];
    BOOST_TEST(mpz_sizeinbase(L.get_mpz_t(), 2) > 16384);
    OJ box = OJ::array(), cube = OJ::array();
    for (int c = 0; c < 8; ++c) {
        OJ v = OJ::array(), w = OJ::array();
        for (int k = 0; k < 3; ++k) {
            v.push_back((c >> k & 1) ? e[k].get_str() : "0");
            w.push_back(std::to_string((k == 0 ? 2 : 0) + (c >> k & 1)));
        }
        box.push_back(v);
        cube.push_back(w);
    }
    const OJ scene{{"P1",
                    {{"parts", {{{"vertices", box}}}},
                     {"seed", {Q(e[0], 2).get_str(), Q(e[1], 2).get_str(), Q(e[2], 2).get_str()}}}},
                   {"P2", {{"parts", {{{"vertices", cube}}}}, {"seed", {"5/2", "1/2", "1/2"}}}},
                   {"I1", {"1/2", "2"}},
                   {"I2", {"1/2", "2"}}};
    const fs::path sp = tmpdir() / "cancelling_pose.json";
    save(scene, sp);
    OJ pose = OJ::array();
    for (int r = 0; r < 3; ++r) {
        OJ row = OJ::array();
        for (int c = 0; c < 4; ++c) row.push_back(r == c ? Q(mpz_class(1), e[r]).get_str() : "0");
        pose.push_back(row);
    }
    const OJ claims{{"format", "scalecert-claims-1"},
                    {"claims",
                     {{{"kind", "verdict"}, {"rho1", 1}, {"rho2", 1}, {"verdict", "separated"}, {"pose1", pose}},
                      {{"kind", "distance"}, {"rho1", 1}, {"rho2", 1}, {"value", 1}, {"pose1", pose}}}}};
    const OJ j = compound_judgements(sp, claims.dump(), "cancelling_pose");  // checked: exit 0
    BOOST_TEST(j["judgements"][0]["right"] == true);
    BOOST_TEST(j["judgements"][1]["right"] == true);
    BOOST_TEST(j["judgements"][1]["proof"]["squared"] == "1");
}

BOOST_AUTO_TEST_SUITE_END()
