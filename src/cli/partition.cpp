// scalecert partition: the certified partition of I1 x I2, the certificate scalecert-check reads.
#include "common.hpp"

namespace scalecert::cli {

using namespace internal;

Command add_partition(CLI::App& app) {
    struct Args {
        SceneArgs scene;
        std::string out;
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand("partition", "the certified partition of I1 x I2 (the certificate, JSON)");
    a->scene.add(sub);
    add_out(sub, a->out);
    example(sub, "Example:\n  scalecert partition certificates/scenes/stacked_cubes.json --out cert.json && scalecert-check cert.json");
    return {sub, [a] {
                StageClock clock;
                const Analysed an = analyse(a->scene, clock);
                emit(dump(partition_json(an.m, an.c, build_partition(an.m, an.c))), a->out);
                clock.lap("partition and output");
                return 0;
            }};
}

}  // namespace scalecert::cli
