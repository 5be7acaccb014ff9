// scalecert partition: the certified partition of I1 x I2, the certificate scalecert-check reads.
#include "common.hpp"

namespace scalecert::cli {

using namespace internal;

Command add_partition(CLI::App& app) {
    struct Args {
        SceneArgs scene;
        std::string out, engine = "auto";
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand("partition", "the certified partition of I1 x I2 (the certificate, JSON)");
    a->scene.add(sub);
    add_out(sub, a->out);
    add_engine(sub, a->engine);
    example(sub,
            "Examples:\n  scalecert partition certificates/scenes/stacked_cubes.json --out cert.json && "
            "scalecert-check cert.json\n"
            "  scalecert partition tests/data/compound_u_peg.json --out u_peg.cert.json   # objects made of parts: a "
            "compound_partition");
    return {sub, [a] {
                StageClock clock;
                // From 2,000 points the walk's curve and witnesses (no hull), as for `curve`; on
                // objects made of parts, the region's certified partition (region --certificate).
                a->scene.opt.allow_parts = true;
                emit(open_engine(a->scene, engine_named(a->engine), clock)->partition_document(), a->out);
                return 0;
            }};
}

}  // namespace scalecert::cli
