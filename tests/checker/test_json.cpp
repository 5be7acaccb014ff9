// Reading a certificate (checker/json.*): strict JSON (duplicate keys refused, not resolved;
// hostile texts unreadable), indices as exact integers in range, and the scene's vertex lists of
// integers read straight from the text, judged as the tree of strings judges them.
#include "checker_tests.hpp"

#include "../../checker/json.hpp"

BOOST_AUTO_TEST_SUITE(checker_json)

BOOST_AUTO_TEST_CASE(duplicate_keys_are_refused_not_resolved) {
    // {"growth_distance": <false>, "growth_distance": <true>}: the last value wins in nlohmann's
    // DOM parser, the first won in the engine's old reader. Both now refuse the file.
    OJ j = bundled("tetra_box_switch");
    std::string text = j.dump(1);
    const std::string key = "\"growth_distance\": \"18/11\"";
    BOOST_TEST_REQUIRE(text.find(key) != std::string::npos);
    text.replace(text.find(key), key.size(), "\"growth_distance\": \"1\",\n \"growth_distance\": \"18/11\"");
    BOOST_TEST(verdict_of(text) == 2);
    fs::path f = tmpdir() / "dup.json";
    std::ofstream(f) << text;
    BOOST_TEST(check_file(f) == 2);
}

BOOST_AUTO_TEST_CASE(indices_must_be_exact_integers_in_range) {
    // 2^32, 0.9 and 0.5 were read as vertex 0. Every index field: features, support vertices,
    // witness and seed weights, region pieces.
    OJ j = bundled("tetra_box_switch");
    const std::vector<std::string> where = {"/pieces/0/features/P1/0",        "/pieces/0/support_vertices/P1",
                                            "/switch_points/0/features/P1/0", "/switch_points/0/witness/P1/0/0",
                                            "/seed_interior/P1/0/0",          "/regions/separated/0/piece"};
    for (const std::string& w : where) {
        OJ::json_pointer ptr(w);
        BOOST_TEST_REQUIRE(j[ptr].is_number_integer(), w);
        const long v = j[ptr].get<long>();
        for (const OJ& bad : {OJ(v + 4294967296L), OJ(0.9 + static_cast<double>(v)), OJ(0.5 + static_cast<double>(v)),
                              OJ(static_cast<double>(v)), OJ(-1), OJ(std::to_string(v)), OJ(1e300)}) {
            OJ f = j;
            f[ptr] = bad;
            BOOST_TEST(verdict_of(f) == 1, w << " = " << bad.dump());
        }
    }
}

BOOST_AUTO_TEST_CASE(hostile_files_exit_2_without_crashing) {
    // Nested 10^6 levels (a stack overflow in a recursive reader or destructor), not JSON,
    // comments, leading zeros, and a directory.
    fs::path deep = tmpdir() / "deep.json";
    std::ofstream(deep) << std::string(1000000, '[') << std::string(1000000, ']');
    BOOST_TEST(check_file(deep) == 2);
    std::string t = bundled("stacked_cubes").dump(1);
    for (const auto& [what, text] :
         std::vector<std::pair<std::string, std::string>>{{"comment", "// c\n" + t},
                                                          {"leading zero", "{\"format\": 01}"},
                                                          {"trailing comma", "{\"a\": 1,}"},
                                                          {"bare key", "{a: 1}"},
                                                          {"NaN", "{\"a\": NaN}"},
                                                          {"two values", t + t}}) {
        BOOST_TEST(verdict_of(text) == 2, what);
    }
    BOOST_TEST(check_file(tmpdir()) == 2);
    // nlohmann's reader stops at a NUL byte: what follows one must still be read (a valid
    // certificate, then NUL and garbage, is malformed); and a byte-order mark is refused.
    BOOST_TEST(verdict_of(t + std::string(1, '\0') + "{\"not\": json") == 2);
    BOOST_TEST(verdict_of("\xEF\xBB\xBF" + t) == 2);
    BOOST_TEST(verdict_of(t) == 0);
    // A JSON number of 400 digits is RFC 8259 but no double: unreadable, and the message says why.
    {
        std::string msg;
        BOOST_TEST(scalecert_check::check_text("{\"zz\": 1" + std::string(400, '0') + "}", msg) == 2);
        BOOST_TEST(msg.find("a JSON number past the double range near byte") != std::string::npos, msg);
    }
    // An index written -0 has a sign: refused.
    std::string neg = t;
    const size_t at = neg.find("\"piece\": ");
    BOOST_TEST_REQUIRE(at != std::string::npos);
    neg.insert(at + 9, "-");
    BOOST_TEST(verdict_of(neg) == 1, neg.substr(at, 20));
}

BOOST_AUTO_TEST_CASE(direct_vertex_lists_are_judged_as_the_tree_judges_them) {
    // Every bundled partition (integer scenes and rational ones) and three compound partitions (one
    // with a rational vertex in one part: its object read as rationals from that part on, the
    // parts before it taken as integers), intact and with each vertex list changed: a coordinate
    // spelled every way an integer must not be, or at and past the limits of int64, or as a
    // rational; a vertex of the wrong shape or kind; vertices deleted, duplicated or added; the
    // list not a list. At the first vertex and the last, so that the reader leaves its form at the
    // start of a list and deep inside one.
    std::vector<std::pair<std::string, OJ>> certs;
    for (const auto& e : fs::directory_iterator(fs::path(SCALECERT_SOURCE_DIR) / "certificates"))
        if (e.path().string().size() > 15 &&
            e.path().string().rfind(".partition.json") == e.path().string().size() - 15)
            certs.push_back({e.path().filename().string(), load(e.path())});
    certs.push_back({"compound band", compound_certificate(data("compound_band.json"), "band")});
    certs.push_back({"compound u_peg", compound_certificate(data("compound_u_peg.json"), "u_peg")});
    certs.push_back({"compound mixed", compound_certificate(mixed_compound(), "mixed")});
    const std::vector<OJ> coordinates = {"-0",
                                         "007",
                                         "-01",
                                         "00",
                                         "+1",
                                         "1.0",
                                         "1e3",
                                         "",
                                         " 1",
                                         "1 ",
                                         "-",
                                         "--1",
                                         "1/1",
                                         "2/4",
                                         "1/2",
                                         "-7/3",
                                         "0",
                                         "-1",
                                         "0x10",
                                         "\u0661",
                                         std::string("1\0", 2),
                                         "4611686018427387903",
                                         "4611686018427387904",
                                         "-4611686018427387903",
                                         "-4611686018427387904",
                                         "9223372036854775807",
                                         "9223372036854775808",
                                         "-9223372036854775808",
                                         "-9223372036854775809",
                                         "9999999999999999999",
                                         "10000000000000000000",
                                         "123456789012345678901234567890",
                                         "-123456789012345678901234567890",
                                         5,
                                         -5,
                                         1.5,
                                         nullptr,
                                         true,
                                         OJ::object(),
                                         OJ::array(),
                                         OJ::array({"1"})};
    const std::vector<OJ> vertices = {OJ::array(),
                                      OJ::array({"1", "2"}),
                                      OJ::array({"1", "2", "3", "4"}),
                                      OJ::array({OJ::array({"1"}), "2", "3"}),
                                      OJ::array({1, 2, 3}),
                                      OJ::array({"9223372036854775808", "-4611686018427387904", "0"}),
                                      "x",
                                      5,
                                      OJ::object(),
                                      nullptr};
    const std::vector<OJ> lists = {OJ::array(), OJ::object(), "x", nullptr, 5, OJ::array({OJ::array()})};
    int compared = 0, integer_lists = 0, statuses[3] = {0, 0, 0};
    for (const auto& [name, j] : certs) {
        BOOST_TEST(same_both_ways(j, name, compared) == 0);
        // which lists the reader takes: exactly those of integers written canonically
        const sc_::Parsed parsed = sc_::parse_certificate(j.dump(1));
        size_t expect = 0;
        for (const auto& ptr : vertex_lists(j)) {
            bool ints = true;
            for (const OJ& v : j[ptr])
                for (const OJ& c : v) ints = ints && c.get<std::string>().find('/') == std::string::npos;
            expect += ints;
        }
        BOOST_TEST(parsed.points.size() == expect, name);
        integer_lists += static_cast<int>(expect);
        for (const auto& ptr : vertex_lists(j)) {
            const size_t n = j[ptr].size();
            for (size_t at : {size_t(0), n - 1}) {
                const std::string where = name + " " + ptr.to_string() + "/" + std::to_string(at);
                for (size_t c = 0; c < coordinates.size(); ++c) {
                    OJ m = j;
                    m[ptr][at][c % 3] = coordinates[c];
                    ++statuses[same_both_ways(m, where + " coordinate " + coordinates[c].dump(), compared)];
                }
                for (const OJ& v : vertices) {
                    OJ m = j;
                    m[ptr][at] = v;
                    ++statuses[same_both_ways(m, where + " vertex " + v.dump(), compared)];
                }
                OJ del = j, dup = j, add = j;
                del[ptr].erase(at);
                ++statuses[same_both_ways(del, where + " deleted", compared)];
                dup[ptr].insert(dup[ptr].begin() + static_cast<long>(at), j[ptr][at]);
                ++statuses[same_both_ways(dup, where + " duplicated", compared)];
                add[ptr].insert(add[ptr].begin() + static_cast<long>(at),
                                OJ::array({"9223372036854775807", "-9223372036854775808", "1"}));
                ++statuses[same_both_ways(add, where + " a vertex at the int64 limits added", compared)];
            }
            for (const OJ& l : lists) {
                OJ m = j;
                m[ptr] = l;
                ++statuses[same_both_ways(m, name + " " + ptr.to_string() + " = " + l.dump(), compared)];
            }
        }
    }
    std::cout << "direct and tree reading compared on " << compared << " texts (" << statuses[0] << " valid, "
              << statuses[1] << " invalid, " << statuses[2] << " unreadable); " << integer_lists
              << " integer vertex lists in the intact files\n";
    BOOST_TEST(integer_lists >= 15);
    BOOST_TEST(statuses[0] > 50);
    BOOST_TEST(statuses[1] > 1000);
}

BOOST_AUTO_TEST_SUITE_END()
