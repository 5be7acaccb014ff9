// The scalecert command: what every subcommand shares. Each subcommand lives in its own file,
// registers its options and returns the function that runs it.
#pragma once
#include "certify/certificate.hpp"
#include "segment/segment.hpp"
#include "session/engine.hpp"
#include "numeric/timing.hpp"

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace scalecert::cli {

using internal::Model;
using internal::Q;
using internal::ReadOptions;

// The scene, from a scene file or from mesh files and ranges (--p1 --p2 --i1 --i2 [--seed1 --seed2]).
struct SceneArgs {
    std::string path, mesh[2], interval[2], seed[2], pose[2];
    ReadOptions opt;
    void add(CLI::App* sub);            // the options, with --numbers
    internal::ExactScene load() const;  // refuses both forms at once, and neither
    // The scene in compact form (IntPoints), read straight from OFF files of plain decimals when
    // given as --p1/--p2; otherwise through load(). Null when the points do not fit IntPoints.
    std::shared_ptr<const internal::CompactScene> load_compact() const;
    // The same, or else the exact scene in *full (a scene of parts, or points that do not fit
    // IntPoints): the file is read once either way.
    std::shared_ptr<const internal::CompactScene> load_compact(internal::ExactScene* full) const;
    std::string name() const;       // the scene file, or "--p1 A --p2 B": prefixes geometric errors
    bool given() const;             // any of the pair's options given
    std::string pair_name() const;  // "A-B": the meshes' file names without their extensions
    // With --p1/--p2 there is no SCENE, but the first positional word lands there: move it and
    // the words after it one place on, into the command's own positionals (in order), when the
    // last of those is empty. Then SCENE is empty, or the words were too many and load() says so.
    void shift_positionals(std::initializer_list<std::string*> rest);
};

// --p1, --p2, --i1, --i2, --seed1, --seed2, --pose1, --pose2 on a command that takes SCENES (golden,
// audit): a pair of meshes as one more scene; `what` ends --p1's help.
void add_mesh_pair(CLI::App* sub, SceneArgs& pair, const std::string& what);

// The readers' remarks on a scene (an OBJ with groups read as one convex object, decimals that the
// reading did not take as written), once each on stderr.
void say_notes(const internal::ExactScene& sc);

// --out FILE means the same for every command: its one output document goes to FILE, written
// atomically (a temporary file beside it, synced, renamed), instead of standard output.
void add_out(CLI::App* sub, std::string& out);
void emit(const std::string& text, const std::string& out);

Q read_rho(const std::string& text, const char* name, const ReadOptions& opt);
// "A,B" or "A,B,C": numbers separated by commas, read as the scene reader reads them.
// A tolerance option's text (--tolerance, --abs-tolerance): exact, >= 0; InputError naming the option.
Q read_tolerance(const std::string& text, const char* option);
std::vector<Q> number_list(const std::string& text, size_t n, const std::string& option, const ReadOptions& opt);
// The path this command was run by (argv[0]) when it names a folder ("build/scalecert"), else
// "scalecert": how the commands it writes for the user to replay name it. Set by main.
std::string& program_path();

// Sets the --help footer: what the command writes, and an example.
void example(CLI::App* sub, const std::string& text);

// The scene read once into its engine (engine.hpp), with SCALECERT_TIMING laps on `clock`: in
// machine integers when it fits them and the engine may walk, else by the strict reader; objects
// made of parts where scene.opt.allow_parts (else the reader refuses them).
using internal::Engine;
// --engine auto|scan|hull (default auto), read into `engine`.
void add_engine(CLI::App* sub, std::string& engine);
Engine engine_named(const std::string& engine);
std::unique_ptr<internal::SceneEngine> open_engine(const SceneArgs& scene, Engine engine, internal::StageClock& clock);
// The refusal of what is defined for two convex objects only (`what`: "the touching curve"), on
// the scene `name`, for SceneEngine::convex_session.
std::string convex_only(const std::string& name, const std::string& what);
// A segment for --segment: seeds | ellipsoids | x1,y1,z1:x2,y2,z2.
internal::Segment parse_segment(const std::string& spec, const internal::HullModel& m, const ReadOptions& opt);

// A subcommand: its CLI11 app and what runs it (returns the exit status).
struct Command {
    CLI::App* app;
    std::function<int()> run;
};
Command add_curve(CLI::App& app);
Command add_query(CLI::App& app);
Command add_partition(CLI::App& app);
Command add_classify(CLI::App& app);
Command add_grid(CLI::App& app);
Command add_certify_fp(CLI::App& app);
Command add_golden(CLI::App& app);
Command add_region(CLI::App& app);  // objects made of parts: where they meet
Command add_audit(CLI::App& app);
Command add_mujoco(CLI::App& app);  // MuJoCo's collisions at a model's states
Command add_report(CLI::App& app);  // the audit report page (tools/report.py)

}  // namespace scalecert::cli
