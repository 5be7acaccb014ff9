// What the checker's tests (tests/checker/test_MODULE.cpp, one file per module of checker/) share:
// the engine and scalecert-check run as commands, and the mutation rounds: every numeric field of a
// certificate changed, every list element deleted or duplicated, every verdict and flag flipped,
// and the structural attacks (keys added, removed or duplicated, kinds changed, indices made
// fractional, negative, too large or strings), each run through the checker's own check_text in
// this process (the command is that function behind main, both linked from scalecert_check_core).
// A changed certificate the checker accepts must be still true: one of the changes listed in
// kStillTrue with its reason, or, for judgements and compound partitions, one the engine, re-run on
// the changed file, agrees with. The test files are compiled as one translation unit
// (tests/CMakeLists.txt), each a Boost.Test suite checker_MODULE.
#pragma once
#include <boost/test/unit_test.hpp>

#include "../files.hpp"
#include "numeric/exact.hpp"

#include <sys/wait.h>

#include "../../checker/check.hpp"
#include "../../checker/polygon.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using OJ = nlohmann::ordered_json;

namespace checker_tests {

// ---- the engine and the checker as commands, and files -----------------------------------------
inline fs::path tmpdir() {
    static fs::path d = test::scratch_dir("checker");
    return d;
}

inline int status_of(const std::string& cmd) {
    int st = std::system((cmd + " >/dev/null 2>&1").c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}
inline int check_file(const fs::path& p) { return status_of(std::string(SCALECERT_CHECK_BIN) + " " + p.string()); }
inline int engine(const std::string& args) { return status_of(std::string(SCALECERT_BIN) + " " + args); }

inline OJ load(const fs::path& p) {
    std::ifstream in(p);
    return OJ::parse(in);
}
inline void save(const OJ& j, const fs::path& p) { std::ofstream(p) << j.dump(1); }

// ---- every mutation of a certificate ----------------------------------------------------------
// Changes that leave a true certificate, matched against "what at path": annotation fields that
// are not claims, a feature list naming another vertex that also attains the support value, and
// scene changes for which the stored claim still holds. The checker proves the claims for the
// scene stored in the file (FORMAT.md: comparing it with your own scene is yours to do).
struct StillTrue {
    std::regex re;
    std::string why;
    bool query_only;
};
inline const std::vector<StillTrue> kStillTrue = {
    {std::regex(".* at /model/.*"), "engine statistics (hull sizes, pairs tested): not a claim", false},
    {std::regex(".* at .*/closed_form$"),
     "name of the paper's formula that also gives the line: provenance, not a claim", false},
    {std::regex(".* at .*/equation$"),
     "name of the paper's equation that gives the switch point: provenance, not a claim", false},
    {std::regex(
         "optional member removed at (/model|.*/closed_form|.*/equation|.*/same_line_normals|/growth_distance_note)$"),
     "an annotation left out (it is optional)", false},
    {std::regex(".* at .*/features/P[12]/[0-9]+$"),
     "another vertex of the same contact feature, or fewer that still span it", false},
    {std::regex(".* at .*/support_vertices/P[12]$"), "another vertex attaining the same support value", false},
    {std::regex(".* at .*/zero_witness/P2/[0-9]+/0$"),
     "another vertex under a zero witness's P2 weights: P2(0) is its seed, whatever the weights", false},
    {std::regex(".* at /pieces/[0-9]+/same_line_normals/[0-9]+(/[0-2])?$"),
     "another normal that gives the very same line (the checker recomputes its line and maximisers), or one listed "
     "twice",
     false},
    {std::regex("element duplicated at /scene/P[12]/vertices/[0-9]+$"),
     "a repeated vertex is the same polyhedron (a copy of the last vertex shifts no index)", false},
    {std::regex(".* at /scene/I[12]/.*"), "the scaling ranges I1, I2 take no part in a single query's claim", true},
    {std::regex(".* at /judgements/[0-9]+/index$"), "a judgement's place in the user's claims file: an annotation",
     false},
    {std::regex("element deleted at /judgements/[0-9]+$"), "a judgement left out: the others still hold", false},
};
// A changed judgements file that the checker still accepts must state the judgements the engine
// gives: scalecert certify-fp is re-run here on the changed file's scene, claims and tolerance,
// and compared claim by claim (a judgement's truth does not depend on its proof).
inline bool g_judgements = false;
inline bool engine_judges_the_same(const std::string& text) {
    const OJ j = OJ::parse(text);
    const fs::path scene = tmpdir() / "rejudge_scene.json", claims = tmpdir() / "rejudge_claims.json",
                   rep = tmpdir() / "rejudge.json";
    { std::ofstream(scene) << j["scene"].dump(1); }
    OJ doc{{"format", "scalecert-claims-1"}, {"claims", OJ::array()}};
    for (const OJ& e : j["judgements"]) doc["claims"].push_back(e["claim"]);
    { std::ofstream(claims) << doc.dump(1); }
    const int st = status_of(
        std::string(SCALECERT_BIN) + " certify-fp " + scene.string() + " " + claims.string() + " --json --tolerance " +
        j["tolerance"].get<std::string>() +
        (j.contains("abs_tolerance") ? " --abs-tolerance " + j["abs_tolerance"].get<std::string>() : std::string()) +
        " --out " + rep.string());
    if (st != 0 && st != 1) return false;
    const OJ r = load(rep);
    for (size_t k = 0; k < j["judgements"].size(); ++k)
        if (r["claims"][k]["right"] != j["judgements"][k]["right"]) return false;
    return true;
}

// A changed compound partition that the checker still accepts must state what the engine finds
// for the changed file's scene: scalecert region is re-run on it, and every pair that meets
// somewhere must have the file's polygon, and the growth set must be the file's.
inline bool g_compound = false;
inline bool engine_finds_the_same_region(const std::string& text) {
    const OJ j = OJ::parse(text);
    const fs::path scene = tmpdir() / "reregion_scene.json", rep = tmpdir() / "reregion.json";
    { std::ofstream(scene) << j["scene"].dump(1); }
    if (status_of(std::string(SCALECERT_BIN) + " region " + scene.string() + " --out " + rep.string()) != 0)
        return false;
    const OJ r = load(rep);
    OJ mine = OJ::array();
    for (const OJ& e : j["pairs"])
        if (!e["vertices"].empty())
            mine.push_back(
                OJ{{"P1_part", e["P1_parts"][0]}, {"P2_part", e["P2_parts"][0]}, {"vertices", e["vertices"]}});
    // The growth set by its intervals and first pairs (the region document adds each first
    // contact's features, which the certificate does not state).
    auto intervals = [](const OJ& set) {
        OJ out = OJ::array();
        for (const OJ& g : set)
            out.push_back(OJ{{"from", g["from"]},
                             {"to", g["to"]},
                             {"P1_part", g["first_contact"]["P1_part"]},
                             {"P2_part", g["first_contact"]["P2_part"]}});
        return out;
    };
    return r["pair_regions"] == mine && intervals(r["growth_set"]) == intervals(j["growth_set"]);
}

struct Tally {
    int tried = 0, rejected = 0;
    std::map<std::string, int> still_true;
};

inline bool g_query = false;  // mutating a query answer (vs a partition)

// Vertices of P1 and P2 that carry a weight in some combination (witnesses, seed weights),
// collected from the unmutated file. Moving any other vertex leaves every claim true unless the
// moved point becomes a maximiser of a piece's normal, or a named maximiser stops being one: the
// checker recomputes every support value from all vertices, and then it must reject.
inline std::set<std::pair<int, long>> g_named;
inline void collect_named(const OJ& node, bool in_scene) {
    if (node.is_object()) {
        for (auto it = node.begin(); it != node.end(); ++it) {
            const bool scene = in_scene || it.key() == "scene";
            if (!scene && (it.key() == "P1" || it.key() == "P2") &&
                (it.value().is_array() || it.value().contains("in"))) {
                const int poly = it.key() == "P1" ? 1 : 2;
                for (const OJ& e : it.value().is_array() ? it.value() : it.value()["in"]) {
                    if (e.is_array() && !e.empty() && e[0].is_number_integer())
                        g_named.insert({poly, e[0].get<long>()});
                }
            }
            collect_named(it.value(), scene);
        }
    } else if (node.is_array()) {
        for (const OJ& e : node) collect_named(e, in_scene);
    }
}
inline bool moves_an_unnamed_vertex(const std::string& key) {
    std::smatch m;
    static const std::regex re("numerator \\+ 1 at /scene/P([12])/vertices/([0-9]+)/[0-2]");
    return std::regex_match(key, m, re) && !g_named.count({std::stoi(m[1]), std::stol(m[2])});
}

// The checker's verdict on a text: 1 (invalid) is a rejection; 2 (unreadable) is one too for the
// attacks that make the text non-strict JSON (a duplicated key).
inline void try_text(const std::string& text, const std::string& path, const std::string& what, Tally& t,
                     int expected = 1) {
    ++t.tried;
    std::string msg;
    int st = scalecert_check::check_text(text, msg);
    if (st == expected) {
        ++t.rejected;
        return;
    }
    const std::string key = what + " at " + path;
    if (g_judgements) {  // whatever changed: true iff the engine judges the file's claims the same way
        if (engine_judges_the_same(text)) {
            static const std::regex claim_or_tolerance(
                ".* at (/judgements/[0-9]+/claim(/.*)?|/tolerance|/abs_tolerance)$");
            ++t.still_true
                  [std::regex_match(key, claim_or_tolerance)
                       ? "a changed claim or tolerance that the engine, re-run, judges the same way"
                       : "a changed proof, scene or annotation, and the engine, re-run on the file's scene, claims and "
                         "tolerance, "
                         "gives every judgement the file states (another normal along the same direction, another "
                         "surface of difference points, I1 or I2, which no judgement uses, ...)"];
            return;
        }
        BOOST_ERROR("tampered judgements certificate accepted, and the engine judges its claims otherwise: "
                    << key << " (" << msg << ")");
        return;
    }
    if (g_compound) {  // whatever changed: true iff the engine finds the same pair polygons and growth set
        if (std::regex_match(key, std::regex(".* at /statistics(/.*)?$"))) {
            ++t.still_true["engine statistics (pairs pruned and built): not a claim"];
            return;
        }
        if (engine_finds_the_same_region(text)) {
            ++t.still_true
                  ["a changed scene or normal, and the engine, re-run on the file's scene, finds the file's pair "
                   "polygons and "
                   "growth set (a vertex that no normal's support or witness uses, moved; another normal along the "
                   "same "
                   "direction; ...)"];
            return;
        }
        BOOST_ERROR("tampered compound partition accepted, and the engine finds another region: " << key << " (" << msg
                                                                                                  << ")");
        return;
    }
    for (const StillTrue& s : kStillTrue)
        if ((!s.query_only || g_query) && std::regex_match(key, s.re)) {
            ++t.still_true[s.why];
            return;
        }
    if (moves_an_unnamed_vertex(key)) {
        ++t.still_true
              ["a vertex in no weighted combination, moved with every support value unchanged: every claim still holds "
               "for the new points"];
        return;
    }
    BOOST_ERROR("tampered certificate accepted (exit " << st << "): " << key << " (" << msg << ")");
}
inline void try_mutation(const OJ& j, const std::string& path, const std::string& what, Tally& t) {
    try_text(j.dump(1), path, what, t);
}

inline bool is_exact(const std::string& s) { return std::regex_match(s, std::regex("-?[0-9]+(/[0-9]+)?")); }

inline void mutate_all(const OJ& root, const OJ& node, const OJ::json_pointer& ptr, Tally& t) {
    const std::string path = ptr.to_string();
    auto with = [&](const OJ& v, const std::string& what) {
        OJ m = root;
        m[ptr] = v;
        try_mutation(m, path, what, t);
    };
    if (node.is_string()) {
        std::string s = node.get<std::string>();
        if (is_exact(s)) {
            scalecert::internal::Q q(s);
            q += scalecert::internal::Q(1, q.get_den());  // numerator + 1, written in lowest terms
            with(q.get_str(), "numerator + 1");
        } else if (s == "separated" || s == "touching" || s == "overlapping") {
            for (const char* v : {"separated", "touching", "overlapping"})
                if (s != v) with(v, std::string("verdict flipped to ") + v);
        } else if (s == "partition" || s == "query" || s == "judgements" || s == "compound_partition" ||
                   s == "compound_judgements") {
            for (const char* v :
                 {"partition", "query", "curve", "judgements", "compound_partition", "compound_judgements", "region"})
                if (s != v) with(v, std::string("kind changed to ") + v);
        } else {
            with(s + "X", "string changed");
        }
    } else if (node.is_number_float()) {
        with(std::nextafter(node.get<double>(), INFINITY), "double moved to the next double");
    } else if (node.is_number_integer()) {
        const long i = node.get<long>();
        with(i + 1, "integer + 1");
        // Indices and counts that are not exact non-negative integers in range.
        with(static_cast<double>(i), "integer written as a double");
        with(static_cast<double>(i) + 0.5, "integer + 1/2");
        with(static_cast<double>(i) + 0.9, "integer + 9/10");
        with(i + (1L << 32), "integer + 2^32");
        with(-1 - i, "integer made negative");
        with(std::to_string(i), "integer written as a string");
    } else if (node.is_boolean()) {
        with(!node.get<bool>(), "flag flipped");
    } else if (node.is_object()) {
        {  // a key added
            OJ m = root;
            m[ptr]["extra"] = 1;
            try_mutation(m, path, "key added", t);
        }
        if (!node.empty()) {  // the first key written twice, with its own value: the file means two things
            OJ m = root;
            m[ptr]["__duplicate__"] = node.begin().value();
            std::string text = m.dump(1);
            text.replace(text.find("\"__duplicate__\""), 15, "\"" + node.begin().key() + "\"");
            try_text(text, path, "key duplicated", t, 2);
        }
        for (auto it = node.begin(); it != node.end(); ++it) {  // each member removed
            OJ m = root;
            m[ptr].erase(it.key());
            try_mutation(m, (ptr / it.key()).to_string(), "optional member removed", t);
        }
        for (auto it = node.begin(); it != node.end(); ++it) mutate_all(root, it.value(), ptr / it.key(), t);
    } else if (node.is_array()) {
        for (size_t i = 0; i < node.size(); ++i) {
            if (node[i].is_structured()) {
                OJ del = root, dup = root;
                del[ptr].erase(i);
                try_mutation(del, (ptr / i).to_string(), "element deleted", t);
                dup[ptr].insert(dup[ptr].begin() + static_cast<long>(i), node[i]);
                try_mutation(dup, (ptr / i).to_string(), "element duplicated", t);
            }
            mutate_all(root, node[i], ptr / i, t);
        }
    }
}

inline void report(const std::string& name, const Tally& t) {
    int kept = 0;
    for (const auto& [why, n] : t.still_true) kept += n;
    BOOST_TEST_MESSAGE(name << ": " << t.tried << " mutations tried, " << t.rejected << " rejected, " << kept
                            << " still true");
    std::cout << name << ": " << t.tried << " mutations tried, " << t.rejected << " rejected, " << kept
              << " still true\n";
    for (const auto& [why, n] : t.still_true) std::cout << "    still true (" << n << "): " << why << "\n";
    BOOST_TEST(t.tried > 50);
    BOOST_TEST(t.rejected + kept == t.tried);
}
// Every mutation of a certificate (a query answer's when `query`), tallied and reported.
inline void mutate_and_report(const OJ& j, const std::string& name, bool query, bool judgements = false,
                              bool compound = false) {
    Tally t;
    g_query = query;
    g_judgements = judgements;
    g_compound = compound;
    g_named.clear();
    collect_named(j, false);
    mutate_all(j, j, OJ::json_pointer(), t);
    report(name, t);
}

// ---- certificates to start from ----------------------------------------------------------------
inline OJ bundled(const std::string& name) {
    return load(fs::path(SCALECERT_SOURCE_DIR) / "certificates" / (name + ".partition.json"));
}
inline int verdict_of(const std::string& text) {
    std::string msg;
    return scalecert_check::check_text(text, msg);
}
inline int verdict_of(const OJ& j) { return verdict_of(j.dump(1)); }
// The engine's partition certificate of a scene in tests/data, accepted by the checker.
inline OJ fresh_partition(const std::string& data_scene) {
    const fs::path scene = fs::path(SCALECERT_SOURCE_DIR) / "tests/data" / data_scene;
    const fs::path cert = tmpdir() / (data_scene + ".partition.json");
    BOOST_TEST_REQUIRE(engine("partition " + scene.string() + " --out " + cert.string()) == 0);
    OJ j = load(cert);
    BOOST_TEST_REQUIRE(verdict_of(j) == 0);
    return j;
}

// ---- the checker's own types, random rationals, and plain reimplementations of its stages --------
namespace sc_ = scalecert_check;
using CQ = sc_::Q;
using CV = sc_::V3;

inline CQ cq(long p, long q) {
    CQ x(p, q);
    x.canonicalize();
    return x;
}
// A random integer in [0, m) (m > 0), from g's words.
inline mpz_class rz(std::mt19937_64& g, const mpz_class& m) {
    std::vector<uint64_t> w(mpz_sizeinbase(m.get_mpz_t(), 2) / 64 + 2);
    for (auto& x : w) x = g();
    mpz_class z;
    mpz_import(z.get_mpz_t(), w.size(), 1, sizeof(uint64_t), 0, 0, w.data());
    return z % m;
}
// A random rational p/q with |p| <= range and 1 <= q <= den_range, in lowest terms.
inline CQ rq(std::mt19937_64& g, const mpz_class& range, const mpz_class& den_range) {
    const mpz_class p = rz(g, 2 * range + 1) - range,
                    q = den_range > 1 ? mpz_class(rz(g, den_range) + 1) : mpz_class(1);
    CQ x(p, q);
    x.canonicalize();
    return x;
}

// The earlier O(n^2) normalisation and the clip by every line, kept here as references.
inline std::vector<sc_::P2> ref_normalize(std::vector<sc_::P2> p) {
    auto cr = [](const sc_::P2& o, const sc_::P2& a, const sc_::P2& b) -> CQ {
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    };
    std::vector<sc_::P2> q;
    for (const sc_::P2& v : p)
        if (q.empty() || q.back() != v) q.push_back(v);
    while (q.size() > 1 && q.front() == q.back()) q.pop_back();
    for (size_t i = 0; q.size() > 2 && i < q.size();) {
        if (sgn(cr(q[(i + q.size() - 1) % q.size()], q[i], q[(i + 1) % q.size()])) == 0) {
            q.erase(q.begin() + static_cast<long>(i));
            i = 0;
        } else
            ++i;
    }
    if (q.size() == 2 && q[1] < q[0]) std::swap(q[0], q[1]);
    if (q.size() > 2)
        std::rotate(q.begin(),
                    std::min_element(
                        q.begin(), q.end(),
                        [](const sc_::P2& a, const sc_::P2& b) { return a[1] != b[1] ? a[1] < b[1] : a[0] < b[0]; }),
                    q.end());
    return q;
}
inline std::vector<sc_::P2> ref_clip(const std::vector<sc_::P2>& p, const sc_::Line& L, bool above) {
    std::vector<sc_::P2> out;
    for (size_t i = 0; i < p.size(); ++i) {
        const sc_::P2 &u = p[i], &v = p[(i + 1) % p.size()];
        CQ fu = u[1] - L.at(u[0]), fv = v[1] - L.at(v[0]);
        if (!above) {
            fu = -fu;
            fv = -fv;
        }
        if (sgn(fu) >= 0) out.push_back(u);
        if (sgn(fu) * sgn(fv) < 0) {
            CQ t = fu / (fu - fv);
            out.push_back({u[0] + t * (v[0] - u[0]), u[1] + t * (v[1] - u[1])});
        }
    }
    return ref_normalize(out);
}

// ---- objects made of parts ---------------------------------------------------------------------
inline fs::path data(const std::string& name) { return fs::path(SCALECERT_SOURCE_DIR) / "tests" / "data" / name; }
inline OJ compound_certificate(const fs::path& scene, const std::string& name) {
    const fs::path out = tmpdir() / (name + ".cert.json");
    BOOST_REQUIRE(engine("region " + scene.string() + " --certificate " + out.string()) == 0);
    BOOST_REQUIRE(check_file(out) == 0);
    return load(out);
}
inline int check_json(const OJ& j) {
    std::string msg;
    return scalecert_check::check_text(j.dump(1), msg);
}
// Three parts a side: two near each other and one far off along x, so that some pairs meet,
// some are apart in the rectangle and some are pruned (in a block).
inline fs::path mixed_compound() {
    const std::string text = R"({
 "P1": {"parts": [{"vertices": [[0,0,0],[2,0,0],[0,2,0],[0,0,2],[2,2,2]]},
                  {"vertices": [[0,3,0],[2,3,0],[1,5,1],[0,3,2],["1/2","9/2",2]]},
                  {"vertices": [[-40,0,0],[-38,0,0],[-40,2,0],[-40,0,2]]}], "seed": [1, 2, 1]},
 "P2": {"parts": [{"vertices": [[4,0,0],[6,1,0],[4,2,1],[5,0,2],[6,2,2]]},
                  {"vertices": [[4,3,0],[6,3,0],[4,5,0],[4,3,2],[5,5,2]]},
                  {"vertices": [[4,-9,0],[6,-9,0],[4,-7,0],[4,-9,2]]}], "seed": [5, 2, 1]},
 "I1": ["1/2", 3], "I2": ["1/2", 3]})";
    const fs::path p = tmpdir() / "mixed_compound.json";
    std::ofstream(p) << text;
    return p;
}

// certify-fp's certificate for claims on a scene of parts, checked valid.
inline OJ compound_judgements(const fs::path& scene, const std::string& claims, const std::string& name,
                              const std::string& options = "") {
    const fs::path cl = tmpdir() / (name + ".claims.json"), out = tmpdir() / (name + ".judgements.json");
    std::ofstream(cl) << claims;
    const int st = engine("certify-fp " + scene.string() + " " + cl.string() + " --certificate " + out.string() +
                          " --out " + (tmpdir() / (name + ".report")).string() + options);
    BOOST_REQUIRE(st == 0 || st == 1);
    BOOST_REQUIRE(check_file(out) == 0);
    return load(out);
}

// ---- the two ways of reading a vertex list: straight from the text, or through the tree ----------
struct Answer {
    int status;
    std::string message;
    long claims;
};
inline Answer answer(const std::string& text, bool direct) {
    sc_::Context cx;
    cx.direct_points = direct;
    std::string msg;
    const int st = sc_::check_text(text, msg, cx);
    return {st, msg, cx.claims};
}
// Checks j both ways; returns the status.
inline int same_both_ways(const OJ& j, const std::string& what, int& compared) {
    const std::string text = j.dump(1);
    const Answer a = answer(text, true), b = answer(text, false);
    BOOST_TEST(a.status == b.status, what);
    BOOST_TEST(a.message == b.message, what << ": " << a.message << " | " << b.message);
    BOOST_TEST(a.claims == b.claims, what);
    ++compared;
    return a.status;
}
// The vertex lists of a certificate's scene (of each part, for a compound one), as JSON pointers.
inline std::vector<OJ::json_pointer> vertex_lists(const OJ& j) {
    std::vector<OJ::json_pointer> out;
    for (const char* p : {"P1", "P2"}) {
        const OJ& o = j["scene"][p];
        if (o.contains("vertices")) out.push_back(OJ::json_pointer("/scene/" + std::string(p) + "/vertices"));
        if (o.contains("parts"))
            for (size_t k = 0; k < o["parts"].size(); ++k)
                out.push_back(
                    OJ::json_pointer("/scene/" + std::string(p) + "/parts/" + std::to_string(k) + "/vertices"));
    }
    return out;
}

}  // namespace checker_tests
using namespace checker_tests;
