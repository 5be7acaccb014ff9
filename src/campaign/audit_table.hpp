// An audit's rows: what each floating-point method got wrong on a scene, and how fast, written as
// JSON and CSV. The baselines (src/baselines) fill them; campaigns shard, merge and write them.
#pragma once
#include "certify/certificate.hpp"

#include <optional>
#include <string>
#include <vector>

namespace scalecert::internal {

// The floating-point methods' own settings (audit options, docs/audits.md): each method reads the
// ones it has, and its rows record them. The defaults are FCL's and libccd's own, except libccd's
// iteration limit (unlimited by default; 500 here) and Bullet's margin (0: the shapes as given).
struct MethodSettings {
    double bullet_margin = 0;                                   // every Bullet shape's collision margin
    double fcl_gjk_tolerance = 1e-6;                            // FCL's CollisionRequest::gjk_tolerance
    double fcl_distance_tolerance = 1e-6;                       // FCL's DistanceRequest::distance_tolerance
    unsigned long ccd_max_iterations = 500;                     // libccd's ccd_t::max_iterations
    double ccd_epa_tolerance = 1e-4, ccd_mpr_tolerance = 1e-4;  // libccd's ccd_t
    double command_timeout = 600;  // seconds the user's program (audit --command) may run per scene
    // Not a method's: the relative error past which a method's distance or depth is listed as a
    // failure with a reproducer (audit --measure-tolerance).
    double measure_tolerance = 1e-6;
};

struct AuditRow {
    std::string scene, method;
    Q eps;
    // Wrong verdicts (CLAIMS.md's verdict rules): said separated where they meet; said they overlap
    // where they are apart (or said strictly overlapping where they only touch); said touching where
    // they do not touch. Their sum is wrong().
    // Of a program's own claims (audit --command): the pairs asked whose claim is no answer to the
    // question (at another pair or pose, of another kind, unreadable, or missing), each wrong.
    long queries = 0, false_separated = 0, false_overlapping = 0, false_touching = 0, not_answered = 0;
    long wrong() const { return false_separated + false_overlapping + false_touching + not_answered; }
    // Why the method did not run on this scene ("" when it ran): its counts are then all 0. A
    // method that cannot run on one scene (libccd's EPA tolerance finer than doubles resolve
    // there, coordinates past the doubles' range, a program that failed) says so here, and the
    // audit goes on with the other methods and scenes.
    std::string not_run;
    long extra_claims = 0;  // a program's claims past the pairs asked: answers to no question, left out
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
    long contacts_apart = 0;   // objects made of parts: contacts reported on a part pair that does not overlap
    double distance_err_median = 0, distance_err_max = 0, depth_err_median = 0, depth_err_max = 0,
           direction_err_max = 0;
    // With by_distance: at relative distances 2^-k above and below the curve (k = 4, 8, ..., 52),
    // how many pairs, how many wrong verdicts, and how many pairs were exactly touching once
    // rounded to doubles (counted apart, not in the rate).
    struct ByDistance {
        int k;
        long pairs = 0, wrong = 0, touching = 0;
    };
    std::vector<ByDistance> by_distance;
    // Objects made of parts (baselines/compound_audit.cpp): the sample points on the boundary of
    // the overlap region, as doubles. `touching`: those exactly touching, with what the method said
    // there; `moved`: those that rounding to doubles moved off the boundary (judged exactly), and
    // the method's wrong verdicts on them. None for convex audits.
    struct OnBoundary {
        long points = 0, touching = 0, said_separated = 0, said_touching = 0, said_overlapping = 0, moved = 0,
             moved_wrong = 0;
    };
    std::optional<OnBoundary> on_boundary;
    // The settings the method ran with (by option name, e.g. "bullet-margin"): JSON "settings".
    std::vector<std::pair<std::string, double>> settings;
    // Where the method's verdicts were wrong (the counts above), the first kMaxFailures of them in
    // the audit's order: (ρ1, ρ2) as the doubles it was asked at, what it said (a Said) and the
    // exact verdict at those doubles. `audit --failures DIR` writes them as claims files that
    // certify-fp replays.
    // A claim of the program's that is no answer (said == kSaidNoAnswer) has its reason and what
    // the program wrote for that pair, as JSON text ("" when it wrote nothing there).
    // What a method said (its classify, whose answer codes these are): separated, touching,
    // intersecting (overlapping or touching: what a collision query's "colliding" means) or
    // overlapping (strictly: only a program's own claims say it); no answer: a program's claim
    // that does not answer the pair asked (wrong whatever the exact verdict).
    enum Said : int {
        kSaidNoAnswer = -3,
        kSaidOverlapping = -2,
        kSaidIntersecting = -1,
        kSaidTouching = 0,
        kSaidSeparated = 1
    };
    struct Failure {
        double rho1, rho2;
        int said;  // a Said
        Verdict exact;
        std::string reason = {}, claim = {};
    };
    std::vector<Failure> failures;
    static constexpr size_t kMaxFailures = 50;
    static const char* said_word(int said);
    // Whether saying `said` where the exact verdict is `exact` is wrong.
    static bool wrong(int said, Verdict exact);
    // A verdict `said` at (r1, r2) where the exact one is `exact`: counted and, when wrong, noted.
    void count(double r1, double r2, int said, Verdict exact);
    // A pair (r1, r2) whose claim is no answer: counted and noted with its reason and the claim.
    void count_no_answer(double r1, double r2, Verdict exact, std::string reason, std::string claim);
    // Where the method's distances or depths were off by more than the audit's measure tolerance
    // (relative): `measures_wrong` of them, the worst kMaxFailures listed (largest error first,
    // ties in the audit's order), each with the pair asked, the value, its relative error and, on
    // objects made of parts, a depth's part pair. --failures writes them as claims that certify-fp
    // replays at that tolerance.
    struct MeasureFailure {
        double rho1 = 0, rho2 = 0;
        bool depth = false;
        double value = 0, error = 0;
        int part1 = -1, part2 = -1;
    };
    std::vector<MeasureFailure> measure_failures;
    long measures_wrong = 0;
    // Keeps, of every measured value and its error, those past the tolerance (with a margin of
    // 2^-40 of it, for the error's own rounding), the worst first.
    void note_measures(std::vector<MeasureFailure> all, double tolerance);
};

// Without timing, the timing columns are left empty (CSV) and out (JSON): the rest is the same
// bytes for the same arguments, on any number of processes. When some row has by_distance (or
// on_boundary), the CSV has their columns too (bdK_pairs, bdK_wrong, bdK_touching for K = 4 ... 52;
// on_points ... on_moved_wrong), empty in the rows without them; likewise not_answered and
// not_run (the reason, quoted) when some row has them.
std::string audit_csv(const std::vector<AuditRow>& rows, bool timing = true);
Json audit_json(const std::vector<AuditRow>& rows, bool timing = true);

}  // namespace scalecert::internal
