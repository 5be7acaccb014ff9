// scalecert/gtest.hpp as a user's GoogleTest program uses it. The ctest tests run it twice: the
// Right.* tests must pass, and the Wrong.* tests must fail with the wrong judgements in the
// message (tests/CMakeLists.txt matches them), derived by hand in tests/test_mujoco.cpp and
// CLAIMS.md: MuJoCo 2.2.2 reports contacts for the touching cube of boxes.xml (state 1), and on
// the stacked cubes (touching on rho1 + rho2 = 3) (2, 2) overlaps.
#include <scalecert/gtest.hpp>

#include <string>
#include <vector>

namespace {
const std::string kBoxes = std::string(SCALECERT_SOURCE_DIR) + "/tests/data/mujoco/boxes.xml";
const std::vector<double> kApart = {0, 0, 2, 1, 0, 0, 0, 5, 0, 0, 1, 0, 0, 0, -5, 0, 0, 1, 0, 0, 0};
const std::vector<double> kTouching = {0, 0, 0.5, 1, 0, 0, 0, 5, 0, 0, 1, 0, 0, 0, -5, 0, 0, 1, 0, 0, 0};
scalecert::Scene stacked() {
    return scalecert::Scene::load(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/stacked_cubes.json");
}
}  // namespace

TEST(Right, MujocoApart) { EXPECT_MUJOCO_RIGHT(kBoxes, {kApart}); }
TEST(Right, MujocoTouchingWithinATolerance) {
    scalecert::MujocoOptions o;
    o.abs_tolerance = scalecert::parse_rational("1e-9");
    EXPECT_MUJOCO_RIGHT(kBoxes, {kTouching}, o);
}
TEST(Right, Claims) { EXPECT_CLAIMS_RIGHT(stacked(), "1 1 separated\n3/2 3/2 touching\n"); }

TEST(Wrong, MujocoTouching) { EXPECT_MUJOCO_RIGHT(kBoxes, {kApart, kTouching}); }
TEST(Wrong, Claims) { EXPECT_CLAIMS_RIGHT(stacked(), "1 1 separated\n2 2 not_overlapping\n"); }
