// scalecert query: separated / touching / overlapping at one scaling pair, with its certificate.
#include "common.hpp"
#include "segment/segment_json.hpp"

namespace scalecert::cli {

using namespace internal;

Command add_query(CLI::App& app) {
    struct Args {
        SceneArgs scene;
        std::string out, rho1, rho2, segment, engine = "auto";
        bool json = false, in_t = false;
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand("query", "separated / touching / overlapping at (RHO1, RHO2)");
    a->scene.add(sub);
    sub->add_option("RHO1", a->rho1,
                    "scaling of P1: a fraction (3/2, exact) or a decimal (1.5, read as --numbers says)");
    sub->add_option("RHO2", a->rho2, "scaling of P2");
    sub->add_flag("--json", a->json, "the verdict with its certificate, as JSON");
    sub->add_option("--segment", a->segment,
                    "report t1, t2 and the gap along a segment: seeds | ellipsoids | x1,y1,z1:x2,y2,z2");
    sub->add_flag("--in-t", a->in_t, "RHO1 RHO2 are t1 t2 along the segment (default: seeds)");
    add_out(sub, a->out);
    add_engine(sub, a->engine);
    example(sub,
            "Examples:\n  scalecert query certificates/scenes/stacked_cubes.json 3/2 3/2        # touching\n"
            "  scalecert query certificates/scenes/stacked_cubes.json 1 1.9 --json  # with its certificate");
    return {sub, [a] {
                a->scene.shift_positionals({&a->rho1, &a->rho2});
                if (a->rho1.empty() || a->rho2.empty())
                    throw InputError("RHO1 and RHO2 are required (see scalecert query --help)");
                StageClock clock;
                // The verdict and its certificate may come from the walk; a segment needs the hull.
                a->scene.opt.allow_parts = true;
                std::unique_ptr<SceneEngine> engine = open_engine(a->scene, engine_named(a->engine), clock);
                std::string segment = a->segment;
                if (a->in_t && segment.empty()) segment = "seeds";
                // A segment lies in two convex objects' hulls.
                Session* session = nullptr;
                std::optional<Segment> seg;
                if (!segment.empty()) {
                    session = &engine->convex_session(
                        "--segment and --in-t are for two convex objects (`scalecert region` gives where objects made "
                        "of parts meet)");
                    seg = parse_segment(segment, session->hull(), a->scene.opt);
                }
                Q r1, r2;
                if (a->in_t) {
                    const Q t1 = read_rho(a->rho1, "T1", a->scene.opt), t2 = read_rho(a->rho2, "T2", a->scene.opt);
                    auto x = rho_from_t(*seg, 0, t1), y = rho_from_t(*seg, 1, t2);
                    if (!x) throw InputError("T1: outside t1(I1)");
                    if (!y) throw InputError("T2: outside t2(I2)");
                    r1 = *x;
                    r2 = *y;
                } else {
                    r1 = read_rho(a->rho1, "RHO1", a->scene.opt);
                    r2 = read_rho(a->rho2, "RHO2", a->scene.opt);
                }
                std::string text;
                if (a->json && !seg) {
                    text = engine->verdict_document(r1, r2);
                } else if (a->json) {
                    const Model& m = session->hull();
                    Json j = query_json(m, internal::query(m, session->hull_curve(), r1, r2, true),
                                        internal::seed_weights(m));
                    add_query_segment_json(j, *seg, r1, r2);
                    text = dump(j);
                } else {
                    text = std::string(verdict_name(engine->verdict(r1, r2))) + "\n";
                    if (a->in_t) text += "rho1 " + to_exact_string(r1) + "\nrho2 " + to_exact_string(r2) + "\n";
                    if (seg) {
                        if (!seg->note.empty()) text += "note " + seg->note + "\n";
                        const Q g = directional_gap(*seg, r1, r2);
                        text += "t1 " + to_exact_string(eval(seg->t[0], r1)) + "\nt2 " +
                                to_exact_string(eval(seg->t[1], r2)) + "\ngap_fraction " + to_exact_string(g) +
                                "\ngap_distance ~" + std::to_string(scaled_length(seg->v1, seg->v2, g)) + "\n";
                    }
                }
                emit(text, a->out);
                clock.lap("query and output");
                return 0;
            }};
}

}  // namespace scalecert::cli
