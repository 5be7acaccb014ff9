// scalecert mujoco (src/baselines/mujoco_judge.cpp) on models whose answers are worked out by hand
// in the comments: which geom pairs MuJoCo 2.2.2's pipeline considers, the exact signed distances
// of boxes at states, each judgement recomputed here from what MuJoCo said, the reproducers
// replayed by certify-fp, and bad input refused in one line.
#include <boost/test/unit_test.hpp>

#include "engines/mujoco_judge.hpp"
#include "scalecert/scalecert.hpp"
#include "files.hpp"
#include "support.hpp"

#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <random>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace scalecert::internal;
using test::input_error;

namespace {
const std::string kData = std::string(SCALECERT_SOURCE_DIR) + "/tests/data/mujoco/";
fs::path workdir() {
    static const fs::path d = test::scratch_dir("mujoco");
    return d;
}
struct Run {
    int status;
    std::string out, err;
};
Run run(const std::string& args) {
    const fs::path o = workdir() / "stdout", e = workdir() / "stderr";
    const std::string cmd = std::string(SCALECERT_BIN) + " " + args + " >" + o.string() + " 2>" + e.string();
    const int st = std::system(cmd.c_str());
    return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, test::slurp(o), test::slurp(e)};
}
fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = workdir() / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
}
}  // namespace

BOOST_AUTO_TEST_CASE(the_pairs_mujoco_considers) {
    // filters.xml: bodies world, a (free), b (hinged to a), c (hinged to b), d (free); geoms w1, w2
    // (world), a1, a2 (a), b1 (b), c1 (c), d1 (d: contype = conaffinity = 2, margin 0.01), d2 (d:
    // contype = conaffinity = 0), numbered 0 to 7. Considered, by MuJoCo 2.2.2's rules: each world
    // geom with a1, a2, b1, c1 (the parent filter spares the world); not w1-w2, a1-a2, d1-d2 (one
    // weld body); not a-b, b-c (parent and child); not a-c (<exclude>); nothing with d1 or d2 by
    // contype and conaffinity (1 & 2 = 0, 0); and the explicit <pair> d2-w2, margin 0.25. a1 has a
    // margin of 1/2, so w2-a1 has it (the larger of the two geoms'), but the <pair> w1-a1 replaces
    // the filters' pair with its own margin, 1/8 (MuJoCo 2.2.2 collides it once, at that margin).
    const auto m = mj::load_model(kData + "filters.xml");
    std::vector<std::array<int, 2>> got;
    std::vector<double> margins;
    for (const mj::Considered& c : mj::considered_pairs(m->info())) {
        got.push_back({c.g1, c.g2});
        margins.push_back(c.margin);
    }
    const std::vector<std::array<int, 2>> want = {{0, 2}, {0, 3}, {0, 4}, {0, 5}, {1, 2},
                                                  {1, 3}, {1, 4}, {1, 5}, {1, 7}};
    BOOST_TEST(got == want, [&] {
        std::string t;
        for (auto p : got) t += std::to_string(p[0]) + "-" + std::to_string(p[1]) + " ";
        return t;
    }());
    BOOST_TEST_REQUIRE(margins.size() == 9u);
    BOOST_TEST(margins[8] == 0.25);
    BOOST_TEST(margins[0] == 0.125);
    BOOST_TEST(margins[4] == 0.5);
    BOOST_TEST(margins[1] == 0.0);
    // MuJoCo 2.2.2 takes the larger of two geoms' margins: d1's 0.01 is its own (w-d1 is not
    // considered, so its margin shows nowhere); boxes.xml has none.
    BOOST_TEST(m->info().geoms[6].margin == 0.01);
}

BOOST_AUTO_TEST_CASE(collision_modes_and_a_full_contact_buffer) {
    // Two boxes 1/4 deep in each other, no <pair>: <option collision="predefined"> tests the
    // <pair>s only, so MuJoCo reports nothing and nothing is judged; "dynamic" ignores a <pair>.
    const std::string boxes = R"(<worldbody><geom name="f" type="box" size="1 1 1" pos="0 0 -1"/>
      <body pos="0 0 0.25"><freejoint/><geom name="c" type="box" size="0.5 0.5 0.5"/></body></worldbody>)";
    const Run pre =
        run("mujoco " + write("pre.xml", "<mujoco><option collision=\"predefined\"/>" + boxes + "</mujoco>").string());
    BOOST_TEST(pre.status == 0, pre.out + pre.err);
    BOOST_TEST(pre.out.find("pairs considered: 0") != std::string::npos, pre.out);
    const Run dyn = run("mujoco " +
                        write("dyn.xml", "<mujoco><option collision=\"dynamic\"/>" + boxes +
                                             R"(<contact><pair geom1="f" geom2="c" margin="1"/></contact></mujoco>)")
                            .string() +
                        " --json");
    const auto d = nlohmann::json::parse(dyn.out);
    BOOST_TEST(d["frames"][0]["pairs"][0]["margin"] == 0.0);  // the filters' pair, not the <pair>'s margin 1
    // nconmax 1: MuJoCo keeps one contact and warns; the pair without one is not judged (no
    // contact says nothing then), and the warning is said on stderr.
    const std::string three = R"(<mujoco><size nconmax="1"/><worldbody>
      <geom name="f" type="box" size="1 1 1" pos="0 0 -1"/>
      <body pos="0 0 0.25"><freejoint/><geom name="c" type="box" size="0.25 0.25 0.5"/></body>
      <body pos="0.5 0.5 0.25"><freejoint/><geom name="e" type="box" size="0.1 0.1 0.5"/></body></worldbody></mujoco>)";
    const Run full = run("mujoco " + write("full.xml", three).string() + " --json");
    const auto j = nlohmann::json::parse(full.out);
    BOOST_TEST(j["summary"]["verdicts_unjudged_buffer_full"].get<long>() >= 1);
    BOOST_TEST(full.err.find("scalecert: note: MuJoCo warned (1 state)") != std::string::npos, full.err);
    for (const auto& p : j["frames"][0]["pairs"])
        if (p["contacts"] == 0 && !p["signed_distance"].contains("decided_by"))
            BOOST_TEST(p["verdict"]["right"].is_null());
}

BOOST_AUTO_TEST_CASE(boxes_at_states_judged_by_hand) {
    // boxes.xml: the floor [-1, 1]^2 x [-1, 0]; the cube of half-extent 1/2 about (x, y, z) with
    // the identity quaternion, so MuJoCo holds exact frames: its bottom at z − 1/2. boxes.qpos:
    // z = 2: 3/2 apart; z = 1/2: touching (S = 0); (1/4, 0, 3/8): 1/8 deep (horizontally the cube,
    // [-1/4, 3/4] x [-1/2, 1/2], would move 7/4 or 3/2 to come free), the normal +z from floor to cube.
    const Run r = run("mujoco " + kData + "boxes.xml --qpos " + kData + "boxes.qpos --json");
    BOOST_TEST_REQUIRE((r.status == 0 || r.status == 1), r.err);
    const auto j = nlohmann::json::parse(r.out);
    BOOST_TEST_REQUIRE(j["frames"].size() == 3u);
    const char* exact[] = {"1.5", "0", "-0.125"};  // exact decimals
    const char* state[] = {"separated", "touching", "overlapping"};
    const double value[] = {1.5, 0, -0.125};
    long wrong_pairs = 0;
    for (size_t f = 0; f < 3; ++f) {
        const nlohmann::json* p = nullptr;
        for (const auto& q : j["frames"][f]["pairs"])
            if (q["names"] == nlohmann::json::array({"floor", "cube"})) p = &q;
        BOOST_TEST_REQUIRE(p != nullptr);
        // At z = 2 the boxes are 3/2 apart along z, more than the margin 0: filter 12 decides it
        // with no exact distance; the others are exact.
        if (f == 0)
            BOOST_TEST((*p)["signed_distance"]["decided_by"] == "their boxes, more than the margin apart");
        else
            BOOST_TEST((*p)["signed_distance"]["exact"] == exact[f], f);
        BOOST_TEST((*p)["verdict"]["exact"] == state[f], f);
        // The judgements recomputed from what MuJoCo said, at tolerance 0: a contact claims S <= 0
        // (the margin), none claims S >= 0; its dist claims S itself.
        const bool contact = (*p)["contacts"].get<int>() > 0;
        BOOST_TEST((*p)["verdict"]["right"] == (contact ? value[f] <= 0 : value[f] >= 0), f);
        bool right = contact ? value[f] <= 0 : value[f] >= 0;
        if (contact) {
            const double said = (*p)["dist"]["said"].get<double>();
            BOOST_TEST((*p)["dist"]["right"] == (said == value[f]), f);
            right = right && said == value[f];
            if (said < 0 && value[f] < 0) {
                // The normal +z attains the depth; any other does not.
                const auto n = (*p)["normal"]["said"];
                const bool up = n[0] == 0.0 && n[1] == 0.0 && n[2] == 1.0;
                BOOST_TEST((*p)["normal"]["right"] == up, f);
                right = right && up;
                // Each contact's pos lies within |dist|/2 of both boxes: the cube [-1/4, 3/4] x
                // [-1/2, 1/2] x [-1/8, 7/8] and the floor [-1, 1]^2 x [-1, 0] (axis-aligned, so the
                // distance to each is the length of the clamping, exact in doubles here).
                bool near = true;
                const double r = std::fabs((*p)["dist"]["said"].get<double>()) / 2;
                auto dist_to = [](const double(&lo)[3], const double(&hi)[3], const nlohmann::json& c) {
                    double s = 0;
                    for (int k = 0; k < 3; ++k) {
                        const double x = c[k].get<double>(), e = x < lo[k] ? lo[k] - x : x > hi[k] ? x - hi[k] : 0;
                        s += e * e;
                    }
                    return std::sqrt(s);
                };
                const double cube_lo[3] = {-0.25, -0.5, -0.125}, cube_hi[3] = {0.75, 0.5, 0.875},
                             floor_lo[3] = {-1, -1, -1}, floor_hi[3] = {1, 1, 0};
                for (const auto& c : (*p)["pos"]["all_said"])
                    near = near && dist_to(cube_lo, cube_hi, c) <= r && dist_to(floor_lo, floor_hi, c) <= r;
                BOOST_TEST((*p)["pos"]["right"] == near, f);
                right = right && near;
            }
        }
        wrong_pairs += !right;
    }
    // The other judged pairs (floor-tet, cube-tet) are far apart at every state: right.
    BOOST_TEST(j["summary"]["wrong_pairs"] == wrong_pairs);
    BOOST_TEST(r.status == (wrong_pairs > 0 ? 1 : 0));
    // The sphere of radius 1/4 at (−5, 0, 0) is judged too: 3.75 or more from the floor, the cube
    // and the tet at every state, no contact, right.
    BOOST_TEST(j["summary"]["pairs_unjudged"] == 0);
    for (const auto& fr : j["frames"])
        for (const auto& p : fr["pairs"])
            if (p["names"][0] == "ball" || p["names"][1] == "ball") {
                BOOST_TEST(p["verdict"]["exact"] == "separated");
                BOOST_TEST(p["verdict"]["right"] == true);
            }
    // Within --abs-tolerance 1e-9 a contact at S = 0 is right too, as is a dist within it.
    const Run t = run("mujoco " + kData + "boxes.xml --qpos " + kData + "boxes.qpos --json --abs-tolerance 1e-9");
    const auto k = nlohmann::json::parse(t.out);
    for (const auto& q : k["frames"][1]["pairs"])
        if (q["names"] == nlohmann::json::array({"floor", "cube"})) BOOST_TEST(q["verdict"]["right"] == true);
}

BOOST_AUTO_TEST_CASE(reproducers_replay_in_certify_fp) {
    // Every wrong pair state leaves a scene and claims that certify-fp judges alike: exit 1, and
    // as many wrong claims as the report has wrong judgements in that pair state.
    const fs::path dir = workdir() / "failures";
    fs::remove_all(dir);
    const Run r = run("mujoco " + kData + "boxes.xml --qpos " + kData + "boxes.qpos --json --failures " + dir.string());
    const auto j = nlohmann::json::parse(r.out);
    long files = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string n = e.path().filename().string();
        if (n.size() < 11 || n.substr(n.size() - 11) != ".scene.json") continue;
        ++files;
        const std::string stem = e.path().string().substr(0, e.path().string().size() - 11);
        const Run c = run("certify-fp " + stem + ".scene.json " + stem + ".claims.json");
        BOOST_TEST(c.status == 1, n << c.err);
        const auto about = nlohmann::json::parse(test::slurp(stem + ".about.json"));
        BOOST_TEST(about["qpos"].size() == 21u);
    }
    BOOST_TEST(files == j["summary"]["wrong_pairs"].get<long>());
}

BOOST_AUTO_TEST_CASE(bad_input_is_one_line) {
    auto bad = [](const std::string& args, const std::string& needle) {
        const Run r = run("mujoco " + args);
        BOOST_TEST(r.status == 2, args);
        BOOST_TEST(r.out.empty(), args);
        BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, args << ": " << r.err);
        BOOST_TEST(r.err.find(needle) != std::string::npos, args << ": " << r.err);
    };
    const std::string boxes = kData + "boxes.xml";
    bad((workdir() / "none.xml").string(), "cannot open");
    bad(write("broken.xml", "<mujoco><worldbody><geom type=\"box\"").string(), "MuJoCo:");
    bad(boxes + " --qpos " + write("short.qpos", "0 0 2 1 0 0 0\n").string(),
        "line 1: 7 numbers; the model's qpos has 21");
    std::string nan_line = "nan";
    for (int k = 0; k < 20; ++k) nan_line += " 0";
    bad(boxes + " --qpos " + write("nan.qpos", nan_line + "\n").string(), "line 1: 'nan' is not a number");
    bad(boxes + " --key 3", "--key 3: the model has 0 keyframes");
    bad(boxes + " --tolerance -1", "--tolerance must be >= 0");
    bad(boxes + " --key -7", "--key -7: a keyframe is numbered from 0");
    // A mesh the model names that is a FIFO: MuJoCo would wait on it forever.
    const fs::path mfifo = workdir() / "mesh.stl";
    fs::remove(mfifo);
    BOOST_TEST_REQUIRE(::mkfifo(mfifo.c_str(), 0600) == 0);
    bad(write("fifomesh.xml", R"(<mujoco><asset><mesh name="m" file="mesh.stl"/></asset><worldbody>
      <geom type="mesh" mesh="m"/></worldbody></mujoco>)")
            .string(),
        "is not a regular file: MuJoCo would open it");
    // The same in single quotes and with spaces around '=' (both XML).
    bad(write("fifomesh2.xml", R"(<mujoco><asset><mesh name='m' file = 'mesh.stl'/></asset><worldbody>
      <geom type="mesh" mesh="m"/></worldbody></mujoco>)")
            .string(),
        "is not a regular file: MuJoCo would open it");
    // Past the scan's reach before: a name with an XML character reference, a mesh in an
    // <include> under the includer's meshdir, and <compiler strippath> (the name's last part).
    const fs::path amp = workdir() / "a&b.stl", sub = workdir() / "sub", inc_fifo = sub / "f.stl";
    fs::create_directories(sub);
    fs::remove(amp);
    fs::remove(inc_fifo);
    BOOST_TEST_REQUIRE(::mkfifo(amp.c_str(), 0600) == 0);
    BOOST_TEST_REQUIRE(::mkfifo(inc_fifo.c_str(), 0600) == 0);
    bad(write("entity.xml", R"(<mujoco><asset><mesh name="m" file="a&amp;b.stl"/></asset><worldbody>
      <geom type="mesh" mesh="m"/></worldbody></mujoco>)")
            .string(),
        "is not a regular file: MuJoCo would open it");
    write("inc.xml", R"(<mujoco><asset><mesh name="m" file="f.stl"/></asset></mujoco>)");
    bad(write("includer.xml", R"(<mujoco><compiler meshdir="sub"/><include file="inc.xml"/><worldbody>
      <geom type="mesh" mesh="m"/></worldbody></mujoco>)")
            .string(),
        "is not a regular file: MuJoCo would open it");
    bad(write("strip.xml", R"(<mujoco><compiler strippath="true"/><asset><mesh name="m" file="elsewhere/mesh.stl"/>
      </asset><worldbody><geom type="mesh" mesh="m"/></worldbody></mujoco>)")
            .string(),
        "is not a regular file: MuJoCo would open it");
    // MuJoCo's own error in mj_forward (its stack too small for the model): one line, exit 2.
    bad(write("stack.xml", R"(<mujoco><size nstack="76"/><worldbody><geom type="box" size="1 1 1"/>
      <body pos="0 0 3"><freejoint/><geom type="box" size="1 1 1"/></body></worldbody></mujoco>)")
                .string() +
            " --qpos " + write("stack.qpos", "0 0 1.5 1 0 0 0\n").string(),
        "MuJoCo failed in mj_forward: Stack overflow");
    // Outputs that would replace the model's own files are refused.
    bad(boxes + " --qpos " + write("out.qpos", "0 0 2 1 0 0 0 5 0 0 1 0 0 0 -5 0 0 1 0 0 0\n").string() + " --out " +
            (workdir() / "out.qpos").string(),
        "an output names an input file");
    const fs::path fifo = workdir() / "model.fifo";
    fs::remove(fifo);
    BOOST_TEST_REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    bad(fifo.string(), "not a model file");
}

BOOST_AUTO_TEST_CASE(intended_judges_the_model_as_written) {
    // tenth.xml: the floor's top face at z = 0 and a mesh cube written as [-0.1, 0.1]^3
    // (tenth_cube.obj) on a free body. At z = 0.1 the cube as written rests on the floor: S = 0,
    // up to the double poses MuJoCo computed (the geom's frame turns by MuJoCo's principal axes and
    // back: |S| < 1e-15 here). MuJoCo holds 0.1 as a float32 (and the turned vertices rounded to
    // float32), so the cube it collides sinks into the floor by less than sqrt(3)·0.2·2^-24 <
    // 2.1e-8, more than 0: it reports a contact, right for both (S < 0 held; 0 < 0 + 1e-9 as
    // written). Its dist is the held depth within 1e-9, but as written it is off by the whole
    // rounding, more than 1e-9: the error is the input's rounding, not the collision code's. (Its
    // normal, tilted by 4e-8 rad from MuJoCo's float32 frame, is judged in both and is not the
    // point here.) At z = 0.5 the cube is 0.4 above the floor: no contact, right for both.
    const Run r =
        run("mujoco " + kData + "tenth.xml --qpos " + kData + "tenth.qpos --json --intended --abs-tolerance 1e-9");
    BOOST_TEST_REQUIRE((r.status == 0 || r.status == 1), r.err);
    const auto j = nlohmann::json::parse(r.out);
    const auto& p = j["frames"][0]["pairs"][0];
    BOOST_TEST_REQUIRE(p["contacts"].get<int>() > 0);
    const double held = std::stod(p["signed_distance"]["exact"].get<std::string>()),
                 written = std::stod(p["intended"]["signed_distance"]["exact"].get<std::string>()),
                 said = p["dist"]["said"].get<double>();
    BOOST_TEST(held < 0);
    BOOST_TEST(held > -2.1e-8);
    BOOST_TEST(std::fabs(written) < 1e-15);
    BOOST_TEST(p["verdict"]["right"] == true);
    BOOST_TEST(p["intended"]["verdict"]["right"] == true);
    BOOST_TEST(p["dist"]["right"] == (std::fabs(said - held) <= 1e-9));
    BOOST_TEST(p["dist"]["right"] == true);
    BOOST_TEST(p["intended"]["dist"]["right"] == (std::fabs(said - written) <= 1e-9 + 1e-15));
    BOOST_TEST(p["intended"]["dist"]["right"] == false);
    const auto& q = j["frames"][1]["pairs"][0];
    BOOST_TEST(q["intended"]["verdict"]["right"] == true);
    BOOST_TEST(r.status == (j["summary"]["wrong_pairs"] > 0 ? 1 : 0));  // the held geometry's
    BOOST_TEST(j["summary"]["intended"]["wrong_pairs"] == 1);
    BOOST_TEST(r.out.find("AS WRITTEN") == std::string::npos);  // the text is not in the JSON
    const Run t = run("mujoco " + kData + "tenth.xml --qpos " + kData + "tenth.qpos --intended --abs-tolerance 1e-9");
    BOOST_TEST(t.out.find("AS WRITTEN  state 0 (") != std::string::npos, t.out);
    BOOST_TEST(t.out.find("as written (--intended): wrong: 1 pair states") != std::string::npos, t.out);
    // A mesh written inline (boxes.xml's tet) has no file to read: its pairs are unjudged as
    // written, and said so; the held judgement is the same as without --intended.
    const Run b = run("mujoco " + kData + "boxes.xml --qpos " + kData + "boxes.qpos --json --intended");
    const Run c = run("mujoco " + kData + "boxes.xml --qpos " + kData + "boxes.qpos --json");
    const auto bj = nlohmann::json::parse(b.out), cj = nlohmann::json::parse(c.out);
    BOOST_TEST(bj["summary"]["wrong_pairs"] == cj["summary"]["wrong_pairs"]);
    bool said_why = false;
    for (const auto& x : bj["frames"][0]["pairs"])
        if (x["names"][1] == "tet" || x["names"][0] == "tet")
            said_why =
                said_why || x["intended"]["why"].get<std::string>().find("written in the model") != std::string::npos;
    BOOST_TEST(said_why);
    // Where the model written back is not the model (a scale MuJoCo writes to 6 digits) or the
    // file is not what MuJoCo holds (a vertex no face uses, which MuJoCo drops), the pair is
    // unjudged as written, and says why; never judged against the wrong geometry.
    const std::string cube = (fs::path(kData) / "tenth_cube.obj").string();
    auto written_why = [&](const std::string& name, const std::string& mesh) {
        const fs::path x = write(name, R"(<mujoco><asset>)" + mesh + R"(</asset><worldbody>
          <geom name="floor" type="box" size="1 1 0.5" pos="0 0 -0.5"/><body pos="0 0 0.1"><freejoint/>
          <geom name="cube" type="mesh" mesh="c"/></body></worldbody></mujoco>)");
        const Run w = run("mujoco " + x.string() + " --json --intended");
        BOOST_TEST_REQUIRE((w.status == 0 || w.status == 1), w.err);
        return nlohmann::json::parse(w.out)["frames"][0]["pairs"][0]["intended"]["why"].get<std::string>();
    };
    BOOST_TEST(written_why("scaled.xml", "<mesh name=\"c\" file=\"" + cube + "\" scale=\"1.0000001 1 1\"/>")
                   .find("differ from the model's") != std::string::npos);
    std::string extra = test::slurp(cube) + "v 5 5 5\n";
    write("extra.obj", extra);
    BOOST_TEST(
        written_why("extra.xml", "<mesh name=\"c\" file=\"extra.obj\"/>").find("9 distinct vertices, MuJoCo holds 8") !=
        std::string::npos);
}

BOOST_AUTO_TEST_CASE(contact_points_against_posed_boxes_by_brute_force) {
    // posed_box_side against the claim rules' own membership (a witness_point in a box at the pose,
    // the other object a box holding everything): where it decides, inside or within len must be
    // right, farther than len wrong, and inside must be inside at len 0 too. Boxes of dyadic sizes
    // at poses of double rotation matrices (not exactly orthogonal), points near their faces,
    // edges and corners.
    std::mt19937_64 g(5);
    std::uniform_real_distribution<double> u(-1, 1);
    const scalecert::Rational len("1/1000000");
    long decided = 0, n = 0;
    for (int trial = 0; trial < 60; ++trial) {
        mj::Geom box;
        box.type = mj::kBox;
        for (double& s : box.size) s = std::ldexp(std::floor(1 + 64 * (u(g) + 1)), -6);
        double q[4] = {u(g), u(g), u(g), u(g)}, nq = 0;
        for (double x : q) nq += x * x;
        for (double& x : q) x /= std::sqrt(nq);
        const double R[3][3] = {
            {1 - 2 * (q[2] * q[2] + q[3] * q[3]), 2 * (q[1] * q[2] - q[0] * q[3]), 2 * (q[1] * q[3] + q[0] * q[2])},
            {2 * (q[1] * q[2] + q[0] * q[3]), 1 - 2 * (q[1] * q[1] + q[3] * q[3]), 2 * (q[2] * q[3] - q[0] * q[1])},
            {2 * (q[1] * q[3] - q[0] * q[2]), 2 * (q[2] * q[3] + q[0] * q[1]), 1 - 2 * (q[1] * q[1] + q[2] * q[2])}};
        const double t[3] = {u(g), u(g), u(g)};
        scalecert::Pose pose;
        for (size_t r = 0; r < 3; ++r) {
            for (size_t c = 0; c < 3; ++c) pose[r][c] = scalecert::exact(R[r][c]);
            pose[r][3] = scalecert::exact(t[r]);
        }
        std::vector<scalecert::Point> p1, p2;
        for (int k = 0; k < 8; ++k) {
            p1.push_back({scalecert::exact(k & 1 ? box.size[0] : -box.size[0]),
                          scalecert::exact(k & 2 ? box.size[1] : -box.size[1]),
                          scalecert::exact(k & 4 ? box.size[2] : -box.size[2])});
            p2.push_back({k & 1 ? 10 : -10, k & 2 ? 10 : -10, k & 4 ? 10 : -10});
        }
        const scalecert::Analysis a(scalecert::Scene(p1, p2, {}, {}));
        const mj::ExactPosedBox eb = mj::exact_posed_box(box, pose);
        std::vector<scalecert::Claim> claims;
        std::vector<Vec3q> points;
        for (int i = 0; i < 12; ++i) {
            // A box point (local: each coordinate inside, on a face, or past it), moved by the pose,
            // then nudged by up to 2·10^-6 in a random direction.
            double v[3];
            for (size_t k = 0; k < 3; ++k) {
                const int kind = static_cast<int>(g() % 3);
                v[k] = kind == 0 ? box.size[k] * u(g) : (kind == 1 ? 1 : -1) * box.size[k];
            }
            const double nudge = std::ldexp(u(g), -static_cast<int>(g() % 40) - 19);
            Vec3q p;
            for (size_t r = 0; r < 3; ++r)
                p[r] = scalecert::exact(R[r][0] * v[0] + R[r][1] * v[1] + R[r][2] * v[2] + t[r] + nudge * u(g));
            scalecert::Claim c;
            c.kind = scalecert::ClaimKind::WitnessPoint;
            c.point = {p[0], p[1], p[2]};
            c.pose1 = pose;
            claims.push_back(c);
            points.push_back(p);
        }
        scalecert::ClaimOptions within;
        within.abs_tolerance = len;
        const scalecert::Judgements at_len = a.certify(claims, within), at_zero = a.certify(claims);
        for (size_t i = 0; i < points.size(); ++i, ++n) {
            const mj::BoxSide s = mj::posed_box_side(eb, points[i], len);
            if (s == mj::BoxSide::Unsure) continue;
            ++decided;
            BOOST_TEST(at_len.items[i].right == (s != mj::BoxSide::Farther), trial << "/" << i);
            if (s == mj::BoxSide::Inside) BOOST_TEST(at_zero.items[i].right, trial << "/" << i);
            if (mj::posed_box_side(eb, points[i], 0) == mj::BoxSide::Inside)
                BOOST_TEST(at_zero.items[i].right);
            else if (at_zero.items[i].right)
                BOOST_ERROR("a point in the box not found inside: " << trial << "/" << i);
        }
    }
    BOOST_TEST(decided > n * 9 / 10);  // the fast path decides nearly all
}

BOOST_AUTO_TEST_CASE(collision_disabled_by_the_constraint_flag) {
    // <flag constraint="disable"/>: MuJoCo 2.2.2 runs no collision (mj_collision returns), so no
    // pair is considered and the cube 1/8 into the floor is no wrong "no contact".
    const Run r = run("mujoco " +
                      write("noconstraint.xml", R"(<mujoco><option><flag constraint="disable"/></option>
      <worldbody><geom name="floor" type="box" size="1 1 0.5" pos="0 0 -0.5"/><body pos="0 0 0.375"><freejoint/>
      <geom name="cube" type="box" size="0.5 0.5 0.5"/></body></worldbody></mujoco>)")
                          .string() +
                      " --json");
    BOOST_TEST(r.status == 0, r.err);
    BOOST_TEST(nlohmann::json::parse(r.out)["summary"]["pairs_considered"] == 0);
    BOOST_TEST(r.err.find("nothing of the model was judged") != std::string::npos, r.err);
}

BOOST_AUTO_TEST_CASE(planes_at_states_by_hand) {
    // plane.xml: the floor is the half-space z <= 0. plane.qpos: (0) the cube 3/2 above it, the tet
    // 1 above (no contacts: right); (1) the cube 1/8 deep (S = −1/8 exactly), the tet's lowest
    // vertex at z ≈ −1/4 (MuJoCo's float32 re-centred vertices: S within 10^-7 of −1/4); (2) the
    // cube touching (S = 0 = the margin: a contact there is right, and so would be none).
    const std::string args = "mujoco " + kData + "plane.xml --qpos " + kData + "plane.qpos --json";
    const auto j = nlohmann::json::parse(run(args).out);
    auto pair = [&](size_t f, const char* other) {
        for (const auto& p : j["frames"][f]["pairs"])
            if (p["names"] == nlohmann::json::array({"floor", other})) return p;
        return nlohmann::json();
    };
    BOOST_TEST(pair(0, "cube")["verdict"]["right"] == true);
    BOOST_TEST(pair(0, "tet")["verdict"]["right"] == true);
    BOOST_TEST(pair(1, "cube")["signed_distance"]["exact"] == "-0.125");
    BOOST_TEST(pair(1, "cube")["verdict"]["exact"] == "overlapping");
    const double tet = std::stod(pair(1, "tet")["signed_distance"]["exact"].get<std::string>());
    BOOST_TEST(std::fabs(tet + 0.25) < 1e-7);
    BOOST_TEST(pair(2, "cube")["signed_distance"]["exact"] == "0");
    BOOST_TEST(pair(2, "cube")["verdict"]["right"] == true);
    const auto k = nlohmann::json::parse(run(args + " --abs-tolerance 1e-9").out);
    for (const auto& p : k["frames"][2]["pairs"])
        if (p["names"] == nlohmann::json::array({"floor", "cube"})) BOOST_TEST(p["verdict"]["right"] == true);
    BOOST_TEST(j["summary"]["pairs_unjudged"] == 0);  // planes are judged now
}

BOOST_AUTO_TEST_CASE(spheres_and_capsules_at_states_by_hand) {
    // rounded.xml: the plane z = 0, the box [5/2, 7/2] x [-1/2, 1/2] x [0, 1], a sphere of radius
    // 1/4 and a capsule of radius 1/8, half-length 1/2, upright (rounded.qpos, every number
    // dyadic). State 0: the ball rests on the floor, S = 1/4 − 1/4 = 0; MuJoCo reports a contact at
    // dist 0 with margin 0, which claims S <= 0: right.
    // State 1: the ball's centre at 3/16, S = −1/16, its normal the plane's (0, 0, 1); the rod
    // over the block, its axis's lower end at 1.609375 − 1/2 = 1 + 7/64, S = 7/64 − 1/8 = −1/64.
    // State 2: the ball's centre 1/4 from the rod's axis, S = 1/4 − 1/4 − 1/8 = −1/8, along x.
    // State 3: 1/2 from it, S = 1/8: no contact, right.
    const Run r = run("mujoco " + kData + "rounded.xml --qpos " + kData + "rounded.qpos --json");
    BOOST_TEST(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    BOOST_TEST(j["summary"]["pairs_unjudged"] == 0);
    BOOST_TEST(j["summary"]["wrong_pairs"] == 0);
    auto pair = [&](size_t f, const std::string& a, const std::string& b) {
        for (const auto& p : j["frames"][f]["pairs"])
            if ((p["names"][0] == a && p["names"][1] == b) || (p["names"][0] == b && p["names"][1] == a)) return p;
        BOOST_FAIL("no pair " + a + "-" + b);
        return nlohmann::json();
    };
    BOOST_TEST(pair(0, "floor", "ball")["verdict"]["exact"] == "touching");
    BOOST_TEST(pair(0, "floor", "ball")["verdict"]["right"] == true);
    BOOST_TEST(pair(0, "floor", "ball")["dist"]["right"] == true);
    const auto b1 = pair(1, "floor", "ball");
    BOOST_TEST(b1["signed_distance"]["exact"] == "-0.0625");
    BOOST_TEST(b1["dist"]["right"] == true);
    BOOST_TEST(b1["normal"]["right"] == true);
    const auto r1 = pair(1, "rod", "block");
    BOOST_TEST(r1["signed_distance"]["exact"] == "-0.015625");
    BOOST_TEST(r1["signed_distance"]["radii"] == "1/8");
    BOOST_TEST(r1["dist"]["right"] == true);
    BOOST_TEST(r1["pos"]["right"] == true);
    const auto r2 = pair(2, "ball", "rod");
    BOOST_TEST(r2["signed_distance"]["exact"] == "-0.125");
    BOOST_TEST(r2["normal"]["right"] == true);
    BOOST_TEST(pair(3, "ball", "rod")["verdict"]["exact"] == "separated");
    BOOST_TEST(run("mujoco " + kData + "rounded.xml --qpos " + kData + "rounded.qpos --abs-tolerance 1e-9").status ==
               0);
    // A ball stays a ball whatever its frame (found by the hostile review): a wall x <= p0 turned
    // from a plane, and a unit ball whose centre MuJoCo holds at 1 − 2^-53 under a rotated frame.
    // MuJoCo holds n = (1 + 2^-52, 0, 0) and p0 = −(2^-54 + 2^-60), so S = −63·2^-60 < 0: "no
    // contact" is wrong, however the ball is turned (a box posed through its frame falls short).
    const fs::path wall = write("wall.xml", R"(<mujoco><option gravity="0 0 0"/><worldbody>
      <geom name="wall" type="plane" size="10 10 0.1" pos="-5.637851296924623e-17 0 0"
            quat="0.7071067811865476 0 0.7071067811865476 0"/>
      <body name="ball" pos="3 0 0"><freejoint/><geom name="ball" type="sphere" size="1"/></body>
    </worldbody></mujoco>)");
    for (const char* q :
         {"0.9999999999999999 0 0 0.9791266840921002 0.203250920044187 0 0\n", "0.9999999999999999 0 0 1 0 0 0\n"}) {
        const Run w = run("mujoco " + wall.string() + " --qpos " + write("wall.qpos", q).string() + " --json");
        BOOST_TEST(w.status == 1);
        const auto wj = nlohmann::json::parse(w.out);
        BOOST_TEST(wj["frames"][0]["pairs"][0]["verdict"]["exact"] == "overlapping");
    }
}
