// The scene stored in a certificate and the values recomputed from it (checker/scene.*): seed
// weights counted against the work limit, and support values of a scene at the limits of int64
// recomputed exactly.
#include "checker_tests.hpp"

#include "../../checker/json.hpp"
#include "../../checker/numbers.hpp"

#include <array>
#include <functional>

BOOST_AUTO_TEST_SUITE(checker_scene)

BOOST_AUTO_TEST_CASE(weights_over_coprime_denominators_meet_the_work_limit) {
    // 7,031 weights 1/(10^99 + j + 1): each addition pays for the whole running denominator (13 s
    // on 885 KB if uncounted). The additions are counted: such a list is refused at the work
    // limit, exit 2.
    OJ j = bundled("stacked_cubes");
    OJ& vs = j["scene"]["P1"]["vertices"];
    const OJ first = vs[0];
    OJ w = OJ::array();
    const mpz_class big = mpz_class("1" + std::string(99, '0'));
    for (int k = 0; k < 7000; ++k) {
        if (k >= 8) vs.push_back(first);
        w.push_back(OJ::array({k, "1/" + mpz_class(big + k + 1).get_str()}));
    }
    j["seed_interior"]["P1"] = w;
    std::string msg;
    BOOST_TEST(scalecert_check::check_text(j.dump(1), msg) == 2);
    BOOST_TEST(msg.find("work limit") != std::string::npos, msg);
}

BOOST_AUTO_TEST_CASE(a_scene_at_the_limits_of_int64_is_checked_exactly) {
    // The stacked cubes' partition ([0,2]^3 below [0,2]^2 x [3,5], seeds the centres; the curve
    // rho1 + rho2 = 3 with the normal (0, 0, 1), h1 = h2 = 1) with every point x mapped to K x + t,
    // K = 2^61 - 1: the scalings, slopes, intercepts, weights and regions stay (h1, h2 and n.d all
    // scale by K), the points of the scene and the witnesses move, h1 = h2 = K. With t = (1, 1, 1)
    // P1's coordinates are 1 and 2K + 1 = 2^62 - 1 (the largest held as int64) and P2's z are
    // 3K + 1 = 3 * 2^61 - 2 (an int64 from 2^62: GMP) and 5K + 1 = 5 * 2^61 - 4 (past int64); with
    // t = (1, 1, -2^61) P2's bottom face is small (z = 2^62 - 3) and its top face big (z = 2^63 - 5,
    // an int64).
    const mpz_class K = (mpz_class(1) << 61) - 1;
    auto stretch = [&](const std::array<mpz_class, 3>& t) {
        OJ j = bundled("stacked_cubes");
        auto move = [&](OJ& p, OJ* dbl) {
            for (int c = 0; c < 3; ++c) {
                const CQ x = CQ(p[c].get<std::string>()) * K + t[static_cast<size_t>(c)];
                p[c] = x.get_str();
                if (dbl) (*dbl)[c] = sc_::nearest(x);
            }
        };
        std::function<void(OJ&)> walk = [&](OJ& o) {
            if (o.is_object()) {
                if (o.contains("point") && o.contains("point_double")) move(o["point"], &o["point_double"]);
                for (const char* h : {"h1", "h2"})
                    if (o.contains(h)) {
                        const CQ v = CQ(o[h].get<std::string>()) * K;
                        o[h] = v.get_str();
                        o[std::string(h) + "_double"] = sc_::nearest(v);
                    }
            }
            if (o.is_structured())
                for (auto& e : o) walk(e);
        };
        walk(j);
        for (const char* p : {"P1", "P2"}) {
            for (OJ& v : j["scene"][p]["vertices"]) move(v, nullptr);
            move(j["scene"][p]["seed"], nullptr);
        }
        return j;
    };
    int compared = 0;
    const mpz_class one = 1;
    for (const auto& t : {std::array<mpz_class, 3>{one, one, one}, std::array<mpz_class, 3>{one, one, -(one << 61)}}) {
        const OJ j = stretch(t);
        BOOST_TEST(j["pieces"][0]["h1"] == "2305843009213693951");  // 2^61 - 1
        BOOST_TEST(same_both_ways(j, "stretched stacked cubes", compared) == 0);
        const sc_::Parsed parsed = sc_::parse_certificate(j.dump(1));
        BOOST_TEST_REQUIRE(parsed.points.size() == 2u);
        BOOST_TEST(parsed.points[0].big.empty());  // P1: int64
        BOOST_TEST(parsed.points[1].big.size() == (t[2] == 1 ? 8u : 4u));
        // h1 off by one in its last digit: 2^61 - 1 and 2^61 have one nearest double (2^61), so
        // only the exact recomputation rejects it.
        OJ f = j;
        f["pieces"][0]["h1"] = "2305843009213693952";
        BOOST_TEST(sc_::nearest(CQ("2305843009213693952")) == sc_::nearest(CQ("2305843009213693951")));
        BOOST_TEST(f["pieces"][0]["h1_double"] == OJ(sc_::nearest(CQ("2305843009213693952"))));
        BOOST_TEST(same_both_ways(f, "h1 + 1", compared) == 1);
        BOOST_TEST(answer(f.dump(1), true)
                       .message.find("pieces[0].h1 = max n.(v - s1) over P1, recomputed: "
                                     "2305843009213693951") != std::string::npos);
        f = j;
        f["growth_distance_certificate"]["h2"] = "2305843009213693950";
        BOOST_TEST(same_both_ways(f, "growth h2 - 1", compared) == 1);
        // a witness's point off by one in its last digit (its double, within 2^9 of it, the same)
        f = j;
        OJ& z = f["pieces"][0]["contact_witness"]["point"][2];
        const CQ moved = CQ(z.get<std::string>()) + 1;
        BOOST_TEST(sc_::nearest(moved) == f["pieces"][0]["contact_witness"]["point_double"][2].get<double>());
        z = moved.get_str();
        BOOST_TEST(same_both_ways(f, "witness point + 1", compared) == 1);
        // a scene vertex moved by one: P1's top face at 2^62 - 1 + 1 = 2^62 (then big), which
        // raises h1 (the vertex 4 attains the normal's maximum) and is rejected
        f = j;
        const std::string top = f["scene"]["P1"]["vertices"][4][2];
        f["scene"]["P1"]["vertices"][4][2] = CQ(CQ(top) + 1).get_str();
        BOOST_TEST(same_both_ways(f, "P1 vertex + 1", compared) == 1);
    }
    BOOST_TEST(compared == 10);
}

BOOST_AUTO_TEST_SUITE_END()
