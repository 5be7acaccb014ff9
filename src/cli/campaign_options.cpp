#include "campaign_options.hpp"
#include "file_name.hpp"

#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#ifdef SCALECERT_WITH_BASELINES
#include "baselines/audit.hpp"
#endif

namespace scalecert::cli {

CLI::Option* add_numbers(CLI::App* sub, Numbers& numbers) {
    CLI::Option* o =
        sub->add_option_function<std::string>(
               "--numbers",
               [&numbers](const std::string& v) {
                   if (v == "double")
                       numbers = Numbers::Double;
                   else if (v == "float32")
                       numbers = Numbers::Float32;
                   else if (v == "exact")
                       numbers = Numbers::Exact;
                   else
                       throw CLI::ValidationError("--numbers", "expected double, float32 or exact, not '" + v + "'");
               },
               "what a decimal written as a floating-point program writes it means (a JSON number, a mesh's or a "
               "claim's number, a number on the command line): double (default: the double strtod reads), "
               "float32 (the float strtof reads) or exact (as written: 0.1 = 1/10); JSON strings and fractions "
               "p/q are exact always")
            ->type_name("double|float32|exact");
    // The earlier name of the default, kept so that scripts written for it still run; with
    // --numbers it is refused, as two answers to one question.
    sub->add_flag_callback("--binary-doubles",
                           [&numbers, o] {
                               if (o->count() > 0)
                                   throw CLI::ValidationError("--binary-doubles",
                                                              "the earlier name of --numbers double: give one of them");
                               numbers = Numbers::Double;
                           })
        ->group("");
    return o;
}

namespace {

// A seed's check: decimal digits only (CLI11 then refuses a value past 2^64 - 1).
CLI::Validator digits_only() {
    return CLI::Validator(
        [](std::string& v) {
            return !v.empty() && v.find_first_not_of("0123456789") == std::string::npos
                       ? std::string()
                       : "not a whole number from 0 to 2^64 - 1: " + v;
        },
        "UINT64");
}

}  // namespace

void add_golden_options(CLI::App* sub, internal::CampaignArgs& a) {
    a.golden = true;
    a.opt.allow_parts = true;  // scenes of objects made of parts: golden data at their region's boundary
    add_numbers(sub, a.opt.numbers);
    sub->add_flag("--parts-from-groups", a.opt.parts_from_groups,
                  "read each OBJ mesh (--p1, --p2, or one a scene names) as an object made of convex parts, a part "
                  "per 'o' or 'g' group");
    sub->add_option(
        "SCENES", a.scenes,
        "your own scene files: golden data for each (NAME.golden.json and .csv, NAME its file name without .json)");
    sub->add_option("--family", a.family,
                    "random | parallel-faces | nearly-equal-slopes | nearly-parallel-edges | vertex-vertex | "
                    "far-from-origin | sliver | near-sphere");
    CLI::Option* count = sub->add_option("--count", a.count, "how many scenes of the family (1 to 10^7)")
                             ->check(whole_number(1, internal::kMaxGoldenCount));
    sub->add_option("--seed", a.seed, "the run's random seed (scene i's own seed is derived from it and i)")
        ->check(digits_only());
    CLI::Option* eps = sub->add_option("--eps", a.eps_text, "the family's degeneracy parameter (exact, default 2^-20)");
    sub->add_option("--verticals", a.points.verticals,
                    "how many values of rho1 to sample the boundary at, spread over the part of I1 where it crosses "
                    "the rectangle (0 to 1000; default 7), besides its switch points and where it enters and leaves")
        ->type_name("N");
    sub->add_option_function<std::string>(
           "--offsets",
           [&a](const std::string& v) {
               try {
                   a.points.offsets = internal::parse_offsets(v);
               } catch (const InputError& e) {
                   throw CLI::ValidationError(e.what());
               }
           },
           "the pairs above, below, left and right of each sampled boundary point, 2^-K of its coordinate away, "
           "for each K given (1 to 1074; default 4,12,20,30,40,52)")
        ->type_name("K,K,...");
    // --count and --eps make a family's scenes: with scenes of the user's alone they would do nothing.
    sub->parse_complete_callback([&a, count, eps] {
        if (a.family.empty() && (count->count() > 0 || eps->count() > 0))
            throw CLI::ValidationError(count->count() > 0 ? "--count" : "--eps",
                                       "sets the scenes of a --family; for your scenes' pairs give --verticals N "
                                       "and --offsets K,K,...");
    });
    sub->add_option("--dir", a.dir,
                    "output directory (created): NAME.scene.json, NAME.golden.json, NAME.golden.csv, "
                    "NAME.golden.rational.csv per scene")
        ->required()
        ->check(file_name());
}

namespace {
// A finite number above `lo` (strictly, or at least `lo`): the methods' settings.
// A finite double above (strict) or at least lo, read as strtod reads it (a subnormal is its
// value, not an error); as_float: also 0 or a number whose nearest float is normal, for what
// Bullet (built with float btScalar, as Debian's is) holds, and taken as that float (so the rows
// record the value Bullet used).
}  // namespace

CLI::Validator whole_number(long long lo, long long hi) {
    return CLI::Validator(
        [lo, hi](std::string& v) {
            const size_t digits = v.size() - (!v.empty() && v[0] == '-' && lo < 0);
            bool ok =
                digits > 0 && digits <= 19 && v.find_first_not_of("0123456789", v.size() - digits) == std::string::npos;
            if (ok) {
                errno = 0;
                const long long x = std::strtoll(v.c_str(), nullptr, 10);
                ok = errno == 0 && x >= lo && x <= hi;
            }
            return ok ? std::string()
                      : "not a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ": " + v;
        },
        "INT in [" + std::to_string(lo) + " - " + std::to_string(hi) + "]");
}

namespace {

CLI::Validator finite_number(double lo, bool strict, bool as_float = false) {
    return CLI::Validator(
        [lo, strict, as_float](std::string& v) {
            errno = 0;
            char* end = nullptr;
            const double x =
                v.empty() || std::isspace(static_cast<unsigned char>(v[0])) ? NAN : std::strtod(v.c_str(), &end);
            if (end != v.c_str() + v.size() || !std::isfinite(x) || (strict ? !(x > lo) : !(x >= lo)))
                return std::string("not a finite number ") + (strict ? "above " : "of at least ") +
                       (lo == 0 ? "0" : std::to_string(lo)) + ": " + v;
            if (as_float) {
                const float f = static_cast<float>(x);
                if (x != 0 && !(std::fabs(f) >= FLT_MIN && std::isfinite(f)))
                    return "Bullet holds it as a float, so it must be 0 or have a normal float nearest it (from "
                           "1.17549435e-38 to 3.40282347e38), not " +
                           v;
                char held[40];
                std::snprintf(held, sizeof held, "%.17g", static_cast<double>(f));
                v = held;
            }
            return std::string();
        },
        "NUMBER");
}
}  // namespace

void add_audit_options(CLI::App* sub, internal::CampaignArgs& a) {
    a.golden = false;
#ifdef SCALECERT_WITH_BASELINES
    a.auditor = internal::baseline_auditor();
#endif
    sub->add_option("SCENES", a.scenes, "scene files");
    a.opt.allow_parts = true;  // scenes of objects made of parts, for the compound methods
    sub->add_option(
           "--methods", a.methods,
           "libccd-gjk libccd-mpr double-envelope paper-tritri fcl-gjk-libccd fcl-gjk-indep bullet-gjk-epa grid; "
           "for objects made of parts: bullet-compound fcl-compound-libccd fcl-compound-indep libccd-gjk-parts")
        ->delimiter(',');
    sub->add_option("--grid", a.grid, "grid resolutions for the grid method (2 to 4096)")
        ->delimiter(',')
        ->check(whole_number(2, 4096));
    sub->add_option("--family", a.family, "also audit a family over an eps sweep (with --sweep)");
    sub->add_option(
           "--command", a.command,
           "audit your own program beside --methods: run once per scene as CMD SCENE.json PAIRS.json CLAIMS.json, it "
           "reads the scene and the pairs of doubles asked and writes one verdict claim per pair (docs/audits.md)")
        ->type_name("CMD")
        ->check(CLI::Validator(
            [](std::string& v) {
                return v.find_first_not_of(" \t\r\n") == std::string::npos ? std::string("an empty command") : "";
            },
            "CMD"));
    sub->add_option("--command-timeout", a.settings.command_timeout,
                    "seconds --command's program may run per scene before it is stopped, with every process it "
                    "started, its row then saying it did not run (default 600)")
        ->type_name("SECONDS")
        ->check(finite_number(0, true));
    // After --methods (whatever the order on the line): the user's program is one method more.
    sub->parse_complete_callback([&a] {
        if (!a.command.empty()) a.methods.push_back(internal::kCommandMethod + a.command);
    });
    sub->add_flag("--atlas", a.atlas,
                  "also audit the failure atlas: a family per class of failure users report (face-to-face, "
                  "long-edge, scaled, touching, decomposition-gap), each at its own eps values, --count scenes each "
                  "(docs/audits.md)");
    sub->add_option("--sweep", a.sweep_from, "eps = 2^-K for K from this (0 to 1074) ...")
        ->check(whole_number(0, 1074));
    sub->add_option("--sweep-to", a.sweep_to, "... to this (inclusive, 0 to 1074)")->check(whole_number(0, 1074));
    sub->add_option("--count", a.count, "scenes per eps in the sweep (1 to 10^6)")->check(whole_number(1, 1000000));
    sub->add_option("--seed", a.seed,
                    "the run's random seed (each family scene's own seed is derived from it, K and its index)")
        ->check(digits_only());
    add_numbers(sub, a.opt.numbers);
    sub->add_flag("--parts-from-groups", a.opt.parts_from_groups,
                  "read each OBJ mesh a scene names as an object made of convex parts, a part per 'o' or 'g' group");
    sub->add_option("--out", a.out, "write the JSON to FILE (atomically) instead of standard output")
        ->type_name("FILE")
        ->check(file_name());
    sub->add_option("--failures", a.failures,
                    "write reproducers into DIR (created): for each scene and method with wrong verdicts, a claims "
                    "file of them (the first 50) that scalecert certify-fp replays, exit 1 while the method is "
                    "wrong; a family scene's file beside it; DIR/index.json lists each with its command")
        ->type_name("DIR")
        ->check(file_name());
    sub->add_option("--csv", a.csv, "also write the rows as CSV to FILE (both files written together)")
        ->type_name("FILE")
        ->check(file_name());
    sub->add_flag("!--no-measures", a.measures,
                  "verdicts only: skip comparing the methods' distances and depths with the exact ones (proved at "
                  "floating-point speed)");
    sub->add_option("--measure-tolerance", a.settings.measure_tolerance,
                    "the relative error past which a method's distance or depth is listed as a failure, with a "
                    "reproducer under --failures replayed at that tolerance (default 1e-6)")
        ->type_name("REL")
        ->check(finite_number(0, true));
    sub->add_flag("--by-distance", a.by_distance,
                  "also count wrong verdicts at relative distances 2^-4 ... 2^-52 from the curve, or from the region's "
                  "boundary for objects made of parts (JSON: by_distance)");
    sub->add_flag("--no-timing", a.no_timing,
                  "leave the timing columns out: the rest is byte-identical on any number of processes");
    // The methods' own settings: each method reads those it has, and its rows record them.
    internal::MethodSettings& st = a.settings;
    sub->add_option("--bullet-margin", st.bullet_margin,
                    "Bullet's collision margin on every shape (bullet-*; default 0, the shapes as given; Bullet's "
                    "own default is 0.04)")
        ->type_name("M")
        ->transform(finite_number(0, false, true));  // transform: takes the float it holds
    sub->add_option("--fcl-gjk-tolerance", st.fcl_gjk_tolerance,
                    "FCL's CollisionRequest gjk_tolerance (fcl-*; default 1e-6, FCL's)")
        ->type_name("T")
        ->check(finite_number(0, true));
    sub->add_option("--fcl-distance-tolerance", st.fcl_distance_tolerance,
                    "FCL's DistanceRequest distance_tolerance (fcl-*; default 1e-6, FCL's)")
        ->type_name("T")
        ->check(finite_number(0, true));
    sub->add_option("--ccd-max-iterations", st.ccd_max_iterations, "libccd's max_iterations (libccd-*; default 500)")
        ->type_name("N")
        ->check(whole_number(1, 1000000000));
    sub->add_option("--ccd-epa-tolerance", st.ccd_epa_tolerance, "libccd's epa_tolerance (default 1e-4, libccd's)")
        ->type_name("T")
        ->check(finite_number(0, true));
    sub->add_option("--ccd-mpr-tolerance", st.ccd_mpr_tolerance, "libccd's mpr_tolerance (default 1e-4, libccd's)")
        ->type_name("T")
        ->check(finite_number(0, true));
}

}  // namespace scalecert::cli
