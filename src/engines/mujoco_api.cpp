// The public judge_mujoco (scalecert.hpp): scalecert mujoco's judgement from the library.
#include "engines/mujoco_judge.hpp"
#include "scalecert/scalecert.hpp"

namespace scalecert {

MujocoJudgement judge_mujoco(const std::string& model, const std::vector<std::vector<double>>& qpos,
                             const MujocoOptions& options) {
    using namespace internal;
    if (sgn(options.tolerance) < 0) throw InputError("tolerance must be >= 0");
    if (sgn(options.abs_tolerance) < 0) throw InputError("abs_tolerance must be >= 0");
    const std::unique_ptr<mj::Loaded> m = mj::load_model(model);
    std::vector<std::string> labels;
    const std::vector<std::vector<double>> states = mj::choose_states(m->info(), qpos, labels, options.key);
    const mj::MujocoResult r = mj::judge_states(
        *m, states, labels,
        mj::MujocoOptions{Tolerance{options.tolerance, options.abs_tolerance}, model, options.failures});
    return {dump(r.report), r.text, r.wrong, r.report["summary"]["judgements"].get<long>()};
}

}  // namespace scalecert
