// Campaigns without the floating-point baselines (src/campaign): the audit table's verdict counts
// and CSV, the generator and the families of scenes (each scene what its family's name promises,
// the same for the same seed), and the campaign's shards and arguments. Values by hand in the
// comments.
#include <boost/test/unit_test.hpp>

#include "support.hpp"

#include "campaign/audit_table.hpp"
#include "campaign/campaign.hpp"
#include "campaign/families.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <vector>

using namespace scalecert::internal;
using test::input_error;

namespace {
Q q(long p, long d = 1) {
    Q r(p, d);
    r.canonicalize();
    return r;
}
// The lines of a text ending in a newline.
std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    for (size_t b = 0, e; (e = text.find('\n', b)) != std::string::npos; b = e + 1)
        out.push_back(text.substr(b, e - b));
    return out;
}
bool ends_with(const std::string& s, const std::string& end) {
    return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}
// The least and the largest z over points.
std::pair<Q, Q> z_range(const std::vector<Vec3q>& p) {
    Q lo = p[0][2], hi = p[0][2];
    for (const Vec3q& v : p) lo = std::min(lo, v[2]), hi = std::max(hi, v[2]);
    return {lo, hi};
}
bool same_scene(const ExactScene& a, const ExactScene& b) {
    for (int i = 0; i < 2; ++i)
        if (a.P[i].points != b.P[i].points || a.P[i].seed != b.P[i].seed || a.lo[i] != b.lo[i] || a.hi[i] != b.hi[i])
            return false;
    return true;
}
ExactScene family(const std::string& name, const Q& eps, std::uint64_t seed) {
    Rng g(seed);
    return make_family_scene(name, eps, g);
}
}  // namespace

BOOST_AUTO_TEST_CASE(audit_rows_count_wrong_verdicts_by_the_claims_rules) {
    // Separated is right only where they are apart, touching only where they touch, intersecting
    // wherever they meet, overlapping only where they overlap strictly; no answer is wrong always.
    AuditRow r;
    r.count(1, 1, AuditRow::kSaidSeparated, Verdict::Touching);      // wrong: they touch
    r.count(1, 1, AuditRow::kSaidIntersecting, Verdict::Touching);   // right
    r.count(1, 1, AuditRow::kSaidIntersecting, Verdict::Separated);  // wrong: apart
    r.count(1, 1, AuditRow::kSaidTouching, Verdict::Overlapping);    // wrong: they overlap
    r.count(1, 1, AuditRow::kSaidOverlapping, Verdict::Touching);    // wrong: they only touch
    r.count(1, 1, AuditRow::kSaidSeparated, Verdict::Separated);     // right
    r.count(2, 3, AuditRow::kSaidNoAnswer, Verdict::Separated);      // wrong
    BOOST_TEST(r.queries == 7);
    BOOST_TEST(r.false_separated == 1);
    BOOST_TEST(r.false_overlapping == 2);
    BOOST_TEST(r.false_touching == 1);
    BOOST_TEST(r.not_answered == 1);
    BOOST_TEST(r.wrong() == 5);
    BOOST_TEST_REQUIRE(r.failures.size() == 5u);
    BOOST_TEST(r.failures[1].said == AuditRow::kSaidIntersecting);
    BOOST_TEST((r.failures[1].exact == Verdict::Separated));
    BOOST_TEST(r.failures[4].rho1 == 2.0);
    BOOST_TEST(r.failures[4].reason == "no answer");
    BOOST_TEST(std::string(AuditRow::said_word(AuditRow::kSaidIntersecting)) == "intersecting");
    // Every wrong verdict counted, the first 50 listed.
    AuditRow many;
    for (int k = 0; k < 60; ++k) many.count(k, 1, AuditRow::kSaidSeparated, Verdict::Overlapping);
    BOOST_TEST(many.false_separated == 60);
    BOOST_TEST(many.failures.size() == 50u);
    BOOST_TEST(many.failures.back().rho1 == 49.0);
}

BOOST_AUTO_TEST_CASE(measures_past_the_tolerance_are_kept_worst_first) {
    // Tolerance 10^-6 with its margin of 2^-40 of it (about 9.1e-19): 10^-6 itself and 5e-7 are
    // within; 10^-6 + 10^-12, 2e-6 and 3e-6 past, listed 3e-6, 2e-6, then 10^-6 + 10^-12.
    AuditRow r;
    std::vector<AuditRow::MeasureFailure> all(5);
    const double errors[5] = {5e-7, 2e-6, 1e-6, 1e-6 + 1e-12, 3e-6};
    for (int k = 0; k < 5; ++k) all[static_cast<size_t>(k)].error = errors[k], all[static_cast<size_t>(k)].rho1 = k;
    r.note_measures(all, 1e-6);
    BOOST_TEST(r.measures_wrong == 3);
    BOOST_TEST_REQUIRE(r.measure_failures.size() == 3u);
    BOOST_TEST(r.measure_failures[0].rho1 == 4.0);
    BOOST_TEST(r.measure_failures[1].rho1 == 1.0);
    BOOST_TEST(r.measure_failures[2].rho1 == 3.0);
}

BOOST_AUTO_TEST_CASE(audit_csv_quotes_text_fields_as_rfc_4180_says) {
    // A field with a comma, a quote or a line end goes in quotes, each quote inside doubled; the
    // reason a method did not run is quoted always, and its column is there when some row has
    // one. Without timing, seconds_per_query (8th) and seconds_per_curve (10th) are empty.
    AuditRow a, b, c;
    a.scene = "a,b \"c\".json", a.eps = q(1, 4), a.method = "libccd-gjk", a.queries = 3, a.false_separated = 1;
    b.scene = "plain.json", b.eps = q(1), b.method = "command=echo \"x\"", b.not_run = "exit 1, \"boom\"";
    c.scene = "two\nlines.json", c.eps = q(1, 2), c.method = "grid", c.not_run = "plain";
    const std::string csv = audit_csv({a, b, c}, false);
    const std::string zeros = "0,0,0,0,0,0,0,0,0,0,0,0,0";  // growth_error to direction_err_max
    const std::string want = "\"a,b \"\"c\"\".json\",0.25,libccd-gjk,3,1,0,0,,0,," + zeros + ",\n" +
                             "plain.json,1,\"command=echo \"\"x\"\"\",0,0,0,0,,0,," + zeros +
                             ",\"exit 1, \"\"boom\"\"\"\n" + "\"two\nlines.json\",0.5,grid,0,0,0,0,,0,," + zeros +
                             ",\"plain\"\n";
    const size_t header_end = csv.find('\n');
    BOOST_TEST_REQUIRE(header_end != std::string::npos);
    const std::string header = csv.substr(0, header_end);
    BOOST_TEST(header.rfind("scene,eps,method,queries,false_separated,", 0) == 0u, header);
    BOOST_TEST(ends_with(header, ",direction_err_max,not_run"), header);
    BOOST_TEST(csv.substr(header_end + 1) == want);
    // Without a reason in any row, no not_run column, and no trailing comma.
    const std::vector<std::string> plain = lines_of(audit_csv({a}, false));
    BOOST_TEST_REQUIRE(plain.size() == 2u);
    BOOST_TEST(ends_with(plain[0], ",direction_err_max"), plain[0]);
    BOOST_TEST(plain[1] == "\"a,b \"\"c\"\".json\",0.25,libccd-gjk,3,1,0,0,,0,," + zeros);
}

BOOST_AUTO_TEST_CASE(the_generator_is_splitmix64) {
    // Rng(seed) starts splitmix64 at seed * 0x9E3779B97F4A7C15 + 1 (mod 2^64); the seed
    // 0x0E217C1E66C88CC3 is -1/0x9E3779B97F4A7C15 mod 2^64, so the state starts at 0, whose first
    // outputs are splitmix64's published ones: E220A8397B1DCDAF, 6E789E6AA1B965F4, 06C45D188009454F.
    Rng g(0x0E217C1E66C88CC3ull);
    BOOST_TEST(g.next() == 0xE220A8397B1DCDAFull);
    BOOST_TEST(g.next() == 0x6E789E6AA1B965F4ull);
    BOOST_TEST(g.next() == 0x06C45D188009454Full);
    // uniform(lo, hi) is inclusive at both ends, and stays within them.
    Rng u(3);
    std::set<long> seen;
    for (int k = 0; k < 1000; ++k) seen.insert(u.uniform(-2, 2));
    BOOST_TEST((seen == std::set<long>{-2, -1, 0, 1, 2}));
}

BOOST_AUTO_TEST_CASE(each_family_is_what_its_name_promises) {
    const Q eps = q(1, 1024);
    // The same seed, the same scene; every family named, described and in the atlas by name.
    for (const std::string& name : family_names()) {
        BOOST_TEST(same_scene(family(name, eps, 7), family(name, eps, 7)), name);
        BOOST_TEST(!family_description(name).empty(), name);
    }
    for (const AtlasClass& c : atlas_classes())
        BOOST_TEST(std::count(family_names().begin(), family_names().end(), c.family) == 1, c.family);
    BOOST_TEST(!same_scene(family("random", eps, 7), family("random", eps, 8)));
    // ε unused: random polytopes and near-spheres (200 points each).
    BOOST_TEST(same_scene(family("random", eps, 7), family("random", q(1, 4), 7)));
    const ExactScene sphere = family("near-sphere", eps, 7);
    BOOST_TEST(sphere.P[0].points.size() == 200u);
    BOOST_TEST(sphere.P[1].points.size() == 200u);
    BOOST_TEST(same_scene(sphere, family("near-sphere", q(1, 4), 7)));
    // parallel-faces: P2's bottom face tilted by ε: each bottom vertex (below P2's top z = 5) at
    // z = 3 + ε x.
    const ExactScene pf = family("parallel-faces", eps, 7);
    int bottom = 0;
    for (const Vec3q& v : pf.P[1].points)
        if (v[2] < 4) {
            BOOST_TEST(v[2] - 3 == eps * v[0]);
            ++bottom;
        } else {
            BOOST_TEST(v[2] == 5);
        }
    BOOST_TEST(bottom == 4);
    // sliver: a tetrahedron of height ε.
    const ExactScene sl = family("sliver", eps, 7);
    BOOST_TEST(sl.P[1].points.size() == 4u);
    BOOST_TEST(z_range(sl.P[1].points).second - z_range(sl.P[1].points).first == eps);
    // face-to-face: a gap of ε times the boxes' height between P1's top and P2's bottom; touching:
    // no gap, so that they touch at (1, 1).
    const ExactScene ff = family("face-to-face", eps, 7), to = family("touching", eps, 7);
    const auto f1 = z_range(ff.P[0].points), f2 = z_range(ff.P[1].points);
    BOOST_TEST(f2.first - f1.second == eps * (f1.second - f1.first));
    BOOST_TEST(z_range(to.P[1].points).first == z_range(to.P[0].points).second);
    // long-edge: a bar 1/ε times longer (in x) than thick (in z).
    const ExactScene le = family("long-edge", eps, 7);
    Q x_lo = le.P[0].points[0][0], x_hi = x_lo;
    for (const Vec3q& v : le.P[0].points) x_lo = std::min(x_lo, v[0]), x_hi = std::max(x_hi, v[0]);
    const auto bar = z_range(le.P[0].points);
    BOOST_TEST((x_hi - x_lo) / (bar.second - bar.first) == 1 / eps);
    // nearly-parallel-edges: P2's bottom edge (its two lowest points) turned by ε from P1's top
    // edge (its two highest points, along x): dy/dx = ε between its ends.
    const ExactScene ne = family("nearly-parallel-edges", eps, 7);
    std::vector<Vec3q> top, low;
    for (const Vec3q& v : ne.P[0].points)
        if (v[2] == z_range(ne.P[0].points).second) top.push_back(v);
    for (const Vec3q& v : ne.P[1].points)
        if (v[2] == z_range(ne.P[1].points).first) low.push_back(v);
    BOOST_TEST_REQUIRE(top.size() == 2u);
    BOOST_TEST_REQUIRE(low.size() == 2u);
    BOOST_TEST(top[0][1] == top[1][1]);
    BOOST_TEST((low[1][1] - low[0][1]) / (low[1][0] - low[0][0]) == eps);
    // scaled: every coordinate times 1024ε, so twice ε (the same draws) is the scene doubled.
    const ExactScene s1 = family("scaled", eps, 7), s2 = family("scaled", 2 * eps, 7);
    for (int i = 0; i < 2; ++i) {
        BOOST_TEST_REQUIRE(s1.P[i].points.size() == s2.P[i].points.size());
        for (size_t k = 0; k < s1.P[i].points.size(); ++k)
            for (int c = 0; c < 3; ++c) BOOST_TEST(s2.P[i].points[k][c] == 2 * s1.P[i].points[k][c]);
    }
    BOOST_TEST(input_error([&] { family("cube", eps, 7); }) == "--family: unknown family 'cube'");
}

BOOST_AUTO_TEST_CASE(campaigns_plan_their_shards_and_refuse_bad_arguments) {
    // golden: the scene files first, then the family's count in shards of 16: 40 scenes are
    // [0, 16), [16, 32), [32, 40).
    CampaignArgs g;
    g.golden = true;
    g.family = "sliver";
    g.count = 40;
    g.scenes = {"/nonexistent/one.json"};
    const std::vector<Shard> p = plan(g);
    BOOST_TEST_REQUIRE(p.size() == 4u);
    BOOST_TEST(p[0].scene_file == 0);
    BOOST_TEST(p[0].scenes() == 1);
    const int ranges[3][2] = {{0, 16}, {16, 32}, {32, 40}};
    for (int k = 0; k < 3; ++k) {
        BOOST_TEST(p[k + 1].index == k + 1);
        BOOST_TEST(p[k + 1].scene_file == -1);
        BOOST_TEST(p[k + 1].first == ranges[k][0]);
        BOOST_TEST(p[k + 1].last == ranges[k][1]);
    }
    // audit --atlas with 5 scenes per ε: shards of 4, so two for each ε of each class.
    CampaignArgs a;
    a.atlas = true;
    a.count = 5;
    size_t eps_values = 0;
    for (const AtlasClass& c : atlas_classes()) eps_values += c.ks.size();
    const std::vector<Shard> atlas = plan(a);
    BOOST_TEST(atlas.size() == 2 * eps_values);
    BOOST_TEST(atlas.back().first == 4);
    BOOST_TEST(atlas.back().last == 5);
    BOOST_TEST(atlas.back().atlas == static_cast<int>(atlas_classes().size()) - 1);
    // A user's scene file's stem: its name without .json, and without .scene before it.
    BOOST_TEST(golden_stem("dir/a.scene.json") == "a");
    BOOST_TEST(golden_stem("b.json") == "b");
    BOOST_TEST(golden_stem("c") == "c");
    BOOST_TEST(golden_stem("e.json.json") == "e.json");
    // Two scenes of one stem would write the same files; a count of 0 is no count; an audit needs
    // the baselines' methods, which this program has none of.
    CampaignArgs twice;
    twice.golden = true;
    twice.scenes = {"/nonexistent/x/a.json", "/nonexistent/y/a.scene.json"};
    BOOST_TEST(input_error([&] { validate(twice); }) == "golden: two scenes named 'a' (their files would be the same)");
    g.count = 0;
    BOOST_TEST(input_error([&] { validate(g); }) == "golden: the count of scenes must be from 1 to 10^7 (got 0)");
    CampaignArgs audit;
    audit.scenes = {"/nonexistent/s.json"};
    BOOST_TEST(input_error([&] { validate(audit); }) ==
               "audit: this build has no floating-point baselines (configure with SCALECERT_BUILD_BASELINES=ON)");
}
