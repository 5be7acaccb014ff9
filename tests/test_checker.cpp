// The independent checker: it accepts every certificate the engine writes (bundled and fresh,
// for random scenes), and it rejects tampered ones — every numeric field changed, every list
// element deleted or duplicated, every verdict and flag flipped — except changes that leave a
// still-true certificate, each listed below with the reason.
#define BOOST_TEST_MODULE checker
#include <boost/test/unit_test.hpp>

#include "files.hpp"
#include "support.hpp"

#include <sys/wait.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
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
struct StillTrue { std::regex re; std::string why; bool query_only; };
const std::vector<StillTrue> kStillTrue = {
    {std::regex(".* at /model/.*"), "engine statistics (hull sizes, pairs tested): not a claim", false},
    {std::regex(".* at .*/closed_form$"), "name of the paper's formula that also gives the line: provenance, not a claim", false},
    {std::regex(".* at .*/equation$"), "name of the paper's equation that gives the switch point: provenance, not a claim", false},
    {std::regex(".* at .*/features/P[12]/[0-9]+$"), "another vertex of the same contact feature: still a maximiser", false},
    {std::regex(".* at .*/support_vertices/P[12]$"), "another vertex attaining the same support value", false},
    {std::regex("element duplicated at /scene/P[12]/vertices/[0-9]+$"), "a repeated vertex is the same polyhedron (a copy of the last vertex shifts no index)", false},
    {std::regex(".* at /scene/I[12]/.*"), "the scaling ranges I1, I2 take no part in a single query's claim", true},
};

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
            if (!scene && (it.key() == "P1" || it.key() == "P2") && it.value().is_array()) {
                const int poly = it.key() == "P1" ? 1 : 2;
                for (const OJ& e : it.value()) {
                    if (e.is_array() && !e.empty() && e[0].is_number_integer()) g_named.insert({poly, e[0].get<long>()});
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

void try_mutation(const OJ& j, const std::string& path, const std::string& what, Tally& t) {
    fs::path f = tmpdir() / "m.json";
    save(j, f);
    ++t.tried;
    int st = check_file(f);
    if (st == 1) { ++t.rejected; return; }
    const std::string key = what + " at " + path;
    for (const StillTrue& s : kStillTrue)
        if ((!s.query_only || g_query) && std::regex_match(key, s.re)) { ++t.still_true[s.why]; return; }
    if (moves_an_unnamed_vertex(key)) {
        ++t.still_true["a vertex in no weighted combination, moved with every support value unchanged: every claim still holds for the new points"];
        return;
    }
    BOOST_ERROR("tampered certificate accepted (exit " << st << "): " << key);
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
            scalecert::Q q(s);
            q += scalecert::Q(1, q.get_den());  // numerator + 1, written in lowest terms
            with(q.get_str(), "numerator + 1");
        } else if (s == "separated" || s == "touching" || s == "overlapping") {
            for (const char* v : {"separated", "touching", "overlapping"})
                if (s != v) with(v, std::string("verdict flipped to ") + v);
        } else {
            with(s + "X", "string changed");
        }
    } else if (node.is_number_float()) {
        with(std::nextafter(node.get<double>(), INFINITY), "double moved to the next double");
    } else if (node.is_number_integer()) {
        with(node.get<long>() + 1, "integer + 1");
    } else if (node.is_boolean()) {
        with(!node.get<bool>(), "flag flipped");
    } else if (node.is_object()) {
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
    BOOST_TEST_MESSAGE(name << ": " << t.tried << " mutations tried, " << t.rejected << " rejected, " << kept << " still true");
    std::cout << name << ": " << t.tried << " mutations tried, " << t.rejected << " rejected, " << kept << " still true\n";
    for (const auto& [why, n] : t.still_true) std::cout << "    still true (" << n << "): " << why << "\n";
    BOOST_TEST(t.tried > 50);
    BOOST_TEST(t.rejected + kept == t.tried);
}
}  // namespace

BOOST_AUTO_TEST_CASE(bundled_certificates_are_valid) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(fs::path(SCALECERT_SOURCE_DIR) / "certificates"))
        if (e.path().string().size() > 15 && e.path().string().rfind(".partition.json") == e.path().string().size() - 15) {
            BOOST_TEST(check_file(e.path()) == 0, e.path());
            ++n;
        }
    BOOST_TEST(n >= 4);
}

BOOST_AUTO_TEST_CASE(tampered_partitions_are_rejected) {
    for (const char* name : {"stacked_cubes", "tetra_box_switch", "fig5_vf_ve_ee", "roof_nearly_equal_slopes"}) {
        fs::path p = fs::path(SCALECERT_SOURCE_DIR) / "certificates" / (std::string(name) + ".partition.json");
        OJ j = load(p);
        Tally t;
        g_named.clear();
        collect_named(j, false);
        mutate_all(j, j, OJ::json_pointer(), t);
        report(name, t);
    }
}

BOOST_AUTO_TEST_CASE(tampered_query_answers_are_rejected) {
    fs::path scene = fs::path(SCALECERT_SOURCE_DIR) / "certificates/scenes/tetra_box_switch.json";
    // separated, touching (on the (E,E) piece, derived by hand in test_hand_curves) and overlapping
    for (const char* q : {"1 1", "3/2 12/7", "2 2"}) {
        fs::path out = tmpdir() / "q.json";
        BOOST_TEST_REQUIRE(engine("query " + scene.string() + " " + q + " --json --out " + out.string()) == 0);
        BOOST_TEST_REQUIRE(check_file(out) == 0);
        OJ j = load(out);
        Tally t;
        g_query = true;
        g_named.clear();
        collect_named(j, false);
        mutate_all(j, j, OJ::json_pointer(), t);
        report(std::string("query ") + q + " (" + j["verdict"].get<std::string>() + ")", t);
    }
}

BOOST_AUTO_TEST_CASE(fresh_certificates_for_random_scenes_are_valid) {
    std::mt19937 g(31);
    int partitions = 0, queries = 0;
    for (int t = 0; t < 12; ++t) {
        scalecert::Scene sc = test::random_scene(g, 4 + t % 6, 5 + t % 4);
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
    }
    std::cout << "fresh certificates checked: " << partitions << " partitions, " << queries << " query answers\n";
}

BOOST_AUTO_TEST_CASE(unreadable_files_exit_2) {
    BOOST_TEST(check_file(tmpdir() / "absent.json") == 2);
    std::ofstream(tmpdir() / "junk.json") << "{not json";
    BOOST_TEST(check_file(tmpdir() / "junk.json") == 2);
}
