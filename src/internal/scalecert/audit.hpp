// Audits of floating-point collision code against the exact engine: certifying a program's
// claims, golden data for test suites, and per-method error and speed tables.
#pragma once
#include "scalecert/baselines.hpp"
#include "scalecert/certificate.hpp"
#include "scalecert/families.hpp"
#include "scalecert/session.hpp"

#include <functional>

namespace scalecert::internal {

// Marks a floating-point program's claims right or wrong, exactly, and reports the exact values
// and errors (text, or JSON with `json`); the number of wrong claims in *wrong. Two formats:
// - JSON (text starting with '{'): {"format": "scalecert-claims-1", "claims": [...]} with the kinds
//   verdict, curve, switch_point, growth_distance, separating_plane, witness_point, distance and
//   penetration_depth (certificates/CLAIMS.md);
// - lines ('#' comments): 'RHO1 RHO2 VERDICT' (separated | touching | overlapping | intersecting,
//   = not separated), 'curve RHO1 RHO2' (a claimed point of the touching curve) or 'growth RHO'.
// Numbers are exact as written (with binary_doubles, JSON numbers and line numbers are the doubles
// strtod gives). `tolerance` (a relative error, >= 0) accepts numeric values within it; verdicts,
// labels, planes and witness points must be exactly right.
struct ClaimOptions {
    bool binary_doubles = false;
    Q tolerance = 0;
};
// What claims are checked against: the hull model and its curve over all ρ1 > 0 (built on first
// use), and the exact verdict and curve value at a pair (a session takes them from the walk where
// it proved the curve: no hull for verdicts on a large scene).
struct ClaimModels {
    std::function<const Model&()> model;
    std::function<const Curve&()> curve;
    std::function<Verdict(const Q&, const Q&)> verdict;
    std::function<Q(const Q&)> curve_value;
    std::function<Q()> growth;  // ρ*
    static ClaimModels of(const Model& m, const Curve& c);
    static ClaimModels of(Session& s);
};
std::string certify_fp(const ClaimModels& models, const std::string& claims, const std::string& name, const ClaimOptions& opt,
                       bool json, long* wrong);
inline std::string certify_fp(Session& s, const std::string& claims, const std::string& name, const ClaimOptions& opt,
                              bool json, long* wrong) {
    return certify_fp(ClaimModels::of(s), claims, name, opt, json, wrong);
}
inline std::string certify_fp(const Model& m, const Curve& c, const std::string& claims, const std::string& name,
                              const ClaimOptions& opt, bool json, long* wrong) {
    return certify_fp(ClaimModels::of(m, c), claims, name, opt, json, wrong);
}
inline std::string certify_fp(const Model& m, const Curve& c, const std::string& claims, const std::string& name,
                              bool binary_doubles, bool json, long* wrong) {
    return certify_fp(m, c, claims, name, ClaimOptions{binary_doubles, Q(0)}, json, wrong);
}
// The line format alone.
std::string certify_claim_lines(const ClaimModels& models, const std::string& claims, const std::string& name,
                                bool binary_doubles, bool json, long* wrong);

// Scene i of a family with its exact answers, drawn with scene_seed (campaign.hpp derives it from
// the run's seed): the files NAME-i.scene.json, NAME-i.golden.json and NAME-i.golden.csv, by name
// and text. The golden JSON records the run's seed and i.
std::vector<std::pair<std::string, std::string>> golden_scene(const std::string& family, int i, std::uint64_t scene_seed,
                                                              std::uint64_t run_seed, const Q& eps);
// Writes COUNT scenes of a family with their exact answers into DIR (campaign.cpp: the same
// shards as scalecert-mpi). Byte-identical for the same arguments.
void write_golden(const std::string& family, int count, std::uint64_t seed, const Q& eps, const std::string& dir);

struct AuditRow {
    std::string scene, method;
    Q eps;
    long queries = 0, false_separated = 0, false_overlapping = 0;
    double seconds_per_query = 0;
    // curve methods (grid search): errors against the exact curve
    bool has_curve = false;
    int grid_n = 0;
    double growth_error = 0, max_junction_error = 0, seconds_per_curve = 0;
    int exact_junctions = 0, junctions_found = 0, junctions_missed = 0, junctions_merged = 0;
    // What the method measures (distances of separated pairs, depths of overlapping ones, where
    // its API gives them and its verdict is right), against the exact values: how many, and the
    // relative errors |c − exact| / exact (median and largest); for depth directions, the relative
    // excess of the depth along the reported direction over the true depth.
    long distances = 0, depths = 0;
    long closest_outside = 0;  // reported closest (witness) points not in their scaled body, exactly
    double distance_err_median = 0, distance_err_max = 0, depth_err_median = 0, depth_err_max = 0, direction_err_max = 0;
    // With by_distance: at relative distances 2^-k above and below the curve (k = 4, 8, ..., 52),
    // how many pairs, how many wrong verdicts, and how many pairs were exactly touching once
    // rounded to doubles (counted apart, not in the rate).
    struct ByDistance { int k; long pairs = 0, wrong = 0, touching = 0; };
    std::vector<ByDistance> by_distance;
};

// Runs every method on the scene: random pairs plus pairs at relative distances 2^-k above and
// below the curve; and the grid search at each resolution in grid_ns.
// With by_distance, also the wrong-verdict counts on 15 verticals at relative distances 2^-4 …
// 2^-52 above and below the curve (their own 390 pairs; the other counts are unchanged).
std::vector<AuditRow> audit_scene(const std::string& name, const Scene& s, const Q& eps,
                                  const std::vector<std::string>& methods, const std::vector<int>& grid_ns,
                                  bool by_distance = false);
// Without timing, the timing columns are left empty (CSV) and out (JSON): the rest is the same
// bytes for the same arguments, on any number of processes.
std::string audit_csv(const std::vector<AuditRow>& rows, bool timing = true);
Json audit_json(const std::vector<AuditRow>& rows, bool timing = true);

}  // namespace scalecert::internal
