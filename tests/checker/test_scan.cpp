// Support scans (checker/scan.*): support values and maximisers in int64, __int128 and GMP
// integers against the plain rational definition.
#include "checker_tests.hpp"

#include "../../checker/numbers.hpp"
#include "../../checker/scan.hpp"
#include "../../checker/scene.hpp"

#include <algorithm>
#include <memory>

BOOST_AUTO_TEST_SUITE(checker_scan)

namespace {
// A scene of the checker from its vertices and seeds (I1, I2 unused here).
sc_::Scene make_scene(sc_::Context& cx, const std::vector<CV> P[2], const CV s[2]) {
    sc_::Scene sc;
    for (int i = 0; i < 2; ++i) {
        sc.s[i] = s[i];
        sc.scan[i] = std::make_unique<sc_::Scan>(cx, P[i], i ? "P2" : "P1");
    }
    sc.prepare(cx);
    return sc;
}
// The plain rational definition: max over k of σ n·(v_k − s_i) and every k attaining it.
CQ plain_h(const std::vector<CV>& P, const CV& s, const CV& n, int sigma, std::vector<int>& arg) {
    CQ best;
    arg.clear();
    for (size_t k = 0; k < P.size(); ++k) {
        CQ v = n[0] * (P[k][0] - s[0]) + n[1] * (P[k][1] - s[1]) + n[2] * (P[k][2] - s[2]);
        if (sigma < 0) v = -v;
        if (k == 0 || v > best) {
            best = v;
            arg.clear();
        }
        if (v == best) arg.push_back(static_cast<int>(k));
    }
    return best;
}
}  // namespace

BOOST_AUTO_TEST_CASE(support_scans_equal_the_plain_rational_definition) {
    // Random scenes of every number kind (small integers, small fractions, integers past 2^62,
    // 200-bit fractions, few distinct values so that maximisers tie, small and large vertices
    // mixed in one polytope, tying across the two), random integer normals of
    // every size (int64, __int128 and GMP paths), their multiples through the cache, and scans of
    // subsets (the switch points' ends): value and ascending maximiser list as the definition.
    std::mt19937_64 g(2024);
    const mpz_class one = 1;
    struct Kind {
        mpz_class range, den;
    };
    const std::vector<Kind> kinds = {
        {20, 1}, {3, 1}, {1000, 7}, {one << 70, 1}, {one << 61, 1}, {one << 200, one << 100}, {5, one << 90}, {-1, 1}};
    const std::vector<mpz_class> normal_sizes = {5, 1000, one << 40, one << 61, one << 90, one << 300};
    int checks = 0, direct_checks = 0, paths[3] = {0, 0, 0};
    for (int t = 0; t < 400; ++t) {
        const Kind& kd = kinds[static_cast<size_t>(t) % kinds.size()];
        std::vector<CV> P[2];
        CV s[2];
        for (int i = 0; i < 2; ++i) {
            const int n = 4 + static_cast<int>(g() % 27);
            for (int k = 0; k < n; ++k) {
                if (k > 0 && g() % 5 == 0) {
                    P[i].push_back(P[i][g() % static_cast<size_t>(k)]);
                    continue;
                }                  // a repeated vertex
                if (kd.range < 0)  // mixed: small vertices, and some with a first coordinate past 2^62
                    P[i].push_back({g() % 3 ? rq(g, 3, 1) : rq(g, one << 70, 1), rq(g, 3, 1), rq(g, 3, 1)});
                else
                    P[i].push_back({rq(g, kd.range, kd.den), rq(g, kd.range, kd.den), rq(g, kd.range, kd.den)});
            }
            s[i] = {rq(g, abs(kd.range), kd.den), rq(g, abs(kd.range), 3), rq(g, 7, 5)};
        }
        sc_::Context cx;
        sc_::Scene sc = make_scene(cx, P, s);
        // For integer vertices, the same scan built from integers as the reader holds them
        // (small points as int64, the others in GMP integers): its every X and maximiser list the
        // same as the rational path's.
        std::unique_ptr<sc_::Scan> direct[2];
        if (kd.den == 1)
            for (int i = 0; i < 2; ++i) {
                sc_::IntPoints ip;
                for (const CV& v : P[i]) {
                    int64_t x[3];
                    bool small = true;
                    for (int c = 0; c < 3; ++c) {
                        small = small && mpz_sizeinbase(v[c].get_num_mpz_t(), 2) <= 62;
                        if (small) x[c] = v[c].get_num().get_si();
                    }
                    if (small)
                        ip.add_small(x);
                    else
                        ip.add_big({v[0].get_num(), v[1].get_num(), v[2].get_num()});
                }
                direct[i] = std::make_unique<sc_::Scan>(cx, std::move(ip));
                BOOST_TEST(direct[i]->size() == P[i].size());
                for (size_t k = 0; k < P[i].size(); ++k) BOOST_TEST((direct[i]->X(k) == sc.scan[i]->X(k)));
            }
        for (int r = 0; r < 12; ++r) {
            const mpz_class& size = normal_sizes[static_cast<size_t>(g() % normal_sizes.size())];
            CV n;
            do n = {rq(g, size, 1), rq(g, size, 1), rq(g, size, 1)};
            while (!sgn(n[0]) && !sgn(n[1]) && !sgn(n[2]));
            if (r % 4 == 0)
                n = {CQ(g() % 3) - 1, CQ(g() % 3) - 1, CQ(1)};  // small normals: many ties on repeated vertices
            if (r % 4 == 1 && kd.range < 0)
                n = {CQ(0), CQ(g() % 3) - 1, CQ(1)};  // ties between small and large vertices
            mpz_class H[2];
            const std::vector<int>* cached[2];
            sc.support(cx, n, H, cached);
            for (int i = 0; i < 2; ++i) {
                std::vector<int> want, got;
                const CQ h = plain_h(P[i], s[i], n, i ? -1 : 1, want);
                BOOST_TEST((sc.h(cx, i, n, &got) == h));
                BOOST_TEST(got == want);
                BOOST_TEST(*cached[i] == want);
                BOOST_TEST(sc.over(h, H[i]));
                // a multiple of the normal: the cached direction, scaled
                const CV m = {n[0] * 6, n[1] * 6, n[2] * 6};
                mpz_class Hm[2];
                const std::vector<int>* cm[2];
                sc.support(cx, m, Hm, cm);
                BOOST_TEST(sc.over(h * 6, Hm[i]));
                BOOST_TEST(*cm[i] == want);
                // a subset: the vertices of even index
                std::vector<int> sub, want_sub;
                for (int k = 0; k < static_cast<int>(P[i].size()); k += 2) sub.push_back(k);
                sc_::Z3 u = sc_::ints(n);
                if (i)
                    for (auto& c : u) c = -c;
                std::vector<CV> Ps;
                for (int k : sub) Ps.push_back(P[i][static_cast<size_t>(k)]);
                plain_h(Ps, s[i], n, i ? -1 : 1, want_sub);
                for (int& k : want_sub) k = sub[static_cast<size_t>(k)];
                BOOST_TEST(sc.scan[i]->argmax(cx, u, &sub) == want_sub);
                // the largest u·X over all vertices (a compound block's per part): D (h + u·s)
                mpz_class top;
                sc.scan[i]->max_dot(cx, sc_::Direction(u), top);
                CQ top_want = h;
                for (int c = 0; c < 3; ++c) top_want += CQ(u[c]) * s[i][c];
                BOOST_TEST((CQ(top) / CQ(sc.scan[i]->D()) == top_want));
                if (direct[i]) {
                    sc_::Z3 all = sc_::ints(n);
                    if (i)
                        for (auto& c : all) c = -c;
                    BOOST_TEST(direct[i]->argmax(cx, all) == want);
                    BOOST_TEST(direct[i]->argmax(cx, u, &sub) == want_sub);
                    ++direct_checks;
                }
                ++checks;
                int ub = 0;
                for (const auto& c : u) ub = std::max(ub, static_cast<int>(mpz_sizeinbase(c.get_mpz_t(), 2)));
                ++paths[ub <= 62 && kd.range >= 0 && kd.range < (one << 62) && kd.den < (one << 20) ? (ub <= 40 ? 0 : 1)
                                                                                                    : 2];
            }
        }
    }
    std::cout << "support scans compared: " << checks << " (normals of up to 40 bits " << paths[0] << ", up to 62 bits "
              << paths[1] << ", larger or large coordinates " << paths[2] << ")\n";
    BOOST_TEST(paths[0] > 100);
    BOOST_TEST(paths[1] > 100);
    BOOST_TEST(paths[2] > 100);
    std::cout << "support scans on integers as the reader holds them: " << direct_checks << "\n";
    BOOST_TEST(direct_checks > 300);
}

BOOST_AUTO_TEST_SUITE_END()
