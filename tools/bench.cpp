// scalecert-bench: speed of the exact engine against floating-point baselines measured in the
// same run, reported as ratios. Usage: scalecert-bench [--quick] [--sizes] [--with-slow]
// (--sizes: only the whole-process table of the hull and scan paths on 10^3..10^6 points;
// --with-slow adds the hull path on two 10^6-point near-spheres: two minutes and 7 GB.)
// scalecert-bench --checker [--timeout S] [--keep DIR] [CHECKER ...]: scalecert-check on 1 MB
// hostile certificates against reading them as plain JSON (tools/bench_checker.cpp).
#include "baselines/audit.hpp"
#include "certify/claims.hpp"
#include "baselines/baselines.hpp"
#include "campaign/families.hpp"
#include "certify/classify.hpp"
#include "certify/region_certificate.hpp"
#include "compound/boundary.hpp"
#include "compound/locate.hpp"
#include "compound/region.hpp"
#include "quick_query.hpp"
#include "session/session.hpp"
#include "scalecert/scalecert.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <nlohmann/json.hpp>
#include <cstdio>
#include <cstring>
#include <random>

using namespace scalecert::internal;
using Clock = std::chrono::steady_clock;

namespace {

// Seconds per call of f (best of `reps` runs of `n` calls).
template <class F>
double per_call(F&& f, long n, int reps = 3) {
    double best = 1e300;
    for (int r = 0; r < reps; ++r) {
        auto t0 = Clock::now();
        for (long i = 0; i < n; ++i) f(i);
        best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count() / static_cast<double>(n));
    }
    return best;
}

Q qc(long p, long q) {
    Q r(p, q);
    r.canonicalize();
    return r;
}

// Two boxes: P1 = [−1,1]^3; P2 a 2×1×1 box turned by the exact rotation with cos 3/5, sin 4/5
// about z, then about x, centred at (3, 1/2, 1/3).
ExactScene boxes() {
    ExactScene s;
    for (int x : {-1, 1})
        for (int y : {-1, 1})
            for (int z : {-1, 1}) s.P[0].points.push_back({Q(x), Q(y), Q(z)});
    for (int x : {-2, 2})
        for (int y : {-1, 1})
            for (int z : {-1, 1}) {
                Q X = qc(3 * x - 4 * y, 5), Y = qc(4 * x + 3 * y, 5), Z = Q(z);
                Q Y2 = qc(3, 5) * Y - qc(4, 5) * Z, Z2 = qc(4, 5) * Y + qc(3, 5) * Z;
                s.P[1].points.push_back({X + 3, Y2 + qc(1, 2), Z2 + qc(1, 3)});
            }
    s.P[0].seed = {Q(0), Q(0), Q(0)};
    s.P[1].seed = {Q(3), qc(1, 2), qc(1, 3)};
    s.lo[0] = s.lo[1] = qc(1, 2);
    s.hi[0] = s.hi[1] = Q(3);
    return s;
}

// n integer points near spheres of radius R (a many-vertex hull), the second offset by 3R.
ExactScene spheres(int n, long R, unsigned seed) {
    std::mt19937_64 g(seed);
    std::normal_distribution<double> N(0, 1);
    ExactScene s;
    for (int i = 0; i < 2; ++i) {
        for (int k = 0; k < n; ++k) {
            double x = N(g), y = N(g), z = N(g), l = std::sqrt(x * x + y * y + z * z);
            s.P[i].points.push_back({Q(std::lround(R * x / l) + (i ? 3 * R : 0)),
                                     Q(std::lround(R * y / l) + (i ? R / 10 : 0)), Q(std::lround(R * z / l))});
        }
        Vec3q c{Q(0), Q(0), Q(0)};
        for (auto& v : s.P[i].points)
            for (int k = 0; k < 3; ++k) c[k] += v[k];
        for (int k = 0; k < 3; ++k) c[k] /= Q(n);
        s.P[i].seed = c;
        s.lo[i] = qc(1, 2);
        s.hi[i] = Q(2);
    }
    return s;
}

struct Row {
    std::string method, scene;
    double seconds;
    std::string ratio;
};
std::vector<Row> rows;
void row(const std::string& m, const std::string& sc, double t, const std::string& ratio = "") {
    rows.push_back({m, sc, t, ratio});
    std::fprintf(stderr, "  %-44s %-14s %12.3g s %s\n", m.c_str(), sc.c_str(), t, ratio.c_str());
}
std::string ratio(const char* fmt, double x) {
    char b[64];
    std::snprintf(b, sizeof b, fmt, x);
    return b;
}

void query_benchmarks(const std::string& name, const ExactScene& sc, long nq) {
    HullModel m = build_model(sc);
    TouchingCurve c = build_curve(m);
    fp::FpScene f = fp::to_fp(sc);
    auto gjk = fp::make_libccd_gjk(f);
    FastCurve fc(m, c);
    FastDirect fd(m);
    std::mt19937_64 g(7);
    std::uniform_real_distribution<double> u1(f.lo[0], f.hi[0]), u2(f.lo[1], f.hi[1]);
    std::vector<double> r1(nq), r2(nq);
    for (long i = 0; i < nq; ++i) r1[i] = u1(g), r2[i] = u2(g);
    volatile int sink = 0;
    double t_gjk = per_call([&](long i) { sink += gjk->classify(r1[i], r2[i]); }, nq);
    double t_curve = per_call([&](long i) { sink += static_cast<int>(fc.classify(r1[i], r2[i])); }, nq);
    double t_direct = per_call([&](long i) { sink += static_cast<int>(fd.classify(r1[i], r2[i])); }, nq);
    QuickScene qs(sc);  // doubles of the scene, as GJK has them; the model is never built here
    double t_quick = per_call([&](long i) { sink += static_cast<int>(qs.classify(r1[i], r2[i])); }, nq);
    long wrong = 0;
    for (long i = 0; i < nq; ++i) {
        int e = fc.classify(r1[i], r2[i]) == Verdict::Separated ? 1 : -1;
        wrong += gjk->classify(r1[i], r2[i]) != e;
    }
    row("libccd GJK, one query", name, t_gjk, "1 (baseline)");
    row("exact query with curve (filtered)", name, t_curve, ratio("%.1fx faster than GJK", t_gjk / t_curve));
    row("exact query, model built, no curve (filtered)", name, t_direct, ratio("%.3gx GJK's time", t_direct / t_gjk));
    row("exact query from the scene: no model, no curve", name, t_quick,
        ratio("%.3gx GJK's time (target <= 3x on boxes)", t_quick / t_gjk));
    std::fprintf(stderr,
                 "    stages: with curve %lu filtered / %lu exact; no curve %lu / %lu; from the scene %lu / %lu; GJK "
                 "verdicts differing from exact: %ld of %ld\n",
                 (unsigned long)fc.counts().filtered, (unsigned long)fc.counts().exact,
                 (unsigned long)fd.counts().filtered, (unsigned long)fd.counts().exact,
                 (unsigned long)qs.counts().filtered, (unsigned long)qs.counts().exact, wrong, nq);
    // Points exactly on the curve: the filter cannot decide them; all go to the exact stage.
    FastCurve fc2(m, c);
    QuickScene qs2(sc);
    long on = 0;
    for (long i = 0; i < 1000; ++i) {
        double x = r1[i];
        Q y = c.env.value(m.lines, exact_from_double(x));
        double yd = to_double_rn(y);
        if (exact_from_double(yd) == y) {
            fc2.classify(x, yd);
            qs2.classify(x, yd);
            ++on;
        }
    }
    std::fprintf(
        stderr,
        "    on-curve points representable as doubles: %ld, decided exactly: %lu with the curve, %lu from the scene\n",
        on, (unsigned long)fc2.counts().exact, (unsigned long)qs2.counts().exact);
}

std::vector<std::string> growth_rows;
void growth(const std::string& name, const ExactScene& sc) {
    auto t0 = Clock::now();
    HullModel m = build_model(sc);
    TouchingCurve c = build_curve(m);
    double t = std::chrono::duration<double>(Clock::now() - t0).count();
    FastCurve fc(m, c);
    for (int i = 1; i < 200; ++i) {  // pairs at relative distances 2^-10 .. 2^-50 from the curve
        Q x = sc.lo[0] + (sc.hi[0] - sc.lo[0]) * Q(i, 200);
        x.canonicalize();
        Q y = c.env.value(m.lines, x);
        if (sgn(y) <= 0) continue;
        Q d = y / Q(Z(1) << (10 + i % 41));
        fc.classify(to_double_rn(x), to_double_rn(y + d));
        fc.classify(to_double_rn(x), to_double_rn(y - d));
    }
    char b[512];
    std::snprintf(b, sizeof b, "| %s | %.3g s | %lu / %lu | %lu / %lu | %lu / %lu |", name.c_str(), t,
                  (unsigned long)(m.P[0].predicates[filter::Predicate::SupportCmp].filtered +
                                  m.P[1].predicates[filter::Predicate::SupportCmp].filtered),
                  (unsigned long)(m.P[0].predicates[filter::Predicate::SupportCmp].exact +
                                  m.P[1].predicates[filter::Predicate::SupportCmp].exact),
                  (unsigned long)m.stats.predicates[filter::Predicate::ArcSide].filtered,
                  (unsigned long)m.stats.predicates[filter::Predicate::ArcSide].exact,
                  (unsigned long)fc.counts().filtered, (unsigned long)fc.counts().exact);
    growth_rows.push_back(b);
    std::fprintf(stderr, "  %s\n", b);
}

// ---- The whole `scalecert curve` process on large meshes: hull path against scan path ----------

extern "C" char** environ;

struct ProcessRun {
    double seconds;
    long peak_kb;
    int status;
};
// A program built beside the bench (scalecert, scalecert-check).
std::string sibling(const char* name) {
    return (std::filesystem::canonical("/proc/self/exe").parent_path() / name).string();
}
// A fresh scratch folder for one table's files, named by `tag` and this process.
std::filesystem::path scratch_dir(const std::string& tag) {
    const auto dir = std::filesystem::temp_directory_path() / (tag + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}
// Waits for child `pid`, started at t0: its wall time, peak resident size and exit status.
ProcessRun reaped(pid_t pid, Clock::time_point t0) {
    int st = 0;
    struct rusage ru {};
    wait4(pid, &st, 0, &ru);
    return {std::chrono::duration<double>(Clock::now() - t0).count(), ru.ru_maxrss,
            WIFEXITED(st) ? WEXITSTATUS(st) : -1};
}
// Runs `bin args...` and measures wall time and peak resident size; with `quiet` its standard
// output and error go to /dev/null.
ProcessRun run_process(const std::string& bin, const std::vector<std::string>& args, bool quiet = false) {
    std::vector<std::string> all{bin};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    if (quiet) {
        posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
        posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    }
    auto t0 = Clock::now();
    pid_t pid;
    const int spawned = posix_spawn(&pid, bin.c_str(), &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    if (spawned != 0) return {0, 0, -1};
    return reaped(pid, t0);
}

// Runs f in a child process (fork) and measures its wall time and peak resident size, as
// run_process does for a program: what a program calling the library alone would use.
ProcessRun run_in_child(const std::function<int()>& f) {
    std::fflush(nullptr);
    auto t0 = Clock::now();
    const pid_t pid = fork();
    if (pid < 0) return {0, 0, -1};
    if (pid == 0) {
        int r = 3;
        try {
            r = f();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "bench child: %s\n", e.what());
        }
        std::fflush(nullptr);
        _exit(r);
    }
    return reaped(pid, t0);
}
// Runs `scalecert args...` (its output in the file its arguments name).
ProcessRun run_scalecert(const std::vector<std::string>& args) {
    static const std::string bin = sibling("scalecert");
    return run_process(bin, args);
}

// n points per polytope as an OFF file of integers: near a sphere of radius R (every point a
// hull vertex, or nearly), or uniform in the ball (most points interior), offset by (3R, R/10, 0).
void write_cloud(const std::string& path, int n, long R, bool on_sphere, bool second, unsigned seed) {
    std::mt19937_64 g(seed);
    std::normal_distribution<double> N(0, 1);
    std::uniform_real_distribution<double> U(0, 1);
    std::ofstream o(path);
    o << "OFF\n" << n << " 0 0\n";
    for (int k = 0; k < n; ++k) {
        double x = N(g), y = N(g), z = N(g), l = std::sqrt(x * x + y * y + z * z);
        const double r = on_sphere ? R : R * std::cbrt(U(g));
        o << std::lround(r * x / l) + (second ? 3 * R : 0) << ' ' << std::lround(r * y / l) + (second ? R / 10 : 0)
          << ' ' << std::lround(r * z / l) << '\n';
    }
}

std::string curve_without_model(const std::string& path) {
    std::ifstream in(path);
    auto j = nlohmann::json::parse(in);
    j.erase("model");
    return j.dump();
}

std::vector<std::string> size_rows;
void curve_sizes(bool with_slow) {
    const auto dir = scratch_dir("scalecert-bench");
    std::fprintf(stderr,
                 "whole `scalecert curve` process, hull path against scan path (best of 3 below 10^6 points):\n");
    size_rows.push_back(
        "| polytopes (points each) | hull path: time | peak memory | scan path: time | peak memory | scan path faster "
        "by | same curve |");
    size_rows.push_back("|---|---|---|---|---|---|---|");
    for (bool sphere : {true, false})
        for (int n : {1000, 10000, 100000, 1000000}) {
            const std::string a = (dir / "a.off").string(), b = (dir / "b.off").string();
            const long R = sphere ? 10L * n * 1000 : 1000000;
            write_cloud(a, n, R, sphere, false, 5 + n);
            write_cloud(b, n, R, sphere, true, 6 + n);
            auto best = [&](const std::string& engine, const std::string& out, int reps) {
                ProcessRun r{1e300, 0, 0};
                for (int k = 0; k < reps; ++k) {
                    ProcessRun x = run_scalecert({"curve", "--engine", engine, "--p1", a, "--p2", b, "--i1", "1/2,2",
                                                  "--i2", "1/2,2", "--out", out});
                    if (x.seconds < r.seconds) r.seconds = x.seconds;
                    r.peak_kb = std::max(r.peak_kb, x.peak_kb);
                    r.status = x.status;
                }
                return r;
            };
            const int reps = n >= 1000000 ? 1 : 3;
            const std::string so = (dir / "scan.json").string(), ho = (dir / "hull.json").string();
            const ProcessRun s = best("scan", so, reps);
            const bool slow = n >= 1000000 && sphere && !with_slow;
            ProcessRun h{0, 0, 0};
            if (!slow) h = best("hull", ho, reps);
            char buf[512];
            const std::string name = std::string(sphere ? "near-spheres, " : "random in balls, ") + std::to_string(n);
            if (slow)
                std::snprintf(buf, sizeof buf, "| %s | (--with-slow) | | %.3g s | %.0f MB | | |", name.c_str(),
                              s.seconds, s.peak_kb / 1024.0);
            else
                std::snprintf(buf, sizeof buf, "| %s | %.3g s | %.0f MB | %.3g s | %.0f MB | %.1fx | %s |",
                              name.c_str(), h.seconds, h.peak_kb / 1024.0, s.seconds, s.peak_kb / 1024.0,
                              h.seconds / s.seconds,
                              s.status || h.status                                 ? "exit status!"
                              : curve_without_model(so) == curve_without_model(ho) ? "yes"
                                                                                   : "NO");
            size_rows.push_back(buf);
            std::fprintf(stderr, "  %s\n", buf);
        }
    std::filesystem::remove_all(dir);
}

// Crossed prisms: a regular n-gon (rounded to integers on a circle of radius R) extruded along z
// for P1 and along x for P2 above it: O(n^2) facet normals of the Minkowski sum, few on the curve.
void write_prism(const std::string& path, int n, long R, bool second) {
    std::ofstream o(path);
    o << "OFF\n" << 2 * n << " 0 0\n";
    const double pi = std::acos(-1.0);
    for (int k = 0; k < n; ++k) {
        const long x = std::lround(R * std::cos(2 * pi * k / n + 0.1)),
                   y = std::lround(R * std::sin(2 * pi * k / n + 0.1));
        for (long z : {-3 * R, 3 * R}) {
            if (second)
                o << z + 12345 << ' ' << y + R / 5 << ' ' << x + 3 * R << '\n';
            else
                o << x << ' ' << y << ' ' << z << '\n';
        }
    }
}

// Every claim kind on crossed n-gon prisms (O(n^2) Minkowski facets), one whole `certify-fp
// --certificate` process per kind, and the checker on its certificate: each claim answers from the
// walk and the two hulls, none from the hull model (76 s and 2.26 GB at n = 4,800).
std::vector<std::string> prism_claim_rows;
void prism_claim_costs(const std::vector<int>& sizes) {
    const auto dir = scratch_dir("scalecert-bench-pc");
    static const std::string checker = sibling("scalecert-check");
    const std::string a = (dir / "a.off").string(), b = (dir / "b.off").string(), out = (dir / "cert.json").string();
    prism_claim_rows.push_back("| crossed prisms | claim kind | certify-fp --certificate | scalecert-check |");
    prism_claim_rows.push_back("|---|---|---|---|");
    // Points on the curve's first stretch (it reaches rho2 = 0 inside I1 = [1/2, 2]).
    const std::vector<std::pair<std::string, std::string>> kinds = {
        {"verdict", R"({"kind": "verdict", "rho1": 0.75, "rho2": 0.75, "verdict": "separated"})"},
        {"separating_plane", R"({"kind": "separating_plane", "rho1": 0.75, "rho2": 0.5, "normal": [0, 0, 1]})"},
        {"witness_point", R"({"kind": "witness_point", "rho1": 1.5, "rho2": 1.5, "point": [12345, 200000, 3000000]})"},
        {"distance",
         R"({"kind": "distance", "rho1": 0.5, "rho2": 0.5, "value": 1e6, "closest": [[0, 0, 3000000], [12345, 0, )"
         R"(3000000]]})"},
        {"penetration_depth",
         R"({"kind": "penetration_depth", "rho1": 2, "rho2": 2, "value": 1e6, "direction": [0, 0, 1]})"},
        {"curve_point", R"({"kind": "curve_point", "rho1": 0.6, "rho2": 0.9})"},
        {"curve", R"({"kind": "curve", "vertices": [[0.55, 1.0], [0.6, 0.95], [0.65, 0.9]]})"},
        {"switch_point", R"({"kind": "switch_point", "rho1": 0.6, "rho2": 0.9})"},
        {"growth_distance", R"({"kind": "growth_distance", "value": 0.7})"},
    };
    for (int n : sizes) {
        write_prism(a, n, 1000000, false);
        write_prism(b, n, 1000000, true);
        for (const auto& [kind, claim] : kinds) {
            const std::string cf = (dir / "claims.json").string();
            std::ofstream(cf) << R"({"format": "scalecert-claims-1", "claims": [)" << claim << "]}";
            const ProcessRun r =
                run_scalecert({"certify-fp", "--p1", a, "--p2", b, "--i1", "1/2,2", "--i2", "1/2,2", cf,
                               "--certificate", out, "--out", (dir / "report.json").string(), "--tolerance", "1/1000"});
            const auto t0 = std::chrono::steady_clock::now();
            const int check = std::system((checker + " " + out + " >/dev/null 2>&1").c_str());
            const double check_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            char buf[256];
            std::snprintf(buf, sizeof buf, "| %d-gon | %s | %.3g s, %.0f MB%s | %.3g s%s |", n, kind.c_str(), r.seconds,
                          r.peak_kb / 1024.0, r.status == 0 || r.status == 1 ? "" : " (exit status 2 or 3!)", check_s,
                          check ? " (REJECTED)" : "");
            prism_claim_rows.push_back(buf);
            std::fprintf(stderr, "  %s\n", buf);
        }
    }
    std::filesystem::remove_all(dir);
}

std::vector<std::string> query_rows;
// Whole processes from the scene files: `query` (a verdict), `query --json` (with its
// certificate) and `partition`, on the walk where it proves the curve (the default from 2,000
// points), against `partition --engine hull` (the hull model) in the same run; the checker on the
// walk's partition beside: its time and memory, and its time over the partition's that wrote it.
void query_costs(bool with_slow) {
    const auto dir = scratch_dir("scalecert-bench");
    std::fprintf(stderr, "whole process: query, query --json, partition (walk) against partition --engine hull:\n");
    query_rows.push_back(
        "| scene | query | query --json | partition | partition --engine hull | hull / walk | scalecert-check | "
        "Analysis::query (C++ API) |");
    query_rows.push_back("|---|---|---|---|---|---|---|---|");
    const std::string a = (dir / "a.off").string(), b = (dir / "b.off").string(), out = (dir / "out.txt").string();
    static const std::string checker = sibling("scalecert-check");
    auto cell = [](const ProcessRun& r) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "%.3g s, %.0f MB%s", r.seconds, r.peak_kb / 1024.0,
                      r.status ? " (exit status!)" : "");
        return std::string(buf);
    };
    auto row = [&](const std::string& name, bool hull_too) {
        const std::vector<std::string> scene = {"--p1", a, "--p2", b, "--i1", "1/2,2", "--i2", "1/2,2", "--out", out};
        auto with = [&](std::vector<std::string> v) {
            v.insert(v.end(), scene.begin(), scene.end());
            return v;
        };
        const ProcessRun q = run_scalecert(with({"query", "", "1", "1"}));
        const ProcessRun qj = run_scalecert(with({"query", "", "1", "1", "--json"}));
        const ProcessRun p = run_scalecert(with({"partition", ""}));
        // The same query through the public API, in a process of its own: the scene from the mesh
        // files, its analysis and one query with its evidence.
        const ProcessRun api = run_in_child([&] {
            using scalecert::Rational;
            const scalecert::Scene s =
                scalecert::Scene::from_meshes(a, b, {Rational(1, 2), Rational(2)}, {Rational(1, 2), Rational(2)});
            const scalecert::Analysis an(s);
            const scalecert::QueryResult res = an.query(Rational(1), Rational(1));
            return res.plane || res.common ? 0 : 4;
        });
        const ProcessRun c = run_process(checker, {out}, true);
        ProcessRun h{0, 0, 0};
        if (hull_too) h = run_scalecert(with({"partition", "", "--engine", "hull"}));
        char ratio[32] = "";
        if (hull_too) std::snprintf(ratio, sizeof ratio, "%.0fx", h.seconds / p.seconds);
        char cs[96];  // the checker: time and memory, and its time against the partition's that wrote the file
        std::snprintf(cs, sizeof cs, "%.3g s, %.0f MB (%.2gx the partition)%s", c.seconds, c.peak_kb / 1024.0,
                      c.seconds / p.seconds, c.status ? " (REJECTED)" : "");
        const std::string r = "| " + name + " | " + cell(q) + " | " + cell(qj) + " | " + cell(p) + " | " +
                              (hull_too ? cell(h) : std::string("(--with-slow)")) + " | " + ratio + " | " + cs + " | " +
                              cell(api) + " |";
        query_rows.push_back(r);
        std::fprintf(stderr, "  %s\n", r.c_str());
    };
    for (int n : {100000, 1000000}) {
        const long R = 10L * n * 1000;
        write_cloud(a, n, R, true, false, 5 + n);
        write_cloud(b, n, R, true, true, 6 + n);
        row("near-spheres, " + std::to_string(n) + " points each", n < 1000000 || with_slow);
    }
    for (int n : {200, 800, 3200}) {
        write_prism(a, n, 1000000, false);
        write_prism(b, n, 1000000, true);
        row("crossed " + std::to_string(n) + "-gon prisms", n < 3200 || with_slow);
    }
    std::filesystem::remove_all(dir);
}

}  // namespace

// Certifying 1,000 claims on two 1,000-vertex hulls (250 each of verdicts, separating planes,
// distances and penetration depths at random pairs) against the floating-point libraries
// producing the same outputs in the same run: libccd GJK verdicts (for verdicts and planes), FCL's
// GJK distances and libccd's EPA depths. With a judgements certificate too.
std::vector<std::string> claim_rows;
void claim_costs(const ExactScene& h1000, bool quick) {
    HullModel m = build_model(h1000);
    TouchingCurve c = build_curve(m);
    fp::FpScene f = fp::to_fp(h1000);
    auto gjk = fp::make_libccd_gjk(f);
    auto fcl = fp::make_fcl(m, f, false);
    auto bullet = fp::make_bullet(f);
    std::mt19937_64 g(7);
    std::uniform_real_distribution<double> u(0.5, 2);
    std::vector<double> a(1000), b(1000);
    std::vector<bool> sep(1000);
    std::string claims = "{\"format\": \"scalecert-claims-1\", \"claims\": [";
    char buf[256];
    for (int i = 0; i < 1000; ++i) {
        a[i] = u(g), b[i] = u(g);
        const int kind = i % 4;
        sep[i] = query(m, c, exact_from_double(a[i]), exact_from_double(b[i]), false).verdict == Verdict::Separated;
        if (kind == 0)
            std::snprintf(buf, sizeof buf,
                          "{\"kind\": \"verdict\", \"rho1\": %.17g, \"rho2\": %.17g, \"verdict\": \"separated\"}", a[i],
                          b[i]);
        if (kind == 1)
            std::snprintf(buf, sizeof buf,
                          "{\"kind\": \"separating_plane\", \"rho1\": %.17g, \"rho2\": %.17g, \"normal\": [1, 0.1, 0]}",
                          a[i], b[i]);
        if (kind >= 2)
            std::snprintf(buf, sizeof buf, "{\"kind\": \"%s\", \"rho1\": %.17g, \"rho2\": %.17g, \"value\": 1}",
                          sep[i] ? "distance" : "penetration_depth", a[i], b[i]);
        claims += std::string(i ? ", " : "") + buf;
    }
    claims += "]}";
    long wrong = 0;
    volatile double sink = 0;
    const double t_fp = per_call(
        [&](long) {
            for (int i = 0; i < 1000; ++i) {
                if (i % 4 < 2)
                    sink = sink + gjk->classify(a[i], b[i]);
                else if (auto me = (sep[i] ? *fcl : *gjk).measure(a[i], b[i], sep[i]))
                    sink = sink + me->value;
            }
        },
        1, quick ? 1 : 3);
    // The baseline by output: verdicts (for verdict and plane claims), distances, depths.
    double t_kind[3] = {0, 0, 0}, t_posed_kind[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
        t_kind[k] = per_call(
            [&](long) {
                for (int i = 0; i < 1000; ++i) {
                    const int kind = i % 4 < 2 ? 0 : sep[i] ? 1 : 2;
                    if (kind != k) continue;
                    if (k == 0)
                        sink = sink + gjk->classify(a[i], b[i]);
                    else if (auto me = (sep[i] ? *fcl : *gjk).measure(a[i], b[i], sep[i]))
                        sink = sink + me->value;
                }
            },
            1, quick ? 1 : 3);
    const double t_claims = per_call(
        [&](long) {
            certify_fp(m, c, claims, "bench", ClaimOptions{Numbers::Double, Q(0), true}, &wrong);
        },
        1, 1);
    // Bullet's GJK distance on the same pairs (btConvexHullShape, margin 0): the fastest distance.
    const double t_bullet = per_call(
        [&](long) {
            for (int i = 0; i < 1000; ++i)
                if (i % 4 >= 2 && sep[i])
                    if (auto me = bullet->measure(a[i], b[i], true)) sink = sink + me->value;
        },
        1, quick ? 1 : 3);
    double t_ours[3] = {0, 0, 0};  // ours by output too: below, through the typed API
    std::string cert;
    const double t_cert = per_call(
        [&](long) {
            certify_fp(HullClaimModels(m, c), claims, "bench", ClaimOptions{Numbers::Double, Q(0), true}, &wrong,
                       nullptr, &cert);
        },
        1, 1);
    auto add = [&](const char* what, double t, const std::string& r) {
        row(what, "hulls (1000)", t, r);
        char line[256];
        std::snprintf(line, sizeof line, "| %s | %.3g s | %s |", what, t, r.c_str());
        claim_rows.push_back(line);
    };
    long nk[3] = {0, 0, 0};
    for (int i = 0; i < 1000; ++i) ++nk[i % 4 < 2 ? 0 : sep[i] ? 1 : 2];
    char what[160];
    std::snprintf(what, sizeof what,
                  "1 (baseline: %ld verdicts %.3g s, %ld FCL distances %.3g s, %ld libccd EPA depths %.3g s)", nk[0],
                  t_kind[0], nk[1], t_kind[1], nk[2], t_kind[2]);
    add("the same 1,000 outputs from libccd GJK/EPA and FCL", t_fp, what);
    add("1,000 claims certified (verdicts, planes, distances, depths)", t_claims,
        ratio("%.2gx the libraries' time (target <= 10x)", t_claims / t_fp));
    add("the same, with the judgements certificate", t_cert, ratio("%.2gx the libraries' time", t_cert / t_fp));
    // The typed API against certify-fp's text, on the same scene through the public Analysis (both
    // after the Analysis is built): the same 1,000 claims as scalecert::Claim values.
    {
        const scalecert::Analysis an(scalecert::Scene(h1000.P[0].points, h1000.P[1].points, {h1000.lo[0], h1000.hi[0]},
                                                      {h1000.lo[1], h1000.hi[1]}, h1000.P[0].seed, h1000.P[1].seed));
        std::vector<scalecert::Claim> typed(1000);
        for (int i = 0; i < 1000; ++i) {
            scalecert::Claim& t = typed[static_cast<size_t>(i)];
            t.rho1 = scalecert::exact(a[i]), t.rho2 = scalecert::exact(b[i]);
            if (i % 4 == 0) t.kind = scalecert::ClaimKind::Verdict, t.verdict = scalecert::ClaimedVerdict::Separated;
            if (i % 4 == 1) t.kind = scalecert::ClaimKind::SeparatingPlane, t.normal = {1, scalecert::exact(0.1), 0};
            if (i % 4 >= 2)
                t.kind = sep[i] ? scalecert::ClaimKind::Distance : scalecert::ClaimKind::PenetrationDepth, t.value = 1;
        }
        an.certify({typed[0]});  // the claim models, built once, in neither time
        const double t_text = per_call([&](long) { an.certify_fp(claims); }, 1, quick ? 1 : 3);
        const double t_typed = per_call([&](long) { an.certify(typed); }, 1, quick ? 1 : 3);
        add("the same 1,000 claims through Analysis::certify_fp (JSON text)", t_text,
            ratio("%.2gx the libraries' time", t_text / t_fp));
        add("the same 1,000 claims through Analysis::certify (typed)", t_typed,
            ratio("%.2gx the JSON text's time (target <= 1)", t_typed / t_text));
        // Each claim at its own random pose: both objects turned about random axes by random
        // angles held as doubles (R not exactly orthogonal) and moved by up to 1/4. Against the
        // libraries' time unposed: a pose costs them a 3x3 product per support call, which this
        // leaves out (their time is, if anything, understated).
        std::vector<scalecert::Claim> posed = typed;
        std::uniform_real_distribution<double> turn(-3.14159, 3.14159), shift(-0.25, 0.25);
        for (scalecert::Claim& t : posed)
            for (int k = 0; k < 2; ++k) {
                const double x = turn(g), y = turn(g), z = turn(g);
                const double cx = std::cos(x), sx = std::sin(x), cy = std::cos(y), sy = std::sin(y), cz = std::cos(z),
                             sz = std::sin(z);
                const double m[3][3] = {{cy * cz, -cy * sz, sy},
                                        {sx * sy * cz + cx * sz, -sx * sy * sz + cx * cz, -sx * cy},
                                        {-cx * sy * cz + sx * sz, cx * sy * sz + sx * cz, cx * cy}};
                scalecert::Pose p;
                for (int r = 0; r < 3; ++r) {
                    for (int q = 0; q < 3; ++q) p[r][q] = scalecert::exact(m[r][q]);
                    p[r][3] = scalecert::exact(shift(g));
                }
                (k ? t.pose2 : t.pose1) = p;
            }
        const double t_posed = per_call([&](long) { an.certify(posed); }, 1, quick ? 1 : 3);
        // Ours by output, one kind at a time, typed (no JSON in or out, as the libraries' outputs).
        std::vector<scalecert::Claim> by_kind[3];
        for (int i = 0; i < 1000; ++i) by_kind[i % 4 < 2 ? 0 : sep[i] ? 1 : 2].push_back(typed[static_cast<size_t>(i)]);
        for (int k = 0; k < 3; ++k) t_ours[k] = per_call([&](long) { an.certify(by_kind[k]); }, 1, quick ? 1 : 3);
        std::vector<scalecert::Claim> posed_kind[3];
        for (int i = 0; i < 1000; ++i)
            posed_kind[i % 4 < 2 ? 0 : sep[i] ? 1 : 2].push_back(posed[static_cast<size_t>(i)]);
        for (int k = 0; k < 3; ++k)
            t_posed_kind[k] = per_call([&](long) { an.certify(posed_kind[k]); }, 1, quick ? 1 : 3);
        // Against the fastest library for each kind, unposed: libccd's verdicts, Bullet's
        // distances, libccd's EPA depths (each share named).
        const double fastest = t_kind[0] + std::min(t_kind[1], t_bullet) + t_kind[2];
        char r[320];
        std::snprintf(r, sizeof r,
                      "%.2gx the fastest library for each kind, unposed (libccd verdicts %.3g s + Bullet distances "
                      "%.3g s + libccd EPA depths %.3g s = %.3g s; target <= 2x)",
                      t_posed / fastest, t_kind[0], std::min(t_kind[1], t_bullet), t_kind[2], fastest);
        add("the same 1,000 claims, each at its own random pose (typed)", t_posed, r);
    }
    const char* kinds[3] = {"verdicts and planes (typed)", "distances (typed)", "depths (typed)"};
    const char* libs[3] = {"libccd GJK verdicts", "FCL distances", "libccd EPA depths"};
    for (int k = 0; k < 3; ++k) {
        std::snprintf(what, sizeof what, "  of which %ld %s", nk[k], kinds[k]);
        char r[160];
        std::snprintf(r, sizeof r, "%.3gx %s (%.3g s)", t_ours[k] / t_kind[k], libs[k], t_kind[k]);
        add(what, t_ours[k], r);
    }
    std::snprintf(what, sizeof what, "  the %ld distances by Bullet's GJK (btConvexHullShape, margin 0)", nk[1]);
    add(what, t_bullet, ratio("ours %.3gx Bullet's (target <= 2x)", t_ours[1] / t_bullet));
    const double fastest[3] = {t_kind[0], std::min(t_kind[1], t_bullet), t_kind[2]};
    const char* fastest_name[3] = {"libccd GJK verdicts", t_bullet < t_kind[1] ? "Bullet's distances" : "FCL distances",
                                   "libccd EPA depths"};
    for (int k = 0; k < 3; ++k) {
        std::snprintf(what, sizeof what, "  of which %ld %s, at their poses", nk[k], kinds[k]);
        char r[160];
        std::snprintf(r, sizeof r, "%.3gx %s unposed (%.3g s)", t_posed_kind[k] / fastest[k], fastest_name[k],
                      fastest[k]);
        add(what, t_posed_kind[k], r);
    }
}

// One distance and one depth claim on two near-spheres of 10^6 points each, after the scene is
// read, with no hull: the walk's point trees (CloudPoints) answer every support query. Against
// Bullet's GJK distance (btConvexHullShape of the points) and libccd's EPA depth on the same
// points (both support by a scan of all points), in the same run.
void large_claim_costs() {
    const auto dir = scratch_dir("scalecert-bench-large");
    const int n = 1000000;
    const long R = 10L * n * 1000;
    const std::string a = (dir / "a.off").string(), b = (dir / "b.off").string();
    write_cloud(a, n, R, true, false, 5 + n);
    write_cloud(b, n, R, true, true, 6 + n);
    auto cs = std::make_shared<CompactScene>();
    cs->P[0] = *read_off_fast(a, Numbers::Exact);
    cs->P[1] = *read_off_fast(b, Numbers::Exact);
    for (int i = 0; i < 2; ++i) cs->seed[i] = cs->P[i].mean(), cs->lo[i] = Q(1, 2), cs->hi[i] = 2;
    std::filesystem::remove_all(dir);
    fp::FpScene f;
    for (int i = 0; i < 2; ++i) {
        for (size_t k = 0; k < cs->P[i].size(); ++k) {
            const std::int64_t* x = cs->P[i].at(k);
            f.P[i].pts.push_back({static_cast<double>(x[0]), static_cast<double>(x[1]), static_cast<double>(x[2])});
        }
        f.P[i].seed = {to_double_rn(cs->seed[i][0]), to_double_rn(cs->seed[i][1]), to_double_rn(cs->seed[i][2])};
        f.lo[i] = 0.5, f.hi[i] = 2;
    }
    auto gjk = fp::make_libccd_gjk(f);
    auto bullet = fp::make_bullet(f);
    volatile double sink = 0;
    // Distance at (1, 1): apart by about R; depth at (2, 2): overlapping by about R.
    const double t_ccd_dist = per_call(
        [&](long) {
            if (auto me = bullet->measure(1, 1, true))
                sink = sink + me->value;
            else
                std::abort();
        },
        1, 3);
    const double t_ccd_depth = per_call(
        [&](long) {
            if (auto me = gjk->measure(2, 2, false))
                sink = sink + me->value;
            else
                std::abort();
        },
        1, 3);
    Session s(cs, "bench");
    const double t_index = per_call(
        [&](long) {
            Session t(cs, "bench");
            (void)t.points();
        },
        1, 1);
    (void)s.points();
    const std::string dist =
        R"({"format": "scalecert-claims-1", "claims": [{"kind": "distance", "rho1": 1, "rho2": 1, "value": 1}]})";
    const std::string depth =
        R"({"format": "scalecert-claims-1", "claims": [{"kind": "penetration_depth", "rho1": 2, "rho2": 2, )"
        R"("value": 1}]})";
    long wrong = 0;
    std::string cert;
    const ClaimModels& cm = s.claim_models();
    const double t_dist = per_call(
        [&](long) {
            certify_fp(cm, dist, "bench", ClaimOptions{Numbers::Double, Q(0), true}, &wrong);
        },
        1, 3);
    const double t_depth = per_call(
        [&](long) {
            certify_fp(cm, depth, "bench", ClaimOptions{Numbers::Double, Q(0), true}, &wrong);
        },
        1, 3);
    const double t_dist_c = per_call(
        [&](long) {
            certify_fp(cm, dist, "bench", ClaimOptions{Numbers::Double, Q(0), true}, &wrong, nullptr, &cert);
        },
        1, 1);
    const double t_depth_c = per_call(
        [&](long) {
            certify_fp(cm, depth, "bench", ClaimOptions{Numbers::Double, Q(0), true}, &wrong, nullptr, &cert);
        },
        1, 1);
    auto add = [&](const char* what, double t, const std::string& r) {
        char line[256];
        std::snprintf(line, sizeof line, "| %s | %.3g ms | %s |", what, t * 1e3, r.c_str());
        claim_rows.push_back(line);
        std::fprintf(stderr, "  %s\n", line);
    };
    add("10^6 + 10^6 points: Bullet GJK distance (support: scan of all points)", t_ccd_dist, "1 (baseline)");
    add("10^6 + 10^6 points: libccd EPA depth", t_ccd_depth, "1 (baseline)");
    add("10^6 + 10^6 points: the walk and its point trees, once per scene (no hull)", t_index, "");
    add("10^6 + 10^6 points: one distance claim certified (target < 50 ms)", t_dist,
        ratio("%.2gx Bullet's distance", t_dist / t_ccd_dist));
    add("10^6 + 10^6 points: one depth claim certified (target < 50 ms)", t_depth,
        ratio("%.2gx libccd's EPA depth", t_depth / t_ccd_depth));
    add("10^6 + 10^6 points: the distance with its judgements certificate (the file holds the 2 x 10^6 points)",
        t_dist_c, "");
    add("10^6 + 10^6 points: the depth with its judgements certificate", t_depth_c, "");
}

// Compounds: two objects of k × k parts (random 8-point parts on a grid, 4 apart), at
// `gap` along x; I1 = I2 = [1/2, 2]. The region, its certificate, and queries located on the grid
// against libccd's GJK looped over the part pairs (all of them, and those the boxes do not prune).
ExactScene compound(int k, int gap, unsigned seed) {
    std::mt19937 g(seed);
    std::uniform_int_distribution<int> u(-2, 2), h(0, 3);
    ExactScene s;
    for (int i = 0; i < 2; ++i) {
        for (int p = 0; p < k * k; ++p) {
            std::vector<Vec3q> v;
            const int cx = (i ? gap : 0) + (p % k) * 4, cy = (p / k) * 4, cz = h(g);
            for (int q = 0; q < 8; ++q) v.push_back({Q(cx + u(g)), Q(cy + u(g)), Q(cz + u(g))});
            s.P[i].parts.push_back(v);
            s.P[i].points.insert(s.P[i].points.end(), v.begin(), v.end());
        }
        Vec3q c{Q(0), Q(0), Q(0)};
        for (const Vec3q& x : s.P[i].points)
            for (int d = 0; d < 3; ++d) c[d] += x[d];
        for (int d = 0; d < 3; ++d) c[d] /= Q(static_cast<long>(s.P[i].points.size()));
        s.P[i].seed = c;
        s.lo[i] = qc(1, 2);
        s.hi[i] = Q(2);
    }
    return s;
}
std::vector<std::string> compound_rows;
void compound_costs(bool quick) {
    auto secs = [](Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); };
    for (const int gap : {30, 400}) {
        const ExactScene sc = compound(10, gap, 3);
        auto t0 = Clock::now();
        // A flat part cannot occur: 8 random points of a 5-cube span 3 dimensions here (seeded).
        const CompoundRegion r = compound_region(sc, "bench");
        const double t_region = secs(t0);
        t0 = Clock::now();
        const CompoundBoundary bd = label_boundary(r, sc);
        const double t_labels = secs(t0);
        size_t n_edges = 0;
        for (const BoundaryRing& ring : bd.rings) n_edges += ring.edges.size();
        t0 = Clock::now();
        const std::string cert = dump(compound_partition_json(sc, r));
        const double t_cert = secs(t0);
        t0 = Clock::now();
        const int G = CompoundLocator::grid_for(r);
        const CompoundLocator L(r, sc.lo, sc.hi, G);
        const double t_grid = secs(t0);
        const long nq = quick ? 200000 : 2000000;
        std::mt19937_64 g(11);
        std::uniform_real_distribution<double> u1(0.5, 2.0);
        std::vector<double> r1(static_cast<size_t>(nq)), r2(static_cast<size_t>(nq));
        for (long i = 0; i < nq; ++i) r1[static_cast<size_t>(i)] = u1(g), r2[static_cast<size_t>(i)] = u1(g);
        filter::PredicateStats st;
        volatile int sink = 0;
        const double t_query = per_call(
            [&](long i) {
                sink += static_cast<int>(L.verdict(r1[static_cast<size_t>(i)], r2[static_cast<size_t>(i)], st));
            },
            nq);
        // The baseline: libccd GJK on the part pairs, per query, stopping at the first pair that meets.
        std::vector<std::unique_ptr<fp::Method>> all, kept;
        const size_t n2 = sc.P[1].parts.size();
        for (size_t a = 0; a < sc.P[0].parts.size(); ++a)
            for (size_t b = 0; b < n2; ++b) {
                ExactScene pair;
                pair.P[0].points = sc.P[0].parts[a];
                pair.P[1].points = sc.P[1].parts[b];
                for (int i = 0; i < 2; ++i) pair.P[i].seed = sc.P[i].seed, pair.lo[i] = sc.lo[i], pair.hi[i] = sc.hi[i];
                auto m = fp::make_libccd_gjk(fp::to_fp(pair));
                if (!r.prune[a * n2 + b]) kept.push_back(fp::make_libccd_gjk(fp::to_fp(pair)));
                all.push_back(std::move(m));
            }
        auto loop = [&](const std::vector<std::unique_ptr<fp::Method>>& ms, long i) {
            for (const auto& mth : ms)
                if (mth->classify(r1[static_cast<size_t>(i)], r2[static_cast<size_t>(i)]) <= 0) return 1;
            return 0;
        };
        const long ng = quick ? 200 : 2000;
        const double t_all = per_call([&](long i) { sink += loop(all, i); }, ng, 1);
        const double t_kept = per_call([&](long i) { sink += loop(kept, i); }, ng, 1);
        char b[512], k[64];
        if (kept.empty())
            std::snprintf(k, sizeof k, "no pair");
        else
            std::snprintf(k, sizeof k, "%.1f us (%.0fx)", t_kept * 1e6, t_kept / t_query);
        std::snprintf(b, sizeof b,
                      "| 10 x 10 parts each, %s | %zu | %ld | %.3f s | %.3f s (%zu edges, %zu switch points) | %.3f s "
                      "(%zu KB) | %.3f s (%d x %d cells) | %.0f ns | %s | %.1f us (%.0fx) |",
                      gap == 30 ? "side by side" : "far apart", r.prune.size(), r.built, t_region, t_labels, n_edges,
                      bd.switches.size(), t_cert, cert.size() / 1024, t_grid, G, G, t_query * 1e9, k, t_all * 1e6,
                      t_all / t_query);
        compound_rows.push_back(b);
        std::fprintf(stderr, "%s\n", b);
    }
}

// Objects of 10 x 10 parts each through the public API (scalecert.hpp), each row from a fresh
// Analysis, so that each time includes what it builds: a query (the verdict at (1, 1) with its
// evidence), the compound partition with scalecert-check on it (a process), 1,000 typed claims
// (250 each of verdicts, separating planes, witness points and distances at random pairs of
// doubles, at their exact values), and golden data.
std::vector<std::string> compound_api_rows;
void compound_api_costs() {
    using scalecert::Rational;
    auto secs = [](Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); };
    static const std::string checker = sibling("scalecert-check");
    for (const int gap : {30, 400}) {
        const ExactScene sc = compound(10, gap, 3);
        std::vector<std::vector<scalecert::Point>> parts[2];
        for (int i = 0; i < 2; ++i)
            for (const std::vector<Vec3q>& p : sc.P[i].parts) parts[i].push_back({p.begin(), p.end()});
        const scalecert::Scene scene = scalecert::Scene::from_parts(parts[0], parts[1], {sc.lo[0], sc.hi[0]},
                                                                    {sc.lo[1], sc.hi[1]}, sc.P[0].seed, sc.P[1].seed);
        auto t0 = Clock::now();
        const scalecert::Verdict v = scalecert::Analysis(scene).verdict(Rational(1), Rational(1));
        const double t_query = secs(t0);
        t0 = Clock::now();
        const std::string cert = scalecert::Analysis(scene).partition_json();
        const auto dir = scratch_dir("scalecert-bench");
        const std::string path = (dir / "compound_partition.json").string();
        std::ofstream(path) << cert;
        const int check = std::system((checker + " " + path + " >/dev/null 2>&1").c_str());
        const double t_partition = secs(t0);
        std::filesystem::remove_all(dir);
        std::mt19937_64 g(17);
        std::uniform_real_distribution<double> u(0.5, 2.0), n(-1.0, 1.0);
        std::vector<scalecert::Claim> claims;
        for (int k = 0; k < 1000; ++k) {
            scalecert::Claim c;
            c.rho1 = scalecert::exact(u(g));
            c.rho2 = scalecert::exact(u(g));
            switch (k % 4) {
            case 0:
                c.kind = scalecert::ClaimKind::Verdict;
                c.verdict = scalecert::ClaimedVerdict::Separated;
                break;
            case 1:
                c.kind = scalecert::ClaimKind::SeparatingPlane;
                c.normal = {scalecert::exact(1.0), scalecert::exact(n(g)), scalecert::exact(n(g))};
                break;
            case 2:
                c.kind = scalecert::ClaimKind::WitnessPoint;
                c.point = {scalecert::exact(20 + 10 * n(g)), scalecert::exact(18 + 18 * n(g)),
                           scalecert::exact(1 + n(g))};
                break;
            default: c.kind = scalecert::ClaimKind::Distance; c.value = scalecert::exact(u(g));
            }
            claims.push_back(std::move(c));
        }
        t0 = Clock::now();
        const scalecert::Judgements j = scalecert::Analysis(scene).certify(claims);
        const double t_claims = secs(t0);
        t0 = Clock::now();
        std::string golden;  // its time and rows, or its refusal (a work limit)
        try {
            const scalecert::GoldenData gd = scalecert::Analysis(scene).golden();
            char g[64];
            std::snprintf(g, sizeof g, "%.3f s (%zu CSV rows)", secs(t0),
                          static_cast<size_t>(std::count(gd.csv.begin(), gd.csv.end(), '\n')) - 1);
            golden = g;
        } catch (const scalecert::InputError& e) {
            char g[64];
            std::snprintf(g, sizeof g, "refused after %.3f s", secs(t0));
            golden = g;
        }
        char b[512];
        std::snprintf(b, sizeof b,
                      "| 10 x 10 parts each, %s | %.3f s (%s) | %.3f s (%zu KB%s) | %.3f s (%ld wrong) | %s |",
                      gap == 30 ? "side by side" : "far apart", t_query, scalecert::name(v), t_partition,
                      cert.size() / 1024, check ? ", REJECTED" : ", checked", t_claims, j.wrong, golden.c_str());
        compound_api_rows.push_back(b);
        std::fprintf(stderr, "%s\n", b);
    }
}

int checker_bench(int argc, char** argv);  // tools/bench_checker.cpp
int round_bench(bool quick);               // tools/bench_round.cpp
int robot_bench(bool quick);               // tools/bench_round.cpp

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "--checker") == 0) return checker_bench(argc - 2, argv + 2);
    if (argc > 1 && std::strcmp(argv[1], "--round") == 0)
        return round_bench(argc > 2 && std::strcmp(argv[2], "--quick") == 0);
    if (argc > 1 && std::strcmp(argv[1], "--robot") == 0)
        return robot_bench(argc > 2 && std::strcmp(argv[2], "--quick") == 0);
    bool quick = false, with_slow = false, sizes_only = false, queries_only = false, claims_only = false,
         compound_only = false;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") == 0)
            quick = true;
        else if (std::strcmp(argv[i], "--with-slow") == 0)
            with_slow = true;
        else if (std::strcmp(argv[i], "--sizes") == 0)
            sizes_only = true;
        else if (std::strcmp(argv[i], "--queries") == 0)
            queries_only = true;
        else if (std::strcmp(argv[i], "--claims") == 0)
            claims_only = true;
        else if (std::strcmp(argv[i], "--compound") == 0)
            compound_only = true;
        else if (std::strcmp(argv[i], "--prism-claims") == 0) {  // every claim kind on crossed prisms
            prism_claim_costs(quick ? std::vector<int>{1200} : std::vector<int>{1200, 4800});
            for (const std::string& r : prism_claim_rows) std::printf("%s\n", r.c_str());
            return 0;
        } else {
            std::fprintf(stderr,
                         "usage: scalecert-bench [--quick] [--sizes] [--queries] [--claims] [--compound] "
                         "[--prism-claims] [--with-slow] | --round [--quick] | --checker [--timeout S] [--keep DIR] "
                         "[CHECKER ...]\n");
            return 2;
        }
    }
    if (queries_only) {  // only the query table (its 10^6 hull run with --with-slow: minutes, GBs)
        query_costs(with_slow);
        for (const std::string& r : query_rows) std::printf("%s\n", r.c_str());
        return 0;
    }
    if (compound_only) {  // only the compounds' table
        std::printf(
            "| scene | part pairs | built | region | labels | certificate | query grid | query | libccd GJK over the "
            "built pairs | over all pairs |\n|---|---|---|---|---|---|---|---|---|---|\n");
        compound_costs(quick);
        for (const std::string& r : compound_rows) std::printf("%s\n", r.c_str());
        std::printf(
            "\n| scene (public API, each from a fresh Analysis; target: each under 2 s) | query | partition + "
            "scalecert-check | 1,000 typed claims | golden |\n|---|---|---|---|---|\n");
        compound_api_costs();
        for (const std::string& r : compound_api_rows) std::printf("%s\n", r.c_str());
        return 0;
    }
    if (claims_only) {  // only the claims' table
        claim_costs(spheres(1000, 1000000, 1), quick);
        large_claim_costs();
        for (const std::string& r : claim_rows) std::printf("%s\n", r.c_str());
        return 0;
    }
    if (sizes_only) {  // only the whole-process table (its 10^6 hull run with --with-slow: minutes, GBs)
        curve_sizes(with_slow);
        for (const std::string& r : size_rows) std::printf("%s\n", r.c_str());
        return 0;
    }
    long nq = quick ? 20000 : 200000;
    std::fprintf(stderr, "scalecert-bench%s (times per call, best of 3)\n", quick ? " --quick" : "");
    ExactScene bx = boxes(), h1000 = spheres(1000, 1000000, 1), h10k = spheres(10000, 10000000, 2);
    query_benchmarks("boxes (8+8)", bx, nq);
    query_benchmarks("hulls (1000)", h1000, nq / 10);
    // The whole curve: exact engine against the paper's grid search at 256 x 256 with 20 bisection
    // steps per column. The paper classifies every node (exhaustive search, Section 2.3.2) with its
    // triangle-triangle test, and repeats each bisection and averages (x3). For comparison, the
    // same grid with libccd GJK at the nodes, and a grid that stops each column at its first
    // overlapping node (a shortcut the paper does not take).
    for (auto* sc : {&bx, &h1000}) {
        const bool small = sc == &bx;
        const char* nm = small ? "boxes (8+8)" : "hulls (1000)";
        fp::FpScene f = fp::to_fp(*sc);
        auto gjk = fp::make_libccd_gjk(f);
        const long calls = small ? (quick ? 200 : 2000) : 3;
        double t_exact = per_call(
            [&](long) {
                HullModel m = build_model(*sc);
                TouchingCurve c = build_curve(m);
            },
            calls, quick ? 1 : 3);
        const int n = 256;
        fp::GridCurve gc;
        if (small) {  // the paper's own node test: triangle-triangle on the triangulated faces
            HullModel m = build_model(*sc);
            auto tt = fp::make_paper_tritri(m, f);
            double t_tt = per_call([&](long) { gc = fp::grid_search(*tt, f, n, 20, 3, true); }, 1, 1);
            row("paper's grid search: 256x256 exhaustive, 20 bisections x3, triangle-triangle", nm, t_tt,
                "1 (baseline)");
            row("exact curve (hull, lines, envelope)", nm, t_exact,
                ratio("%.0fx faster than the paper's grid (target 1000x)", t_tt / t_exact));
            double t_te = per_call([&](long) { gc = fp::grid_search(*tt, f, n, 20, 3, false); }, 1, 1);
            row("same grid, each column stopped at its first overlap", nm, t_te,
                ratio("exact curve %.0fx faster", t_te / t_exact));
        }
        double t_grid = per_call([&](long) { gc = fp::grid_search(*gjk, f, n, 20, 1, true); }, 1, 1);
        row("grid 256x256 exhaustive + 20 bisections, libccd GJK", nm, t_grid, "1 (baseline)");
        row("exact curve (hull, lines, envelope)", nm, t_exact,
            ratio("%.0fx faster than the GJK grid", t_grid / t_exact));
        double t_ge = per_call([&](long) { gc = fp::grid_search(*gjk, f, n, 20, 1, false); }, 1, 1);
        row("same GJK grid, each column stopped at its first overlap", nm, t_ge,
            ratio("exact curve %.0fx faster", t_ge / t_exact));
    }
    claim_costs(h1000, quick);
    double t10k = per_call(
        [&](long) {
            HullModel m = build_model(h10k);
            TouchingCurve c = build_curve(m);
        },
        1, 1);
    row("exact curve, two 10,000-vertex hulls", "hulls (10000)", t10k, "target < 1 s");
    // Growth with size and with degeneracy: curve time, and how often each stage decided.
    std::fprintf(
        stderr, "growth (exact curve; filter/exact decisions in support climbs, arc signs, queries near the curve):\n");
    growth_rows.push_back(
        "| case | curve time | support comparisons filtered / exact | arc signs filtered / exact | queries near the "
        "curve filtered / exact |");
    growth_rows.push_back("|---|---|---|---|---|");
    for (int n : {100, 1000, 10000})
        growth("near-sphere, " + std::to_string(n) + " vertices", spheres(n, 10 * n * 1000L, 5));
    for (int k : {4, 20, 40}) {
        Rng g(1);
        growth("nearly-equal-slopes, eps = 2^-" + std::to_string(k),
               make_family_scene("nearly-equal-slopes", Q(1, Z(1) << k), g));
    }
    // Batch: many pairs on one core and on two.
    {
        HullModel m = build_model(bx);
        TouchingCurve c = build_curve(m);
        FastCurve fc(m, c);
        long n = quick ? 200000 : 2000000;
        std::mt19937_64 g(3);
        std::uniform_real_distribution<double> u(0.5, 3);
        std::vector<double> a(n), b(n);
        for (long i = 0; i < n; ++i) a[i] = u(g), b[i] = u(g);
        std::vector<Verdict> out;
        double t1 = per_call([&](long) { classify_batch(fc, a, b, out, 1); }, 1);
        double t2 = per_call([&](long) { classify_batch(fc, a, b, out, 2); }, 1);
        row("batch " + std::to_string(n) + " pairs, 1 thread", "boxes (8+8)", t1, "1 (baseline)");
        row("batch " + std::to_string(n) + " pairs, 2 threads", "boxes (8+8)", t2, ratio("%.2fx faster", t1 / t2));
        // The same pairs as text, as `scalecert classify` reads them from a file.
        std::string text;
        char buf[64];
        for (long i = 0; i < n; ++i)
            text.append(buf, static_cast<size_t>(std::snprintf(buf, sizeof buf, "%.17g %.17g\n", a[i], b[i])));
        std::vector<double> pa, pb;
        double p1 = per_call([&](long) { parse_pairs(text, pa, pb, 1); }, 1);
        double p2 = per_call([&](long) { parse_pairs(text, pa, pb, 2); }, 1);
        row("reading " + std::to_string(n) + " pairs from text, 1 thread", "boxes (8+8)", p1, "1 (baseline)");
        row("reading " + std::to_string(n) + " pairs from text, 2 threads", "boxes (8+8)", p2,
            ratio("%.2fx faster", p1 / p2));
    }
    std::printf("| method | case | time | ratio |\n|---|---|---|---|\n");
    for (const Row& r : rows) {
        double t = r.seconds;
        char buf[32];
        if (t < 1e-6)
            std::snprintf(buf, sizeof buf, "%.0f ns", t * 1e9);
        else if (t < 1e-3)
            std::snprintf(buf, sizeof buf, "%.2f µs", t * 1e6);
        else if (t < 1)
            std::snprintf(buf, sizeof buf, "%.1f ms", t * 1e3);
        else
            std::snprintf(buf, sizeof buf, "%.2f s", t);
        std::printf("| %s | %s | %s | %s |\n", r.method.c_str(), r.scene.c_str(), buf, r.ratio.c_str());
    }
    std::printf("\n");
    for (const std::string& g : growth_rows) std::printf("%s\n", g.c_str());
    if (!quick) {
        curve_sizes(with_slow);
        std::printf("\n");
        for (const std::string& r : size_rows) std::printf("%s\n", r.c_str());
    }
}
