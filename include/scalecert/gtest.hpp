// GoogleTest gates on scalecert: predicates that return ::testing::AssertionResult, whose failure
// lists every wrong judgement (docs/library.md, "Gates in pytest and GoogleTest"). Header-only;
// include it where the tests use GoogleTest, and link scalecert::core and GTest.
//
//   TEST(Gripper, MuJoCoIsRight) {
//       scalecert::MujocoOptions o;
//       o.abs_tolerance = scalecert::parse_rational("1e-9");
//       EXPECT_MUJOCO_RIGHT("gripper.xml", states, o);
//   }
//
// A gate that judged nothing (a model of spheres alone, an empty claims file) fails too.
#pragma once
#include "scalecert/scalecert.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace scalecert::testing {

// A MuJoCo judgement as a gate: nothing judged fails; else every judgement right, or the failure
// lists each wrong one by its state (and where the reproducers are, when asked for).
inline ::testing::AssertionResult MujocoGate(const MujocoJudgement& j, const MujocoOptions& options) {
    if (j.judgements == 0)
        return ::testing::AssertionFailure() << "scalecert: nothing of the model was judged:\n" << j.text;
    if (j.wrong_pairs == 0) return ::testing::AssertionSuccess();
    ::testing::AssertionResult r = ::testing::AssertionFailure();
    r << "scalecert: MuJoCo was wrong at " << j.wrong_pairs << " pair state" << (j.wrong_pairs == 1 ? "" : "s") << ":\n"
      << j.text;
    if (!options.failures.empty()) r << "reproducers (scalecert certify-fp replays them): " << options.failures;
    return r;
}

// scalecert mujoco: every judgement right; else the failure lists each wrong one by its state.
inline ::testing::AssertionResult MujocoIsRight(const std::string& model,
                                                const std::vector<std::vector<double>>& qpos = {},
                                                const MujocoOptions& options = {}) {
    return MujocoGate(judge_mujoco(model, qpos, options), options);
}

// The same on what the program's own MuJoCo holds (scalecert/mujoco.hpp fills the arrays).
inline ::testing::AssertionResult MujocoHeldIsRight(const MujocoHeldModel& model,
                                                    const std::vector<MujocoHeldData>& data,
                                                    const MujocoOptions& options = {}) {
    return MujocoGate(judge_mujoco_held(model, data, options), options);
}

// scalecert certify-fp: every claim right (a claims file's text, JSON or lines); else the failure
// lists each wrong claim's line.
inline ::testing::AssertionResult ClaimsAreRight(const Scene& scene, const std::string& claims,
                                                 ClaimOptions options = {}) {
    options.json = false;
    const ClaimReport r = Analysis(scene).certify_fp(claims, options);
    if (r.claims == 0) return ::testing::AssertionFailure() << "scalecert: no claims to judge";
    if (r.wrong == 0) return ::testing::AssertionSuccess();
    ::testing::AssertionResult f = ::testing::AssertionFailure();
    f << "scalecert: " << r.wrong << " of " << r.claims << " claims wrong:\n";
    for (size_t b = 0; b < r.report.size();) {
        const size_t e = r.report.find('\n', b);
        const std::string line = r.report.substr(b, e == std::string::npos ? std::string::npos : e - b);
        if (line.rfind("WRONG", 0) == 0) f << line << "\n";
        if (e == std::string::npos) break;
        b = e + 1;
    }
    return f;
}

}  // namespace scalecert::testing

#define EXPECT_MUJOCO_RIGHT(...) EXPECT_TRUE(::scalecert::testing::MujocoIsRight(__VA_ARGS__))
#define ASSERT_MUJOCO_RIGHT(...) ASSERT_TRUE(::scalecert::testing::MujocoIsRight(__VA_ARGS__))
#define EXPECT_MUJOCO_HELD_RIGHT(...) EXPECT_TRUE(::scalecert::testing::MujocoHeldIsRight(__VA_ARGS__))
#define ASSERT_MUJOCO_HELD_RIGHT(...) ASSERT_TRUE(::scalecert::testing::MujocoHeldIsRight(__VA_ARGS__))
#define EXPECT_CLAIMS_RIGHT(...) EXPECT_TRUE(::scalecert::testing::ClaimsAreRight(__VA_ARGS__))
#define ASSERT_CLAIMS_RIGHT(...) ASSERT_TRUE(::scalecert::testing::ClaimsAreRight(__VA_ARGS__))
