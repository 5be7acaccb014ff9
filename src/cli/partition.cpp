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
                internal::Session session = open_session(a->scene, Engine::Hull, clock);
                const Model& m = session.hull();
                const internal::Curve& c = session.hull_curve();
                emit(dump(partition_json(m, c, build_partition(m, c))), a->out);
                clock.lap("partition and output");
                return 0;
            }};
}

}  // namespace scalecert::cli
