// Convex polygons in their written form (checker/polygon.*): the one-pass normalisation against
// the one-at-a-time removal of collinear vertices.
#include "checker_tests.hpp"

#include "../../checker/polygon.hpp"

BOOST_AUTO_TEST_SUITE(checker_polygon)

BOOST_AUTO_TEST_CASE(normalize_is_the_one_at_a_time_removal_on_convex_polygons) {
    // Convex polygons (a rectangle clipped by random lines), with repeated vertices and points
    // inside edges inserted, started anywhere: the one-pass normalisation gives what removing
    // collinear vertices one at a time gave.
    std::mt19937_64 g(7);
    int compared = 0;
    for (int t = 0; t < 3000; ++t) {
        const CQ x0 = rq(g, 10, 3), y0 = rq(g, 10, 3);
        std::vector<sc_::P2> p = ref_normalize({{x0, y0},
                                                {x0 + rq(g, 5, 2) * rq(g, 5, 2) + 1, y0},
                                                {x0 + 6, y0 + 5},
                                                {x0, y0 + rq(g, 4, 1) * rq(g, 4, 1) + 1}});
        for (int c = static_cast<int>(g() % 4); c > 0 && p.size() >= 3; --c) {
            const sc_::P2& a = p[g() % p.size()];
            p = ref_clip(p, sc_::Line{rq(g, 5, 4), a[1] - CQ(rq(g, 5, 4)) * a[0] + rq(g, 2, 3)}, g() % 2);
        }
        if (p.size() < 3) continue;
        std::vector<sc_::P2> q;  // duplicates and edge points, from a random start
        const size_t start = g() % p.size();
        for (size_t k = 0; k < p.size(); ++k) {
            const sc_::P2 &a = p[(start + k) % p.size()], &b = p[(start + k + 1) % p.size()];
            q.push_back(a);
            if (g() % 3 == 0) q.push_back(a);
            for (int m = static_cast<int>(g() % 3); m > 0; --m) {
                const CQ t1 = cq(static_cast<long>(g() % 7 + 1), 8);
                q.push_back({a[0] + t1 * (b[0] - a[0]), a[1] + t1 * (b[1] - a[1])});
            }
        }
        BOOST_TEST((sc_::normalize(q) == ref_normalize(q)));
        BOOST_TEST((sc_::normalize(q) == p));
        ++compared;
    }
    BOOST_TEST(compared > 1000);
}

BOOST_AUTO_TEST_SUITE_END()
