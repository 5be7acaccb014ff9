// scalecert golden: scenes of a family with their exact answers, for other projects' test suites.
#include "campaign_options.hpp"
#include "common.hpp"

#include <iostream>

namespace scalecert::cli {

using namespace internal;

Command add_golden(CLI::App& app) {
    auto a = std::make_shared<CampaignArgs>();
    CLI::App* sub = app.add_subcommand("golden", "exact answers near the touching curve of your scenes, or of a family's, as JSON and CSV files in a directory");
    add_golden_options(sub, *a);
    example(sub, "Examples:\n  scalecert golden --family nearly-equal-slopes --count 10 --eps 1/1024 --dir golden/\n"
                 "  scalecert golden certificates/scenes/tetra_box_switch.json --dir golden/\n"
                 "(On a cluster: mpirun scalecert-mpi golden, with the same options and a run folder.)");
    return {sub, [a] {
                validate(*a);  // an unknown family is refused before anything is created
                make_output_dir(a->dir);
                run_campaign(*a);
                const long n = static_cast<long>(a->scenes.size()) + (a->family.empty() ? 0 : a->count);
                const std::string what = a->scenes.empty() ? " " + a->family : "";
                std::cerr << "scalecert: wrote " << n << what << (n == 1 ? " scene" : " scenes") << " with exact answers to " << a->dir << "\n";
                return 0;
            }};
}

}  // namespace scalecert::cli
