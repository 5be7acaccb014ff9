// scalecert certify-fp: a floating-point program's claims marked right or wrong, exactly. Exit 1
// when any claim is wrong, so that it can gate another project's CI.
#include "common.hpp"

#include "file_name.hpp"
#include "io/files.hpp"

#include <memory>
#include <optional>

namespace scalecert::cli {

using namespace internal;

Command add_certify_fp(CLI::App& app) {
    struct Args {
        SceneArgs scene;
        std::string out, claims, tolerance = "0", abs_tolerance = "0", certificate;
        bool json = false;
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand(
        "certify-fp", "mark a floating-point program's claims right or wrong, exactly (exit 1 if any is wrong)");
    a->scene.add(sub);
    sub->add_option(
        "CLAIMS", a->claims,
        "claims ('-': standard input): JSON (scalecert-claims-1, certificates/CLAIMS.md), or lines 'RHO1 RHO2 "
        "VERDICT', 'curve RHO1 RHO2', 'growth RHO'; "
        "on objects made of parts: verdict, separating_plane, witness_point and distance claims, and verdict lines");
    sub->add_option("--tolerance", a->tolerance,
                    "accept numeric claims within this relative error (exact, e.g. 1e-9; JSON claims); verdicts, "
                    "contacts, planes and witness points must be exact, unless --abs-tolerance")
        ->type_name("REL");
    sub->add_option("--abs-tolerance", a->abs_tolerance,
                    "a length (exact, e.g. 1e-9; JSON claims): a point within it of its body is taken as in it, a "
                    "distance or depth within it plus the relative tolerance as right, a body within it past a "
                    "separating plane as on its side (certificates/CLAIMS.md, \"Tolerances\")")
        ->type_name("LEN");
    sub->add_flag("--json", a->json, "the report as JSON");
    // The earlier name of --numbers exact, kept so that scripts written for it still run.
    sub->add_flag_callback("--exact-decimals",
                           [a, numbers = sub->get_option("--numbers"), binary = sub->get_option("--binary-doubles")] {
                               if (numbers->count() > 0 || binary->count() > 0)
                                   throw CLI::ValidationError("--exact-decimals",
                                                              "the earlier name of --numbers exact: give one of them");
                               a->scene.opt.numbers = Numbers::Exact;
                           })
        ->group("");
    add_out(sub, a->out);
    sub->add_option(
           "--certificate", a->certificate,
           "also write the judgements certificate: the proof of every judgement, for scalecert-check "
           "(certificates/FORMAT.md, \"A judgements file\"; on objects made of parts, \"A compound judgements file\")")
        ->type_name("FILE")
        ->check(file_name());
    example(sub,
            "Exit status: 0 all claims right, 1 some claim wrong, 2 bad input. Example:\n"
            "  printf '1 1 separated\\ngrowth 1.5\\n' > claims.txt\n"
            "  scalecert certify-fp certificates/scenes/stacked_cubes.json claims.txt\n"
            "  scalecert certify-fp certificates/scenes/stacked_cubes.json examples/claims.json --tolerance 1e-12\n"
            "  scalecert certify-fp tests/data/compound_band.json tests/data/compound_band_claims.json   # objects "
            "made of parts");
    return {sub, [a] {
                a->scene.shift_positionals({&a->claims});
                if (a->claims.empty()) throw InputError("CLAIMS is required (see scalecert certify-fp --help)");
                internal::refuse_outputs_over_inputs({a->out, a->certificate},
                                                     {a->claims, a->scene.path, a->scene.mesh[0], a->scene.mesh[1]});
                // The tolerances first: a mistyped one is said before a large scene is read.
                ClaimOptions opt{a->scene.opt.numbers, Q(0), a->json};
                opt.tolerance = read_tolerance(a->tolerance, "--tolerance");
                opt.abs_tolerance = read_tolerance(a->abs_tolerance, "--abs-tolerance");
                StageClock clock;
                // A scene of parts goes to the compound judge; a plain one to the session.
                a->scene.opt.allow_parts = true;
                std::unique_ptr<SceneEngine> engine = open_engine(a->scene, Engine::Auto, clock);
                const std::string claims = read_input(a->claims, "claims file", kMaxSceneBytes);
                long wrong = 0;
                std::string certificate;
                std::string* cert = a->certificate.empty() ? nullptr : &certificate;
                const std::unique_ptr<ClaimRules> rules = engine->rules({opt.tolerance, opt.abs_tolerance});
                const std::string report = certify_fp(*rules, claims, a->claims, opt, &wrong, nullptr, cert);
                if (a->certificate.empty())
                    emit(report, a->out);
                else if (a->out.empty()) {
                    write_file_atomically(a->certificate, certificate);
                    emit(report, a->out);
                } else {
                    write_files_atomically({{a->certificate, certificate}, {a->out, report}});
                }
                return wrong > 0 ? 1 : 0;
            }};
}

}  // namespace scalecert::cli
