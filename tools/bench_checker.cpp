// scalecert-bench --checker: scalecert-check on 1 MB hostile certificates. Each shape is built in
// this run from a certificate the engine writes (or by hand, for the unreadable ones), written to a
// temporary directory, and checked by each binary given (default: the scalecert-check next to this
// bench) as a whole process; the baseline is reading the same file as plain JSON (nlohmann's DOM
// parser, in this process, in the same run). Usage:
//   scalecert-bench --checker [--timeout SECONDS] [--keep DIR] [CHECKER ...]
// Prints one markdown row per shape: bytes, the JSON read, and per checker its exit status, its
// time (best of 3; one run when it exceeds 2 s; "> T s" when killed at the timeout) and the ratio.
#include "numeric/exact.hpp"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern "C" char** environ;

namespace {
using OJ = nlohmann::ordered_json;
using scalecert::internal::Q;
using scalecert::internal::Z;
using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

constexpr size_t kBytes = 1000000;  // every shape is about this size

struct Run {
    double seconds;
    int status;
    bool killed;
};

// `bin args...` with stdout and stderr to /dev/null; killed after `timeout` seconds.
Run run(const std::string& bin, const std::vector<std::string>& args, double timeout) {
    std::vector<std::string> all{bin};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    const auto t0 = Clock::now();
    pid_t pid;
    const int err = posix_spawn(&pid, bin.c_str(), &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    if (err != 0) return {0, -1, false};
    int st = 0;
    bool killed = false;
    for (long us = 50;; us = std::min(us * 2, 2000L)) {
        if (waitpid(pid, &st, WNOHANG) == pid) break;
        if (std::chrono::duration<double>(Clock::now() - t0).count() > timeout) {
            kill(pid, SIGKILL);
            waitpid(pid, &st, 0);
            killed = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(us));
    }
    return {std::chrono::duration<double>(Clock::now() - t0).count(), WIFEXITED(st) ? WEXITSTATUS(st) : -1, killed};
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// ---- exact numbers as the certificate writes them ----------------------------------------------
OJ exact(const Q& q) { return q.get_str(); }
OJ nearest(const Q& q) {
    const double d = scalecert::internal::to_double_rn(q);
    return std::isinf(d) ? OJ(nullptr) : OJ(d);
}
void put(OJ& o, const std::string& key, const Q& q) {
    o[key] = exact(q);
    o[key + "_double"] = nearest(q);
}
Q q_of(const OJ& j) { return Q(j.get<std::string>()); }
std::array<Q, 3> point_of(const OJ& j) { return {q_of(j[0]), q_of(j[1]), q_of(j[2])}; }
size_t bytes(const OJ& j) { return j.dump().size(); }

// ---- the engine's certificates the shapes start from --------------------------------------------
struct Engine {
    std::string bin;
    fs::path dir;
    OJ partition(const std::string& name, const std::string& scene) {
        const fs::path s = dir / (name + ".scene.json"), c = dir / (name + ".engine.json");
        std::ofstream(s) << scene;
        Run r = run(bin, {"partition", s.string(), "--out", c.string()}, 600);
        if (r.status != 0) throw std::runtime_error("scalecert partition failed on " + name);
        return OJ::parse(slurp(c));
    }
};

// The bundled tetra_box_switch scene: a tetrahedron and a cube, two pieces (VF and EE).
const char* kTetraBox = R"({"P1": {"vertices": [[2,0,2],[-2,2,5],[-1,-2,6],[2,0,7]], "seed": [0,0,"9/2"]},
 "P2": {"vertices": [[-1,-1,-1],[1,-1,-1],[-1,1,-1],[1,1,-1],[-1,-1,1],[1,-1,1],[-1,1,1],[1,1,1]], "seed": [0,0,0]},
 "I1": ["1/2", 2], "I2": [1, 4]})";
// Two square pyramids tip to tip on the z axis: the curve is the one line rho1 + rho2 = 3, and
// every normal (x, y, z) with |x| + |y| < 2z gives it (each pyramid lies in its tip's cone).
const char* kPyramids =
    R"({"P1": {"vertices": [[0,0,10],[10,10,-10],[10,-10,-10],[-10,10,-10],[-10,-10,-10]], "seed": [0,0,0]},
 "P2": {"vertices": [[0,0,20],[10,10,40],[10,-10,40],[-10,10,40],[-10,-10,40]], "seed": [0,0,30]},
 "I1": ["1/2", 2], "I2": ["1/2", 2]})";
// A prism over an n-gon of radius 10^7 (no three base points collinear at this radius), seeded
// off centre, against a box up and to the right: the contact runs around the n-gon as the ratio of
// the scalings changes, so the curve has about n/5 pieces, nearly all inside I1 x I2.
std::string ngon_scene(int n) {
    const long R = 10000000;
    std::ostringstream o;
    o << "{\"P1\": {\"vertices\": [";
    for (int k = 0; k < n; ++k) {
        const double a = 2 * M_PI * k / n;
        const long x = std::lround(R * std::cos(a)), y = std::lround(R * std::sin(a));
        o << (k ? "," : "") << "[" << x << "," << y << ",-100],[" << x << "," << y << ",100]";
    }
    o << "], \"seed\": [" << R * 9 / 10 << ",0,0]}, \"P2\": {\"vertices\": [";
    bool first = true;
    for (long x : {R, R * 13 / 10})
        for (long y : {R, R * 13 / 10})
            for (int z : {-100, 100}) {
                o << (first ? "" : ",") << "[" << x << "," << y << "," << z << "]";
                first = false;
            }
    o << "], \"seed\": [" << R + R / 100 << "," << R + R / 100
      << ",0]}, \"I1\": [\"1/10\", 10], \"I2\": [\"1/10\", 100]}";
    return o.str();
}

// The scene text with every vertex and seed coordinate (integers or "p/q" strings) times f.
std::string scaled_scene(const std::string& scene, const std::string& f) {
    OJ j = OJ::parse(scene);
    const Q k(f);
    auto scale = [&](OJ& x) { x = Q((x.is_string() ? Q(x.get<std::string>()) : Q(x.get<long>())) * k).get_str(); };
    for (const char* p : {"P1", "P2"}) {
        for (OJ& v : j[p]["vertices"])
            for (OJ& x : v) scale(x);
        for (OJ& x : j[p]["seed"]) scale(x);
    }
    return j.dump();
}

// Appends `count` copies of `p` to the vertices of polytope i ("P1", "P2").
void pad(OJ& c, const char* poly, const OJ& p, size_t count) {
    OJ& vs = c["scene"][poly]["vertices"];
    for (size_t k = 0; k < count; ++k) vs.push_back(p);
}
OJ seed_point(const OJ& c, const char* poly) { return c["scene"][poly]["seed"]; }
// How many copies of `element` (in a list) fit in `room` bytes.
size_t fit(const OJ& element, size_t room) { return room / (bytes(element) + 1); }
size_t room(const OJ& c) { return bytes(c) < kBytes ? kBytes - bytes(c) : 0; }

// Pieces with contact null (rho2 <= 0 all along) and distinct normals n with n.d < 0, each right on
// its own (h1, h2, line, support vertices recomputed here from the scene), over the whole of I1;
// the file then fails where pieces must be contiguous, after every piece has been checked.
OJ distinct_null_pieces(const OJ& c, size_t count) {
    std::vector<std::array<Q, 3>> P[2];
    std::array<Q, 3> s[2];
    for (int i = 0; i < 2; ++i) {
        const char* poly = i ? "P2" : "P1";
        for (const OJ& v : c["scene"][poly]["vertices"]) P[i].push_back(point_of(v));
        s[i] = point_of(c["scene"][poly]["seed"]);
    }
    const std::array<Q, 3> d{s[1][0] - s[0][0], s[1][1] - s[0][1], s[1][2] - s[0][2]};
    OJ out = OJ::array();
    for (long z = 1; out.size() < count; ++z)
        for (long x = -z; x <= z && out.size() < count; ++x)
            for (long y = -z; y <= z && out.size() < count; ++y) {
                if (std::gcd(std::gcd(std::labs(x), std::labs(y)), z) != 1) continue;
                const std::array<Q, 3> n{Q(x), Q(y), Q(z)};
                const Q nd = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
                if (sgn(nd) >= 0) {
                    if (out.empty() && z > 50) return out;
                    continue;
                }
                Q h[2];
                size_t arg[2] = {0, 0};
                for (int i = 0; i < 2; ++i)
                    for (size_t k = 0; k < P[i].size(); ++k) {
                        Q v = n[0] * (P[i][k][0] - s[i][0]) + n[1] * (P[i][k][1] - s[i][1]) +
                              n[2] * (P[i][k][2] - s[i][2]);
                        if (i == 1) v = -v;
                        if (k == 0 || v > h[i]) {
                            h[i] = v;
                            arg[i] = k;
                        }
                    }
                OJ p;
                p["rho1"] = c["scene"]["I1"];
                p["rho1_double"] = {nearest(q_of(c["scene"]["I1"][0])), nearest(q_of(c["scene"]["I1"][1]))};
                put(p, "slope", Q(-h[0] / h[1]));
                put(p, "intercept", Q(nd / h[1]));
                p["contact"] = nullptr;
                p["normal"] = {std::to_string(x), std::to_string(y), std::to_string(z)};
                put(p, "h1", h[0]);
                put(p, "h2", h[1]);
                p["support_vertices"] = {{"P1", arg[0]}, {"P2", arg[1]}};
                out.push_back(p);
            }
    return out;
}

// Distinct primitive normals (x, y, z) with |x| + |y| < 2z: each gives the pyramids' one line.
OJ pyramid_normals(size_t count) {
    OJ out = OJ::array();
    for (long z = 1; out.size() < count; ++z)
        for (long x = -2 * z + 1; x < 2 * z && out.size() < count; ++x)
            for (long y = -2 * z + 1 + std::labs(x); std::labs(x) + std::labs(y) < 2 * z && out.size() < count; ++y)
                if (std::gcd(std::gcd(std::labs(x), std::labs(y)), z) == 1)
                    out.push_back({std::to_string(x), std::to_string(y), std::to_string(z)});
    return out;
}

// A decimal string of `digits` digits, not divisible by 3.
std::string digits_not_div3(size_t digits, std::mt19937_64& g) {
    std::string s(digits, '0');
    for (auto& ch : s) ch = static_cast<char>('0' + g() % 10);
    s[0] = '1';
    Z z(s);
    if (z % 3 == 0) z += 1;
    return z.get_str();
}

struct Shape {
    std::string name, text, note;
};

std::vector<Shape> shapes(Engine& e) {
    std::vector<Shape> out;
    auto add = [&](const std::string& name, const OJ& c, const std::string& note) {
        out.push_back({name, c.dump(), note});
    };
    const OJ tetra = e.partition("tetra_box", kTetraBox), pyr = e.partition("pyramids", kPyramids);

    {  // The review's shape: one piece copied ~950 times and ~35,000 tiny vertices.
        OJ c = tetra;
        const OJ piece = c["pieces"][0];
        const size_t r = room(c);
        pad(c, "P2", seed_point(c, "P2"), fit(seed_point(c, "P2"), r / 2));
        c["pieces"] = OJ::array();
        for (size_t k = fit(piece, r / 2); k > 0; --k) c["pieces"].push_back(piece);
        add("one piece copied, P2 padded with copies of its seed", c,
            "fails at the switch count after checking every piece");
    }
    {  // Distinct normals: no two pieces share a support computation.
        OJ c = tetra;
        const size_t r = room(c);
        pad(c, "P2", seed_point(c, "P2"), fit(seed_point(c, "P2"), r / 2));
        const OJ one = distinct_null_pieces(c, 1)[0];
        c["pieces"] = distinct_null_pieces(c, fit(one, r / 2) * 95 / 100);
        add("distinct pieces (contact null), P2 padded", c,
            "each piece right on its own; fails where pieces must be contiguous");
    }
    {  // The engine's many-piece curve: a valid file of ~400 pieces whose overlap polygon has ~400 vertices.
        OJ c = e.partition("ngon2000", ngon_scene(2000));
        pad(c, "P1", seed_point(c, "P1"), fit(seed_point(c, "P1"), room(c)));
        add("valid curve of " + std::to_string(c["pieces"].size()) + " pieces, overlap polygon of " +
                std::to_string(c["regions"]["overlap"]["vertices"].size()) + " vertices",
            c, "valid");
    }
    {  // The same with fewer pieces and the rest padding.
        OJ c = e.partition("ngon600", ngon_scene(600));
        const size_t pieces = c["pieces"].size();
        pad(c, "P1", seed_point(c, "P1"), fit(seed_point(c, "P1"), room(c)) / 2);
        pad(c, "P2", seed_point(c, "P2"), fit(seed_point(c, "P2"), room(c)));
        add("valid curve of " + std::to_string(pieces) + " pieces, both polytopes padded", c, "valid");
    }
    {  // The pyramids' one piece with ~29,000 distinct same-line normals and ~34,000 tiny vertices.
        OJ c = pyr;
        const size_t r = room(c);
        pad(c, "P1", seed_point(c, "P1"), fit(seed_point(c, "P1"), r / 4));
        pad(c, "P2", seed_point(c, "P2"), fit(seed_point(c, "P2"), r / 4));
        const OJ probe = pyramid_normals(20000);
        c["pieces"][0]["same_line_normals"] = pyramid_normals(fit(probe.back(), r / 2));
        add("same_line_normals: " + std::to_string(c["pieces"][0]["same_line_normals"].size()) + " directions, padded",
            c, "valid, past the work limit");
    }
    {  // The same with 15% of the file in normals (~8,800) and 85% in vertices (~60,000): within
        // the work limit.
        OJ c = pyr;
        const size_t r = room(c);
        pad(c, "P1", seed_point(c, "P1"), fit(seed_point(c, "P1"), r * 85 / 200));
        pad(c, "P2", seed_point(c, "P2"), fit(seed_point(c, "P2"), r * 85 / 200));
        const OJ probe = pyramid_normals(20000);
        c["pieces"][0]["same_line_normals"] = pyramid_normals(fit(probe.back(), r * 15 / 100));
        add("same_line_normals: " + std::to_string(c["pieces"][0]["same_line_normals"].size()) + " directions, padded",
            c, "valid");
    }
    {  // One same-line normal repeated, and its multiples.
        OJ c = pyr;
        const size_t r = room(c);
        pad(c, "P1", seed_point(c, "P1"), fit(seed_point(c, "P1"), r / 4));
        pad(c, "P2", seed_point(c, "P2"), fit(seed_point(c, "P2"), r / 4));
        OJ list = OJ::array();
        for (size_t k = 1; bytes(list) < r / 2; ++k) list.push_back({"0", "0", std::to_string(k % 1000 + 1)});
        c["pieces"][0]["same_line_normals"] = list;
        add("same_line_normals: (0,0,k) repeated, padded", c, "valid");
    }
    {  // Interior vertices of P2 with coordinates over a ~4,900-digit denominator (3^10300: the
        // largest common denominator the engine reads has 16,384 bits), and distinct pieces: every
        // support value meets them, in GMP integers.
        OJ c = tetra;
        std::mt19937_64 g(11);
        Z q;
        mpz_ui_pow_ui(q.get_mpz_t(), 3, 10300);
        const size_t dg = q.get_str().size() - 1;
        for (int m = 0; m < 20; ++m) {
            OJ v = OJ::array();
            for (int k = 0; k < 3; ++k) v.push_back((k == 1 ? "-" : "") + digits_not_div3(dg, g) + "/" + q.get_str());
            c["scene"]["P2"]["vertices"].push_back(v);
        }
        const OJ one = distinct_null_pieces(c, 1)[0];
        c["pieces"] = distinct_null_pieces(c, fit(one, room(c)) * 95 / 100);
        add("20 interior vertices over a 4,900-digit denominator, distinct pieces", c,
            "fails where pieces must be contiguous");
    }
    {  // The review's shape with 20-digit coordinates (past 2^62: GMP integers in every scan).
        OJ c = e.partition("tetra_box_e20", scaled_scene(kTetraBox, "100000000000000000000"));
        const size_t r = room(c);
        pad(c, "P2", seed_point(c, "P2"), fit(seed_point(c, "P2"), r / 2));
        const OJ one = distinct_null_pieces(c, 1)[0];
        c["pieces"] = distinct_null_pieces(c, fit(one, r / 2) * 95 / 100);
        add("distinct pieces, P2 padded, coordinates times 10^20", c, "fails where pieces must be contiguous");
    }
    {  // Same-line normals with 20-digit coordinates: past the work limit.
        OJ c = e.partition("pyramids_e20", scaled_scene(kPyramids, "100000000000000000000"));
        const size_t r = room(c);
        pad(c, "P1", seed_point(c, "P1"), fit(seed_point(c, "P1"), r / 4));
        pad(c, "P2", seed_point(c, "P2"), fit(seed_point(c, "P2"), r / 4));
        const OJ probe = pyramid_normals(20000);
        c["pieces"][0]["same_line_normals"] = pyramid_normals(fit(probe.back(), r / 2));
        add("same_line_normals: distinct directions, padded, coordinates times 10^20", c, "valid, past the work limit");
    }
    {  // Seed weights on ~30,000 vertices (half the weight on the original combination).
        OJ c = tetra;
        const OJ s = seed_point(c, "P2");
        const size_t n0 = c["scene"]["P2"]["vertices"].size();
        const size_t n = room(c) / (bytes(s) + 1 + 20);
        pad(c, "P2", s, n);
        OJ w = OJ::array();
        for (const OJ& e : c["seed_interior"]["P2"]) w.push_back({e[0], Q(q_of(e[1]) / 2).get_str()});
        const std::string each = Q(1, 2 * n).get_str();
        for (size_t k = 0; k < n; ++k) w.push_back({n0 + k, each});
        c["seed_interior"]["P2"] = w;
        add("seed weights on " + std::to_string(w.size()) + " vertices", c, "valid");
    }
    {  // A contact face of ~25,000 vertices: points of the cube's face z = 1, all listed as features.
        OJ c = tetra;
        OJ& f = c["pieces"][0]["features"]["P2"];
        long a = -996, b = -996;
        while (room(c) > 64) {
            f.push_back(c["scene"]["P2"]["vertices"].size());
            Q x(a, 997), y(b, 997);
            x.canonicalize();
            y.canonicalize();
            c["scene"]["P2"]["vertices"].push_back({x.get_str(), y.get_str(), "1"});
            if (++b > 996) {
                b = -996;
                ++a;
            }
        }
        add("a contact face of " + std::to_string(f.size()) + " listed vertices", c, "valid");
    }
    {  // Unreadable or plainly wrong: deep nesting, many keys, a 10^6-digit JSON number, a
        // 10^6-digit exact number.
        out.push_back(
            {"nesting 500,000 deep", std::string(500000, '[') + std::string(500000, ']'), "unreadable (exit 2)"});
        std::string keys = "{\"format\": \"scalecert-2\", \"kind\": \"partition\", \"model\": {";
        for (size_t k = 0; keys.size() < kBytes - 20; ++k) keys += (k ? ",\"k" : "\"k") + std::to_string(k) + "\":0";
        out.push_back({"an object of 80,000 keys", keys + "}}", "invalid"});
        std::string lit =
            "{\"format\": \"scalecert-2\", \"kind\": \"partition\", \"x\": 1" + std::string(kBytes - 60, '7') + "}";
        out.push_back({"a JSON number of 10^6 digits", lit, "invalid or unreadable"});
        OJ c = tetra;
        c["scene"]["I1"][1] = "2" + std::string(kBytes - bytes(c) - 20, '3');
        add("an exact number of 10^6 digits (I1's end)", c, "invalid");
    }
    return out;
}

std::string seconds(double t) {
    char b[32];
    if (t < 1)
        std::snprintf(b, sizeof b, "%.0f ms", t * 1e3);
    else
        std::snprintf(b, sizeof b, "%.2f s", t);
    return b;
}
}  // namespace

int checker_bench(int argc, char** argv) {
    double timeout = 120;
    fs::path keep;
    std::vector<std::string> bins;
    for (int i = 0; i < argc; ++i) {
        if (std::strcmp(argv[i], "--timeout") == 0 && i + 1 < argc)
            timeout = std::atof(argv[++i]);
        else if (std::strcmp(argv[i], "--keep") == 0 && i + 1 < argc)
            keep = argv[++i];
        else
            bins.push_back(argv[i]);
    }
    const fs::path self = fs::canonical("/proc/self/exe").parent_path();
    if (bins.empty()) bins.push_back((self / "scalecert-check").string());
    const fs::path dir =
        keep.empty() ? fs::temp_directory_path() / ("scalecert-bench-checker-" + std::to_string(::getpid())) : keep;
    fs::create_directories(dir);
    Engine e{(self / "scalecert").string(), dir};
    std::fprintf(stderr, "building the shapes in %s ...\n", dir.c_str());
    const std::vector<Shape> all = shapes(e);
    std::string head = "| shape | bytes | read as JSON |", rule = "|---|---|---|";
    for (size_t b = 0; b < bins.size(); ++b) {
        head += bins.size() > 1 ? " checker " + std::to_string(b + 1) + ": exit | time | × JSON |"
                                : " exit | checker | × JSON |";
        rule += "---|---|---|";
    }
    std::printf("%s\n%s\n", head.c_str(), rule.c_str());
    for (size_t b = 0; b < bins.size(); ++b) std::fprintf(stderr, "checker %zu: %s\n", b + 1, bins[b].c_str());
    for (size_t k = 0; k < all.size(); ++k) {
        const Shape& s = all[k];
        const fs::path p = dir / ("shape" + std::to_string(k + 1) + ".json");
        std::ofstream(p, std::ios::binary) << s.text;
        double json = 1e300;
        for (int r = 0; r < 3; ++r) {
            const auto t0 = Clock::now();
            const std::string text = slurp(p);
            auto j = nlohmann::json::parse(text, nullptr, false);  // a discarded value on error
            json = std::min(json, std::chrono::duration<double>(Clock::now() - t0).count());
        }
        std::string row = "| " + std::to_string(k + 1) + ". " + s.name + " | " + std::to_string(s.text.size()) + " | " +
                          seconds(json) + " |";
        for (const std::string& bin : bins) {
            Run best{1e300, 0, false};
            for (int r = 0; r < 3; ++r) {
                Run x = run(bin, {p.string()}, timeout);
                if (x.seconds < best.seconds) best = x;
                if (x.killed || x.seconds > 2) break;
            }
            char b[128];
            if (best.killed)
                std::snprintf(b, sizeof b, " killed | > %.0f s | > %.0f |", timeout, timeout / json);
            else
                std::snprintf(b, sizeof b, " %d | %s | %.1f |", best.status, seconds(best.seconds).c_str(),
                              best.seconds / json);
            row += b;
        }
        std::printf("%s\n", row.c_str());
        std::fflush(stdout);
    }
    if (keep.empty()) fs::remove_all(dir);
    return 0;
}
