// scalecert/gtest.hpp as a user's GoogleTest program uses it. The ctest tests run it twice: the
// Right.* tests must pass, and the Wrong.* tests must fail with the wrong judgements in the
// message (tests/CMakeLists.txt matches them), derived by hand in tests/test_mujoco.cpp and
// CLAIMS.md: MuJoCo 2.2.2 reports the cube of boxes.xml 1/8 deep at (1/4, 0, 3/8) with dist
// −1/16 (state 2; its contact at touching, S = 0 = the margin, is right), and on the stacked cubes
// (touching on rho1 + rho2 = 3) (2, 2) overlaps.
#include <scalecert/gtest.hpp>

#include <string>
#include <vector>

namespace {
const std::string kBoxes = std::string(SCALECERT_SOURCE_DIR) + "/tests/data/mujoco/boxes.xml";
const std::vector<double> kApart = {0, 0, 2, 1, 0, 0, 0, 5, 0, 0, 1, 0, 0, 0, -5, 0, 0, 1, 0, 0, 0};
const std::vector<double> kTouching = {0, 0, 0.5, 1, 0, 0, 0, 5, 0, 0, 1, 0, 0, 0, -5, 0, 0, 1, 0, 0, 0};
const std::vector<double> kDeep = {0.25, 0, 0.375, 1, 0, 0, 0, 5, 0, 0, 1, 0, 0, 0, -5, 0, 0, 1, 0, 0, 0};
// Two box geoms held by hand, as scalecert/mujoco.hpp would fill them: the floor [-1, 1]^2 x
// [-1, 0] on the world body and a cube of half-extent 1/2 on body 1, its centre at z (3/2 apart
// at z = 2). With a contact said, the pair claims to be closer than the margin 0.
scalecert::MujocoHeldModel two_boxes() {
    scalecert::MujocoHeldModel m;
    m.nq = 7;
    m.geom_type = {6, 6};
    m.geom_bodyid = {0, 1};
    m.geom_contype = m.geom_conaffinity = {1, 1};
    m.geom_dataid = {-1, -1};
    m.geom_size = {1, 1, 0.5, 0.5, 0.5, 0.5};
    m.geom_margin = m.geom_gap = {0, 0};
    m.geom_names = {"floor", "cube"};
    m.body_parentid = {0, 0};
    m.body_weldid = {0, 1};
    return m;
}
scalecert::MujocoHeldData at_height(double z, bool contact) {
    scalecert::MujocoHeldData d;
    d.qpos = {0, 0, z, 1, 0, 0, 0};
    d.geom_xpos = {0, 0, -0.5, 0, 0, z};
    d.geom_xmat = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (contact) d.contact.push_back({0, 1, -0.1, {0, 0, 0}, {0, 0, 1, 1, 0, 0, 0, 1, 0}, 0, 0});
    return d;
}
scalecert::Scene stacked() {
    return scalecert::Scene::load(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json");
}
}  // namespace

TEST(Right, MujocoApart) { EXPECT_MUJOCO_RIGHT(kBoxes, {kApart}); }
TEST(Right, MujocoTouching) { EXPECT_MUJOCO_RIGHT(kBoxes, {kTouching}); }
TEST(Right, MujocoTouchingWithinATolerance) {
    scalecert::MujocoOptions o;
    o.abs_tolerance = scalecert::parse_rational("1e-9");
    EXPECT_MUJOCO_RIGHT(kBoxes, {kTouching}, o);
}
TEST(Right, MujocoHeld) { EXPECT_MUJOCO_HELD_RIGHT(two_boxes(), {at_height(2, false)}); }
TEST(Right, Claims) { EXPECT_CLAIMS_RIGHT(stacked(), "1 1 separated\n3/2 3/2 touching\n"); }

TEST(Wrong, MujocoDeep) { EXPECT_MUJOCO_RIGHT(kBoxes, {kApart, kDeep}); }
TEST(Wrong, MujocoHeld) { EXPECT_MUJOCO_HELD_RIGHT(two_boxes(), {at_height(2, false), at_height(2, true)}); }
TEST(Wrong, Claims) { EXPECT_CLAIMS_RIGHT(stacked(), "1 1 separated\n2 2 not_overlapping\n"); }
