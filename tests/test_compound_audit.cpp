// The audit of objects made of convex parts: its sample points labelled against
// verdicts derived by hand (interval arithmetic on axis-aligned boxes, which shares nothing with
// the engine), a method counted wrong exactly where its verdict differs, and the command's
// refusals and bytes.
#include <boost/test/unit_test.hpp>

#include "baselines/audit.hpp"
#include "files.hpp"
#include "session/compound_session.hpp"
#include "support.hpp"

#include <filesystem>
#include <map>

namespace fs = std::filesystem;
using namespace scalecert::internal;

namespace {

std::string scene_path(const std::string& name) {
    return std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/" + name;
}

ExactScene load(const std::string& name) {
    ReadOptions o;
    o.allow_parts = true;
    return load_scene(scene_path(name), o);
}

// The verdict of two compounds of axis-aligned boxes, by hand: a box [lo, hi] scaled by ρ about
// s spans [s + ρ(lo − s), s + ρ(hi − s)] on each axis; two boxes overlap (interiors meet) when
// their open spans meet on every axis, touch when their closed spans meet on every axis but not
// their open ones. The objects: 2 when some pair overlaps, else 1 when some pair touches, else 0.
int boxes_by_hand(const ExactScene& s, const Q& r1, const Q& r2) {
    auto spans = [&](int i, const Q& rho) {
        std::vector<std::array<std::array<Q, 2>, 3>> out;
        const std::vector<std::vector<Vec3q>> one{s.P[i].points};
        for (const std::vector<Vec3q>& part : s.P[i].parts.empty() ? one : s.P[i].parts) {
            std::array<std::array<Q, 2>, 3> b;
            for (int c = 0; c < 3; ++c) {
                Q lo = part[0][c], hi = lo;
                for (const Vec3q& v : part) lo = std::min(lo, v[c]), hi = std::max(hi, v[c]);
                const Q& sc = s.P[i].seed[c];
                b[static_cast<size_t>(c)] = {sc + rho * (lo - sc), sc + rho * (hi - sc)};
            }
            out.push_back(b);
        }
        return out;
    };
    int best = 0;
    for (const auto& a : spans(0, r1))
        for (const auto& b : spans(1, r2)) {
            bool open = true, closed = true;
            for (size_t c = 0; c < 3; ++c) {
                open = open && a[c][0] < b[c][1] && b[c][0] < a[c][1];
                closed = closed && a[c][0] <= b[c][1] && b[c][0] <= a[c][1];
            }
            best = std::max(best, open ? 2 : closed ? 1 : 0);
        }
    return best;
}

struct Audited {
    ExactScene scene;
    std::vector<CompoundSample> samples;
};
Audited samples_of(const std::string& name, int random = 60, int points = 32) {
    Audited a{load(name), {}};
    CompoundSession session(a.scene, name);
    const CompoundBoundary b = label_boundary(session.region(true), session.scene());
    CompoundJudge judge(session.scene(), name);
    a.samples = compound_samples(judge, b, random, points);
    return a;
}

Q q(double x) { return exact_from_double(x); }

// A method whose verdicts are given: a fixed, scattered function of the pair (+1, 0 or −1).
class Scripted : public fp::Method {
  public:
    std::string name() const override { return "scripted"; }
    int classify(double r1, double r2) const override {
        const std::uint64_t h = std::hash<double>()(r1) * 31 + std::hash<double>()(r2) * 17;
        return static_cast<int>((h >> 7) % 3) - 1;
    }
};
// One that is always right, by the hand verdicts (+1 separated, 0 touching, −1 overlapping).
class ByHand : public fp::Method {
  public:
    explicit ByHand(const ExactScene& s) : s_(s) {}
    std::string name() const override { return "by-hand"; }
    int classify(double r1, double r2) const override { return 1 - boxes_by_hand(s_, q(r1), q(r2)); }

  private:
    ExactScene s_;
};

struct Run {
    int status;
    std::string out, err;
};
fs::path workdir() {
    static fs::path d = test::scratch_dir("compound-audit");
    return d;
}
Run run(const std::string& args) {
    const fs::path o = workdir() / "stdout", e = workdir() / "stderr";
    const int st =
        std::system((std::string(SCALECERT_BIN) + " " + args + " >" + o.string() + " 2>" + e.string()).c_str());
    return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, test::slurp(o), test::slurp(e)};
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_verdict_words_are_judged_by_the_claim_rules) {
    // CLAIMS.md: separated is right only where they are apart, touching only where they touch,
    // intersecting where they touch or overlap, overlapping only where they overlap.
    const int said[4] = {AuditRow::kSaidSeparated, AuditRow::kSaidTouching, AuditRow::kSaidIntersecting,
                         AuditRow::kSaidOverlapping};
    const bool right[4][3] = {{true, false, false}, {false, true, false}, {false, true, true}, {false, false, true}};
    for (int w = 0; w < 4; ++w)
        for (int exact = 0; exact < 3; ++exact)
            BOOST_TEST(AuditRow::wrong(said[w], static_cast<Verdict>(exact)) == !right[w][exact]);
    AuditRow row;
    for (int w = 0; w < 4; ++w)
        for (int exact = 0; exact < 3; ++exact) row.count(w, exact, said[w], static_cast<Verdict>(exact));
    BOOST_TEST(row.queries == 12);
    BOOST_TEST(row.false_separated == 2);    // separated where they touch or overlap
    BOOST_TEST(row.false_touching == 2);     // touching where they are apart or overlap
    BOOST_TEST(row.false_overlapping == 3);  // intersecting where apart; overlapping where apart or touching
    BOOST_TEST(row.failures.size() == 7u);
}

BOOST_AUTO_TEST_CASE(band_samples_lie_where_derived_by_hand) {
    // The band (compound/band.json): parts [2,3] x [-1,1]^2 and [-3,-2] x [-1,1]^2 about the seed
    // 0, against the box [4,5] x [-1,1]^2 about (9/2, 0, 0). The right part spans [2ρ1, 3ρ1] in x,
    // the box [9/2 − ρ2/2, 9/2 + ρ2/2]; y and z always overlap. So they overlap iff
    // 6ρ1 + ρ2 > 9 and 4ρ1 − ρ2 < 9: the region's two contact edges lie on 6ρ1 + ρ2 = 9 (from
    // (1, 3) to (4/3, 1)) and 4ρ1 − ρ2 = 9 (from (5/2, 1) to (3, 3)), and every double ρ1 gives a
    // double ρ2 on both lines: each of the 32 boundary points, 16 an edge, is exactly touching.
    const Audited a = samples_of("compound/band.json");
    int on_left = 0, on_right = 0, random = 0;
    for (const CompoundSample& c : a.samples) {
        const Q x = q(c.r1), y = q(c.r2);
        BOOST_TEST(static_cast<int>(c.exact) == boxes_by_hand(a.scene, x, y),
                   "(" << c.r1 << ", " << c.r2 << ") k " << c.k);
        if (c.k < 0) {
            ++random;
            BOOST_TEST((x >= 1 && x <= 4 && y >= 1 && y <= 3));
        } else if (c.k == 0) {
            BOOST_TEST((c.exact == Verdict::Touching));
            const bool left = Q(6 * x + y) == 9, right = Q(4 * x - y) == 9;
            BOOST_TEST((left != right));
            on_left += left;
            on_right += right;
        } else if (c.k <= 48) {
            // 2^-48 of a coordinate is 2^5 of its last bit: the side survives rounding, and the
            // band is wide (at ρ2 = 1 it spans 4/3 ... 5/2): inward overlapping, outward separated.
            BOOST_TEST(static_cast<int>(c.exact) == (c.side > 0 ? 2 : 0),
                       "(" << c.r1 << ", " << c.r2 << ") k " << c.k << " side " << c.side);
        }
    }
    BOOST_TEST(random == 60);
    BOOST_TEST(on_left == 16);
    BOOST_TEST(on_right == 16);
    BOOST_TEST(a.samples.size() == 60u + 32u * 27u);
}

BOOST_AUTO_TEST_CASE(box_compounds_are_labelled_by_interval_arithmetic) {
    // The L and box (3ρ1 + ρ2 = 6, and the second part touching at (3, 3) only) and the U and peg
    // (walls, then the bottom): every sample's exact verdict equals the hand one.
    for (const char* name : {"compound/l_box.json", "compound/u_peg.json"}) {
        const Audited a = samples_of(name);
        long on = 0, touching = 0;
        for (const CompoundSample& c : a.samples) {
            BOOST_TEST(static_cast<int>(c.exact) == boxes_by_hand(a.scene, q(c.r1), q(c.r2)),
                       name << " (" << c.r1 << ", " << c.r2 << ") k " << c.k);
            if (c.k == 0) ++on, touching += c.exact == Verdict::Touching;
        }
        BOOST_TEST(on == 32);
        BOOST_TEST(touching == 32, name);  // (every contact line has coefficients of few bits: double points)
    }
    // The L's edge on 3ρ1 + ρ2 = 6: 3ρ1 needs more bits than ρ1, so its boundary points are found
    // by solving the line in integers, not by rounding.
    const Audited l = samples_of("compound/l_box.json");
    for (const CompoundSample& c : l.samples)
        if (c.k == 0) {
            const Q line = 3 * q(c.r1) + q(c.r2);  // (a Q: gmpxx's expression templates hold references)
            BOOST_TEST(line == 6);
        }
}

BOOST_AUTO_TEST_CASE(a_verdict_is_counted_wrong_exactly_when_it_differs) {
    const Audited a = samples_of("compound/band.json");
    // Always right: nothing wrong, every touching point said touching.
    {
        AuditRow row;
        score_compound(ByHand(a.scene), a.samples, true, row);
        BOOST_TEST(row.false_separated == 0);
        BOOST_TEST(row.false_overlapping == 0);
        BOOST_TEST_REQUIRE(row.by_distance.size() == 13u);
        for (const AuditRow::ByDistance& b : row.by_distance) BOOST_TEST(b.wrong == 0);
        BOOST_TEST(row.on_boundary->said_touching == 32);
        BOOST_TEST(row.on_boundary->touching == 32);
    }
    // Scattered verdicts: the counts recounted here from the hand verdicts.
    const Scripted m;
    AuditRow row;
    const std::vector<int> said = score_compound(m, a.samples, true, row);
    long fs = 0, fo = 0, ft = 0, said_sep = 0, said_touch = 0, said_over = 0;
    std::vector<AuditRow::Failure> listed;
    std::map<int, std::array<long, 3>> by_k;  // pairs, wrong, touching
    for (size_t i = 0; i < a.samples.size(); ++i) {
        const CompoundSample& c = a.samples[i];
        const int hand = boxes_by_hand(a.scene, q(c.r1), q(c.r2));
        const int v = m.classify(c.r1, c.r2);
        BOOST_TEST(said[i] == v);
        fs += v == 1 && hand != 0;
        fo += v == -1 && hand == 0;
        ft += v == 0 && hand != 1;  // touching said off the boundary, or where they overlap
        if (((v == 1) != (hand == 0) || (v == 0 && hand != 1)) && listed.size() < AuditRow::kMaxFailures)
            listed.push_back({c.r1, c.r2, v, static_cast<Verdict>(hand)});
        if (c.k == 0 && hand == 1) {
            said_sep += v == 1, said_touch += v == 0, said_over += v == -1;
        } else if (c.k > 0) {
            auto& b = by_k[c.k];
            if (hand == 1) {
                ++b[2];
            } else {
                ++b[0];
                b[1] += v != (hand == 0 ? 1 : -1);  // a two-state verdict: touching is wrong off the boundary
            }
        }
    }
    BOOST_TEST(row.queries == static_cast<long>(a.samples.size()));
    BOOST_TEST(row.false_separated == fs);
    BOOST_TEST(row.false_overlapping == fo);
    BOOST_TEST(row.false_touching == ft);
    BOOST_TEST(ft > 0);
    BOOST_TEST(row.wrong() == fs + fo + ft);
    BOOST_TEST_REQUIRE(row.failures.size() == listed.size());
    for (size_t i = 0; i < listed.size(); ++i) {
        BOOST_TEST(row.failures[i].rho1 == listed[i].rho1);
        BOOST_TEST(row.failures[i].rho2 == listed[i].rho2);
        BOOST_TEST(row.failures[i].said == listed[i].said);
        BOOST_TEST((row.failures[i].exact == listed[i].exact));
    }
    BOOST_TEST(row.on_boundary->said_separated == said_sep);
    BOOST_TEST(row.on_boundary->said_touching == said_touch);
    BOOST_TEST(row.on_boundary->said_overlapping == said_over);
    BOOST_TEST(row.on_boundary->moved == 0);
    long wrong = 0;
    for (const AuditRow::ByDistance& b : row.by_distance) {
        BOOST_TEST(b.pairs == by_k[b.k][0]);
        BOOST_TEST(b.wrong == by_k[b.k][1], "k " << b.k);
        BOOST_TEST(b.touching == by_k[b.k][2]);
        wrong += b.wrong;
    }
    BOOST_TEST(wrong > 100);  // (the script is wrong often: the counts above are not all zero)
    // Without by_distance: no table, the same other counts.
    AuditRow plain;
    score_compound(m, a.samples, false, plain);
    BOOST_TEST(plain.by_distance.empty());
    BOOST_TEST(plain.false_separated == fs);
}

BOOST_AUTO_TEST_CASE(the_methods_meet_the_hand_verdicts_away_from_the_boundary) {
    // Every compound method, on the band, at the random pairs at least 1/10 from both contact
    // lines (relative to the line's scale): this checks their wiring (scaling about the seed, the
    // parts), not their precision.
    const Audited a = samples_of("compound/band.json", 200, 4);
    CompoundJudge judge(a.scene, "band");
    const fp::CompoundFp f = compound_fp(judge);
    for (const std::string& name : fp::compound_method_names()) {
        const std::unique_ptr<fp::Method> m = fp::make_compound_method(name, f);
        BOOST_TEST_REQUIRE(m.get() != nullptr);
        BOOST_TEST(m->name() == name);
        int checked = 0;
        for (const CompoundSample& c : a.samples) {
            if (c.k >= 0) continue;
            const Q x = q(c.r1), y = q(c.r2);
            const Q left = abs(Q(6 * x + y - 9)), right = abs(Q(4 * x - y - 9));
            if (left < Q(9, 10) || right < Q(9, 10)) continue;
            BOOST_TEST(m->classify(c.r1, c.r2) == 1 - static_cast<int>(c.exact),
                       name << " at (" << c.r1 << ", " << c.r2 << ")");
            ++checked;
        }
        BOOST_TEST(checked > 50);
    }
}

BOOST_AUTO_TEST_CASE(convex_methods_are_refused_on_parts_and_compound_methods_take_convex_scenes) {
    const ExactScene band = load("compound/band.json");
    try {
        audit_scene("band", band, Q(0), {"bullet-compound", "libccd-gjk"}, {});
        BOOST_FAIL("libccd-gjk on parts was not refused");
    } catch (const InputError& e) {
        BOOST_TEST(std::string(e.what()).find(
                       "P1 is made of parts, and method 'libccd-gjk' audits convex objects only") != std::string::npos,
                   e.what());
    }
    // Stacked cubes (a plain scene: each object one part): they touch on ρ1 + ρ2 = 3 and overlap
    // above it, by hand.
    const ExactScene cubes = load("stacked_cubes.json");
    const std::vector<AuditRow> rows =
        audit_scene("cubes", cubes, Q(0), {"libccd-gjk", "bullet-compound"}, {}, true, false);
    BOOST_TEST_REQUIRE(rows.size() == 3u);  // libccd-gjk, the exact row, bullet-compound
    BOOST_TEST(!rows[0].on_boundary.has_value());
    BOOST_TEST(rows[2].method == "bullet-compound");
    BOOST_TEST_REQUIRE(rows[2].on_boundary.has_value());
    BOOST_TEST(rows[2].on_boundary->touching == 32);
    CompoundSession session(cubes, "cubes");
    CompoundJudge judge(cubes, "cubes");
    for (const CompoundSample& c : compound_samples(judge, label_boundary(session.region(true), cubes))) {
        const Q s = q(c.r1) + q(c.r2);
        BOOST_TEST(static_cast<int>(c.exact) == (s > 3 ? 2 : s == 3 ? 1 : 0));
        if (c.k == 0) BOOST_TEST(s == 3);
    }
}

BOOST_AUTO_TEST_CASE(the_command_refuses_bad_input_in_one_line_and_repeats_its_bytes) {
    const std::string band = scene_path("compound/band.json"), cubes = scene_path("stacked_cubes.json");
    const fs::path out = workdir() / "out.json", csv = workdir() / "out.csv";
    auto refused = [&](const std::string& args, const std::string& needle) {
        fs::remove(out);
        const Run r = run("audit " + args + " --out " + out.string());
        BOOST_TEST_CONTEXT(args) {
            BOOST_TEST(r.status == 2);
            BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
            BOOST_TEST(r.err.find(needle) != std::string::npos, r.err);
            BOOST_TEST(!fs::exists(out));
        }
    };
    // The default methods are convex ones: the line names the compound ones.
    refused(band, band +
                      ": P1 is made of parts, and method 'libccd-gjk' audits convex objects only (for objects made of "
                      "parts: --methods "
                      "bullet-compound,fcl-compound-libccd,fcl-compound-indep,libccd-gjk-parts)");
    refused(cubes + " " + band + " --methods bullet-compound,grid --grid 8",
            band + ": P1 is made of parts, and method 'grid'");
    refused(band + " --methods bullet-compound,no-such", "--methods: unknown method 'no-such'");
    const std::string flat = (workdir() / "flat.json").string();
    std::ofstream(flat) << R"({"P1": {"parts": [{"vertices": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]]}], "seed": [0, 0, 0]},)"
                        << R"( "P2": {"vertices": [[4,0,0],[5,0,0],[4,1,0],[4,0,1]]}, "I1": [1, 2], "I2": [1, 2]})";
    refused(flat + " --methods bullet-compound", "P1.parts[0]");
    // The same input, the same bytes (without timing); the CSV with the by-distance and
    // on-boundary columns.
    const std::string args = "audit " + band + " " + cubes +
                             " --methods fcl-compound-libccd,libccd-gjk-parts --by-distance --no-timing --out " +
                             out.string() + " --csv " + csv.string();
    BOOST_TEST_REQUIRE(run(args).status == 0);
    const std::string j1 = test::slurp(out), c1 = test::slurp(csv);
    BOOST_TEST_REQUIRE(run(args).status == 0);
    BOOST_TEST(test::slurp(out) == j1);
    BOOST_TEST(test::slurp(csv) == c1);
    const nlohmann::json j = nlohmann::json::parse(j1);
    BOOST_TEST_REQUIRE(j.size() == 4u);
    for (const auto& r : j) {
        BOOST_TEST(r.contains("on_boundary"));
        BOOST_TEST(r["by_distance"].size() == 13u);
        BOOST_TEST(!r.contains("seconds_per_query"));
    }
    BOOST_TEST(c1.find(",bd4_pairs,bd4_wrong,bd4_touching,") != std::string::npos);
    BOOST_TEST(c1.find(",on_points,on_touching,on_said_separated,on_said_touching,on_said_overlapping,on_moved,on_"
                       "moved_wrong\n") != std::string::npos);
    BOOST_TEST(std::count(c1.begin(), c1.end(), '\n') == 5);
}

BOOST_AUTO_TEST_CASE(the_panda_finger_scenes_at_one_by_hand) {
    // panda.xml's fingertip pads 2 to 5 span y in [0.002 − 0.002, 0.002 + 0.002] = [0, 0.004] in
    // the finger's frame; the finger mesh's points all have y > 0.0024 and pad 1 starts at 0.0015.
    // At (1, 1) the left finger sits at y = +0.001 and the right, turned half a turn about z, at
    // −0.001 (JSON numbers: the double 0.001): the pads' faces y = ±0.001 are the nearest, 2 × 0.001
    // apart (their x and z ranges meet). The cube's face y = 0.02 meets the left finger's pads
    // opened to y = 0.02: touching, and overlapping once the cube grows.
    const Q mm(0.001);
    const ExactScene fingers = load("compound/panda_fingers.json");
    BOOST_TEST_REQUIRE(fingers.P[0].parts.size() == 6u);
    CompoundJudge f(fingers, "fingers");
    const CompoundJudge::Distance d = f.distance(Q(1), Q(1));
    BOOST_TEST(d.squared == 4 * mm * mm);
    BOOST_TEST((d.part1 >= 2 && d.part2 >= 2));
    BOOST_TEST(d.p1[1] == mm);
    BOOST_TEST(d.p2[1] == -mm);
    const ExactScene cube = load("compound/panda_finger_cube.json");
    CompoundJudge c(cube, "cube");
    BOOST_TEST(static_cast<int>(c.verdict(Q(1), Q(1)).verdict) == 1);
    BOOST_TEST(static_cast<int>(c.verdict(Q(1), Q(1) + Q(1, 1000)).verdict) == 2);
    BOOST_TEST(static_cast<int>(c.verdict(Q(1), Q(1) - Q(1, 1000)).verdict) == 0);
}

BOOST_AUTO_TEST_CASE(compound_contacts_are_judged_against_their_part_pairs_depth) {
    // Stacked cubes, one part each: where they overlap, the pair's depth is the overlap along z,
    // r1 + r2 − 3 (the x and y overlaps, 2 min(r1, r2), are larger on [1/2, 5/2]²: max − min < 3).
    // Each contact a method reports at an overlapping sample it calls overlapping is compared
    // with it: the row's count and worst relative error are those recomputed here.
    {
        const Audited a = samples_of("stacked_cubes.json", 200, 32);
        CompoundJudge judge(a.scene, "cubes");
        const fp::CompoundFp f = compound_fp(judge);
        const std::vector<AuditRow> rows =
            audit_scene("cubes", a.scene, Q(0), {"bullet-compound", "fcl-compound-libccd"}, {}, false, true, {});
        BOOST_TEST_REQUIRE(rows.size() == 2u);
        for (const AuditRow& row : rows) {
            const std::unique_ptr<fp::Method> m = fp::make_compound_method(row.method, f);
            long n = 0;
            double worst = 0;
            for (const CompoundSample& c : a.samples) {
                if (c.exact != Verdict::Overlapping || m->classify(c.r1, c.r2) >= 0) continue;
                const Q d = q(c.r1) + q(c.r2) - 3;
                BOOST_TEST_REQUIRE(sgn(d) > 0);
                for (const fp::PartContact& k : m->contacts(c.r1, c.r2)) {
                    BOOST_TEST((k.part1 == 0 && k.part2 == 0));
                    if (!(k.depth > 0)) continue;
                    ++n;
                    const Q err = abs(Q(q(k.depth) - d)) / d;
                    worst = std::max(worst, err.get_d());
                }
            }
            BOOST_TEST(n > 100, row.method);
            BOOST_TEST(row.depths == n, row.method);
            BOOST_TEST(row.depth_err_max == worst, boost::test_tools::tolerance(1e-9));
            BOOST_TEST(row.contacts_apart == 0);
        }
    }
    // The L and the box: along x the L's foot (part 0) reaches 1/2 + 3 r1/2 and the box starts at
    // 7/2 − r2/2, so they overlap where 3 r1 + r2 > 6; the L's upright (part 1) lies at y >=
    // 1/2 + r1/2, the box at y <= 1/2 + r2/2, and along x it needs r1 + r2 >= 6: with r1 <= 4 and
    // r2 <= 3 only r1 = r2 = 3 (touching). So a contact on the upright is on a pair that does not
    // overlap (contacts_apart), and every other is on the foot: the parts are named right.
    const Audited l = samples_of("compound/l_box.json", 200, 32);
    CompoundJudge judge(l.scene, "l_box");
    const fp::CompoundFp f = compound_fp(judge);
    for (const AuditRow& row :
         audit_scene("l_box", l.scene, Q(0), {"bullet-compound", "fcl-compound-libccd"}, {}, false, true, {})) {
        const std::unique_ptr<fp::Method> m = fp::make_compound_method(row.method, f);
        long foot = 0, upright = 0;
        for (const CompoundSample& c : l.samples) {
            if (c.exact != Verdict::Overlapping || m->classify(c.r1, c.r2) >= 0) continue;
            for (const fp::PartContact& k : m->contacts(c.r1, c.r2)) {
                if (!(k.depth > 0)) continue;
                BOOST_TEST(k.part2 == 0);
                ++(k.part1 == 0 ? foot : upright);
            }
        }
        BOOST_TEST(foot > 100, row.method);
        BOOST_TEST(row.depths == foot, row.method);
        BOOST_TEST(row.contacts_apart == upright, row.method);
    }
}

BOOST_AUTO_TEST_CASE(a_bullet_margin_inflates_the_shapes_and_the_rows_record_it) {
    // Stacked cubes: P1(r1) reaches z = 1 + r1 and P2(r2) starts at z = 4 − r2, a gap of 3 − r1 − r2
    // along z (their x and y ranges always meet). A collision margin m puts a skin of m around each
    // shape, so Bullet finds a contact where the gap is below 2m: at each separated sample with
    // 0 < gap < 2m it says intersecting, and it is wrong nowhere else (no sample lies near 2m).
    const Audited a = samples_of("stacked_cubes.json", 200, 32);  // the audit's samples
    const Q m(1, 8);
    long predicted = 0;
    for (const CompoundSample& c : a.samples) {
        const Q gap = 3 - q(c.r1) - q(c.r2);
        BOOST_TEST_REQUIRE(abs(Q(gap - 2 * m)) > Q(1, 1000));
        if (sgn(gap) > 0 && gap < 2 * m) ++predicted;
    }
    MethodSettings st;
    st.bullet_margin = 0.125;
    st.fcl_gjk_tolerance = 1e-5;
    const std::vector<AuditRow> rows =
        audit_scene("cubes", a.scene, Q(0), {"bullet-compound", "fcl-compound-indep"}, {}, false, false, st);
    BOOST_TEST_REQUIRE(rows.size() == 2u);
    BOOST_TEST(predicted > 100);
    BOOST_TEST(rows[0].false_overlapping == predicted);
    BOOST_TEST(rows[0].false_separated == 0);
    BOOST_TEST((rows[0].settings == std::vector<std::pair<std::string, double>>{{"bullet-margin", 0.125}}));
    // (No distances measured here: FCL's distance tolerance is not read, so not recorded.)
    BOOST_TEST((rows[1].settings == std::vector<std::pair<std::string, double>>{{"fcl-gjk-tolerance", 1e-5}}));
    // With no margin (the default) the same samples are judged as before: none is 2m from contact.
    BOOST_TEST(audit_scene("cubes", a.scene, Q(0), {"bullet-compound"}, {}, false, false)[0].false_overlapping <
               predicted);
}
