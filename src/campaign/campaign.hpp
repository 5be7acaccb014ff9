// Campaigns: golden data and audits split into deterministic shards, so that one process
// (scalecert golden / audit) and many (scalecert-mpi, ranks taking shards dynamically) write the
// same bytes. A shard is a scene file, or a range of scene indices of the family at one ε; every
// family scene has its own seed, derived from the run's seed, ε's exponent and its index.
#pragma once
#include "campaign/audit_table.hpp"
#include "campaign/families.hpp"
#include "certify/certificate.hpp"
#include "certify/golden.hpp"
#include "io/scene.hpp"

#include <functional>
#include <map>

#include <cstdint>
#include <string>
#include <vector>

namespace scalecert::internal {

// What an audit runs: the floating-point methods' names, and the rows of one scene (name, scene,
// ε, methods, grid resolutions, by_distance, measures, the methods' settings). The baselines
// provide it (baselines/audit.hpp: baseline_auditor); a build without them has none, and its
// audits are refused.
struct Auditor {
    std::function<std::vector<std::string>()> method_names;
    std::function<std::vector<AuditRow>(const std::string&, const ExactScene&, const Q&,
                                        const std::vector<std::string>&, const std::vector<int>&, bool, bool,
                                        const MethodSettings&)>
        run;
};

// audit --command CMD: the method "command=CMD", the user's own program (baselines/audit.cpp).
constexpr const char* kCommandMethod = "command=";

struct CampaignArgs {
    bool golden = false;  // golden data, else an audit
    std::string family;
    int count = 1;  // family scenes (golden: 1 to kMaxGoldenCount), or per ε (audit)
    std::uint64_t seed = 1;
    std::string eps_text = "1/1048576";  // golden
    std::string dir;                     // golden: the output directory
    GoldenPoints points;                 // golden: which pairs (--verticals, --offsets)
    std::vector<std::string> scenes;     // audit: scene files, or names of `given` scenes
    // audit: scenes read already (a pair of meshes, --p1/--p2), by the name they have in `scenes`;
    // with --failures each is written as DIR/NAME.scene.json for its reproducers.
    std::map<std::string, ExactScene> given;
    std::vector<std::string> methods{"libccd-gjk",     "libccd-mpr",      "fcl-gjk-libccd", "fcl-gjk-indep",
                                     "bullet-gjk-epa", "double-envelope", "paper-tritri",   "grid"};
    std::vector<int> grid{16, 64, 256};
    int sweep_from = 0, sweep_to = 0;  // audit: ε = 2^-k, k in [sweep_from, sweep_to], with family
    bool atlas = false;                // audit: also every atlas class (families.hpp) at its own ε
    std::string command;               // audit: the user's program, run as the method kCommandMethod + command
    std::string out, csv;              // audit: JSON (or standard output) and CSV files
    bool no_timing = false;            // audit: leave the timing columns out
    bool by_distance = false;          // audit: wrong verdicts by relative distance from the curve
    bool measures = true;              // audit: the methods' distances and depths against the exact ones
    // audit: a directory for the reproducers (write_failures): a claims file per scene and method
    // with wrong verdicts, the family scenes they happened on, and index.json.
    std::string failures;
    // audit --failures: how index.json's replay commands name the scalecert command (the path it
    // was run by, when that names a folder: a build tree's scalecert is not on PATH).
    std::string program = "scalecert";
    ReadOptions opt;
    MethodSettings settings;  // audit: the methods' own settings
    Auditor auditor;          // audit: the methods (none without the baselines)
    int shard_size = 0;       // family scenes per shard; 0: 16 for golden, 4 for audits
};

// audit --failures DIR: for each row with wrong verdicts, DIR/NAME.METHOD.claims.json (verdict
// claims of what the method said at each listed failure, its doubles as JSON numbers, which
// certify-fp reads back as those doubles) and DIR/index.json: each file's scene (the scene file,
// or DIR/NAME.eps-P_Q.scene.json for a family scene), method, counts and replay command.
void write_failures(const CampaignArgs& a, const std::vector<AuditRow>& rows);

// Refuses bad arguments (one line, before any work or any file is made): unknown family or
// method, --sweep-to < --sweep, --eps <= 0, no scenes at all. Notes the scenes as inputs
// (io/files.hpp, note_inputs): no output of the run may replace one.
void validate(const CampaignArgs& a);

struct Shard {
    int index;
    int scene_file = -1;      // audit: an index into CampaignArgs::scenes; or -1 for a family range
    int k = 0;                // ε = 2^-k (audit sweeps); golden: 0
    int first = 0, last = 0;  // family scene indices [first, last)
    int atlas = -1;           // audit: an index into atlas_classes() (the family), or -1 for CampaignArgs::family
    long scenes() const { return scene_file >= 0 ? 1 : last - first; }
};
std::vector<Shard> plan(const CampaignArgs& a);

// Family scene i at ε = 2^-k (golden: k = 0) of a run with this seed.
std::uint64_t scene_seed(std::uint64_t run_seed, int k, int i);

// Runs a shard. Golden: writes its scenes' files into the directory (atomically) and returns
// their names and SHA-256 hashes; audit: returns its rows. Either as the shard file's text.
std::string run_shard(const CampaignArgs& a, const Shard& s);
// Whether a shard's text is what run_shard writes for shard s: JSON naming s's index, with rows
// that read back (audit) or a list of files with hashes (golden). A shard file that is not is
// redone on --resume, whatever the manifest records for it.
bool shard_well_formed(const CampaignArgs& a, const Shard& s, const std::string& shard_text);
// Golden: whether the files a shard's text lists are all present with their hashes.
bool shard_outputs_intact(const CampaignArgs& a, const std::string& shard_text);
// After every shard: writes the audit's JSON and CSV from the shards' texts, in shard order
// (golden: nothing left to write, and a note on stderr for each scene of the user's whose answers
// passed a limit, which has no files while the others do). Returns the number of rows, or of
// scenes written.
long finish_campaign(const CampaignArgs& a, const std::vector<std::string>& shard_texts);
// The whole campaign in this process: what scalecert golden and audit run.
long run_campaign(const CampaignArgs& a);

// Creates an output directory (and its parents). Throws InputError naming it, with the reason,
// when it cannot (a file in the way, no permission).
void make_output_dir(const std::string& dir);

// The files an audit reads, each scene file and the mesh files it names, as [[path, SHA-256 of
// its bytes], ...] in reading order (golden and family runs: none). Reads every scene as its
// shard will (InputError names a bad one); standard input is refused (it cannot be read twice).
Json campaign_inputs(const CampaignArgs& a);
// What a run folder records of the command, the contents of its inputs (campaign_inputs)
// included: shards from one command, or from other contents of its files, cannot mix with another's.
std::string campaign_identity(const CampaignArgs& a, const Json& inputs);
// The first file an audit shard's text records as read ("inputs") that `inputs` does not list with
// the same hash; "" when there is none (golden and family shards record none).
std::string stale_input(const Json& inputs, const std::string& shard_text);

// A scene's golden files under a stem: STEM.scene.json (the scene exactly), STEM.golden.json (the
// curve, `fields` added, and the queries of golden_answers at `points`), STEM.golden.csv and
// STEM.golden.rational.csv, by name and text.
std::vector<std::pair<std::string, std::string>> golden_files(const std::string& stem, const ExactScene& s,
                                                              const GoldenPoints& points,
                                                              const std::function<void(Json&)>& fields);
// A user's scene file's stem: its file name without ".json" (golden SCENES... names its files so).
std::string golden_stem(const std::string& path);
// Scene i of a family with its exact answers, drawn with scene_seed (campaign.hpp derives it from
// the run's seed): golden_files as NAME-i. The golden JSON records the run's seed and i.
std::vector<std::pair<std::string, std::string>> golden_scene(const std::string& family, int i,
                                                              std::uint64_t scene_seed, std::uint64_t run_seed,
                                                              const Q& eps, const GoldenPoints& points);
// Writes COUNT scenes of a family with their exact answers into DIR (campaign.cpp: the same
// shards as scalecert-mpi). Byte-identical for the same arguments.
void write_golden(const std::string& family, int count, std::uint64_t seed, const Q& eps, const std::string& dir,
                  const GoldenPoints& points);

// At most this many scenes of a family in one golden run (--count, write_golden).
constexpr int kMaxGoldenCount = 10000000;

// Files in a run folder (manifest, shards) and golden outputs are read up to this size.
constexpr std::size_t kMaxRunFileBytes = std::size_t(1) << 40;

std::string sha256_hex(const std::string& bytes);

}  // namespace scalecert::internal
