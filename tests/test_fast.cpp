// The filtered queries (doubles with a proven error bound, exact fallback) give exactly the exact
// verdicts: at random pairs, at doubles exactly on the curve and one ulp either side of it.
#include <boost/test/unit_test.hpp>

#include "certify/classify.hpp"
#include "quick_query.hpp"
#include "support.hpp"

#include <cmath>

using namespace scalecert::internal;

BOOST_AUTO_TEST_CASE(filtered_equals_exact) {
    std::mt19937 g(41);
    std::uniform_real_distribution<double> u(0.25, 4.0);
    std::uint64_t exact_stage = 0;
    for (int t = 0; t < 25; ++t) {
        ExactScene sc = test::random_scene(g, 4 + t % 6, 4 + t % 5);
        HullModel m = build_model(sc);
        TouchingCurve c = build_curve(m);
        FastCurve fc(m, c);
        FastDirect fd(m);
        test::Brute brute(sc);
        auto probe = [&](double a, double b) {
            Verdict e = query(m, c, exact_from_double(a), exact_from_double(b), false).verdict;
            BOOST_TEST(fc.classify(a, b) == e);
            BOOST_TEST(fd.classify(a, b) == e);
            BOOST_TEST(test::verdict_sign(e) == brute.classify(sc, exact_from_double(a), exact_from_double(b)));
        };
        for (int k = 0; k < 200; ++k) probe(u(g), u(g));
        for (int k = 0; k < 50; ++k) {
            double a = u(g);
            Q f = c.env.value(m.lines, exact_from_double(a));
            double b = to_double_rn(f);
            if (!(b > 0)) continue;
            probe(a, b);
            probe(a, std::nextafter(b, 0.0));
            probe(a, std::nextafter(b, 10.0));
        }
        exact_stage += fc.counts().exact;
    }
    BOOST_TEST(exact_stage > 0u);  // the near-curve probes did reach the exact stage
}

BOOST_AUTO_TEST_CASE(batch_on_two_threads_equals_one_by_one) {
    HullModel m =
        build_model(load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/fig5_vf_ve_ee.json"));
    TouchingCurve c = build_curve(m);
    FastCurve fc(m, c);
    std::mt19937 g(5);
    std::uniform_real_distribution<double> u(0.8, 3.0);
    std::vector<double> a(20000), b(20000);
    for (size_t i = 0; i < a.size(); ++i) a[i] = u(g), b[i] = u(g);
    std::vector<Verdict> out;
    StageCounts s = classify_batch(fc, a, b, out, 2);
    BOOST_TEST(s.filtered + s.exact == a.size());
    for (size_t i = 0; i < a.size(); i += 97)
        BOOST_TEST(out[i] == query(m, c, exact_from_double(a[i]), exact_from_double(b[i]), false).verdict);
}

// Pair files: doubles written with 17 significant digits read back bit for bit, across the chunk
// boundary of two threads; a leading '+', a bare point; blank lines and comments; the first bad
// line, hexadecimal doubles (which strtod takes) included: CLAIMS.md, "Numbers", refuses them in
// every format.
BOOST_AUTO_TEST_CASE(pair_text_is_read_exactly_on_two_threads) {
    std::mt19937_64 g(4);
    std::uniform_real_distribution<double> u(1e-3, 1e3);
    std::vector<double> a, b;
    std::string text;
    char buf[64];
    for (int i = 0; i < 20000; ++i) {
        a.push_back(u(g)), b.push_back(u(g));
        std::snprintf(buf, sizeof buf, i % 3 ? "%.17g %.17g\n" : "\t%.17g\t %.17g  # note\r\n", a.back(), b.back());
        text += buf;
        if (i % 1000 == 7) text += "\n   \n# a comment line\n";
    }
    text += "+1.5 3.";  // a leading '+' and a trailing point, no final newline
    a.push_back(1.5), b.push_back(3.0);
    BOOST_REQUIRE(text.size() > (1u << 16));
    for (unsigned threads : {1u, 2u, 3u}) {
        std::vector<double> r1, r2;
        parse_pairs(text, r1, r2, threads);
        BOOST_TEST(r1 == a, boost::test_tools::per_element());
        BOOST_TEST(r2 == b, boost::test_tools::per_element());
    }
    // A bad line far into the second half: its number is counted over all lines before it.
    std::string lines;
    for (int i = 1; i <= 19999; ++i) lines += "1 2\n";  // 80 KB: two chunks
    for (const char* bad : {"1 x", "1", "1 2 3", "0 1", "-1 2", "inf 1", "1 nan", "0x1.8p+ 1", "1 0x", "+-1 2", "1e 2",
                            ". 1", "1e400 1", "0x1p1024 1", "1 0x1p-1075", "-0x1p0 1"}) {
        std::vector<double> r1, r2;
        try {
            parse_pairs(lines + bad + "\n1 2\n", r1, r2, 2);
            BOOST_ERROR("accepted '" << bad << "'");
        } catch (const InputError& e) {
            BOOST_TEST(std::string(e.what()) ==
                       "line 20000: expected two numbers > 0 (decimals such as 1.5 or 2e-3, or hex floats such as "
                       "0x1.8p0; not inf or nan)");
        }
    }
    // Hex floats beside decimals, in both halves: 0x1.8p+1 = 3, 0x3 = 3, 0x1p-1074 the least double.
    std::vector<double> r1, r2;
    parse_pairs(lines + "0x1.8p+1 0x3\n0x1p-1074 1\n", r1, r2, 2);
    BOOST_TEST_REQUIRE(r1.size() == 20001u);
    BOOST_TEST(r1[19999] == 3.0);
    BOOST_TEST(r2[19999] == 3.0);
    BOOST_TEST(r1[20000] == std::ldexp(1.0, -1074));
}

// One query from the scene with no model: the GJK proposal and its filtered certificate give the
// exact verdict at random pairs, at doubles on the curve and one ulp either side; undecided pairs
// go to the exact model.
BOOST_AUTO_TEST_CASE(model_free_queries_equal_exact) {
    std::mt19937 g(43);
    std::uniform_real_distribution<double> u(0.25, 4.0);
    std::uint64_t random_filtered = 0, random_exact = 0, near = 0, near_exact = 0, touch = 0;
    for (int t = 0; t < 30; ++t) {
        ExactScene sc = test::random_scene(g, 4 + t % 9, 4 + t % 7);
        HullModel m = build_model(sc);
        TouchingCurve c = build_curve(m);
        QuickScene qs(sc);
        for (int k = 0; k < 60; ++k) {  // random pairs: the filter should decide nearly all
            double x = u(g), y = u(g);
            BOOST_TEST(qs.classify(x, y) == query_direct(m, exact_from_double(x), exact_from_double(y)));
        }
        random_filtered += qs.counts().filtered, random_exact += qs.counts().exact;
        qs.stats = {};
        for (int k = 0; k < 20; ++k) {  // on the curve (to the nearest double) and one ulp either side
            double x = u(g);
            double y = to_double_rn(c.env.value(m.lines, exact_from_double(x)));
            if (!(y > 0)) continue;
            for (double yy : {y, std::nextafter(y, 0.0), std::nextafter(y, INFINITY)}) {
                Verdict want = query_direct(m, exact_from_double(x), exact_from_double(yy));
                BOOST_TEST(qs.classify(x, yy) == want);
                touch += want == Verdict::Touching;
                ++near;
            }
        }
        near_exact += qs.counts().exact;
    }
    std::cout << "model-free queries: random pairs " << random_filtered << " certified by the filter, " << random_exact
              << " exact; pairs within an ulp of the curve " << near - near_exact << " certified, " << near_exact
              << " exact (" << touch << " touching)\n";
    BOOST_TEST(random_filtered >= 50 * random_exact);
    BOOST_TEST(near_exact > 0u);
}

// Coordinates far outside the comfortable double range (10^200 and 10^-200 times a random scene):
// whatever the doubles do, the answer is the exact one.
BOOST_AUTO_TEST_CASE(model_free_queries_at_extreme_scales) {
    std::mt19937 g(47);
    std::uniform_real_distribution<double> u(0.25, 4.0);
    for (int e : {200, -200}) {
        Z p10;
        mpz_ui_pow_ui(p10.get_mpz_t(), 10, 200);
        const Q f = e > 0 ? Q(p10) : Q(1, p10);
        for (int t = 0; t < 4; ++t) {
            ExactScene sc = test::random_scene(g, 5 + t, 6);
            for (int i = 0; i < 2; ++i) {
                for (Vec3q& v : sc.P[i].points)
                    for (Q& c : v) c *= f;
                for (Q& c : sc.P[i].seed) c *= f;
            }
            HullModel m = build_model(sc);
            QuickScene qs(sc);
            for (int k = 0; k < 20; ++k) {
                double x = u(g), y = u(g);
                BOOST_TEST(qs.classify(x, y) == query_direct(m, exact_from_double(x), exact_from_double(y)));
            }
        }
    }
}
