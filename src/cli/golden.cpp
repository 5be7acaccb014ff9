// scalecert golden: scenes of a family with their exact answers, for other projects' test suites.
#include "campaign_options.hpp"
#include "common.hpp"

#include "certify/certificate.hpp"
#include "certify/region_certificate.hpp"
#include "io/files.hpp"

#include <iostream>
#include <optional>

namespace scalecert::cli {

using namespace internal;

Command add_golden(CLI::App& app) {
    auto a = std::make_shared<CampaignArgs>();
    auto pair = std::make_shared<SceneArgs>();  // --p1/--p2: a pair of meshes (no SCENE positional here)
    CLI::App* sub = app.add_subcommand(
        "golden",
        "exact answers near the touching curve of your scenes, or of a family's, as JSON and CSV files in a directory");
    add_golden_options(sub, *a);
    sub->add_option("--scene", a->scenes, "a scene file, as SCENES (may be repeated)")->type_name("FILE");
    add_mesh_pair(sub, *pair,
                  "golden data for the pair, named P1-P2 by the files' names (its "
                  "scene is DIR/P1-P2.scene.json)");
    example(sub,
            "Examples:\n  scalecert golden --family nearly-equal-slopes --count 10 --eps 1/1024 --dir golden/\n"
            "  scalecert golden certificates/scenes/tetra_box_switch.json --dir golden/\n"
            "  scalecert golden --p1 a.off --p2 b.off --i1 1/2,2 --i2 1/2,2 --dir golden/\n"
            "(On a cluster: mpirun scalecert-mpi golden, with the same options and a run folder.)");
    return {sub, [a, pair] {
                // A pair of meshes: read (and refused) before anything is created, its scene then
                // written into the directory and taken as one of SCENES.
                std::optional<std::pair<std::string, std::string>> mesh_scene;
                if (pair->given()) {
                    pair->opt = a->opt;
                    const ExactScene sc = pair->load();
                    // Written as golden writes a scene's copy (NAME.scene.json, the same bytes): three files.
                    const std::string path = a->dir + "/" + pair->pair_name() + ".scene.json";
                    mesh_scene.emplace(path, dump(scene_file_json(sc)));
                    a->scenes.push_back(path);
                }
                validate(*a);  // an unknown family is refused before anything is created
                // Every scene read, and every output name checked, before anything is written (and
                // main's output journal removes what was written if the run fails later).
                for (const std::string& p : a->scenes) {
                    if (mesh_scene && p == mesh_scene->first) continue;  // read above, written below
                    say_notes(load_scene(p, a->opt));
                    for (const char* ext : {".scene.json", ".golden.json", ".golden.csv", ".golden.rational.csv"})
                        refuse_non_regular_output(a->dir + "/" + golden_stem(p) + ext);
                }
                make_output_dir(a->dir);
                if (mesh_scene) write_file_atomically(mesh_scene->first, mesh_scene->second);
                const long n = run_campaign(*a);
                const long asked = static_cast<long>(a->scenes.size()) + (a->family.empty() ? 0 : a->count);
                const std::string what = a->scenes.empty() ? " " + a->family : "";
                if (!internal::quiet())
                    std::cerr << "scalecert: wrote " << n << what << (n == 1 ? " scene" : " scenes")
                              << " with exact answers to " << a->dir
                              << (n < asked ? " (" + std::to_string(asked - n) + " not written, noted above)" : "")
                              << "\n";
                return 0;
            }};
}

}  // namespace scalecert::cli
