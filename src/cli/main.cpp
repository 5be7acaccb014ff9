// The scalecert command: curve, query, partition.
#include "scalecert/certificate.hpp"
#include "scalecert/fast_query.hpp"
#include "scalecert/timing.hpp"
#include "scalecert/audit.hpp"
#include "scalecert/baselines.hpp"
#include "scalecert/mesh.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <cmath>
#include <optional>
#include <thread>

using namespace scalecert;

namespace {

// To standard output, or to --out through a temporary file and a rename.
void emit(const std::string& text, const std::string& out) {
    if (!out.empty()) return write_file_atomically(out, text);
    std::cout << text;
    std::cout.flush();
    if (!std::cout) throw InputError("cannot write to standard output");
}

Q read_rho(const std::string& text, const char* name, const ReadOptions& opt) {
    Q r;
    try {
        r = parse_number(text, opt.binary_doubles);
    } catch (const InputError& e) {
        throw InputError(std::string(name) + ": " + e.what());
    }
    if (sgn(r) <= 0) throw InputError(std::string(name) + ": a scaling factor must be > 0");
    return r;
}

// "A,B" or "A,B,C": numbers separated by commas, read as the scene reader reads them.
std::vector<Q> number_list(const std::string& text, size_t n, const std::string& option, const ReadOptions& opt) {
    std::vector<Q> out;
    size_t b = 0;
    for (;;) {
        const size_t e = text.find(',', b);
        try {
            out.push_back(parse_number(text.substr(b, e == std::string::npos ? std::string::npos : e - b), opt.binary_doubles));
        } catch (const InputError& err) {
            throw InputError(option + ": " + err.what());
        }
        if (e == std::string::npos) break;
        b = e + 1;
    }
    if (out.size() != n) throw InputError(option + ": expected " + std::to_string(n) + " numbers separated by commas, got " + quoted(text));
    return out;
}

Segment parse_segment(const std::string& spec, const Model& m) {
    if (spec == "seeds" || spec == "ellipsoids") return segment_by_kind(m, spec);
    auto colon = spec.find(':');
    if (colon == std::string::npos) throw InputError("--segment: expected 'seeds' or x1,y1,z1:x2,y2,z2");
    Vec3q v[2];
    const std::string parts[2] = {spec.substr(0, colon), spec.substr(colon + 1)};
    for (int i = 0; i < 2; ++i) {
        const std::vector<Q> c = number_list(parts[i], 3, "--segment", ReadOptions{});  // exact, as written
        v[i] = {c[0], c[1], c[2]};
    }
    return make_segment(m, v[0], v[1]);
}

// An error message as one line: control characters (a newline in a file name or a number)
// escaped, and at most 1000 characters.
std::string one_line(const std::string& msg) {
    std::string out;
    for (unsigned char c : msg) {
        if (out.size() >= 1000) return out + "... (cut)";
        if (c < 0x20 || c == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", c);
            out += buf;
        } else {
            out += static_cast<char>(c);
        }
    }
    return out;
}

// A scene straight from two mesh files and the ranges, checked as a scene file would be.
Scene scene_from_options(const std::string mesh[2], const std::string interval[2], const std::string seed[2], const ReadOptions& opt) {
    if (mesh[0].empty() || mesh[1].empty() || interval[0].empty() || interval[1].empty())
        throw InputError("give SCENE, or --p1 and --p2 (mesh files) with --i1 and --i2 (LO,HI)");
    Scene sc;
    for (int i = 0; i < 2; ++i) {
        const std::string n = std::to_string(i + 1);
        sc.P[i].points = read_mesh(mesh[i], opt);
        const std::vector<Q> r = number_list(interval[i], 2, "--i" + n, opt);
        sc.lo[i] = r[0];
        sc.hi[i] = r[1];
        if (!seed[i].empty()) {
            const std::vector<Q> s = number_list(seed[i], 3, "--seed" + n, opt);
            sc.P[i].seed = {s[0], s[1], s[2]};
            sc.P[i].seed_given = true;
        }
    }
    finish_scene(sc, "command line");
    return sc;
}

// The model of a scene read from `path`; geometric errors name the file too.
Model model_of(const Scene& scene, const std::string& path) {
    try {
        return build_model(scene);
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
}

// GMP aborts the process when an allocation fails; this program (not the library, which must not
// replace its host's allocator) turns that into std::bad_alloc, reported below with exit 2.
void* gmp_alloc(size_t n) {
    if (void* p = std::malloc(n)) return p;
    throw std::bad_alloc();
}
void* gmp_realloc(void* p, size_t, size_t n) {
    if (void* q = std::realloc(p, n)) return q;
    throw std::bad_alloc();
}
void gmp_free(void* p, size_t) { std::free(p); }

}  // namespace

int main(int argc, char** argv) {
    mp_set_memory_functions(gmp_alloc, gmp_realloc, gmp_free);
    CLI::App app{"scalecert: exact, certified collision of uniformly scaled convex polyhedra"};
    app.require_subcommand(1);
    ReadOptions opt;
    std::string scene_path, out, rho1s, rho2s;
    bool as_json = false, in_t = false;
    std::string segment_spec;
    std::string mesh_path[2], interval_text[2], seed_text[2];
    auto common = [&](CLI::App* sub) {
        sub->add_option("SCENE", scene_path, "scene file (JSON); or --p1, --p2, --i1, --i2");
        sub->add_option("--p1", mesh_path[0], "P1 from a mesh file (.off .obj .ply .stl), with --p2, --i1, --i2 instead of SCENE");
        sub->add_option("--p2", mesh_path[1], "P2 from a mesh file");
        sub->add_option("--i1", interval_text[0], "I1 as LO,HI (exact: 1/2,3)");
        sub->add_option("--i2", interval_text[1], "I2 as LO,HI");
        sub->add_option("--seed1", seed_text[0], "P1's seed as X,Y,Z (default: the mean of its vertices)");
        sub->add_option("--seed2", seed_text[1], "P2's seed as X,Y,Z");
        sub->add_option("--out", out, "write the output to this file (atomically)");
        sub->add_flag("--binary-doubles", opt.binary_doubles, "read JSON/OFF numbers as IEEE doubles");
    };
    CLI::App* curve = app.add_subcommand("curve", "the touching curve over I1, its switch points and the growth distance");
    common(curve);
    curve->add_option("--segment", segment_spec, "add the t1-t2 curve along a segment: seeds | ellipsoids | x1,y1,z1:x2,y2,z2");
    CLI::App* query = app.add_subcommand("query", "separated / touching / overlapping at (RHO1, RHO2)");
    common(query);
    query->add_option("RHO1", rho1s, "scaling of P1 (exact: 3/2, 1.5, 15e-1)")->required();
    query->add_option("RHO2", rho2s, "scaling of P2")->required();
    query->add_flag("--json", as_json, "the verdict with its certificate, as JSON");
    query->add_option("--segment", segment_spec, "report t1, t2 and the gap along a segment: seeds | ellipsoids | x1,y1,z1:x2,y2,z2");
    query->add_flag("--in-t", in_t, "RHO1 RHO2 are t1 t2 along the segment (default: seeds)");
    CLI::App* part = app.add_subcommand("partition", "the certified partition of I1 x I2 (the certificate)");
    common(part);
    CLI::App* grid = app.add_subcommand("grid", "the paper's floating-point grid search (a baseline, not certified)");
    common(grid);
    int grid_n = 64, grid_bis = 0;
    std::string grid_method = "libccd-gjk";
    grid->add_option("--n", grid_n, "grid resolution per axis")->check(CLI::Range(2, 4096));
    grid->add_option("--bisections", grid_bis, "bisection steps per column")->check(CLI::Range(0, 60));
    grid->add_option("--method", grid_method, "libccd-gjk | libccd-mpr | double-envelope | paper-tritri | fcl-gjk-libccd | fcl-gjk-indep | bullet-gjk-epa");
    CLI::App* certify = app.add_subcommand("certify-fp", "mark a floating-point program's claims right or wrong, exactly");
    std::string claims_path;
    common(certify);
    certify->add_option("CLAIMS", claims_path, "claims: 'RHO1 RHO2 VERDICT', 'curve RHO1 RHO2' or 'growth RHO' per line")->required();
    certify->add_flag("--json", as_json, "the report as JSON");
    CLI::App* golden = app.add_subcommand("golden", "scenes of a family with exact answers, as JSON and CSV");
    std::string family, eps_text = "1/1048576", out_dir;
    int count = 1;
    unsigned long long seed = 1;
    golden->add_option("--family", family, "random | parallel-faces | nearly-equal-slopes | nearly-parallel-edges | vertex-vertex | far-from-origin | sliver | near-sphere")->required();
    golden->add_option("--count", count, "how many scenes")->check(CLI::Range(1, 100000));
    golden->add_option("--seed", seed, "random seed");
    golden->add_option("--eps", eps_text, "degeneracy parameter (exact, default 2^-20)");
    golden->add_option("--out", out_dir, "output directory (created)")->required();
    CLI::App* audit = app.add_subcommand("audit", "run floating-point methods on scenes and compare with the exact answers (CSV and JSON)");
    std::vector<std::string> audit_scenes, methods{"libccd-gjk", "libccd-mpr", "fcl-gjk-libccd", "fcl-gjk-indep", "bullet-gjk-epa", "double-envelope", "paper-tritri", "grid"};
    std::vector<int> grid_ns{16, 64, 256};
    int sweep_from = 0, sweep_to = 0;
    std::string audit_out = "audit";
    audit->add_option("SCENES", audit_scenes, "scene files");
    audit->add_option("--methods", methods, "libccd-gjk libccd-mpr double-envelope paper-tritri fcl-gjk-libccd fcl-gjk-indep bullet-gjk-epa grid")->delimiter(',');
    audit->add_option("--grid", grid_ns, "grid resolutions for the grid method (2 to 4096)")->delimiter(',')->check(CLI::Range(2, 4096));
    audit->add_option("--family", family, "also audit a family over an eps sweep (with --sweep)");
    audit->add_option("--sweep", sweep_from, "eps = 2^-K for K from this (0 to 1074) ...")->check(CLI::Range(0, 1074));
    audit->add_option("--sweep-to", sweep_to, "... to this (inclusive, 0 to 1074)")->check(CLI::Range(0, 1074));
    audit->add_option("--count", count, "scenes per eps in the sweep")->check(CLI::Range(1, 10000));
    audit->add_option("--seed", seed, "random seed for the sweep");
    audit->add_option("--out", audit_out, "write OUT.csv and OUT.json");
    CLI::App* batch = app.add_subcommand("classify", "exact verdicts for many pairs: lines 'rho1 rho2' (doubles, classified at their exact values)");
    std::string pairs_path = "-";
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    common(batch);
    batch->add_option("PAIRS", pairs_path, "file of pairs, one 'rho1 rho2' per line ('-': standard input)");
    batch->add_option("--threads", threads, "threads (default: all cores)")->check(CLI::Range(1u, 256u));
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "scalecert: error: " << one_line(e.what()) << " (see scalecert --help)\n";
        return 2;
    }
    try {
        if (*golden) {
            Q eps = parse_exact(eps_text);
            if (sgn(eps) <= 0) throw InputError("--eps must be > 0");
            family_description(family);  // an unknown family is refused before anything is created
            std::error_code ec;
            std::filesystem::create_directories(out_dir, ec);
            if (ec || !std::filesystem::is_directory(out_dir))
                throw InputError(out_dir + ": cannot create the output directory (" + (ec ? ec.message() : "not a directory") + ")");
            write_golden(family, count, seed, eps, out_dir);
            std::cerr << "scalecert: wrote " << count << " " << family << " scenes with exact answers to " << out_dir << "\n";
            return 0;
        }
        if (*audit) {
            std::vector<AuditRow> rows;
            if (!family.empty()) family_description(family);  // refused before any work
            for (const std::string& p : audit_scenes) {
                std::cerr << "scalecert: audit: " << p << "\n";
                const Scene sc = load_scene(p, opt);  // its errors name the file already
                std::vector<AuditRow> r;
                try {
                    r = audit_scene(p, sc, Q(0), methods, grid_ns);
                } catch (const InputError& e) {
                    throw InputError(p + ": " + e.what());
                }
                rows.insert(rows.end(), r.begin(), r.end());
            }
            if (!family.empty()) {
                if (sweep_to < sweep_from) throw InputError("--sweep-to must be >= --sweep");
                for (int k = sweep_from; k <= sweep_to; ++k) {
                    Q eps(1, Z(1) << k);
                    Rng g(seed);
                    for (int i = 0; i < count; ++i) {
                        std::cerr << "scalecert: audit: " << family << " eps = 2^-" << k << ", scene " << i + 1 << "/" << count << "\r";
                        auto r = audit_scene(family + "-" + std::to_string(i), make_family_scene(family, eps, g), eps, methods, grid_ns);
                        rows.insert(rows.end(), r.begin(), r.end());
                    }
                }
                std::cerr << "\n";
            }
            if (rows.empty()) throw InputError("audit: no scenes (give SCENES or --family with --sweep)");
            // Both texts first, then both files together: a failure leaves neither.
            write_files_atomically({{audit_out + ".csv", audit_csv(rows)}, {audit_out + ".json", dump(audit_json(rows))}});
            std::cerr << "scalecert: audit: " << rows.size() << " rows in " << audit_out << ".csv and " << audit_out << ".json\n";
            return 0;
        }
        StageClock clock;
        const bool timing = clock.on;
        if (!scene_path.empty() && (!mesh_path[0].empty() || !mesh_path[1].empty() || !interval_text[0].empty() || !interval_text[1].empty() ||
                                    !seed_text[0].empty() || !seed_text[1].empty()))
            throw InputError("give SCENE or --p1, --p2, --i1, --i2, not both");
        Scene scene = scene_path.empty() ? scene_from_options(mesh_path, interval_text, seed_text, opt) : load_scene(scene_path, opt);
        if (scene_path.empty()) scene_path = "--p1 " + mesh_path[0] + " --p2 " + mesh_path[1];
        clock.lap("read scene");
        Model m = model_of(scene, scene_path);
        clock.restart();
        Curve c = build_curve(m);
        clock.lap("envelope and curve");
        std::string text;
        std::optional<Segment> seg;
        if (in_t && segment_spec.empty()) segment_spec = "seeds";
        if (!segment_spec.empty()) seg = parse_segment(segment_spec, m);
        if (*curve) {
            Json j = curve_json(m, c);
            if (seg) add_segment_json(j, m, c, *seg);
            text = dump(j);
        } else if (*query) {
            Q r1, r2;
            if (in_t) {
                Q t1 = read_rho(rho1s, "T1", opt), t2 = read_rho(rho2s, "T2", opt);
                auto a = rho_from_t(*seg, 0, t1), b = rho_from_t(*seg, 1, t2);
                if (!a) throw InputError("T1: outside t1(I1)");
                if (!b) throw InputError("T2: outside t2(I2)");
                r1 = *a;
                r2 = *b;
            } else {
                r1 = read_rho(rho1s, "RHO1", opt);
                r2 = read_rho(rho2s, "RHO2", opt);
            }
            QueryResult r = scalecert::query(m, c, r1, r2, as_json);
            if (as_json) {
                Json j = query_json(m, r);
                if (seg) add_query_segment_json(j, *seg, r1, r2);
                text = dump(j);
            } else {
                text = std::string(verdict_name(r.verdict)) + "\n";
                if (in_t) text += "rho1 " + to_exact_string(r1) + "\nrho2 " + to_exact_string(r2) + "\n";
                if (seg) {
                    if (!seg->note.empty()) text += "note " + seg->note + "\n";
                    Q g = directional_gap(*seg, r1, r2);
                    text += "t1 " + to_exact_string(eval(seg->t[0], r1)) + "\nt2 " + to_exact_string(eval(seg->t[1], r2)) +
                            "\ngap_fraction " + to_exact_string(g) + "\ngap_distance ~" +
                            std::to_string(scaled_length(seg->v1, seg->v2, g)) + "\n";
                }
            }
        } else if (*grid) {
            fp::FpScene f = fp::to_fp(m.scene);
            std::unique_ptr<fp::Method> meth = fp::make_method(grid_method, m, f);
            if (!meth) throw InputError("--method: unknown method '" + grid_method + "'");
            fp::GridCurve gc = fp::grid_search(*meth, f, grid_n, grid_bis, grid_bis ? 3 : 1);
            Json j;
            j["method"] = meth->name();
            j["n"] = grid_n;
            j["bisections"] = grid_bis;
            j["classifications"] = gc.classifications;
            Json samples = Json::array();
            for (size_t i = 0; i < gc.rho1.size(); ++i) samples.push_back(Json::array({gc.rho1[i], gc.rho2[i]}));
            j["samples"] = samples;
            text = dump(j);
        } else if (*certify) {
            const std::string claims = read_input(claims_path, "claims file", kMaxSceneBytes);
            long wrong = 0;
            text = certify_fp(m, c, claims, claims_path, opt.binary_doubles, as_json, &wrong);
        } else if (*batch) {
            std::vector<double> r1, r2;
            const std::string pairs = read_input(pairs_path, "pairs file", kMaxPairsBytes);
            clock.lap("read pairs");
            try {
                parse_pairs(pairs, r1, r2, threads);
            } catch (const InputError& e) {
                throw InputError(pairs_path + ": " + e.what());
            }
            clock.lap("parse pairs");
            std::vector<Verdict> out;
            FastCurve fc(m, c);
            StageCounts sc = classify_batch(fc, r1, r2, out, threads);
            clock.lap("classify");
            text = verdict_lines(out);
            if (timing) std::fprintf(stderr, "scalecert: stages: %lu filtered, %lu exact\n", (unsigned long)sc.filtered, (unsigned long)sc.exact);
        } else {
            text = dump(partition_json(m, c, build_partition(m, c)));
        }
        clock.lap("output");
        emit(text, out);
        return 0;
    } catch (const InputError& e) {
        std::cerr << "scalecert: error: " << one_line(e.what()) << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "scalecert: error: out of memory\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "scalecert: internal error: " << one_line(e.what()) << "\n";
        return 3;
    }
}
