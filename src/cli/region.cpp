// scalecert region: where two objects made of convex parts overlap in I1 × I2: each part pair's
// exact polygon, their union, and the growth set along ρ1 = ρ2.
#include "campaign_options.hpp"
#include "common.hpp"
#include "certify/classify.hpp"
#include "file_name.hpp"
#include "io/files.hpp"
#include "session/compound_session.hpp"

#include <algorithm>
#include <thread>

namespace scalecert::cli {

using namespace internal;

Command add_region(CLI::App& app) {
    struct Args {
        SceneArgs scene;
        std::string out, at, certificate, classify;
        unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand("region",
                                       "where objects made of convex parts meet (overlap or touch) in I1 x I2: each "
                                       "part pair's exact polygon, their union with its labelled boundary (JSON)");
    a->scene.add(sub);
    add_out(sub, a->out);
    sub->add_option("--at", a->at, "also the exact verdict at RHO1,RHO2 (in I1 x I2), with the pair that decides it");
    sub->add_option(
           "--certificate", a->certificate,
           "also write the certified partition (kind compound_partition): each part pair's overlap polygon with "
           "witnesses at its corners and the normals that separate the pair outside it, for scalecert-check "
           "(certificates/FORMAT.md, \"A compound partition\")")
        ->type_name("FILE")
        ->check(file_name());
    sub->add_option(
           "--classify", a->classify,
           "instead of the region, the exact verdict of each pair of PAIRS (lines 'rho1 rho2', doubles; '-': standard "
           "input), one per line, located on a grid over I1 x I2 built once")
        ->type_name("PAIRS");
    sub->add_option("--threads", a->threads, "threads for --classify (default: all cores)")
        ->check(whole_number(1, 256));
    example(sub,
            "Examples:\n  scalecert region tests/data/compound_band.json\n  scalecert region "
            "tests/data/compound_band.json --at 7/6,2\n"
            "  printf '1 2\\n1.5 2\\n' | scalecert region tests/data/compound_band.json --classify -\n"
            "  scalecert region tests/data/compound_band.json --certificate band.cert.json && scalecert-check "
            "band.cert.json");
    return {sub, [a, sub] {
                a->scene.opt.allow_parts = true;
                internal::refuse_outputs_over_inputs({a->out, a->certificate},
                                                     {a->scene.path, a->scene.mesh[0], a->scene.mesh[1], a->classify});
                auto sc = std::make_shared<const ExactScene>(a->scene.load());
                std::vector<Q> x;  // --at, read before the work
                if (sub->count("--at")) {
                    x = number_list(a->at, 2, "--at", a->scene.opt);
                    if (x[0] < sc->lo[0] || x[0] > sc->hi[0] || x[1] < sc->lo[1] || x[1] > sc->hi[1])
                        throw InputError("--at: " + internal::in_quotes(a->at) + " lies outside I1 x I2");
                }
                std::string pairs_text;  // --classify: read before the work, like --at
                std::vector<double> p1, p2;
                if (sub->count("--classify")) {
                    if (!a->certificate.empty() || !x.empty())
                        throw InputError("--classify writes verdicts only: not with --certificate or --at");
                    if (a->scene.opt.numbers == Numbers::Exact)
                        throw InputError(
                            "--numbers exact: --classify judges the doubles (or, with --numbers float32, the floats) a "
                            "program holds; --at takes one pair as written");
                    pairs_text = read_input(a->classify.empty() ? "-" : a->classify, "pairs file", kMaxPairsBytes);
                    try {
                        parse_pairs(pairs_text, p1, p2, a->threads, a->scene.opt.numbers == Numbers::Float32);
                    } catch (const InputError& e) {
                        throw InputError(a->classify + ": " + e.what());
                    }
                }
                std::unique_ptr<SceneEngine> engine = internal::open_engine(sc, a->scene.name());
                CompoundSession& session = engine->region();
                if (sub->count("--classify")) {
                    // (Each pair is checked, with the file's name, before the region is built.)
                    emit(verdict_lines(session.classify(p1, p2, a->threads, a->classify.empty() ? "-" : a->classify)),
                         a->out);
                    return 0;
                }
                std::optional<std::array<Q, 2>> at;
                if (!x.empty()) at = std::array<Q, 2>{x[0], x[1]};
                // The document first (the region with its union); the certificate reuses that region.
                const std::string doc = dump(session.region_json(at));
                if (a->certificate.empty()) {
                    emit(doc, a->out);
                } else {
                    const std::string cert = dump(session.partition_json());
                    if (a->out.empty()) {
                        write_file_atomically(a->certificate, cert);
                        emit(doc, a->out);
                    } else {
                        write_files_atomically({{a->certificate, cert}, {a->out, doc}});
                    }
                }
                return 0;
            }};
}

}  // namespace scalecert::cli
