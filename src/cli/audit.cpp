// scalecert audit: floating-point methods run on scenes and compared with the exact answers.
#include "common.hpp"

#include "scalecert/audit.hpp"

#include <iostream>

namespace scalecert::cli {

using namespace internal;

Command add_audit(CLI::App& app) {
    struct Args {
        std::vector<std::string> scenes;
        std::vector<std::string> methods{"libccd-gjk", "libccd-mpr", "fcl-gjk-libccd", "fcl-gjk-indep", "bullet-gjk-epa", "double-envelope", "paper-tritri", "grid"};
        std::vector<int> grid{16, 64, 256};
        std::string family, out, csv;
        int sweep_from = 0, sweep_to = 0, count = 1;
        unsigned long long seed = 1;
        ReadOptions opt;
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand("audit", "run floating-point methods on scenes and compare with the exact answers (JSON, and CSV with --csv)");
    sub->add_option("SCENES", a->scenes, "scene files");
    sub->add_option("--methods", a->methods, "libccd-gjk libccd-mpr double-envelope paper-tritri fcl-gjk-libccd fcl-gjk-indep bullet-gjk-epa grid")->delimiter(',');
    sub->add_option("--grid", a->grid, "grid resolutions for the grid method (2 to 4096)")->delimiter(',')->check(CLI::Range(2, 4096));
    sub->add_option("--family", a->family, "also audit a family over an eps sweep (with --sweep)");
    sub->add_option("--sweep", a->sweep_from, "eps = 2^-K for K from this (0 to 1074) ...")->check(CLI::Range(0, 1074));
    sub->add_option("--sweep-to", a->sweep_to, "... to this (inclusive, 0 to 1074)")->check(CLI::Range(0, 1074));
    sub->add_option("--count", a->count, "scenes per eps in the sweep")->check(CLI::Range(1, 10000));
    sub->add_option("--seed", a->seed, "random seed for the sweep");
    sub->add_flag("--binary-doubles", a->opt.binary_doubles, "read the scene files' numbers as IEEE doubles");
    add_out(sub, a->out);
    sub->add_option("--csv", a->csv, "also write the rows as CSV to FILE (both files written together)")->type_name("FILE");
    example(sub, "Example:\n  scalecert audit certificates/scenes/*.json --grid 64 --out audit.json --csv audit.csv\n"
                 "  scalecert audit --family nearly-equal-slopes --sweep 4 --sweep-to 40 --count 2 --out sweep.json");
    return {sub, [a] {
                if (!a->family.empty()) family_description(a->family);  // refused before any work
                if (!a->family.empty() && a->sweep_to < a->sweep_from) throw InputError("--sweep-to must be >= --sweep");
                std::vector<AuditRow> rows;
                for (const std::string& p : a->scenes) {
                    std::cerr << "scalecert: audit: " << p << "\n";
                    const internal::Scene sc = load_scene(p, a->opt);  // its errors name the file already
                    std::vector<AuditRow> r;
                    try {
                        r = audit_scene(p, sc, Q(0), a->methods, a->grid);
                    } catch (const InputError& e) {
                        throw InputError(p + ": " + e.what());
                    }
                    rows.insert(rows.end(), r.begin(), r.end());
                }
                if (!a->family.empty()) {
                    for (int k = a->sweep_from; k <= a->sweep_to; ++k) {
                        const Q eps(1, Z(1) << k);
                        Rng g(a->seed);
                        for (int i = 0; i < a->count; ++i) {
                            std::cerr << "scalecert: audit: " << a->family << " eps = 2^-" << k << ", scene " << i + 1 << "/" << a->count << "\r";
                            auto r = audit_scene(a->family + "-" + std::to_string(i), make_family_scene(a->family, eps, g), eps, a->methods, a->grid);
                            rows.insert(rows.end(), r.begin(), r.end());
                        }
                    }
                    std::cerr << "\n";
                }
                if (rows.empty()) throw InputError("audit: no scenes (give SCENES or --family with --sweep)");
                const std::string json = dump(audit_json(rows));
                if (a->csv.empty()) {
                    emit(json, a->out);
                } else if (a->out.empty()) {
                    write_file_atomically(a->csv, audit_csv(rows));
                    emit(json, a->out);
                } else {
                    // Both texts first, then both files together: a failure leaves neither.
                    write_files_atomically({{a->csv, audit_csv(rows)}, {a->out, json}});
                }
                std::cerr << "scalecert: audit: " << rows.size() << " rows\n";
                return 0;
            }};
}

}  // namespace scalecert::cli
