// scalecert grid: the paper's floating-point grid search (a baseline, not certified).
#include "campaign_options.hpp"
#include "common.hpp"

#include "baselines/baselines.hpp"

namespace scalecert::cli {

using namespace internal;

Command add_grid(CLI::App& app) {
    struct Args {
        SceneArgs scene;
        std::string out, method = "libccd-gjk";
        int n = 64, bisections = 0;
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub =
        app.add_subcommand("grid", "the paper's floating-point grid search (a baseline, not certified; JSON)");
    a->scene.add(sub);
    sub->add_option("--n", a->n, "grid resolution per axis")->check(whole_number(2, 4096));
    sub->add_option("--bisections", a->bisections, "bisection steps per column")->check(whole_number(0, 60));
    sub->add_option(
        "--method", a->method,
        "libccd-gjk | libccd-mpr | double-envelope | paper-tritri | fcl-gjk-libccd | fcl-gjk-indep | bullet-gjk-epa");
    add_out(sub, a->out);
    example(sub,
            "Example:\n  scalecert grid certificates/scenes/tetra_box_switch.json --n 40 --bisections 8 --method "
            "fcl-gjk-indep");
    return {sub, [a] {
                StageClock clock;
                std::unique_ptr<SceneEngine> engine = open_engine(a->scene, Engine::Hull, clock);
                const Model& m = engine->convex_session(convex_only(a->scene.name(), "the grid search")).hull();
                const fp::FpScene f = fp::to_fp(m.scene);
                std::unique_ptr<fp::Method> meth = fp::make_method(a->method, m, f);
                if (!meth) throw InputError("--method: unknown method '" + a->method + "'");
                const fp::GridCurve gc = fp::grid_search(*meth, f, a->n, a->bisections, a->bisections ? 3 : 1);
                Json j;
                j["method"] = meth->name();
                j["n"] = a->n;
                j["bisections"] = a->bisections;
                j["classifications"] = gc.classifications;
                Json samples = Json::array();
                for (size_t i = 0; i < gc.rho1.size(); ++i) samples.push_back(Json::array({gc.rho1[i], gc.rho2[i]}));
                j["samples"] = samples;
                emit(dump(j), a->out);
                return 0;
            }};
}

}  // namespace scalecert::cli
