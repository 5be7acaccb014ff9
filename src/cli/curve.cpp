// scalecert curve: the touching curve over I1, its switch points and the growth distance.
#include "common.hpp"
#include "segment/segment_json.hpp"

namespace scalecert::cli {

using namespace internal;

Command add_curve(CLI::App& app) {
    struct Args {
        SceneArgs scene;
        std::string out, segment, engine = "auto";
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub =
        app.add_subcommand("curve", "the touching curve over I1, its switch points and the growth distance (JSON)");
    a->scene.add(sub);
    add_out(sub, a->out);
    sub->add_option("--segment", a->segment,
                    "add the t1-t2 curve along a segment: seeds | ellipsoids | x1,y1,z1:x2,y2,z2");
    add_engine(sub, a->engine);
    example(sub,
            "Examples:\n  scalecert curve certificates/scenes/tetra_box_switch.json\n"
            "  scalecert curve --p1 examples/tetra.obj --p2 examples/box.stl --i1 1/2,2 --i2 1,4 --out curve.json");
    return {sub, [a] {
                StageClock clock;
                // --segment lists the faces of both hulls: the hull path.
                const Engine e = !a->segment.empty() ? Engine::Hull : engine_named(a->engine);
                a->scene.opt.allow_parts = true;
                std::unique_ptr<SceneEngine> engine = open_engine(a->scene, e, clock);
                internal::Session& session = engine->convex_session(convex_only(a->scene.name(), "the touching curve"));
                Json j;
                if (a->segment.empty()) {
                    j = curve_json(session.curve_model(), session.curve());
                } else {
                    const internal::HullModel& m = session.hull();
                    const internal::TouchingCurve& c = session.hull_curve();
                    j = curve_json(m, c);
                    add_segment_json(j, m, c, parse_segment(a->segment, m, a->scene.opt));
                }
                emit(dump(j), a->out);
                clock.lap("output");
                return 0;
            }};
}

}  // namespace scalecert::cli
