// scalecert audit: floating-point methods run on scenes and compared with the exact answers.
#include "campaign_options.hpp"
#include "common.hpp"

#include <iostream>

namespace scalecert::cli {

using namespace internal;

Command add_audit(CLI::App& app) {
    auto a = std::make_shared<CampaignArgs>();
    auto pair = std::make_shared<SceneArgs>();  // --p1/--p2: a pair of meshes
    CLI::App* sub = app.add_subcommand(
        "audit", "run floating-point methods on scenes and compare with the exact answers (JSON, and CSV with --csv)");
    add_audit_options(sub, *a);
    add_mesh_pair(sub, *pair,
                  "audits the pair, named P1-P2 by the files' names (with --failures, its scene is "
                  "DIR/P1-P2.scene.json)");
    example(sub,
            "Example:\n  scalecert audit certificates/scenes/*.json --grid 64 --out audit.json --csv audit.csv\n"
            "  scalecert audit --family nearly-equal-slopes --sweep 4 --sweep-to 40 --count 2 --out sweep.json\n"
            "  scalecert audit certificates/scenes/stacked_cubes.json --by-distance --failures repro --out a.json\n"
            "  scalecert audit --p1 a.obj --p2 b.obj --i1 1/2,2 --i2 1/2,2 --methods libccd-gjk --out a.json\n"
            "  scalecert audit --atlas --by-distance --out atlas.json\n"
            "(On a cluster: mpirun scalecert-mpi audit, with the same options and a run folder.)");
    return {sub, [a, pair] {
                if (pair->given()) {  // read (and refused) before anything else, then audited as a scene
                    pair->opt = a->opt;
                    const std::string name = pair->pair_name();
                    a->given[name] = pair->load();
                    a->scenes.push_back(name);
                }
                a->program = program_path();
                validate(*a);  // refused before any work
                // What reading each scene file leaves to say (an OBJ of several groups read as one
                // convex object), as every command says it; standard input is read once, by the run.
                for (const std::string& p : a->scenes)
                    if (p != "-" && !a->given.count(p)) say_notes(load_scene(p, a->opt));
                if (!a->failures.empty()) make_output_dir(a->failures);
                const long rows = run_campaign(*a);
                if (!internal::quiet()) std::cerr << "scalecert: audit: " << rows << (rows == 1 ? " row\n" : " rows\n");
                return 0;
            }};
}

}  // namespace scalecert::cli
