// scalecert mujoco: a MuJoCo model run at its states (mj_forward, as a user's program runs it),
// and every geom pair its collision pipeline considers judged against the exact answer for the
// geometry MuJoCo held (CLAIMS.md, "Engines' conventions"). Exit 1 when any judgement is wrong.
#include "common.hpp"

#include "engines/mujoco_judge.hpp"
#include "file_name.hpp"
#include "io/files.hpp"

#include <iostream>
#include <map>
#include <sstream>

namespace scalecert::cli {

using namespace internal;

namespace {
// --qpos FILE: a qpos a line, nq numbers split by spaces or commas ('#' starts a comment), each
// read as the double a program reads from it.
std::vector<std::vector<double>> read_states(const std::string& path, std::vector<std::string>& labels) {
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
        out.push_back(std::move(q));
        labels.push_back(path + ": line " + std::to_string(n));
    }
    if (out.empty()) throw InputError(path + ": no qpos (one a line)");
    return out;
}
}  // namespace

Command add_mujoco(CLI::App& app) {
    struct Args {
        std::string model, qpos, out, failures, tolerance = "0", abs_tolerance = "0";
        int key = -1;
        bool json = false, timing = false, intended = false;
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
    sub->add_flag("--intended", a->intended,
                  "also judge every output against the model as written: the mesh files' numbers as doubles (no "
                  "float32 rounding), in MuJoCo's mesh frame, at the same geom poses; said beside each judgement "
                  "(\"intended\") and in the summary. The exit status stays the held geometry's");
    add_out(sub, a->out);
    sub->add_flag("--timing", a->timing,
                  "say on stderr the seconds spent in mj_forward and in judging, and their ratio (the report stays "
                  "the same bytes)");
    sub->add_option("--failures", a->failures,
                    "write each wrong pair state as a reproducer: DIR/frameF_gA_gB.scene.json (the geoms as MuJoCo "
                    "held them), .claims.json (replayed by scalecert certify-fp) and .about.json (model, qpos)")
        ->type_name("DIR");
    example(sub,
            "Exit status: 0 all right, 1 some judgement wrong, 2 bad input. Example:\n"
            "  scalecert mujoco tests/data/mujoco/boxes.xml --qpos tests/data/mujoco/boxes.qpos --abs-tolerance 1e-9");
    return {
        sub, [a, sub] {
            if (a->key >= 0 && !a->qpos.empty()) throw InputError("give --qpos or --key, not both");
            if (a->key < 0 && sub->count("--key") > 0)
                throw InputError("--key " + std::to_string(a->key) + ": a keyframe is numbered from 0");
            const Tolerance tol{read_tolerance(a->tolerance, "--tolerance"),
                                read_tolerance(a->abs_tolerance, "--abs-tolerance")};
            internal::refuse_outputs_over_inputs({a->out}, {a->model, a->qpos});
            internal::note_inputs({a->model, a->qpos});
            std::unique_ptr<mj::Loaded> m = mj::load_model(a->model);
            const mj::ModelInfo& info = m->info();
            std::vector<std::string> labels;
            std::vector<std::vector<double>> given;
            if (!a->qpos.empty()) {
                given = read_states(a->qpos, labels);
                internal::note_inputs({a->qpos});  // --out QPOS would replace it
            }
            if (a->key >= static_cast<int>(info.keys.size()))
                throw InputError("--key " + std::to_string(a->key) + ": the model has " +
                                 std::to_string(info.keys.size()) +
                                 (info.keys.size() == 1 ? " keyframe" : " keyframes"));
            const std::vector<std::vector<double>> states = mj::choose_states(info, std::move(given), labels, a->key);
            mj::MujocoOptions opt{tol, a->model, a->failures, a->intended};
            const mj::MujocoResult r = mj::judge_states(*m, states, labels, opt);
            // MuJoCo's warnings, each once, with how often it was given.
            std::map<std::string, long> said;
            for (const std::string& w : r.warning_texts) ++said[w];
            for (const auto& [w, n] : said)
                internal::say_note("MuJoCo warned (" + std::to_string(n) + (n == 1 ? " state" : " states") + "): " + w);
            if (r.report["summary"]["judgements"].get<long>() == 0)
                internal::say_note("nothing of the model was judged (see 'unjudged'): exit 0 says nothing of MuJoCo");
            if (!a->failures.empty() && r.wrong > 0)
                internal::say_note(
                    "wrote " + std::to_string(r.reproducers) + " of " + std::to_string(r.wrong) +
                    " wrong pair states as reproducers to " + a->failures +
                    (r.reproducers < r.wrong ? " (a pair with a plane has none: a scene has no half-spaces)" : ""));
            emit(a->json ? dump(r.report) : r.text, a->out);
            if (a->timing) {
                char line[200];
                std::snprintf(line, sizeof line,
                              "scalecert: timing: %zu states, mj_forward %.4f s, judging %.4f s (%.1fx mj_forward)\n",
                              states.size(), r.forward_seconds, r.judge_seconds,
                              r.forward_seconds > 0 ? r.judge_seconds / r.forward_seconds : 0.0);
                std::cerr << line;
            }
            return r.wrong > 0 ? 1 : 0;
        }};
}

}  // namespace scalecert::cli
