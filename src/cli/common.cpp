#include "common.hpp"
#include "campaign_options.hpp"
#include "file_name.hpp"
#include "io/files.hpp"

#include "io/mesh.hpp"
#include "curve/scan.hpp"

#include <iostream>

namespace scalecert::cli {

using namespace internal;

void SceneArgs::add(CLI::App* sub) {
    sub->add_option("SCENE", path, "scene file (JSON); or --p1, --p2, --i1, --i2");
    sub->add_option("--p1", mesh[0],
                    "P1 from a mesh file (.off .obj .ply .stl), with --p2, --i1, --i2 instead of SCENE");
    sub->add_option("--p2", mesh[1], "P2 from a mesh file");
    sub->add_option("--i1", interval[0],
                    "I1 as LO,HI (fractions exact: 1/2,3; decimals as --numbers says; default 1,1: no scaling)");
    sub->add_option("--i2", interval[1], "I2 as LO,HI (default 1,1)");
    sub->add_option("--seed1", seed[0], "P1's seed as X,Y,Z (default: the mean of its vertices)");
    sub->add_option("--seed2", seed[1], "P2's seed as X,Y,Z");
    sub->add_option("--pose1", pose[0],
                    "P1 at a pose [R | t]: 12 numbers R11,R12,R13,T1,R21,R22,R23,T2,R31,R32,R33,T3 (rows), each point "
                    "v moved to R·v + t exactly (the seed too); R need not be orthogonal")
        ->type_name("R|t");
    sub->add_option("--pose2", pose[1], "P2 at a pose [R | t], as --pose1")->type_name("R|t");
    add_numbers(sub, opt.numbers);
    sub->add_flag(
        "--parts-from-groups", opt.parts_from_groups,
        "read each OBJ mesh of an object (--p1, --p2, or an object's \"mesh\" in SCENE) as an object made of convex "
        "parts: a part per 'o' or 'g' group, of the vertices its faces name (an OFF, PLY or STL mesh stays one convex "
        "object: those formats have no groups)");
}

void say_notes(const internal::ExactScene& sc) {
    for (const std::string& n : internal::scene_notes(sc)) internal::say_note(n);
}

// Decimals read as doubles have denominators near 2^52 or more: a large scene of them fits no
// machine integers over one scale, and the walk needs that. Said once, when it happened.
static void say_off_the_walk(const internal::ExactScene& full) {
    if (full.inexact_numbers > 0 && !full.made_of_parts() &&
        internal::walk_by_default(full.P[0].points.size(), full.P[1].points.size()))
        internal::say_note(
            std::string("read as ") + internal::numbers_name(full.numbers) +
            "s, the points fit no machine integers over one scale: the hull path, slower than the walk on "
            "large meshes (--numbers exact, or float32 when that is what the program held, can keep "
            "the walk)");
}

// --parts-from-groups on a command for two convex objects (curve, grid), refused before any file is read.
static void refuse_groups_unless_parts(const internal::ReadOptions& opt) {
    if (opt.parts_from_groups && !opt.allow_parts)
        throw InputError(
            "--parts-from-groups: this command is for two convex objects (`scalecert region` gives where objects "
            "made of parts meet)");
}

internal::ExactScene SceneArgs::load() const {
    const bool any_mesh_option = !mesh[0].empty() || !mesh[1].empty() || !interval[0].empty() || !interval[1].empty() ||
                                 !seed[0].empty() || !seed[1].empty() || !pose[0].empty() || !pose[1].empty();
    if (!path.empty() && any_mesh_option) throw InputError("give SCENE or --p1, --p2, --i1, --i2, not both");
    refuse_groups_unless_parts(opt);
    if (!path.empty()) {
        internal::ExactScene sc = load_scene(path, opt);
        internal::note_inputs({path});
        internal::note_inputs(sc.files);
        say_notes(sc);
        return sc;
    }
    internal::note_inputs({mesh[0], mesh[1]});
    if (mesh[0].empty() || mesh[1].empty())
        throw InputError("give SCENE, or --p1 and --p2 (mesh files), with --i1 and --i2 (LO,HI; [1, 1] without)");
    internal::ExactScene sc;
    ReadOptions counted = opt;
    counted.inexact = &sc.inexact_numbers;
    sc.numbers = opt.numbers;
    for (int i = 0; i < 2; ++i) {
        const std::string n = std::to_string(i + 1);
        read_mesh_object(mesh[i], counted, sc.P[i]);
        if (interval[i].empty()) {  // no scaling: the object as it is
            sc.lo[i] = sc.hi[i] = 1;
        } else {
            const std::vector<Q> r = number_list(interval[i], 2, "--i" + n, counted);
            sc.lo[i] = r[0];
            sc.hi[i] = r[1];
        }
        if (!seed[i].empty()) {
            const std::vector<Q> s = number_list(seed[i], 3, "--seed" + n, counted);
            sc.P[i].seed = {s[0], s[1], s[2]};
            sc.P[i].seed_given = true;
        }
        if (!pose[i].empty()) {
            const std::vector<Q> m = number_list(pose[i], 12, "--pose" + n, counted);
            internal::Pose p;
            for (size_t k = 0; k < 12; ++k) p[k / 4][k % 4] = m[k];
            internal::apply_pose(p, sc.P[i], "--pose" + n);
        }
    }
    finish_scene(sc, "command line");
    say_notes(sc);
    return sc;
}

std::shared_ptr<const internal::CompactScene> SceneArgs::load_compact() const {
    internal::ExactScene full;
    return load_compact(&full);  // (the caller reads it again when null: open_engine)
}

std::shared_ptr<const internal::CompactScene> SceneArgs::load_compact(internal::ExactScene* full) const {
    refuse_groups_unless_parts(opt);
    internal::note_inputs({path, mesh[0], mesh[1]});  // (a scene naming meshes is read by load(), which notes them)
    const bool scene_only = !path.empty() && mesh[0].empty() && mesh[1].empty() && interval[0].empty() &&
                            interval[1].empty() && seed[0].empty() && seed[1].empty() && pose[0].empty() &&
                            pose[1].empty();
    if (scene_only && path != "-")
        if (auto cs = internal::read_scene_fast(path, opt.numbers))
            return std::make_shared<internal::CompactScene>(std::move(*cs));
    const bool meshes = path.empty() && !mesh[0].empty() && !mesh[1].empty() && pose[0].empty() && pose[1].empty();
    if (meshes) {
        // Any problem sends the scene to load(), whose checks come in its own order: the same
        // error message either way.
        try {
            Q lo[2], hi[2];
            std::optional<Vec3q> sd[2];
            for (int i = 0; i < 2; ++i) {
                const std::string n = std::to_string(i + 1);
                const std::vector<Q> r =
                    interval[i].empty() ? std::vector<Q>{Q(1), Q(1)} : number_list(interval[i], 2, "--i" + n, opt);
                lo[i] = r[0];
                hi[i] = r[1];
                if (!seed[i].empty()) {
                    const std::vector<Q> s = number_list(seed[i], 3, "--seed" + n, opt);
                    sd[i] = Vec3q{s[0], s[1], s[2]};
                }
            }
            if (auto cs = internal::compact_from_off(mesh, lo, hi, sd, opt.numbers))
                return std::make_shared<internal::CompactScene>(std::move(*cs));
        } catch (const InputError&) {}
    }
    *full = load();
    auto cs = internal::compact_scene(*full);
    return cs ? std::make_shared<internal::CompactScene>(std::move(*cs)) : nullptr;
}

void SceneArgs::shift_positionals(std::initializer_list<std::string*> rest) {
    const bool meshes = !mesh[0].empty() || !mesh[1].empty();
    if (!meshes || path.empty() || rest.size() == 0 || !(*(rest.end() - 1))->empty()) return;
    std::string carry = path;
    path.clear();
    for (std::string* p : rest) std::swap(carry, *p);
}

std::string SceneArgs::name() const { return path.empty() ? "--p1 " + mesh[0] + " --p2 " + mesh[1] : path; }

bool SceneArgs::given() const {
    for (int i = 0; i < 2; ++i)
        if (!mesh[i].empty() || !interval[i].empty() || !seed[i].empty() || !pose[i].empty()) return true;
    return false;
}

std::string SceneArgs::pair_name() const {
    auto stem = [](const std::string& p) {
        std::string b = p.substr(p.find_last_of('/') + 1);
        const size_t dot = b.find_last_of('.');
        return dot == std::string::npos || dot == 0 ? b : b.substr(0, dot);
    };
    return stem(mesh[0]) + "-" + stem(mesh[1]);
}

void add_mesh_pair(CLI::App* sub, SceneArgs& pair, const std::string& what) {
    sub->add_option("--p1", pair.mesh[0], "P1 from a mesh file (.off .obj .ply .stl), with --p2, --i1, --i2: " + what);
    sub->add_option("--p2", pair.mesh[1], "P2 from a mesh file");
    sub->add_option("--i1", pair.interval[0],
                    "I1 as LO,HI (fractions exact: 1/2,3; decimals as --numbers says; default 1,1: no scaling)");
    sub->add_option("--i2", pair.interval[1], "I2 as LO,HI");
    sub->add_option("--seed1", pair.seed[0], "P1's seed as X,Y,Z (default: the mean of its vertices)");
    sub->add_option("--seed2", pair.seed[1], "P2's seed as X,Y,Z");
    sub->add_option("--pose1", pair.pose[0], "P1 at a pose [R | t]: 12 numbers, rows R11,R12,R13,T1,...")
        ->type_name("R|t");
    sub->add_option("--pose2", pair.pose[1], "P2 at a pose [R | t]")->type_name("R|t");
}

void add_out(CLI::App* sub, std::string& out) {
    sub->add_option("--out", out, "write the output to FILE (atomically) instead of standard output")
        ->type_name("FILE")
        ->check(file_name());
}

void emit(const std::string& text, const std::string& out) {
    if (!out.empty()) return write_file_atomically(out, text);
    std::cout << text;
    std::cout.flush();
    if (!std::cout) throw InputError("cannot write to standard output");
}

Q read_rho(const std::string& text, const char* name, const ReadOptions& opt) {
    Q r;
    try {
        r = parse_number(text, opt.numbers, opt.inexact);
    } catch (const InputError& e) {
        throw InputError(std::string(name) + ": " + e.what());
    }
    if (sgn(r) <= 0) throw InputError(std::string(name) + ": a scaling factor must be > 0");
    return r;
}

std::vector<Q> number_list(const std::string& text, size_t n, const std::string& option, const ReadOptions& opt) {
    std::vector<Q> out;
    size_t b = 0;
    for (;;) {
        const size_t e = text.find(',', b);
        try {
            out.push_back(parse_number(text.substr(b, e == std::string::npos ? std::string::npos : e - b), opt.numbers,
                                       opt.inexact));
        } catch (const InputError& err) {
            throw InputError(option + ": " + err.what());
        }
        if (e == std::string::npos) break;
        b = e + 1;
    }
    if (out.size() != n)
        throw InputError(option + ": expected " + std::to_string(n) + " numbers separated by commas, got " +
                         in_quotes(text));
    return out;
}

void add_engine(CLI::App* sub, std::string& engine) {
    sub->add_option("--engine", engine,
                    "auto (default: the walk from 2,000 points) | scan (walk the curve: no hull; the hull path if it "
                    "cannot) | hull")
        ->check(CLI::IsMember({"auto", "scan", "hull"}));
}

Engine engine_named(const std::string& engine) {
    return engine == "hull" ? Engine::Hull : engine == "scan" ? Engine::Scan : Engine::Auto;
}

std::unique_ptr<internal::SceneEngine> open_engine(const SceneArgs& args, Engine engine, StageClock& clock) {
    internal::SceneSource src;
    src.name = args.name();
    src.engine = engine;
    src.clock = &clock;
    internal::ExactScene full;
    if (engine != Engine::Hull) src.compact = args.load_compact(&full);
    if (src.compact) {
        clock.lap("read scene (compact)");
    } else {
        if (full.P[0].points.empty())
            full = args.load();
        else
            say_off_the_walk(full);  // read by load_compact, which found no compact form
        clock.lap("read scene");
        src.exact = std::make_shared<const internal::ExactScene>(std::move(full));
    }
    return internal::open_engine(std::move(src));
}

std::string convex_only(const std::string& name, const std::string& what) {
    return name + ": " + what +
           " is defined for two convex objects; on objects made of parts, scalecert region gives where they meet (its "
           "labelled boundary, switch points and growth set)";
}

internal::Segment parse_segment(const std::string& spec, const HullModel& m, const ReadOptions& opt) {
    if (spec == "seeds" || spec == "ellipsoids") return segment_by_kind(m, spec);
    auto colon = spec.find(':');
    if (colon == std::string::npos) throw InputError("--segment: expected 'seeds' or x1,y1,z1:x2,y2,z2");
    Vec3q v[2];
    const std::string parts[2] = {spec.substr(0, colon), spec.substr(colon + 1)};
    for (int i = 0; i < 2; ++i) {
        const std::vector<Q> c = number_list(parts[i], 3, "--segment", opt);  // as --numbers says
        v[i] = {c[0], c[1], c[2]};
    }
    return make_segment(m, v[0], v[1]);
}

void example(CLI::App* sub, const std::string& text) { sub->footer("\n" + text); }

std::string& program_path() {
    static std::string path = "scalecert";
    return path;
}

Q read_tolerance(const std::string& text, const char* option) {
    Q v;
    try {
        v = internal::parse_exact(text);
    } catch (const InputError& e) {
        throw InputError(std::string(option) + ": " + e.what());
    }
    if (sgn(v) < 0) throw InputError(std::string(option) + " must be >= 0");
    return v;
}

}  // namespace scalecert::cli
