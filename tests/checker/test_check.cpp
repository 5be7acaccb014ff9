// The checker as a whole (checker/check.cpp: check_text, and the scalecert-check command around
// it, checker/main.cpp): the certificates of every kind the engine writes for random scenes pass, a
// file is checked as the kind it states, and the command's exit statuses (help, version, unreadable
// files, out of memory).
#include "checker_tests.hpp"
#include "../support.hpp"

#include "../../checker/check.hpp"

#include <cstdio>
#include <random>
#include <sstream>

BOOST_AUTO_TEST_SUITE(checker_check)

// Claims of every kind at five pairs (separated, touching and overlapping ones among
// them), with the judgements certificate written and checked; x is a point for witness claims.
int certify_with_certificate(const fs::path& scene, const scalecert::internal::Vec3q& x) {
    OJ claims = OJ::array();
    const std::string xs[3] = {x[0].get_str(), x[1].get_str(), x[2].get_str()};
    for (const char* q : {"1/2 1/2", "1 1", "2 2", "3 5/2", "7/5 9/11"}) {
        std::istringstream in(q);
        std::string a, b;
        in >> a >> b;
        claims.push_back({{"kind", "verdict"}, {"rho1", a}, {"rho2", b}, {"verdict", "separated"}});
        claims.push_back({{"kind", "distance"},
                          {"rho1", a},
                          {"rho2", b},
                          {"value", "1"},
                          {"closest", {{xs[0], xs[1], xs[2]}, {xs[0], xs[1], xs[2]}}}});
        claims.push_back({{"kind", "penetration_depth"},
                          {"rho1", a},
                          {"rho2", b},
                          {"value", "1/10"},
                          {"direction", {"0", "0", "1"}}});
        claims.push_back({{"kind", "witness_point"}, {"rho1", a}, {"rho2", b}, {"point", {xs[0], xs[1], xs[2]}}});
        claims.push_back({{"kind", "separating_plane"}, {"rho1", a}, {"rho2", b}, {"normal", {"1", "1", "0"}}});
    }
    claims.push_back({{"kind", "growth_distance"}, {"value", "1"}});
    claims.push_back({{"kind", "switch_point"}, {"rho1", "1"}, {"rho2", "1"}});
    claims.push_back(
        {{"kind", "curve"},
         {"vertices", OJ::array({OJ::array({"1/2", "2"}), OJ::array({"1", "1"}), OJ::array({"2", "1/2"})})}});
    const fs::path cl = tmpdir() / "claims.json", cp = tmpdir() / "judgements.json";
    save(OJ{{"format", "scalecert-claims-1"}, {"claims", claims}}, cl);
    const int st = engine("certify-fp " + scene.string() + " " + cl.string() + " --certificate " + cp.string());
    BOOST_TEST((st == 0 || st == 1), scene);
    BOOST_TEST(check_file(cp) == 0, scene);
    return 1;
}

BOOST_AUTO_TEST_CASE(fresh_certificates_for_random_scenes_are_valid) {
    std::mt19937 g(31);
    int partitions = 0, queries = 0, judgements = 0;
    for (int t = 0; t < 12; ++t) {
        scalecert::internal::ExactScene sc = test::random_scene(g, 4 + t % 6, 5 + t % 4);
        OJ s;
        for (int i = 0; i < 2; ++i) {
            OJ vs = OJ::array();
            for (const auto& v : sc.P[i].points) vs.push_back({v[0].get_str(), v[1].get_str(), v[2].get_str()});
            s[i == 0 ? "P1" : "P2"] = {{"vertices", vs}};
        }
        s["I1"] = {"1/2", "3"};
        s["I2"] = {"1/3", "5/2"};
        fs::path sp = tmpdir() / "scene.json", cp = tmpdir() / "cert.json";
        save(s, sp);
        BOOST_TEST_REQUIRE(engine("partition " + sp.string() + " --out " + cp.string()) == 0);
        BOOST_TEST(check_file(cp) == 0);
        ++partitions;
        for (const char* q : {"1/2 1/2", "1 1", "2 2", "3 5/2", "7/5 9/11"}) {
            BOOST_TEST_REQUIRE(engine("query " + sp.string() + " " + q + " --json --out " + cp.string()) == 0);
            BOOST_TEST(check_file(cp) == 0, q);
            ++queries;
        }
        judgements += certify_with_certificate(sp, sc.P[0].points[0]);
    }
    // Boxes with the midpoints of their edges and faces as extra points, at lattice offsets:
    // contact faces then hold points that are not vertices, and several normals share a line
    // (the fuzzer's first finding against the piece contacts: the checker wanted every point).
    for (int t = 0; t < 6; ++t) {
        OJ s;
        for (int i = 0; i < 2; ++i) {
            const int o[3] = {i ? 2 : 0, i ? (t % 3) : 0, i ? 2 * (t / 3) : 0};
            OJ vs = OJ::array();
            for (int x = 0; x <= 2; ++x)
                for (int y = 0; y <= 2; ++y)
                    for (int z = 0; z <= 2; ++z)
                        if (x != 1 || y != 1 || z != 1)
                            vs.push_back(
                                {std::to_string(o[0] + x), std::to_string(o[1] + y), std::to_string(o[2] + z)});
            s[i == 0 ? "P1" : "P2"] = {{"vertices", vs}};
        }
        s["I1"] = {"1/2", "3/2"};
        s["I2"] = {"1/2", "3/2"};
        fs::path sp = tmpdir() / "scene.json", cp = tmpdir() / "cert.json";
        save(s, sp);
        BOOST_TEST_REQUIRE(engine("partition " + sp.string() + " --out " + cp.string()) == 0);
        BOOST_TEST(check_file(cp) == 0, "boxes with midpoints #" << t);
        ++partitions;
        judgements += certify_with_certificate(sp, {1, 0, 2});  // on an edge of P1: boundary weights
    }
    std::cout << "fresh certificates checked: " << partitions << " partitions, " << queries << " query answers, "
              << judgements << " judgements files\n";
}

BOOST_AUTO_TEST_CASE(help_and_version_exit_0) {
    // --help is an option, not a file name (exit 0). --version prints the version of
    // CMakeLists.txt's project(scalecert VERSION ...).
    BOOST_TEST(status_of(std::string(SCALECERT_CHECK_BIN) + " --help") == 0);
    std::ifstream cm(std::string(SCALECERT_SOURCE_DIR) + "/CMakeLists.txt");
    const std::string cml((std::istreambuf_iterator<char>(cm)), std::istreambuf_iterator<char>());
    const size_t at = cml.find("project(scalecert VERSION ");
    BOOST_TEST_REQUIRE(at != std::string::npos);
    const std::string ver = cml.substr(at + 26, cml.find(' ', at + 26) - (at + 26));
    std::FILE* p = ::popen((std::string(SCALECERT_CHECK_BIN) + " --version").c_str(), "r");
    BOOST_TEST_REQUIRE(p != nullptr);
    char buf[128] = {0};
    const size_t n = std::fread(buf, 1, sizeof buf - 1, p);
    BOOST_TEST(::pclose(p) == 0);
    BOOST_TEST(std::string(buf, n) == "scalecert-check " + ver + "\n");
    BOOST_TEST(status_of(std::string(SCALECERT_CHECK_BIN)) == 2);  // no file: the usage, exit 2
}

BOOST_AUTO_TEST_CASE(unreadable_files_exit_2) {
    BOOST_TEST(check_file(tmpdir() / "absent.json") == 2);
    std::ofstream(tmpdir() / "junk.json") << "{not json";
    BOOST_TEST(check_file(tmpdir() / "junk.json") == 2);
}

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SCALECERT_HAS_ASAN 1
#endif
#endif
#ifndef SCALECERT_HAS_ASAN
#define SCALECERT_HAS_ASAN 0
#endif

BOOST_AUTO_TEST_CASE(a_partition_with_a_verdict_key_is_not_checked_as_a_query) {
    // Before: any "verdict" key made the checker check the file as a query answer only, so every
    // partition claim could be false. Now the kind is explicit and unknown keys are rejected.
    OJ j = bundled("tetra_box_switch");
    BOOST_TEST_REQUIRE(verdict_of(j) == 0);
    OJ f = j;
    f["verdict"] = "overlapping";
    BOOST_TEST(verdict_of(f) == 1);
    f["growth_distance"] = "1";  // and a false claim beside it
    BOOST_TEST(verdict_of(f) == 1);
    OJ q = j;
    q["kind"] = "query";
    BOOST_TEST(verdict_of(q) == 1);
    OJ none = j;
    none.erase("kind");
    BOOST_TEST(verdict_of(none) == 1);
}

BOOST_AUTO_TEST_CASE(out_of_memory_in_the_checker_exits_2) {
    // Under a 300 MB address-space limit, a 200 MB certificate cannot be held: exit 2, one line.
    fs::path big = tmpdir() / "big.json";
    {
        std::ofstream f(big);
        f << "{\"format\": \"scalecert-2\", \"kind\": \"partition\", \"pad\": \"";
        std::string block(1 << 20, 'x');
        for (int i = 0; i < 200; ++i) f << block;
        f << "\"}";
    }
#if defined(__SANITIZE_ADDRESS__) || SCALECERT_HAS_ASAN
    BOOST_TEST_MESSAGE("skipped under AddressSanitizer, which reserves more address space than the limit");
    return;
#endif
    fs::path err = tmpdir() / "err.txt";
    int raw = std::system(
        ("ulimit -v 300000; " + std::string(SCALECERT_CHECK_BIN) + " " + big.string() + " >/dev/null 2>" + err.string())
            .c_str());
    int st = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    BOOST_TEST(st == 2);
    std::string e = test::slurp(err);
    BOOST_TEST(e.find("out of memory") != std::string::npos, e);
    BOOST_TEST(std::count(e.begin(), e.end(), '\n') == 1);
    fs::remove(big);
}

BOOST_AUTO_TEST_SUITE_END()
