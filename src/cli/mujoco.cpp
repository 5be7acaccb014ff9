// scalecert mujoco: a MuJoCo model run at its states (mj_forward, as a user's program runs it),
// and every geom pair its collision pipeline considers judged against the exact answer for the
// geometry MuJoCo held (CLAIMS.md, "Engines' conventions"). Exit 1 when any judgement is wrong.
#include "common.hpp"

#include "baselines/mujoco_judge.hpp"
#include "file_name.hpp"
#include "io/files.hpp"

#include <iostream>
#include <sstream>
#include <tuple>

namespace scalecert::cli {

using namespace internal;

namespace {
// --qpos FILE: a qpos a line, nq numbers split by spaces or commas ('#' starts a comment), each
// read as the double a program reads from it.
std::vector<std::vector<double>> read_states(const std::string& path, int nq, std::vector<std::string>& labels) {
    const std::string text = read_input(path, "qpos file", kMaxSceneBytes);
    std::vector<std::vector<double>> out;
    std::istringstream in(text);
    std::string line;
    for (long n = 1; std::getline(in, line); ++n) {
        if (const size_t h = line.find('#'); h != std::string::npos) line.resize(h);
        for (char& c : line)
            if (c == ',' || c == '\t' || c == '\r') c = ' ';
        std::istringstream words(line);
        std::vector<double> q;
        for (std::string w; words >> w;) {
            try {
                q.push_back(parse_number(w, Numbers::Double).get_d());
            } catch (const InputError& e) {
                throw InputError(path + ": line " + std::to_string(n) + ": " + e.what());
            }
        }
        if (q.empty()) continue;
        if (static_cast<int>(q.size()) != nq)
            throw InputError(path + ": line " + std::to_string(n) + ": " + std::to_string(q.size()) +
                             " numbers; the model's qpos has " + std::to_string(nq));
        out.push_back(std::move(q));
        labels.push_back(path + " line " + std::to_string(n));
    }
    if (out.empty()) throw InputError(path + ": no qpos (one a line, " + std::to_string(nq) + " numbers)");
    return out;
}
}  // namespace

Command add_mujoco(CLI::App& app) {
    struct Args {
        std::string model, qpos, out, failures, tolerance = "0", abs_tolerance = "0";
        int key = -1;
        bool json = false;
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand(
        "mujoco",
        "run a MuJoCo model (Debian's libmujoco) at its states and judge every geom pair its collision pipeline "
        "considers against the exact answer for the geometry MuJoCo held (exit 1 if any is wrong)");
    sub->add_option("MODEL", a->model, "the model (MJCF XML, or MuJoCo's binary MJB)")->required();
    sub->add_option("--qpos", a->qpos, "states: a qpos a line (nq numbers, spaces or commas); default: qpos0")
        ->type_name("FILE");
    sub->add_option("--key", a->key, "the state of keyframe N (from 0)")->type_name("N");
    sub->add_option("--tolerance", a->tolerance, "accept a dist within this relative error of the exact one (exact)")
        ->type_name("REL");
    sub->add_option("--abs-tolerance", a->abs_tolerance,
                    "a length in metres (exact, e.g. 1e-9): a dist, a margin's bound and a normal's depth within it "
                    "are right (certificates/CLAIMS.md, \"Tolerances\")")
        ->type_name("LEN");
    sub->add_flag("--json", a->json, "the report as JSON (every pair at every state)");
    add_out(sub, a->out);
    sub->add_option("--failures", a->failures,
                    "write each wrong pair state as a reproducer: DIR/frameF_gA_gB.scene.json (the geoms as MuJoCo "
                    "held them), .claims.json (replayed by scalecert certify-fp) and .about.json (model, qpos)")
        ->type_name("DIR");
    example(sub,
            "Exit status: 0 all right, 1 some judgement wrong, 2 bad input. Example:\n"
            "  scalecert mujoco tests/data/mujoco/boxes.xml --qpos tests/data/mujoco/boxes.qpos --abs-tolerance 1e-9");
    return {sub, [a] {
                if (a->key >= 0 && !a->qpos.empty()) throw InputError("give --qpos or --key, not both");
                Tolerance tol;
                for (auto [text, value, flag] : {std::tuple{&a->tolerance, &tol.rel, "--tolerance"},
                                                 std::tuple{&a->abs_tolerance, &tol.abs, "--abs-tolerance"}}) {
                    try {
                        *value = parse_exact(*text);
                    } catch (const InputError& e) {
                        throw InputError(std::string(flag) + ": " + e.what());
                    }
                    if (sgn(*value) < 0) throw InputError(std::string(flag) + " must be >= 0");
                }
                internal::refuse_outputs_over_inputs({a->out}, {a->model, a->qpos});
                // MuJoCo reads the file itself: only a regular file is handed to it.
                read_input(a->model, "model file", kMaxSceneBytes);
                internal::note_inputs({a->model, a->qpos});
                std::unique_ptr<mj::Loaded> m = mj::load_model(a->model);
                const mj::ModelInfo& info = m->info();
                std::vector<std::vector<double>> states;
                std::vector<std::string> labels;
                if (!a->qpos.empty()) {
                    states = read_states(a->qpos, info.nq, labels);
                } else if (a->key >= 0) {
                    if (a->key >= static_cast<int>(info.keys.size()))
                        throw InputError("--key " + std::to_string(a->key) + ": the model has " +
                                         std::to_string(info.keys.size()) + " keyframes");
                    states.push_back(info.keys[static_cast<size_t>(a->key)]);
                    labels.push_back("key " + std::to_string(a->key));
                } else {
                    states.push_back(info.qpos0);
                    labels.push_back("qpos0");
                }
                mj::MujocoOptions opt{tol, a->model, a->failures};
                const mj::MujocoResult r = mj::judge_states(*m, states, labels, opt);
                emit(a->json ? dump(r.report) : r.text, a->out);
                return r.wrong > 0 ? 1 : 0;
            }};
}

}  // namespace scalecert::cli
