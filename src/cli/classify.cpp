// scalecert classify: exact verdicts for many pairs of doubles, filtered, on every core.
#include "campaign_options.hpp"
#include "common.hpp"
#include "io/files.hpp"

#include "certify/classify.hpp"

#include <thread>

namespace scalecert::cli {

using namespace internal;

Command add_classify(CLI::App& app) {
    struct Args {
        SceneArgs scene;
        std::string out, pairs;
        unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand(
        "classify", "exact verdicts for many pairs: lines 'rho1 rho2' (doubles, classified at their exact values)");
    a->scene.add(sub);
    sub->add_option("PAIRS", a->pairs, "file of pairs, one 'rho1 rho2' per line ('-', the default: standard input)");
    sub->add_option("--threads", a->threads, "threads (default: all cores)")->check(whole_number(1, 256));
    add_out(sub, a->out);
    example(sub,
            "Writes one verdict per line. Example:\n"
            "  printf '1 1\\n1.5 1.5\\n2 2\\n' | scalecert classify certificates/scenes/stacked_cubes.json -");
    return {sub, [a] {
                a->scene.shift_positionals({&a->pairs});
                if (a->pairs.empty()) a->pairs = "-";
                if (a->scene.opt.numbers == Numbers::Exact)
                    throw InputError(
                        "--numbers exact: classify judges the doubles (or, with --numbers float32, the floats) a "
                        "program holds; `scalecert query` takes one pair as written");
                StageClock clock;
                a->scene.opt.allow_parts = true;
                std::unique_ptr<SceneEngine> engine = open_engine(a->scene, Engine::Auto, clock);
                std::vector<double> r1, r2;
                const std::string pairs = read_input(a->pairs, "pairs file", kMaxPairsBytes);
                internal::note_inputs({a->pairs});  // --out PAIRS would replace it
                clock.lap("read pairs");
                try {
                    parse_pairs(pairs, r1, r2, a->threads, a->scene.opt.numbers == Numbers::Float32);
                } catch (const InputError& e) {
                    throw InputError(a->pairs + ": " + e.what());
                }
                clock.lap("parse pairs");
                std::optional<StageCounts> sc;
                const std::vector<Verdict> out = engine->classify(r1, r2, a->threads, a->pairs, &sc);
                clock.lap("classify");
                emit(verdict_lines(out), a->out);
                clock.lap("output");
                if (clock.on && sc)
                    std::fprintf(stderr, "scalecert: stages: %lu filtered, %lu exact\n", (unsigned long)sc->filtered,
                                 (unsigned long)sc->exact);
                return 0;
            }};
}

}  // namespace scalecert::cli
