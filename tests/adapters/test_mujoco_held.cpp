// scalecert/mujoco.hpp and judge_mujoco_held as a user's program uses them: the program loads a
// model with MuJoCo (Debian's libmujoco, linked here as a user's program links it), steps or
// forwards it, and hands its own mjModel and mjData over. Each judgement is checked against the
// model-file route (scalecert's own MuJoCo module at the same qpos) and against values by hand.
#include "scalecert/mujoco.hpp"

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {
const std::string kData = std::string(SCALECERT_SOURCE_DIR) + "/tests/data/mujoco/";

struct Model {
    mjModel* m = nullptr;
    mjData* d = nullptr;
    explicit Model(const std::string& path) {
        char err[500] = "";
        m = mj_loadXML(path.c_str(), nullptr, err, sizeof err);
        BOOST_TEST_REQUIRE(m != nullptr, err);
        d = mj_makeData(m);
    }
    ~Model() {
        mj_deleteData(d);
        mj_deleteModel(m);
    }
    void forward(const std::vector<double>& qpos) {
        for (int k = 0; k < m->nq; ++k) d->qpos[k] = qpos[static_cast<size_t>(k)];
        mj_forward(m, d);
    }
};
std::vector<std::vector<double>> rows(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::vector<double>> out;
    for (std::string line; std::getline(in, line);) {
        std::istringstream s(line);
        std::vector<double> q;
        for (double x; s >> x;) q.push_back(x);
        if (!q.empty()) out.push_back(q);
    }
    return out;
}
// The report without the model's name (the two routes name their source differently).
nlohmann::json unnamed(const std::string& report) {
    nlohmann::json j = nlohmann::json::parse(report);
    j.erase("model");
    return j;
}
}  // namespace

// boxes.xml (tests/test_mujoco.cpp works it out by hand): the cube 3/2 above the floor, then
// touching it, then 1/8 deep at (1/4, 0, 3/8). MuJoCo reports a contact at exactly touching, right
// (S = 0 = the margin); 1/8 deep it says dist −1/16: that pair state alone is wrong, named by
// its data index, and right within 1/16.
BOOST_AUTO_TEST_CASE(boxes_by_hand_through_the_held_arrays) {
    Model w(kData + "boxes.xml");
    const std::vector<double> apart = {0, 0, 2, 1, 0, 0, 0, 5, 0, 0, 1, 0, 0, 0, -5, 0, 0, 1, 0, 0, 0},
                              touching = {0, 0, 0.5, 1, 0, 0, 0, 5, 0, 0, 1, 0, 0, 0, -5, 0, 0, 1, 0, 0, 0},
                              deep = {0.25, 0, 0.375, 1, 0, 0, 0, 5, 0, 0, 1, 0, 0, 0, -5, 0, 0, 1, 0, 0, 0};
    std::vector<scalecert::MujocoHeldData> states;
    for (const auto& q : {apart, touching, deep}) {
        w.forward(q);
        states.push_back(scalecert::mujoco_held(w.m, w.d));
    }
    BOOST_TEST(states[0].contact.empty());
    BOOST_TEST(!states[1].contact.empty());
    const scalecert::MujocoHeldModel held = scalecert::mujoco_held(w.m);
    const scalecert::MujocoJudgement j = scalecert::judge_mujoco_held(held, states);
    BOOST_TEST(j.wrong_pairs == 1);
    BOOST_TEST(j.text.find("data[2]") != std::string::npos, j.text);
    scalecert::MujocoOptions o;
    o.abs_tolerance = scalecert::parse_rational("1/16");
    BOOST_TEST(scalecert::judge_mujoco_held(held, states, o).wrong_pairs == 0);
    // The same as the model-file route at the same states, judgement for judgement.
    const scalecert::MujocoJudgement f = scalecert::judge_mujoco(kData + "boxes.xml", {apart, touching, deep});
    nlohmann::json a = unnamed(j.json), b = unnamed(f.json);
    BOOST_TEST(a["summary"] == b["summary"]);
    BOOST_TEST(a["frames"].size() == b["frames"].size());
    for (size_t i = 0; i < a["frames"].size(); ++i) BOOST_TEST(a["frames"][i]["pairs"] == b["frames"][i]["pairs"]);
}

// The Panda finger and cube (103 states), forwarded by this program: every pair state judged as
// the model-file route judges it.
BOOST_AUTO_TEST_CASE(the_finger_as_the_program_ran_it) {
    Model w(kData + "panda_finger_cube.xml");
    const auto qpos = rows(kData + "panda_finger_cube.qpos");
    BOOST_TEST_REQUIRE(qpos.size() == 103u);
    std::vector<scalecert::MujocoHeldData> states;
    for (const auto& q : qpos) {
        w.forward(q);
        states.push_back(scalecert::mujoco_held(w.m, w.d));
    }
    scalecert::MujocoOptions o;
    o.abs_tolerance = scalecert::parse_rational("1e-9");
    const scalecert::MujocoJudgement h = scalecert::judge_mujoco_held(scalecert::mujoco_held(w.m), states, o);
    const scalecert::MujocoJudgement f = scalecert::judge_mujoco(kData + "panda_finger_cube.xml", qpos, o);
    BOOST_TEST(h.judgements > 0);
    BOOST_TEST(h.judgements == f.judgements);
    BOOST_TEST(h.wrong_pairs == f.wrong_pairs);
    const nlohmann::json a = unnamed(h.json), b = unnamed(f.json);
    for (size_t i = 0; i < a["frames"].size(); ++i) BOOST_TEST(a["frames"][i]["pairs"] == b["frames"][i]["pairs"], i);
}

// A rollout the program steps itself: the cube dropped on the floor, 300 steps of mj_step. Every
// state is judged; each state's judgement is the model-file route's at that state's qpos (the
// geoms' frames depend on qpos alone).
BOOST_AUTO_TEST_CASE(a_stepped_rollout) {
    Model w(kData + "boxes.xml");
    w.d->qpos[2] = 0.7;  // the cube 0.2 above the floor, falling
    std::vector<scalecert::MujocoHeldData> states;
    std::vector<std::vector<double>> qpos;
    for (int i = 0; i < 300; ++i) {
        mj_step(w.m, w.d);
        mj_forward(w.m, w.d);  // the frames and contacts at the qpos mj_step left
        states.push_back(scalecert::mujoco_held(w.m, w.d));
        qpos.push_back(states.back().qpos);
    }
    long with_contact = 0;
    for (const auto& s : states) with_contact += !s.contact.empty();
    BOOST_TEST(with_contact > 0);  // the cube landed
    const scalecert::MujocoJudgement h = scalecert::judge_mujoco_held(scalecert::mujoco_held(w.m), states);
    const scalecert::MujocoJudgement f = scalecert::judge_mujoco(kData + "boxes.xml", qpos);
    BOOST_TEST_MESSAGE("the stepped rollout: " << with_contact << " states with a contact; " << h.text);
    BOOST_TEST(h.wrong_pairs == f.wrong_pairs);
    const nlohmann::json a = unnamed(h.json), b = unnamed(f.json);
    for (size_t i = 0; i < a["frames"].size(); ++i) BOOST_TEST(a["frames"][i]["pairs"] == b["frames"][i]["pairs"], i);
}

// Arrays that do not fit together are refused, each naming its field.
BOOST_AUTO_TEST_CASE(held_arrays_that_do_not_fit) {
    Model w(kData + "boxes.xml");
    w.forward({0, 0, 2, 1, 0, 0, 0, 5, 0, 0, 1, 0, 0, 0, -5, 0, 0, 1, 0, 0, 0});
    const scalecert::MujocoHeldModel good = scalecert::mujoco_held(w.m);
    const scalecert::MujocoHeldData state = scalecert::mujoco_held(w.m, w.d);
    auto refused = [&](scalecert::MujocoHeldModel m, scalecert::MujocoHeldData d, const std::string& word) {
        try {
            scalecert::judge_mujoco_held(m, {d});
        } catch (const scalecert::InputError& e) {
            BOOST_TEST(std::string(e.what()).find(word) != std::string::npos, e.what());
            return;
        }
        BOOST_ERROR("not refused: " << word);
    };
    scalecert::MujocoHeldModel m = good;
    m.geom_size.pop_back();
    refused(m, state, "geom_size");
    m = good;
    m.geom_bodyid[1] = 99;
    refused(m, state, "geom_bodyid[1]");
    m = good;
    m.mesh_vertnum[0] = 1000;
    refused(m, state, "mesh_vertnum");
    m = good;
    m.mesh_vert[0] = NAN;
    refused(m, state, "mesh_vert[0]");
    scalecert::MujocoHeldData d = state;
    d.qpos.pop_back();
    refused(good, d, "qpos");
    d = state;
    d.contact.push_back({0, 77});
    refused(good, d, "contact[0].geom2");
    BOOST_CHECK_THROW(scalecert::judge_mujoco_held(good, {}), scalecert::InputError);
    m = good;
    m.geom_type[0] = 99;
    refused(m, state, "geom_type[0] = 99");
    // A state whose contact buffer was full: its pairs without a contact are not judged (the cube
    // 1/8 into the floor with no contact said would be a wrong verdict otherwise).
    w.forward({0.25, 0, 0.375, 1, 0, 0, 0, 5, 0, 0, 1, 0, 0, 0, -5, 0, 0, 1, 0, 0, 0});
    scalecert::MujocoHeldData dropped = scalecert::mujoco_held(w.m, w.d);
    dropped.contact.clear();
    BOOST_TEST(scalecert::judge_mujoco_held(good, {dropped}).wrong_pairs == 1);
    dropped.contact_buffer_full = true;
    BOOST_TEST(scalecert::judge_mujoco_held(good, {dropped}).wrong_pairs == 0);
}

// plane.xml (planes are half-spaces: CLAIMS.md, "Engines' conventions"): the floor z <= 0, the
// cube of half-extent 1/2 at z = 3/8 is 1/8 deep (S = −1/8 exactly), its normal is +z from the
// floor, and each corner contact's pos (±1/2, ±1/2, −1/16) lies in both (within |dist|/2 = 1/16
// of each). Forged outputs through the held arrays are judged wrong each for its own reason: a
// dist of −0.1, a normal tilted, a pos 1/10 above the floor (more than 1/16 from it).
BOOST_AUTO_TEST_CASE(planes_by_hand_and_forged) {
    Model w(kData + "plane.xml");
    w.forward({0, 0, 0.375, 1, 0, 0, 0, 3, 0, -0.25, 1, 0, 0, 0});
    const scalecert::MujocoHeldModel held = scalecert::mujoco_held(w.m);
    const scalecert::MujocoHeldData state = scalecert::mujoco_held(w.m, w.d);
    auto floor_cube = [](const nlohmann::json& j) {
        for (const auto& p : j["frames"][0]["pairs"])
            if (p["names"] == nlohmann::json::array({"floor", "cube"})) return p;
        return nlohmann::json();
    };
    const nlohmann::json ok = floor_cube(nlohmann::json::parse(scalecert::judge_mujoco_held(held, {state}).json));
    BOOST_TEST_REQUIRE(ok["contacts"].get<int>() == 4);
    BOOST_TEST(ok["signed_distance"]["exact"] == "-0.125");
    BOOST_TEST(ok["verdict"]["right"] == true);
    BOOST_TEST(ok["dist"]["right"] == (ok["dist"]["said"].get<double>() == -0.125));
    BOOST_TEST(ok["normal"]["right"] == (ok["normal"]["said"] == nlohmann::json::array({0.0, 0.0, 1.0})));
    bool corners = true;
    for (const auto& c : ok["pos"]["all_said"])
        corners = corners && std::fabs(c[0].get<double>()) == 0.5 && std::fabs(c[1].get<double>()) == 0.5 &&
                  c[2].get<double>() == -0.0625;
    BOOST_TEST(ok["pos"]["right"] == corners);
    size_t k = 0;  // the floor-cube contacts
    while (k < state.contact.size() && state.contact[k].geom2 != 1 && state.contact[k].geom1 != 1) ++k;
    BOOST_TEST_REQUIRE(k < state.contact.size());
    auto forged = [&](auto change) {
        scalecert::MujocoHeldData s = state;
        for (auto& c : s.contact)
            if (c.geom1 == state.contact[k].geom1 && c.geom2 == state.contact[k].geom2) change(c);
        return floor_cube(nlohmann::json::parse(scalecert::judge_mujoco_held(held, {s}).json));
    };
    BOOST_TEST(forged([](scalecert::MujocoHeldContact& c) { c.dist = -0.1; })["dist"]["right"] == false);
    BOOST_TEST(forged([](scalecert::MujocoHeldContact& c) { c.frame[0] = 1e-3; })["normal"]["right"] == false);
    BOOST_TEST(forged([](scalecert::MujocoHeldContact& c) { c.pos[2] = 0.1; })["pos"]["right"] == false);
    BOOST_TEST(forged([](scalecert::MujocoHeldContact& c) { c.pos[2] = 0.0625; })["pos"]["right"] == true);
    // A contact may not widen its own allowance: its dist must lie between the pair's signed
    // distance and the margin (S = −1/8 <= d < 0), so a dist of +3 with a pos 3/2 above the floor
    // is a wrong dist, not a right pos.
    const nlohmann::json wide = forged([](scalecert::MujocoHeldContact& c) {
        c.dist = 3;
        c.pos = {0.5, 0.5, 1.5};
    });
    BOOST_TEST(wide["contact_dists"]["right"] == false);
    BOOST_TEST(forged([](scalecert::MujocoHeldContact& c) { c.dist = -0.2; })["contact_dists"]["right"] == false);
    BOOST_TEST(ok["contact_dists"]["right"] == true);
    // The floor's normal reversed (from the cube into the floor): wrong.
    BOOST_TEST(forged([](scalecert::MujocoHeldContact& c) { c.frame[2] = -1; })["normal"]["right"] == false);
    // A contact said where the cube is 3/2 above the floor: the verdict is wrong.
    w.forward({0, 0, 2, 1, 0, 0, 0, 3, 0, 1, 1, 0, 0, 0});
    scalecert::MujocoHeldData far = scalecert::mujoco_held(w.m, w.d);
    BOOST_TEST_REQUIRE(far.contact.empty());
    far.contact.push_back(state.contact[k]);
    const nlohmann::json f = floor_cube(nlohmann::json::parse(scalecert::judge_mujoco_held(held, {far}).json));
    BOOST_TEST(f["verdict"]["right"] == false);
    BOOST_TEST(f["signed_distance"]["exact"] == "1.5");
}
