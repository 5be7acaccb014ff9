// The independent checker: it accepts every certificate the engine writes (bundled and fresh,
// for random scenes), and it rejects tampered ones — every numeric field changed, every list
// element deleted or duplicated, every verdict and flag flipped, and the structural attacks:
// keys added, removed or duplicated, kinds changed, indices made fractional, negative, too large
// or strings — except changes that leave a still-true certificate, each listed below with the
// reason. The mutations run the checker's own check_text in this process (the binary is that
// function behind main, both linked from scalecert_check_core); the exit statuses of the binary
// are tested at the end.
#include <boost/test/unit_test.hpp>

#include "files.hpp"
#include "support.hpp"

#include <sys/wait.h>

#include "../checker/check.hpp"
#include "../checker/formats.hpp"
#include "../checker/numbers.hpp"
#include "../checker/polygon.hpp"
#include "../checker/scene.hpp"

#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <set>
#include <chrono>
#include <random>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using OJ = nlohmann::ordered_json;

namespace {
fs::path tmpdir() {
    static fs::path d = test::scratch_dir("checker");
    return d;
}

int status_of(const std::string& cmd) {
    int st = std::system((cmd + " >/dev/null 2>&1").c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}
int check_file(const fs::path& p) { return status_of(std::string(SCALECERT_CHECK_BIN) + " " + p.string()); }
int engine(const std::string& args) { return status_of(std::string(SCALECERT_BIN) + " " + args); }

OJ load(const fs::path& p) {
    std::ifstream in(p);
    return OJ::parse(in);
}
void save(const OJ& j, const fs::path& p) { std::ofstream(p) << j.dump(1); }

// Changes that leave a true certificate, matched against "what at path": annotation fields that
// are not claims, a feature list naming another vertex that also attains the support value, and
// scene changes for which the stored claim still holds. The checker proves the claims for the
// scene stored in the file (FORMAT.md: comparing it with your own scene is yours to do).
struct StillTrue {
    std::regex re;
    std::string why;
    bool query_only;
};
const std::vector<StillTrue> kStillTrue = {
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
bool g_judgements = false;
bool engine_judges_the_same(const std::string& text) {
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
bool g_compound = false;
bool engine_finds_the_same_region(const std::string& text) {
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

bool g_query = false;  // mutating a query answer (vs a partition)

// Vertices of P1 and P2 that carry a weight in some combination (witnesses, seed weights),
// collected from the unmutated file. Moving any other vertex leaves every claim true unless the
// moved point becomes a maximiser of a piece's normal, or a named maximiser stops being one: the
// checker recomputes every support value from all vertices, and then it must reject.
std::set<std::pair<int, long>> g_named;
void collect_named(const OJ& node, bool in_scene) {
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
bool moves_an_unnamed_vertex(const std::string& key) {
    std::smatch m;
    static const std::regex re("numerator \\+ 1 at /scene/P([12])/vertices/([0-9]+)/[0-2]");
    return std::regex_match(key, m, re) && !g_named.count({std::stoi(m[1]), std::stol(m[2])});
}

// The checker's verdict on a text: 1 (invalid) is a rejection; 2 (unreadable) is one too for the
// attacks that make the text non-strict JSON (a duplicated key).
void try_text(const std::string& text, const std::string& path, const std::string& what, Tally& t, int expected = 1) {
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
void try_mutation(const OJ& j, const std::string& path, const std::string& what, Tally& t) {
    try_text(j.dump(1), path, what, t);
}

bool is_exact(const std::string& s) { return std::regex_match(s, std::regex("-?[0-9]+(/[0-9]+)?")); }

void mutate_all(const OJ& root, const OJ& node, const OJ::json_pointer& ptr, Tally& t) {
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

void report(const std::string& name, const Tally& t) {
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
void mutate_and_report(const OJ& j, const std::string& name, bool query, bool judgements = false,
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
}  // namespace

BOOST_AUTO_TEST_CASE(bundled_certificates_are_valid) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(fs::path(SCALECERT_SOURCE_DIR) / "certificates"))
        if (e.path().string().size() > 15 &&
            e.path().string().rfind(".partition.json") == e.path().string().size() - 15) {
            BOOST_TEST(check_file(e.path()) == 0, e.path());
            ++n;
        }
    BOOST_TEST(n >= 4);
}

BOOST_AUTO_TEST_CASE(tampered_partitions_are_rejected) {
    for (const char* name : {"stacked_cubes", "tetra_box_switch", "fig5_vf_ve_ee", "roof_nearly_equal_slopes"}) {
        fs::path p = fs::path(SCALECERT_SOURCE_DIR) / "certificates" / (std::string(name) + ".partition.json");
        mutate_and_report(load(p), name, false);
    }
}

BOOST_AUTO_TEST_CASE(tampered_query_answers_are_rejected) {
    fs::path scene = fs::path(SCALECERT_SOURCE_DIR) / "certificates/scenes/tetra_box_switch.json";
    // separated, touching (on the (E,E) piece, derived by hand in test_hand_curves) and overlapping
    for (const char* q : {"1 1", "3/2 12/7", "2 2"}) {
        fs::path out = tmpdir() / "q.json";
        BOOST_TEST_REQUIRE(engine("query " + scene.string() + " " + q + " --json --out " + out.string()) == 0);
        BOOST_TEST_REQUIRE(check_file(out) == 0);
        const OJ j = load(out);
        mutate_and_report(j, std::string("query ") + q + " (" + j["verdict"].get<std::string>() + ")", true);
    }
}

// certify-fp --certificate: claims of every certified kind, right and wrong, derived by hand.
// Stacked cubes ([0,2]^3 below [0,2]^2 x [3,5], seeds the centres): P1(r1) reaches z = 1 + r1,
// P2(r2) starts at z = 4 − r2; they touch on r1 + r2 = 3, growth distance 3/2; at (1, 1/2) the
// gap is 3.5 − 2 = 3/2; at (2, 2) they overlap by 1 in z (depth 1 along z). The tetrahedron and
// box (tetra_box_switch): (1, 1) separated, (3/2, 12/7) touching, (2, 2) overlapping
// (test_hand_curves).
const char* kCubeClaims = R"({"format": "scalecert-claims-1", "claims": [
  {"kind": "verdict", "rho1": 1, "rho2": "1.5", "verdict": "separated"},
  {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "separated"},
  {"kind": "verdict", "rho1": "3/2", "rho2": "3/2", "verdict": "touching"},
  {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "intersecting"},
  {"kind": "curve", "vertices": [[1, 2], [2, 1]]},
  {"kind": "growth_distance", "value": 1.5},
  {"kind": "growth_distance", "value": 1.25},
  {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0.1, 0, 1], "offset": 2.6},
  {"kind": "separating_plane", "rho1": 2, "rho2": 1, "normal": [0, 0, 1]},
  {"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [1, 1, 2.5]},
  {"kind": "witness_point", "rho1": 1, "rho2": 1.5, "point": [1, 1, 2.5]},
  {"kind": "witness_point", "rho1": 3, "rho2": 3, "point": [0, 0, 2]},
  {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5, "closest": [[1, 1, 2], [1, 1, 3.5]]},
  {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5, "closest": [[1, 1, 2], [1, 1.5, 3.5]]},
  {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.25},
  {"kind": "distance", "rho1": 2, "rho2": 2, "value": 0},
  {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": 1, "direction": [0, 0, 1]},
  {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": 1, "direction": [0, 1, 1]},
  {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": 0.5},
  {"kind": "penetration_depth", "rho1": 1.5, "rho2": 1.5, "value": 0},
  {"kind": "penetration_depth", "rho1": 1, "rho2": 1, "value": 0}]})";
// right or wrong, claim by claim, by hand: the closest points (1, 1.5, 3.5) are not both at the
// distance (|(0, 1/2, 3/2)|² = 5/2 > 9/4); the depth along (0, 1, 1) is h_M/√2 = (6 − 1)/√2 > 1,
// as P1(2) = [−1, 3]^3 reaches y + z = 6 and P2(2) = [−1, 3]^2 x [2, 6] starts at y + z = 1;
// (0, 0, 2) is in P1(3) = [−2, 4]^3 and P2(3) = [−2, 4]^2 x [1, 7].
const std::vector<bool> kCubeRight = {true,  false, true,  true,  /* the curve ρ1 + ρ2 = 3 */ true,
                                      true,  false, true,  false, true,
                                      false, true,  true,  false, false,
                                      true,  true,  false, false, true,
                                      false};

BOOST_AUTO_TEST_CASE(judgements_certificates_are_valid_and_tampering_is_rejected) {
    const fs::path claims = tmpdir() / "cube_claims.json", cert = tmpdir() / "judgements.json",
                   rep = tmpdir() / "report.json";
    { std::ofstream(claims) << kCubeClaims; }
    const std::string cubes = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json";
    BOOST_TEST_REQUIRE(engine("certify-fp " + cubes + " " + claims.string() + " --json --out " + rep.string() +
                              " --certificate " + cert.string()) == 1);
    BOOST_TEST_REQUIRE(check_file(cert) == 0);
    const OJ j = load(cert), r = load(rep);
    BOOST_TEST(j["kind"] == "judgements");
    BOOST_TEST(j["judgements"].size() == 21u);
    std::vector<bool> rights;
    for (const OJ& e : j["judgements"]) {
        rights.push_back(e["right"].get<bool>());
        BOOST_TEST(r["claims"][e["index"].get<size_t>()]["right"] == e["right"]);  // the report says the same
    }
    BOOST_TEST(rights == kCubeRight, [&] {
        std::string t;
        for (bool b : rights) t += b ? '1' : '0';
        return t;
    }());
    // The depth at (2, 2) is 1: its proof's direction is +z and its surface closes around the origin.
    BOOST_TEST(j["judgements"][16]["proof"]["squared"] == "1");
    BOOST_TEST(j["judgements"][16]["proof"]["direction"] == OJ::parse(R"(["0", "0", "1"])"));
    // The curve ρ1 + ρ2 = 3 (one piece, no switch point): proved over a window around [1, 2].
    BOOST_TEST(j["judgements"][4]["proof"]["pieces"].size() == 1u);
    BOOST_TEST(j["judgements"][4]["proof"]["pieces"][0]["slope"] == "-1");
    mutate_and_report(j, "judgements (stacked cubes)", false, true);

    // The tetrahedron and the box: verdicts of all three kinds, and a depth and a distance whose
    // proofs come from facets that are not axis-aligned.
    const fs::path tclaims = tmpdir() / "tetra_claims.json", tcert = tmpdir() / "tetra_judgements.json";
    {
        std::ofstream(tclaims) << R"({"format": "scalecert-claims-1", "claims": [
      {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated"},
      {"kind": "verdict", "rho1": "3/2", "rho2": "12/7", "verdict": "touching"},
      {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "overlapping"},
      {"kind": "distance", "rho1": 1, "rho2": 1, "value": 0.1},
      {"kind": "penetration_depth", "rho1": 2.5, "rho2": 2.5, "value": 0.1},
      {"kind": "growth_distance", "value": 1.6},
      {"kind": "switch_point", "rho1": 1, "rho2": 2, "contact": "VE"},
      {"kind": "switch_point", "rho1": 1, "rho2": 2, "contact": "EE"},
      {"kind": "switch_point", "rho1": "1/2", "rho2": 2},
      {"kind": "curve", "pieces": [
        {"rho1": ["1/2", 1], "slope": "-5/2", "intercept": "9/2", "contact": "VF"},
        {"rho1": [1, "3/2"], "slope": "-4/7", "intercept": "18/7", "contact": "EE"}]},
      {"kind": "curve", "vertices": [["1/2", "13/4"], ["3/2", "12/7"]], "switch_points": []},
      {"kind": "curve", "vertices": [[1, 2], ["3/2", "12/7"]]}]})";
    }
    const std::string tetra = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/tetra_box_switch.json";
    BOOST_TEST_REQUIRE(engine("certify-fp " + tetra + " " + tclaims.string() + " --certificate " + tcert.string()) ==
                       1);
    BOOST_TEST_REQUIRE(check_file(tcert) == 0);
    const OJ t = load(tcert);
    BOOST_TEST(t["judgements"][0]["right"] == true);
    BOOST_TEST(t["judgements"][1]["right"] == true);
    BOOST_TEST(t["judgements"][2]["right"] == true);
    // Its curve (test_claims.cpp, curve_claim_rules): (V,F) ρ2 = 9/2 − 5ρ1/2 up to the switch point
    // (1, 2), of contact VE, then (E,E) ρ2 = (18 − 4ρ1)/7. The chord from ρ1 = 1/2 to 3/2 is off at
    // ρ1 = 1 and misses the switch point; a switch point claimed at ρ1 = 1/2 has the wrong ρ1.
    const std::vector<bool> tetra_right = {true, false, false, true, false, true};  // claims 6 to 11
    for (size_t k = 0; k < tetra_right.size(); ++k)
        BOOST_TEST(t["judgements"][6 + k]["right"] == tetra_right[k], 6 + k);
    BOOST_TEST(t["judgements"][6]["proof"]["switch_points"].size() == 1u);
    BOOST_TEST(t["judgements"][6]["proof"]["switch_points"][0]["rho1"] == "1");
    mutate_and_report(t, "judgements (tetrahedron and box)", false, true);
}

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

// ---- forgeries, each written by hand --------------------------------------------------------
namespace {
OJ bundled(const std::string& name) {
    return load(fs::path(SCALECERT_SOURCE_DIR) / "certificates" / (name + ".partition.json"));
}
int verdict_of(const std::string& text) {
    std::string msg;
    return scalecert_check::check_text(text, msg);
}
int verdict_of(const OJ& j) { return verdict_of(j.dump(1)); }
// The engine's partition certificate of a scene in tests/data, accepted by the checker.
OJ fresh_partition(const std::string& data_scene) {
    const fs::path scene = fs::path(SCALECERT_SOURCE_DIR) / "tests/data" / data_scene;
    const fs::path cert = tmpdir() / (data_scene + ".partition.json");
    BOOST_TEST_REQUIRE(engine("partition " + scene.string() + " --out " + cert.string()) == 0);
    OJ j = load(cert);
    BOOST_TEST_REQUIRE(verdict_of(j) == 0);
    return j;
}
}  // namespace

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

BOOST_AUTO_TEST_CASE(switch_contact_labels_are_recomputed_from_all_maximisers) {
    // tetra_box_switch: P1's vertex 0 touches the middle of P2's edge {5, 7} at (1, 2), a (V,E)
    // contact (derived by hand in test_hand_curves). Listing one end of the edge does not make
    // it (V,V); listing a vertex that is not on the contact is refused; the true label passes.
    OJ j = bundled("tetra_box_switch");
    OJ& sp = j["switch_points"][0];
    BOOST_TEST_REQUIRE(sp["contact"] == "VE");
    OJ vv = j;
    vv["switch_points"][0]["contact"] = "VV";
    vv["switch_points"][0]["features"]["P2"] = OJ::array({5});
    BOOST_TEST(verdict_of(vv) == 1);
    OJ sub = j;
    sub["switch_points"][0]["features"]["P2"] = OJ::array({5});  // a subset with the true label: still true
    BOOST_TEST(verdict_of(sub) == 0);
    OJ off = j;
    off["switch_points"][0]["features"]["P2"] = OJ::array({4});  // on the (V,F) face, not on the contact
    BOOST_TEST(verdict_of(off) == 1);
    OJ ee = j;
    ee["switch_points"][0]["contact"] = "EE";
    ee["switch_points"][0]["features"]["P1"] = OJ::array({0, 1});
    BOOST_TEST(verdict_of(ee) == 1);
}

BOOST_AUTO_TEST_CASE(piece_contacts_where_normals_share_a_line_are_proved_minimal) {
    // Cubes [0,2]^3 and [2,4]×[2,4]×[0,2] (tests/data/cubes_sharing_an_edge.json) touch along the
    // edge {x = y = 2} on the line ρ2 = 2 − ρ1, given by the normals (1,0,0) and (0,1,0) alike:
    // each plane alone supports a face (FF), the contact is EE (derived in test_hand_curves).
    OJ j = fresh_partition("cubes_sharing_an_edge.json");
    OJ& p = j["pieces"][0];
    BOOST_TEST_REQUIRE(p["contact"] == "EE");
    BOOST_TEST_REQUIRE(p["same_line_normals"].size() == 1u);
    // The old label, one normal's faces, with that normal's maximisers and no other normal: no
    // witness can lie inside both faces, so the file's own witness (on the edge) is refused.
    OJ ff = j;
    const OJ face1 = OJ::array({4, 5, 6, 7}), face2 = OJ::array({0, 1, 2, 3});
    const bool x_first = p["normal"] == OJ::array({"1", "0", "0"});
    ff["pieces"][0]["contact"] = "FF";
    ff["pieces"][0]["features"]["P1"] = x_first ? face1 : OJ::array({2, 3, 6, 7});
    ff["pieces"][0]["features"]["P2"] = x_first ? face2 : OJ::array({0, 1, 4, 5});
    ff["pieces"][0].erase("same_line_normals");
    BOOST_TEST(verdict_of(ff) == 1);
    // Leaving the other normal out alone, or keeping it and claiming FF, or listing part of the
    // edge, or a null contact: each refused.
    OJ drop = j;
    drop["pieces"][0].erase("same_line_normals");
    BOOST_TEST(verdict_of(drop) == 1);
    OJ lie = j;
    lie["pieces"][0]["contact"] = "FF";
    BOOST_TEST(verdict_of(lie) == 1);
    OJ part = j;
    part["pieces"][0]["features"]["P1"] = OJ::array({7});
    BOOST_TEST(verdict_of(part) == 1);
    OJ none = j;
    none["pieces"][0]["contact"] = nullptr;
    BOOST_TEST(verdict_of(none) == 1);
    // And every mutation of the whole file, as for the bundled ones.
    mutate_and_report(j, "cubes_sharing_an_edge", false);
}

BOOST_AUTO_TEST_CASE(pieces_below_I2_are_proved_down_to_rho2_zero) {
    // A forged curve below I2. The tetrahedron-and-box scene with P1 and P2 swapped (tests/
    // data/tetra_on_box_curve_below_I2.json), I1 = [1/2, 10], I2 = [3/2, 4]. Swapping ρ1 and ρ2 in
    // test_hand_curves' derivation: (V,F) becomes (F,V) ρ2 = 9/5 − 2ρ1/5 for ρ1 ≥ 2, (E,E) becomes
    // ρ2 = (18 − 7ρ1)/4 on [18/13, 2], switching at (2, 1) — below lo2, where no overlap witness
    // reaches. The last piece reaches ρ2 = 0 at ρ1 = 9/2, where the seed (0,0,9/2) of the
    // tetrahedron lies on the top face z = 9/2 of the box scaled by 9/2: its zero witness.
    OJ j = fresh_partition("tetra_on_box_curve_below_I2.json");
    BOOST_TEST_REQUIRE(j["pieces"].size() == 3u);
    BOOST_TEST(j["pieces"][2]["contact"] == "FV");
    BOOST_TEST(j["pieces"][2]["intercept"] == "9/5");
    BOOST_TEST(j["switch_points"][1]["rho1"] == "2");
    BOOST_TEST(j["switch_points"][1]["rho2"] == "1");
    BOOST_TEST(!j["pieces"][1].contains("zero_witness"));
    const OJ& z = j["pieces"][2]["zero_witness"];
    BOOST_TEST(z["rho1"] == "9/2");
    BOOST_TEST(z["rho2"] == "0");
    BOOST_TEST((z["point"] == OJ::array({"0", "0", "9/2"})));
    // The forgery: the (E,E) piece stretched over [18/13, 10], hiding the switch point (2, 1) and
    // the (F,V) piece; accepted before, as the curve below lo2 was witnessed nowhere.
    OJ f = j;
    f["pieces"][1]["rho1"] = OJ::array({"18/13", "10"});
    f["pieces"][1]["rho1_double"] = OJ::array({18.0 / 13, 10.0});
    f["pieces"].erase(2);
    f["switch_points"].erase(1);
    f["curve_ends"][1] = OJ{{"rho1", "10"}, {"rho1_double", 10.0}, {"rho2", "-13"}, {"rho2_double", -13.0}};
    OJ sep = OJ::array();
    for (const auto& r : f["regions"]["separated"])
        if (r["piece"] != 2) sep.push_back(r);
    f["regions"]["separated"] = sep;
    BOOST_TEST(verdict_of(f) == 1);
    f["pieces"][1]["zero_witness"] = z;  // the true zero witness is not on this line
    BOOST_TEST(verdict_of(f) == 1);
    // A zero witness where ρ2 stays > 0, or none where it falls to 0: refused.
    OJ extra = j;
    extra["pieces"][1]["zero_witness"] = z;
    BOOST_TEST(verdict_of(extra) == 1);
    OJ none = j;
    none["pieces"][2].erase("zero_witness");
    BOOST_TEST(verdict_of(none) == 1);
}

BOOST_AUTO_TEST_CASE(a_curve_below_zero_at_lo1_is_anchored_by_a_witness) {
    // A curve <= 0 at lo1: the pieces must still be pinned, or any normal's line could be claimed
    // there. Cubes [-1,1]^3 and [1,3]×[-1,1]^2 (seeds at their
    // centres, d = (2,0,0)) touch on x = 1 + ρ1 = 3 − ρ2: the curve is ρ2 = 2 − ρ1, at or below 0
    // on I1 = [3, 4]. The witness at (3, 0) is P2's seed (2,0,0), inside P1(3) = [−3,3]^3.
    OJ j = fresh_partition("cubes_side_by_side_curve_below_zero.json");
    BOOST_TEST(j["curve_ends"][0]["rho2"] == "-1");
    BOOST_TEST(j["curve_ends"][0]["witness"]["rho2"] == "0");
    BOOST_TEST((j["curve_ends"][0]["witness"]["point"] == OJ::array({"2", "0", "0"})));
    BOOST_TEST(!j["curve_ends"][1].contains("witness"));
    // The forgery: another normal's line, (−1,0,0) pointing away from P2 (ρ2 = −2 − ρ1), and no
    // witness; refused. With the witness kept, the line's end no longer meets it: refused too.
    OJ f = j;
    f["pieces"][0]["normal"] = OJ::array({"-1", "0", "0"});
    f["pieces"][0]["intercept"] = "-2";
    f["pieces"][0]["intercept_double"] = -2.0;
    f["curve_ends"][0]["rho2"] = "-5";
    f["curve_ends"][0]["rho2_double"] = -5.0;
    f["curve_ends"][1]["rho2"] = "-6";
    f["curve_ends"][1]["rho2_double"] = -6.0;
    BOOST_TEST(verdict_of(f) == 1);
    f["curve_ends"][0].erase("witness");
    BOOST_TEST(verdict_of(f) == 1);
}

BOOST_AUTO_TEST_CASE(below_rho2_zero_the_curve_is_one_line) {
    // tests/data/boxes_curve_goes_on_below_zero.json, derived in test_hand_curves: the curve is
    // ρ2 = 3 − ρ1 (normal (1,0,0)) on I1 = [1, 6], reaching 0 at ρ1 = 3; the line of normal (0,1,0),
    // ρ2 = (1 − ρ1)/2, overtakes it at (5, −2), below ρ2 = 0. The engine once wrote that switch;
    // the curve now goes on as one line there, and a certificate with a switch below 0 is refused.
    OJ j = fresh_partition("boxes_curve_goes_on_below_zero.json");
    BOOST_TEST_REQUIRE(j["pieces"].size() == 1u);
    BOOST_TEST(j["switch_points"].empty());
    BOOST_TEST(j["pieces"][0]["intercept"] == "3");
    BOOST_TEST(j["pieces"][0]["zero_witness"]["rho1"] == "3");
    OJ f = j;
    f["pieces"][0]["rho1"] = OJ::array({"1", "5"});
    f["pieces"][0]["rho1_double"] = OJ::array({1.0, 5.0});
    OJ q = OJ::object();
    q["rho1"] = OJ::array({"5", "6"});
    q["rho1_double"] = OJ::array({5.0, 6.0});
    q["slope"] = "-1/2", q["slope_double"] = -0.5, q["intercept"] = "1/2", q["intercept_double"] = 0.5;
    q["contact"] = nullptr;
    q["closed_form"] = j["pieces"][0]["closed_form"];
    q["normal"] = OJ::array({"0", "1", "0"});
    q["h1"] = "1", q["h1_double"] = 1.0, q["h2"] = "2", q["h2_double"] = 2.0;
    q["support_vertices"] = OJ{{"P1", 2}, {"P2", 0}};
    f["pieces"].push_back(q);
    f["switch_points"].push_back(
        OJ{{"rho1", "5"}, {"rho1_double", 5.0}, {"rho2", "-2"}, {"rho2_double", -2.0}, {"contact", nullptr}});
    f["curve_ends"][1]["rho2"] = "-5/2";
    f["curve_ends"][1]["rho2_double"] = -2.5;
    BOOST_TEST(verdict_of(f) == 1);
    std::string msg;
    scalecert_check::check_text(f.dump(1), msg);
    BOOST_TEST(msg.find("from rho2 = 0 on, the curve goes on as one line") != std::string::npos, msg);
}

namespace {
// A scene file with crossed n-gon prisms (scalecert-bench's family) or two near-spheres of n points.
fs::path write_off(const std::string& name, const std::vector<std::array<long, 3>>& pts) {
    const fs::path p = tmpdir() / name;
    std::ofstream o(p);
    o << "OFF\n" << pts.size() << " 0 0\n";
    for (const auto& v : pts) o << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
    return p;
}
std::string crossed_prisms(int n) {
    const auto P = test::crossed_prisms(n);
    const std::string tag = "prism" + std::to_string(n);
    return "--p1 " + write_off(tag + "a.off", P[0]).string() + " --p2 " + write_off(tag + "b.off", P[1]).string() +
           " --i1 1/2,2 --i2 1/2,2";
}
std::string near_spheres(int n) {
    std::mt19937 g(7);
    std::normal_distribution<double> N(0, 1);
    std::vector<std::array<long, 3>> pts[2];
    const long R = 1000000;
    for (int i = 0; i < 2; ++i)
        for (int k = 0; k < n; ++k) {
            const double x = N(g), y = N(g), z = N(g), l = std::sqrt(x * x + y * y + z * z);
            pts[i].push_back(
                {std::lround(R * x / l) + 3 * R * i, std::lround(R * y / l) + R / 10 * i, std::lround(R * z / l)});
        }
    const std::string tag = "sphere" + std::to_string(n);
    return "--p1 " + write_off(tag + "a.off", pts[0]).string() + " --p2 " + write_off(tag + "b.off", pts[1]).string() +
           " --i1 1/2,2 --i2 1/2,2";
}
OJ run_json(const std::string& args) {
    const fs::path out = tmpdir() / "walk.json";
    fs::remove(out);
    BOOST_TEST_REQUIRE(engine(args + " --out " + out.string()) == 0, args);
    return load(out);
}
}  // namespace

BOOST_AUTO_TEST_CASE(the_walks_partitions_and_query_answers_pass_the_checker) {
    // The walk (no hull) writes partitions and query answers from its support sets: witnesses
    // over the features it walked, seed weights over a few extreme points, and overlap witnesses
    // lifted from the curve point below (query.hpp, lift_witness). Each must pass the checker, give
    // the hull path's regions and verdicts, and hold the same scene.
    const std::string boxes =
        (fs::path(SCALECERT_SOURCE_DIR) / "tests/data/boxes_curve_goes_on_below_zero.json").string();
    const std::string cubes_below =
        (fs::path(SCALECERT_SOURCE_DIR) / "tests/data/cubes_side_by_side_curve_below_zero.json").string();
    for (const std::string& scene : {boxes, cubes_below, crossed_prisms(8), crossed_prisms(40), near_spheres(300)}) {
        const OJ w = run_json("partition " + scene + " --engine scan");
        const OJ h = run_json("partition " + scene + " --engine hull");
        BOOST_TEST_REQUIRE(w["model"]["engine"] == "scan", scene);
        BOOST_TEST(verdict_of(w) == 0, scene);
        BOOST_TEST(w["scene"] == h["scene"]);
        BOOST_TEST(w["pieces"].size() == h["pieces"].size());
        BOOST_TEST(w["regions"]["overlap"]["vertices"] == h["regions"]["overlap"]["vertices"]);
        BOOST_TEST(w["growth_distance"] == h["growth_distance"]);
        // Queries: on the curve at each overlap vertex and piece end, 1/1000 below and above, and
        // far above (the ray from the origin may meet the curve left of the walk: the hull answers).
        std::vector<std::array<mpq_class, 2>> pairs;
        for (const auto& v : w["regions"]["overlap"]["vertices"])
            pairs.push_back({mpq_class(v[0].get<std::string>()), mpq_class(v[1].get<std::string>())});
        for (const auto& e : w["curve_ends"]) {
            const mpq_class x(e["rho1"].get<std::string>()), y(e["rho2"].get<std::string>());
            for (const mpq_class& dy : {mpq_class(0), mpq_class(-1, 1000), mpq_class(1, 1000)})
                if (sgn(y + dy) > 0) pairs.push_back({x, y + dy});
        }
        pairs.push_back({mpq_class(1, 2), mpq_class(1000)});
        for (const auto& [x, y] : pairs) {
            const std::string q = "query " + scene + " " + x.get_str() + " " + y.get_str() + " --json --engine ";
            const OJ a = run_json(q + "scan"), b = run_json(q + "hull");
            BOOST_TEST(verdict_of(a) == 0, q);
            BOOST_TEST(a["verdict"] == b["verdict"], q);
        }
    }
    // By hand (test_hand_curves): the curve 3 − ρ1 reaches 0 at ρ1 = 3, where P2's seed (3, 1, 0)
    // lies on P1(3). The overlap vertices (6, 1) and (6, 2) lie above the curve's negative part:
    // their witnesses are that seed, lifted.
    const OJ w = run_json("partition " + boxes + " --engine scan");
    const OJ& ov = w["regions"]["overlap"];
    BOOST_TEST_REQUIRE(ov["vertices"].size() == 4u);
    BOOST_TEST((ov["vertices"][0] == OJ::array({"2", "1"})));
    for (int k : {1, 2}) {
        BOOST_TEST(ov["vertices"][k][0] == "6");
        BOOST_TEST((ov["witnesses"][k]["point"] == OJ::array({"3", "1", "0"})));
    }
    // The walk's certificate under the structural mutations.
    mutate_and_report(w, "walk partition (boxes)", false);
}

BOOST_AUTO_TEST_CASE(where_the_envelope_turns_at_zero_the_piece_reaching_it_goes_on) {
    // tests/data/boxes_curve_turns_at_zero.json: P1 = [−1,1]^3, P2 = [2,4] × [1,5] × [−1,1] (seeds
    // at the centres, d = (3,3,0)). n = (1,0,0): h1 = h2 = 1, n·d = 3, ρ2 = 3 − ρ1; n = (0,1,0):
    // h1 = 1, h2 = 2, n·d = 3, ρ2 = (3 − ρ1)/2. Both reach 0 at ρ1 = 3, where the envelope turns.
    // The curve is the piece reaching 0, 3 − ρ1 (pinned by its contact and zero witnesses), on all
    // of I1 = [1, 6]; the next line would be pinned by nothing (a forgery could swap it for
    // (1,1,0)'s), so a switch at ρ2 = 0 is refused.
    OJ j = fresh_partition("boxes_curve_turns_at_zero.json");
    BOOST_TEST_REQUIRE(j["pieces"].size() == 1u);
    BOOST_TEST(j["pieces"][0]["intercept"] == "3");
    BOOST_TEST(j["switch_points"].empty());
    BOOST_TEST(j["pieces"][0]["zero_witness"]["rho1"] == "3");
    OJ f = j;
    f["pieces"][0]["rho1"] = OJ::array({"1", "3"});
    f["pieces"][0]["rho1_double"] = OJ::array({1.0, 3.0});
    OJ q = OJ::object();
    q["rho1"] = OJ::array({"3", "6"});
    q["rho1_double"] = OJ::array({3.0, 6.0});
    q["slope"] = "-1/2", q["slope_double"] = -0.5, q["intercept"] = "3/2", q["intercept_double"] = 1.5;
    q["contact"] = nullptr;
    q["closed_form"] = j["pieces"][0]["closed_form"];
    q["normal"] = OJ::array({"0", "1", "0"});
    q["h1"] = "1", q["h1_double"] = 1.0, q["h2"] = "2", q["h2_double"] = 2.0;
    q["support_vertices"] = OJ{{"P1", 2}, {"P2", 0}};
    f["pieces"].push_back(q);
    f["switch_points"].push_back(
        OJ{{"rho1", "3"}, {"rho1_double", 3.0}, {"rho2", "0"}, {"rho2_double", 0.0}, {"contact", nullptr}});
    f["curve_ends"][1]["rho2"] = "-3/2";
    f["curve_ends"][1]["rho2_double"] = -1.5;
    std::string msg;
    BOOST_TEST(scalecert_check::check_text(f.dump(1), msg) == 1);
    BOOST_TEST(msg.find("from rho2 = 0 on, the curve goes on as one line") != std::string::npos, msg);
}

BOOST_AUTO_TEST_CASE(a_single_rho1_at_a_switch_point_is_refused_by_partition) {
    // I1 = [18/13, 18/13], the switch point of the tetrahedron-on-box scene
    // (tests/data/tetra_on_box_curve_below_I2.json, derived there): a piece of no length has no
    // contact of its own; the engine refuses the range (exit 2), it does not stop with exit 3.
    OJ sc = load(fs::path(SCALECERT_SOURCE_DIR) / "tests/data/tetra_on_box_curve_below_I2.json");
    sc["I1"] = OJ::array({"18/13", "18/13"});
    const fs::path p = tmpdir() / "single_rho1_at_switch.json";
    save(sc, p);
    for (const char* e : {"hull", "scan"})
        BOOST_TEST(engine("partition " + p.string() + " --engine " + e + " --out " + (tmpdir() / "x.json").string()) ==
                   2);
    BOOST_TEST(engine("curve " + p.string() + " --out " + (tmpdir() / "x.json").string()) == 0);
    sc["I1"] = OJ::array({"18/13", "2"});  // a range from the switch point on: fine
    save(sc, p);
    BOOST_TEST(engine("partition " + p.string() + " --out " + (tmpdir() / "x.json").string()) == 0);
    BOOST_TEST(check_file(tmpdir() / "x.json") == 0);
}

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

BOOST_AUTO_TEST_CASE(same_line_normals_are_few_and_each_shrinks_the_features) {
    // Cubes sharing an edge: (1,0,0) and (0,1,0) give the line; (1,1,0) and (2,1,0), in their
    // normal cone, give it too, but add nothing once the edge is reached. Listing the same normal
    // again, or the piece's own normal, or five, made the checker scan every vertex for each
    // (30,000 repeats of one normal in an 845 KB file would take 496 s).
    OJ j = fresh_partition("cubes_sharing_an_edge.json");
    const OJ other = j["pieces"][0]["same_line_normals"][0];
    OJ twice = j;
    twice["pieces"][0]["same_line_normals"].push_back(other);
    BOOST_TEST(verdict_of(twice) == 1);
    OJ own = j;
    own["pieces"][0]["same_line_normals"].push_back(j["pieces"][0]["normal"]);
    BOOST_TEST(verdict_of(own) == 1);
    OJ cone = j;
    cone["pieces"][0]["same_line_normals"] =
        OJ::array({OJ::array({"1", "1", "0"})});  // shrinks the face to the edge itself
    BOOST_TEST(verdict_of(cone) == 0);
    cone["pieces"][0]["same_line_normals"].push_back(OJ::array({"2", "1", "0"}));  // shrinks nothing more
    BOOST_TEST(verdict_of(cone) == 1);
    OJ five = j;
    for (int k = 0; k < 4; ++k)
        five["pieces"][0]["same_line_normals"].push_back(OJ::array({"1", std::to_string(k + 2), "0"}));
    BOOST_TEST(verdict_of(five) == 1);
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

BOOST_AUTO_TEST_CASE(doubles_beyond_the_double_range_are_null) {
    // A vertex at 10^400: its nearest double would be infinite; the engine writes null there and
    // the checker accepts null exactly then (FORMAT.md "Numbers").
    fs::path sp = tmpdir() / "far.json", cp = tmpdir() / "far.cert.json", qp = tmpdir() / "far.q.json";
    std::ofstream(sp) << R"({"P1": {"vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,"1e400"]]},
        "P2": {"vertices": [[5,0,0],[6,0,0],[5,1,0],[5,0,1]]}, "I1": [1,2], "I2": [1,2]})";
    BOOST_TEST_REQUIRE(engine("partition " + sp.string() + " --out " + cp.string()) == 0);
    BOOST_TEST(check_file(cp) == 0);
    std::string text = test::slurp(cp);
    BOOST_TEST(text.find("null") != std::string::npos);
    BOOST_TEST_REQUIRE(engine("query --json " + sp.string() + " 1e4000 2 --numbers exact --out " + qp.string()) == 0);
    BOOST_TEST(check_file(qp) == 0);
    OJ q = load(qp);
    BOOST_TEST(q["rho1_double"].is_null());
    q["rho1_double"] = 1.7976931348623157e308;  // the largest double is not the nearest: refused
    BOOST_TEST(verdict_of(q) == 1);
    OJ r = load(qp);
    r["rho2_double"] = nullptr;  // null for a value in range: refused
    BOOST_TEST(verdict_of(r) == 1);
    // Hand-derived neighbours of the overflow threshold 2^1024 - 2^970 (halfway between the
    // largest double and 2^1024, which rounds to even: infinity).
    using scalecert_check::nearest;
    using scalecert_check::Q;
    const mpz_class two1024 = mpz_class(1) << 1024, half = mpz_class(1) << 970;
    BOOST_TEST(std::isinf(nearest(Q(two1024 - half))));
    BOOST_TEST(nearest(Q(two1024 - half - 1)) == 1.7976931348623157e308);
    BOOST_TEST(std::isinf(nearest(Q(-two1024))));
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

BOOST_AUTO_TEST_CASE(numbers_every_judgement_uses_are_counted_at_each_use) {
    // A tolerance of 10^6 digits with 1,000 distance judgements (1.2 MB), and seeds of 2·10^5
    // digits with plane judgements: the arithmetic on a number stored once is counted per use
    // (uncounted, 29 s and 19 ms a judgement). Both are refused at the work limit, at once.
    const fs::path claims = tmpdir() / "one_distance.json", cert = tmpdir() / "one_distance.cert.json";
    std::ofstream(claims)
        << R"({"format": "scalecert-claims-1", "claims": [{"kind": "distance", "rho1": 1, "rho2": "1/2", )"
           R"("value": 1.5}]})";
    const std::string cubes = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json";
    BOOST_TEST_REQUIRE(engine("certify-fp " + cubes + " " + claims.string() + " --certificate " + cert.string()) == 0);
    OJ j = load(cert);
    BOOST_TEST_REQUIRE(check_file(cert) == 0);
    const OJ one = j["judgements"][0];
    j["judgements"] = OJ::array();
    for (int k = 0; k < 1000; ++k) {
        OJ e = one;
        e["index"] = k;
        j["judgements"].push_back(e);
    }
    j["tolerance"] = "1/1" + std::string(1000000, '0') + "1";
    std::string msg;
    const auto t0 = std::chrono::steady_clock::now();
    BOOST_TEST(scalecert_check::check_text(j.dump(), msg) == 2);
    BOOST_TEST(msg.find("work limit") != std::string::npos, msg);
    BOOST_TEST(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < 5.0);
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

// ---- the checker's linear stages against plain reimplementations ---------------------------------
// Support values and maximisers (integer scans in int64, __int128 or GMP integers), the overlap
// region (built from the verified pieces), polygon normalisation (one pass) and the work limit.
namespace {
namespace sc_ = scalecert_check;
using CQ = sc_::Q;
using CV = sc_::V3;

CQ cq(long p, long q) {
    CQ x(p, q);
    x.canonicalize();
    return x;
}
// A random integer in [0, m) (m > 0), from g's words.
mpz_class rz(std::mt19937_64& g, const mpz_class& m) {
    std::vector<uint64_t> w(mpz_sizeinbase(m.get_mpz_t(), 2) / 64 + 2);
    for (auto& x : w) x = g();
    mpz_class z;
    mpz_import(z.get_mpz_t(), w.size(), 1, sizeof(uint64_t), 0, 0, w.data());
    return z % m;
}
// A random rational p/q with |p| <= range and 1 <= q <= den_range, in lowest terms.
CQ rq(std::mt19937_64& g, const mpz_class& range, const mpz_class& den_range) {
    const mpz_class p = rz(g, 2 * range + 1) - range,
                    q = den_range > 1 ? mpz_class(rz(g, den_range) + 1) : mpz_class(1);
    CQ x(p, q);
    x.canonicalize();
    return x;
}
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

// The earlier O(n^2) normalisation and the clip by every line, kept here as references.
std::vector<sc_::P2> ref_normalize(std::vector<sc_::P2> p) {
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
std::vector<sc_::P2> ref_clip(const std::vector<sc_::P2>& p, const sc_::Line& L, bool above) {
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

BOOST_AUTO_TEST_CASE(overlap_region_equals_the_clip_by_every_line) {
    // Random convex, decreasing piecewise-linear curves over I1 (slopes increasing, neighbouring
    // lines meeting at the breakpoints) and random I2, including I2 ends through breakpoints, the
    // curve through a corner, rectangles without area, one piece and many: the region built from
    // the pieces equals the rectangle clipped by every line (the earlier O(K^2) method).
    std::mt19937_64 g(11);
    int cases = 0, empty = 0, points = 0, polygons = 0;
    for (int t = 0; t < 3000; ++t) {
        const size_t K = 1 + g() % (t % 10 == 0 ? 40 : 6);
        sc_::Scene sc;
        sc.lo[0] = cq(static_cast<long>(1 + g() % 4), static_cast<long>(1 + g() % 3));
        sc.hi[0] = t % 50 == 0 && K == 1
                       ? sc.lo[0]
                       : CQ(sc.lo[0] + cq(static_cast<long>(1 + g() % 9), static_cast<long>(1 + g() % 4)));
        std::vector<CQ> x{sc.lo[0]}, a;
        for (size_t k = 1; k < K; ++k)
            x.push_back(x.back() + cq(static_cast<long>(1 + g() % 5), static_cast<long>(1 + g() % 7)));
        const CQ stretch = (sc.hi[0] - sc.lo[0]) / (x.back() + 1 - sc.lo[0]);
        for (CQ& v : x) v = sc.lo[0] + (v - sc.lo[0]) * stretch;
        x.push_back(sc.hi[0]);
        for (size_t k = 0; k < K; ++k)
            a.push_back(-cq(static_cast<long>(1 + g() % 40), static_cast<long>(1 + g() % 5)));
        std::sort(a.begin(), a.end());
        a.erase(std::unique(a.begin(), a.end()), a.end());
        while (a.size() < K) a.push_back(a.back() / 2);  // still increasing and negative
        std::vector<sc_::Line> lines;
        std::vector<std::array<CQ, 2>> ranges;
        CQ y = rq(g, 20, 3) + 10;
        for (size_t k = 0; k < K; ++k) {
            lines.push_back({a[k], y - a[k] * x[k]});
            ranges.push_back({x[k], x[k + 1]});
            y = lines.back().at(x[k + 1]);
        }
        std::vector<CQ> ys;  // values the curve takes at breakpoints, and around them
        for (size_t k = 0; k <= K; ++k) ys.push_back(k < K ? lines[k].at(x[k]) : lines[K - 1].at(x[K]));
        auto pick = [&]() { return g() % 3 == 0 ? ys[g() % ys.size()] : ys[g() % ys.size()] + rq(g, 6, 4); };
        CQ lo2 = pick(), hi2 = pick();
        if (hi2 < lo2) std::swap(lo2, hi2);
        if (g() % 25 == 0) hi2 = lo2;
        if (sgn(lo2) <= 0) {
            hi2 += 1 - lo2;
            lo2 = 1;
        }
        sc.lo[1] = lo2;
        sc.hi[1] = hi2;
        const std::vector<sc_::P2> rect =
            sc_::normalize({{sc.lo[0], sc.lo[1]}, {sc.hi[0], sc.lo[1]}, {sc.hi[0], sc.hi[1]}, {sc.lo[0], sc.hi[1]}});
        BOOST_TEST(
            (rect ==
             ref_normalize({{sc.lo[0], sc.lo[1]}, {sc.hi[0], sc.lo[1]}, {sc.hi[0], sc.hi[1]}, {sc.lo[0], sc.hi[1]}})));
        std::vector<sc_::P2> want = rect;
        for (const sc_::Line& L : lines)
            if (!want.empty()) want = ref_clip(want, L, true);
        const std::vector<sc_::P2> got = sc_::overlap_region(sc, rect, lines, ranges);
        BOOST_TEST((got == want), "case " << t << ": " << got.size() << " vertices against " << want.size());
        ++cases;
        (want.empty() ? empty : want.size() < 3 ? points : polygons)++;
    }
    std::cout << "overlap regions compared: " << cases << " (" << empty << " empty, " << points
              << " of one or two points, " << polygons << " polygons)\n";
    BOOST_TEST(empty > 20);
    BOOST_TEST(points > 20);
    BOOST_TEST(polygons > 1000);
}

BOOST_AUTO_TEST_CASE(the_work_limit_and_the_denominator_limit_refuse_with_exit_2) {
    // Two square pyramids tip to tip: one piece. With 2,000 more vertices (copies of the seeds)
    // the file is valid; under a work limit lowered for the test it is refused with exit status 2,
    // at a point that depends on the file only (the same message every time). (Same-line normals,
    // which this test once multiplied, are at most four now, each one shrinking the features.)
    const fs::path scene = tmpdir() / "pyramids.json", cert = tmpdir() / "pyramids.partition.json";
    std::ofstream(scene)
        << R"({"P1": {"vertices": [[0,0,10],[10,10,-10],[10,-10,-10],[-10,10,-10],[-10,-10,-10]], "seed": [0,0,0]},
 "P2": {"vertices": [[0,0,20],[10,10,40],[10,-10,40],[-10,10,40],[-10,-10,40]], "seed": [0,0,30]}, "I1": ["1/2",
 2], "I2": ["1/2", 2]})";
    BOOST_TEST_REQUIRE(engine("partition " + scene.string() + " --out " + cert.string()) == 0);
    OJ j = load(cert);
    BOOST_TEST_REQUIRE(j["pieces"].size() == 1u);
    for (int k = 0; k < 1000; ++k) {
        j["scene"]["P1"]["vertices"].push_back(j["scene"]["P1"]["seed"]);
        j["scene"]["P2"]["vertices"].push_back(j["scene"]["P2"]["seed"]);
    }
    const std::string text = j.dump(1);
    std::string msg;
    scalecert_check::Context cx;
    BOOST_TEST(scalecert_check::check_text(text, msg, cx) == 0, msg);
    const double work = cx.work;
    BOOST_TEST(work > 2.0 * 1005);  // at least one normal scanned both polytopes
    scalecert_check::Context tight;
    tight.work_per_byte = 0.5 * work / static_cast<double>(text.size());
    tight.min_work = 0;
    std::string first, again;
    BOOST_TEST(scalecert_check::check_text(text, first, tight) == 2);
    BOOST_TEST(first.find("work limit") != std::string::npos, first);
    BOOST_TEST(scalecert_check::check_text(text, again, tight) == 2);
    BOOST_TEST(first == again);
    BOOST_TEST(scalecert_check::check_text(text, msg) == 0, msg);
    // A vertex whose denominator takes the polytope's common denominator past 2^16384 (the
    // engine's own limit): refused with exit status 2, before any scan.
    OJ big = bundled("tetra_box_switch");
    big["scene"]["P2"]["vertices"].push_back(OJ::array({"1/" + mpz_class(mpz_class(1) << 16384).get_str(), "0", "0"}));
    BOOST_TEST(verdict_of(big) == 2);
    OJ fits = bundled("tetra_box_switch");
    fits["scene"]["P2"]["vertices"].push_back(OJ::array({"1/" + mpz_class(mpz_class(1) << 16383).get_str(), "0", "0"}));
    BOOST_TEST(verdict_of(fits) == 0);  // a point inside the cube: every claim still holds
}

// ---- compound partitions --------------------------------------------------------------------

namespace {
fs::path data(const std::string& name) { return fs::path(SCALECERT_SOURCE_DIR) / "tests" / "data" / name; }
OJ compound_certificate(const fs::path& scene, const std::string& name) {
    const fs::path out = tmpdir() / (name + ".cert.json");
    BOOST_REQUIRE(engine("region " + scene.string() + " --certificate " + out.string()) == 0);
    BOOST_REQUIRE(check_file(out) == 0);
    return load(out);
}
int check_json(const OJ& j) {
    std::string msg;
    return scalecert_check::check_text(j.dump(1), msg);
}
// Three parts a side: two near each other and one far off along x, so that some pairs meet,
// some are apart in the rectangle and some are pruned (in a block).
fs::path mixed_compound() {
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
}  // namespace

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

BOOST_AUTO_TEST_CASE(a_switch_point_claim_is_right_when_any_exact_one_matches) {
    // The Fig. 5 scene's switch points (README): (23/19, 45/19) VE and (29/13, 18/13) EV. The
    // claim (7/4, 45/19, VE) is nearer in rho1 to the second (|7/4 − 29/13| = 11/52 against
    // |7/4 − 23/19| = 41/76), but matches the first within 0.45: |7/4 − 23/19|/(23/19) = 41/92 ≈
    // 0.4457 and rho2 exactly. Right at tolerance 0.45 (judged against the nearest in both
    // coordinates, not in rho1 alone), wrong at 0.44; and with contact EV wrong at 0.45 (the
    // second's rho2 18/13 is off by 0.71).
    const std::string fig5 = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/fig5_vf_ve_ee.json";
    const fs::path claims = tmpdir() / "switch_any.json", cert = tmpdir() / "switch_any.cert.json";
    {
        std::ofstream(claims) << R"({"format": "scalecert-claims-1", "claims": [
      {"kind": "switch_point", "rho1": "7/4", "rho2": "45/19", "contact": "VE"},
      {"kind": "switch_point", "rho1": "7/4", "rho2": "45/19", "contact": "EV"},
      {"kind": "switch_point", "rho1": "7/4", "rho2": "45/19"}]})";
    }
    for (const auto& [tol, rights] : std::vector<std::pair<std::string, std::vector<bool>>>{
             {"0.45", {true, false, true}}, {"0.44", {false, false, false}}, {"2", {true, true, true}}}) {
        // (tolerance 2: the second matches too, 18/13 within 2 x 18/13 of 45/19, so EV is right)
        const int st = engine("certify-fp " + fig5 + " " + claims.string() + " --tolerance " + tol + " --certificate " +
                              cert.string());
        BOOST_TEST(st == (std::count(rights.begin(), rights.end(), false) ? 1 : 0), tol);
        BOOST_TEST_REQUIRE(check_file(cert) == 0);
        const OJ j = load(cert);
        for (size_t k = 0; k < rights.size(); ++k)
            BOOST_TEST(j["judgements"][k]["right"] == rights[k], tol << " claim " << k);
        // Flipping a judgement is rejected.
        OJ f = j;
        f["judgements"][0]["right"] = !rights[0];
        BOOST_TEST(check_json(f) == 1);
    }
}

BOOST_AUTO_TEST_CASE(a_long_tolerance_is_shown_by_its_size) {
    // The summary writes the tolerance whole: cut to its first 40 characters, 1.2e-9 and 1.2e52
    // written with the same leading digits would look alike. A verdict's judgement does not
    // depend on the tolerance, so both files are valid; their summaries must differ.
    const std::string cubes = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json";
    const fs::path claims = tmpdir() / "tol_claims.json", cert = tmpdir() / "tol.cert.json";
    {
        std::ofstream(claims)
            << R"({"format": "scalecert-claims-1", "claims": [{"kind": "verdict", "rho1": 1, "rho2": 1, )"
               R"("verdict": "separated"}]})";
    }
    BOOST_REQUIRE(engine("certify-fp " + cubes + " " + claims.string() + " --certificate " + cert.string()) == 0);
    OJ j = load(cert);
    const std::string digits = "12345678901234567890123456789012345678901";
    std::string small_msg, big_msg;
    j["tolerance"] = digits + "/" + "1" + std::string(49, '0');
    BOOST_TEST(scalecert_check::check_text(j.dump(1), small_msg) == 0);
    j["tolerance"] = digits + std::string(12, '0');
    BOOST_TEST(scalecert_check::check_text(j.dump(1), big_msg) == 0);
    BOOST_TEST(small_msg.find("tolerance ~1.23457e-09") != std::string::npos, small_msg);
    BOOST_TEST(big_msg.find("tolerance ~1.23457e+52") != std::string::npos, big_msg);
}

BOOST_AUTO_TEST_CASE(judgements_at_poses_are_valid_and_tampering_is_rejected) {
    // The stacked cubes ([0,2]^3 about (1,1,1) below [0,2]^2 x [3,5] about (1,1,4)) with P2 turned a
    // quarter about the vertical line through (1, 1) (A: onto itself) or also lifted by 1 (B):
    // under A every claim is judged as on the unposed cubes (touching on rho1 + rho2 = 3, the gap
    // 1 at (1, 1), depth 1 at (2, 2)); under B, P2(1) starts at z = 4: 2 apart at (1, 1), and at
    // (1, 2) P2 starts at z = 3 > 2 = P1's top, separated.
    const std::string A = "[[0,-1,0,2],[1,0,0,0],[0,0,1,0]]", B = "[[0,-1,0,2],[1,0,0,0],[0,0,1,1]]";
    const fs::path claims = tmpdir() / "posed_claims.json", cert = tmpdir() / "posed.cert.json";
    std::ofstream(claims) << R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "touching", "pose2": )" +
                                 A + R"(},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1, "pose2": )" +
                                 A + R"(},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 2, "pose2": )" +
                                 B + R"(, "closest": [[1, 1, 2], [1, 1, 4]]},
     {"kind": "verdict", "rho1": 2, "rho2": 2, "verdict": "overlapping", "pose2": )" +
                                 A + R"(},
     {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": 1, "direction": [0, 0, 1], "pose2": )" +
                                 A + R"(},
     {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0, 0, 1], "offset": 2.5, "pose2": )" +
                                 A + R"(},
     {"kind": "witness_point", "rho1": 2, "rho2": 2, "point": [1, 1, 2.5], "pose1": )" +
                                 A + R"(, "pose2": )" + A + R"(},
     {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "touching", "pose2": )" +
                                 B + R"(}
    ]})";
    const std::string cubes = std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json";
    BOOST_REQUIRE(engine("certify-fp " + cubes + " " + claims.string() + " --certificate " + cert.string()) == 1);
    const OJ j = load(cert);
    const std::vector<bool> right = {true, true, true, true, true, true, true, false};
    BOOST_TEST_REQUIRE(j["judgements"].size() == right.size());
    for (size_t k = 0; k < right.size(); ++k) BOOST_TEST(j["judgements"][k]["right"] == right[k], k);
    BOOST_TEST(check_file(cert) == 0);
    mutate_and_report(j, "judgements at poses", false, true);
    // A claim with no answer is still a claim of its kind: its pose too (exact, R nonsingular).
    for (const char* pose : {R"(["0","-1","0","2"])", R"("garbage")", "[[0,0,0,0],[0,0,0,0],[0,0,0,0]]",
                             R"([["0","-1","0","2"],["1","0","0","0"],["0","0","1","0"]])"}) {
        OJ f = j;
        f["judgements"][1]["claim"]["value"] = nullptr;
        f["judgements"][1]["claim"]["pose2"] = OJ::parse(pose);
        f["judgements"][1]["proof"] = OJ::parse(R"({"no_answer": "value"})");
        f["judgements"][1]["right"] = false;
        // (the last, the claim's own pose as exact strings, is valid: the control)
        BOOST_TEST(check_json(f) == (std::string(pose).rfind("[[\"", 0) == 0 ? 0 : 1), pose);
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

// ---- compound judgements --------------------------------------------------------------------

namespace {
// certify-fp's certificate for claims on a scene of parts, checked valid.
OJ compound_judgements(const fs::path& scene, const std::string& claims, const std::string& name,
                       const std::string& options = "") {
    const fs::path cl = tmpdir() / (name + ".claims.json"), out = tmpdir() / (name + ".judgements.json");
    std::ofstream(cl) << claims;
    const int st = engine("certify-fp " + scene.string() + " " + cl.string() + " --certificate " + out.string() +
                          " --out " + (tmpdir() / (name + ".report")).string() + options);
    BOOST_REQUIRE(st == 0 || st == 1);
    BOOST_REQUIRE(check_file(out) == 0);
    return load(out);
}
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

// ---- a common denominator per part ------------------------------------------------------------
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

// ---- vertex lists read straight from the text ----------------------------------------------------
// The reader takes a scene's vertex list of integers into int64 (GMP integers past 2^62) without
// building a tree of strings (json.hpp, parse_certificate); any other list goes into the tree and
// is judged by num() as before. Both ways must give the same status, line and count of claims on
// every text, and the integers must be exact at the limits of int64.
namespace {
struct Answer {
    int status;
    std::string message;
    long claims;
};
Answer answer(const std::string& text, bool direct) {
    sc_::Context cx;
    cx.direct_points = direct;
    std::string msg;
    const int st = sc_::check_text(text, msg, cx);
    return {st, msg, cx.claims};
}
// Checks j both ways; returns the status.
int same_both_ways(const OJ& j, const std::string& what, int& compared) {
    const std::string text = j.dump(1);
    const Answer a = answer(text, true), b = answer(text, false);
    BOOST_TEST(a.status == b.status, what);
    BOOST_TEST(a.message == b.message, what << ": " << a.message << " | " << b.message);
    BOOST_TEST(a.claims == b.claims, what);
    ++compared;
    return a.status;
}
// The vertex lists of a certificate's scene (of each part, for a compound one), as JSON pointers.
std::vector<OJ::json_pointer> vertex_lists(const OJ& j) {
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
}  // namespace

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

BOOST_AUTO_TEST_CASE(integers_at_the_limits_of_int64_are_read_exactly) {
    // Below 2^62 in magnitude a coordinate is held as int64; from 2^62 on (INT64_MAX and INT64_MIN
    // among them, and 2^63 and 20 digits past them) its vertex is held in GMP integers. The
    // maximum along each axis, by hand, and ties between a small vertex and big ones merged.
    const std::string text = R"({"scene": {"P1": {"vertices": [
        ["4611686018427387903", "-4611686018427387903", "0"],
        ["4611686018427387904", "0", "0"],
        ["-4611686018427387904", "0", "0"],
        ["9223372036854775807", "0", "0"],
        ["-9223372036854775808", "0", "0"],
        ["9223372036854775808", "1", "2"],
        ["99999999999999999999", "0", "0"],
        ["1", "2", "3"],
        ["0", "2", "-1"],
        ["4611686018427387904", "2", "-1"]]}}})";
    sc_::Parsed parsed = sc_::parse_certificate(text);
    BOOST_TEST_REQUIRE(parsed.points.size() == 1u);
    sc_::Context cx;
    cx.points = &parsed.points;
    sc_::IntPoints* ip = sc_::captured(cx, parsed.root["scene"]["P1"]["vertices"]);
    BOOST_TEST_REQUIRE(ip == &parsed.points[0]);
    BOOST_TEST(ip->n == 10u);
    BOOST_TEST(ip->small() == 3u);  // vertices 0, 7 and 8
    BOOST_TEST((ip->orig == std::vector<int>{0, 7, 8}));
    BOOST_TEST((ip->big == std::vector<int>{1, 2, 3, 4, 5, 6, 9}));
    const std::vector<std::array<const char*, 3>> want = {{"4611686018427387903", "-4611686018427387903", "0"},
                                                          {"4611686018427387904", "0", "0"},
                                                          {"-4611686018427387904", "0", "0"},
                                                          {"9223372036854775807", "0", "0"},
                                                          {"-9223372036854775808", "0", "0"},
                                                          {"9223372036854775808", "1", "2"},
                                                          {"99999999999999999999", "0", "0"},
                                                          {"1", "2", "3"},
                                                          {"0", "2", "-1"},
                                                          {"4611686018427387904", "2", "-1"}};
    std::vector<CV> rational;
    for (const auto& w : want) rational.push_back({CQ(w[0]), CQ(w[1]), CQ(w[2])});
    const sc_::Scan from_text(cx, std::move(*ip)), from_rationals(cx, rational, "P1");
    for (size_t k = 0; k < want.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            BOOST_TEST(from_text.X(k)[c] == mpz_class(want[k][c]), k << "," << c);
            BOOST_TEST(from_rationals.X(k)[c] == mpz_class(want[k][c]), k << "," << c);
        }
    auto argmax = [&](long a, long b, long c) {
        const sc_::Z3 u{mpz_class(a), mpz_class(b), mpz_class(c)};
        const std::vector<int> m = from_text.argmax(cx, u);
        BOOST_TEST((m == from_rationals.argmax(cx, u)));
        return m;
    };
    BOOST_TEST((argmax(1, 0, 0) == std::vector<int>{6}));        // 10^20 - 1
    BOOST_TEST((argmax(-1, 0, 0) == std::vector<int>{4}));       // -2^63
    BOOST_TEST((argmax(0, 1, 0) == std::vector<int>{7, 8, 9}));  // y = 2: small 7, 8 and big 9 tie
    BOOST_TEST((argmax(0, -1, 0) == std::vector<int>{0}));       // y = -(2^62 - 1)
    BOOST_TEST((argmax(0, 0, 1) == std::vector<int>{7}));        // z = 3
    BOOST_TEST((argmax(0, 0, -1) == std::vector<int>{8, 9}));    // z = -1: a small and a big vertex
    // (2^62 - 1) x − y over vertex 0 is 2^62 (2^62 − 1) + ... : past int64 products, exact
    const sc_::Z3 u{mpz_class("4611686018427387903"), mpz_class(-1), mpz_class(0)};
    BOOST_TEST((from_text.argmax(cx, u) == std::vector<int>{6}));
    BOOST_TEST((from_text.argmax(cx, u) == from_rationals.argmax(cx, u)));
    // A subset holding only small vertices, and one holding both.
    const std::vector<int> small_only{0, 7, 8}, both{3, 8};
    BOOST_TEST((from_text.argmax(cx, {mpz_class(1), mpz_class(0), mpz_class(0)}, &small_only) == std::vector<int>{0}));
    BOOST_TEST((from_text.argmax(cx, {mpz_class(1), mpz_class(0), mpz_class(0)}, &both) == std::vector<int>{3}));
}

BOOST_AUTO_TEST_CASE(large_integer_lists_grow_exactly) {
    // A list long enough that each coordinate array is a mapping of its own (from 1 MiB: 2^17
    // coordinates), grown by remapping, with big points among the small ones: every point where
    // it was put.
    auto coord = [](size_t k, int c) { return static_cast<int64_t>(k * 7919 % 1000003) * (c + 1) - 1000000; };
    const mpz_class two70 = mpz_class(1) << 70;
    sc_::IntPoints all;
    const size_t n = 603003;
    std::vector<size_t> bigs;
    for (size_t k = 0; k < n; ++k)
        if (k % 50021 == 17) {  // a big point: x past int64
            all.add_big({mpz_class(two70 + k), mpz_class(coord(k, 1)), mpz_class(coord(k, 2))});
            bigs.push_back(k);
        } else {
            const int64_t x[3] = {coord(k, 0), coord(k, 1), coord(k, 2)};
            all.add_small(x);
        }
    BOOST_TEST(all.n == n);
    BOOST_TEST(all.big.size() == bigs.size());
    BOOST_TEST(all.small() + all.big.size() == n);
    sc_::Context cx;
    const sc_::Scan s(cx, std::move(all));
    BOOST_TEST(s.size() == n);
    size_t wrong = 0;
    for (size_t k = 0; k < n; ++k) {
        const bool big = std::binary_search(bigs.begin(), bigs.end(), k);
        const sc_::Z3 X = s.X(k);
        wrong += X[0] != (big ? mpz_class(two70 + k) : mpz_class(static_cast<long>(coord(k, 0)))) ||
                 X[1] != mpz_class(static_cast<long>(coord(k, 1))) || X[2] != mpz_class(static_cast<long>(coord(k, 2)));
    }
    BOOST_TEST(wrong == 0u);
    // the largest x: the last big point
    BOOST_TEST(
        (s.argmax(cx, {mpz_class(1), mpz_class(0), mpz_class(0)}) == std::vector<int>{static_cast<int>(bigs.back())}));
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

BOOST_AUTO_TEST_CASE(absolute_tolerance_judgements_are_valid_and_tampering_is_rejected) {
    // Points 1e-9 off their bodies, values 1e-9 off, planes the bodies reach (test_claims.cpp,
    // absolute_tolerance_on_points_values_and_planes, derives each by hand): right within 1e-9 by
    // {"near"} memberships, wrong ones by {"out"} normals showing more than 1e-9, on the stacked
    // cubes and on the band of parts. Every mutation is rejected or judged the same by the engine.
    const std::string cubes_claims = R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5,
      "closest": [[1, 1, "2000000001/1000000000"], [1, 1, "3499999999/1000000000"]]},
     {"kind": "distance", "rho1": 1, "rho2": 0.5, "value": 1.5,
      "closest": [[1, 1, "1999999999/1000000000"], [1, 1, "3500000002/1000000000"]]},
     {"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [1, 1, "2500000001/1000000000"]},
     {"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [1, 1, "2500000002/1000000000"]},
     {"kind": "separating_plane", "rho1": 1.5, "rho2": 1.5, "normal": [0, 0, 2], "offset": "5000000001/1000000000"},
     {"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": "999999999/1000000000", "direction": [0, 0, 1]}]})";
    const OJ cubes = compound_judgements(fs::path(SCALECERT_SOURCE_DIR) / "certificates/scenes/stacked_cubes.json",
                                         cubes_claims, "abs_cubes", " --abs-tolerance 1e-9");
    BOOST_TEST(cubes["abs_tolerance"] == "1/1000000000");
    const std::vector<bool> right = {true, false, true, false, true, true};
    BOOST_TEST_REQUIRE(cubes["judgements"].size() == right.size());
    for (size_t k = 0; k < right.size(); ++k) BOOST_TEST(cubes["judgements"][k]["right"] == right[k], k);
    BOOST_TEST(cubes["judgements"][2]["proof"]["P1"].contains("near"));
    BOOST_TEST(cubes["judgements"][3]["proof"]["P1"].contains("out"));
    mutate_and_report(cubes, "judgements at an absolute tolerance (stacked cubes)", false, true);
    // A "near" point farther than the tolerance: the checker says so. (The engine's own file is
    // made to lie: claim 3's point, 2e-9 out, given the weights of claim 2's near point.)
    OJ forged = cubes;
    forged["judgements"][3]["right"] = true;
    forged["judgements"][3]["proof"]["P1"] = cubes["judgements"][2]["proof"]["P1"];
    std::string msg;
    BOOST_TEST(scalecert_check::check_text(forged.dump(1), msg) == 1);
    BOOST_TEST(msg.find("within abs_tolerance") != std::string::npos, msg);
    // Without the tolerance, a "near" proof is no membership proof at all.
    OJ exact = cubes;
    exact.erase("abs_tolerance");
    BOOST_TEST(scalecert_check::check_text(exact.dump(1), msg) == 1);

    // The band of parts: P1's right box [2, 3] x [-1, 1]^2 scaled about the origin, P2 [4, 5] x
    // [-1, 1]^2 about (9/2, 0, 0); at (4/3, 1) they touch at x = 4.
    const std::string band_claims = R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1, "closest": [["3000000001/1000000000", 0, 0], [4, 0, 0]]},
     {"kind": "witness_point", "rho1": "4/3", "rho2": 1, "point": ["4000000001/1000000000", 0, 0]},
     {"kind": "witness_point", "rho1": "4/3", "rho2": 1, "point": ["4000000002/1000000000", 0, 0]},
     {"kind": "separating_plane", "rho1": "4/3", "rho2": 1, "normal": [1, 0, 0], "offset": 4},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": "999999999/1000000000"}]})";
    const OJ band = compound_judgements(data("compound_band.json"), band_claims, "abs_band", " --abs-tolerance 1e-9");
    const std::vector<bool> band_right = {true, true, false, true, true};
    BOOST_TEST_REQUIRE(band["judgements"].size() == band_right.size());
    for (size_t k = 0; k < band_right.size(); ++k) BOOST_TEST(band["judgements"][k]["right"] == band_right[k], k);
    BOOST_TEST(band["judgements"][1]["proof"]["P1"]["near"].is_array());
    mutate_and_report(band, "compound judgements at an absolute tolerance (band)", false, true);
}
