// scalecert golden: scenes of a family with their exact answers, for other projects' test suites.
#include "common.hpp"

#include "scalecert/audit.hpp"

#include <filesystem>
#include <iostream>

namespace scalecert::cli {

using namespace internal;

Command add_golden(CLI::App& app) {
    struct Args {
        std::string family, eps = "1/1048576", dir;
        int count = 1;
        unsigned long long seed = 1;
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand("golden", "scenes of a family with exact answers, as JSON and CSV files in a directory");
    sub->add_option("--family", a->family, "random | parallel-faces | nearly-equal-slopes | nearly-parallel-edges | vertex-vertex | far-from-origin | sliver | near-sphere")->required();
    sub->add_option("--count", a->count, "how many scenes")->check(CLI::Range(1, 100000));
    sub->add_option("--seed", a->seed, "random seed");
    sub->add_option("--eps", a->eps, "degeneracy parameter (exact, default 2^-20)");
    sub->add_option("--dir", a->dir, "output directory (created): NAME-i.scene.json, NAME-i.golden.json, NAME-i.golden.csv")->required();
    example(sub, "Example:\n  scalecert golden --family nearly-equal-slopes --count 10 --eps 1/1024 --dir golden/");
    return {sub, [a] {
                const Q eps = parse_exact(a->eps);
                if (sgn(eps) <= 0) throw InputError("--eps must be > 0");
                family_description(a->family);  // an unknown family is refused before anything is created
                std::error_code ec;
                std::filesystem::create_directories(a->dir, ec);
                if (ec || !std::filesystem::is_directory(a->dir))
                    throw InputError(a->dir + ": cannot create the output directory (" + (ec ? ec.message() : "not a directory") + ")");
                write_golden(a->family, a->count, a->seed, eps, a->dir);
                std::cerr << "scalecert: wrote " << a->count << " " << a->family << " scenes with exact answers to " << a->dir << "\n";
                return 0;
            }};
}

}  // namespace scalecert::cli
