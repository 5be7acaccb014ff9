// Audits of floating-point collision code against the exact engine: per-method error and speed
// tables (the rows of campaign/audit_table.hpp).
#pragma once
#include "baselines/baselines.hpp"
#include "campaign/campaign.hpp"
#include "certify/compound_judge.hpp"
#include "compound/boundary.hpp"

namespace scalecert::internal {

// Runs every method on the scene: random pairs plus pairs at relative distances 2^-k above and
// below the curve; and the grid search at each resolution in grid_ns.
// With by_distance, also the wrong-verdict counts on 15 verticals at relative distances 2^-4 …
// 2^-52 above and below the curve (their own 390 pairs; the other counts are unchanged).
// The compound methods (fp::compound_method_names) run through audit_compound, on any scene (a
// plain object is one part); a scene with parts takes only those: any other method is refused
// (InputError, before any work).
std::vector<AuditRow> audit_scene(const std::string& name, const ExactScene& s, const Q& eps,
                                  const std::vector<std::string>& methods, const std::vector<int>& grid_ns,
                                  bool by_distance = false, bool measures = true, const MethodSettings& settings = {});
// ---- Objects made of convex parts (compound_audit.cpp) -----------------------------------------

// A point at which the methods are judged: the exact verdict (0 separated, 1 touching,
// 2 overlapping, by CompoundJudge at the doubles' exact values), and where it comes from: k = −1 a
// random pair in I1 × I2; k = 0 a point on a contact edge of the region's boundary: a double point
// exactly on the edge near an exact point of it where one exists (A X + B Y = C 2^m solved in
// integers, the edge's line in coprime integers A, B, C), else that exact point's nearest doubles;
// k > 0 that point pushed off the edge by the relative distance 2^-k, inward (side +1, towards the
// region) or outward (−1), then rounded to doubles. The push moves one coordinate: ρ2 for an edge
// nearer horizontal (ρ2(1 ± 2^-k)), else ρ1.
struct CompoundSample {
    int k = 0;
    int side = 0;
    double r1 = 0, r2 = 0;
    Verdict exact = Verdict::Separated;
};
// The samples of a scene: `random` random pairs; up to `points` points on the contact edges of
// the region's boundary (every edge when there are at most that many, the points spread evenly
// along each; else `points` edges spread evenly, one point each), each pushed by 2^-k for k = 4,
// 8, ..., 52 both ways. Deterministic. The region must have its union (b from label_boundary).
std::vector<CompoundSample> compound_samples(CompoundJudge& judge, const CompoundBoundary& b, int random = 200,
                                             int points = 32);
// A method's verdicts at the samples, counted into `row`: queries and wrong verdicts
// (AuditRow::count), by_distance (k > 0: wrong where the method's verdict differs from the
// exact one; exactly touching samples counted apart) when by_distance, and
// on_boundary (k = 0). Returns the method's verdicts.
std::vector<int> score_compound(const fp::Method& m, const std::vector<CompoundSample>& samples, bool by_distance,
                                AuditRow& row);
// The compound audit of a scene: the region and its labelled boundary (CompoundSession), the
// samples, every method's verdicts, and where a method measures and its verdict is right, its
// distances against the exact ones (CompoundJudge::distance); the methods run with `settings`.
// InputError for an unknown method. When the region's union is not formed (past
// kMaxUnionPolygons pair polygons) or the scene is past the doubles' range, every method's row
// says it did not run, and why.
std::vector<AuditRow> audit_compound(const std::string& name, const ExactScene& s, const Q& eps,
                                     const std::vector<std::string>& methods, bool by_distance, bool measures,
                                     const MethodSettings& settings = {});
// The doubles the methods see: each part's points (nearest doubles) and its exact hull's faces.
fp::CompoundFp compound_fp(const CompoundJudge& judge);
// |value − √squared| / √squared (MPFR-rounded), for a method's distance or depth against the
// exact squared one; none when √squared is 0 or past the doubles (no relative error in them).
std::optional<double> relative_error(const Q& squared, double value);
// The median of v (the mean of the middle two for an even count; 0 when empty).
double median(std::vector<double> v);
// (√along − √squared) / √squared: how much deeper the bodies are along a method's direction than
// their depth (`along` the squared depth along it, `squared` the exact squared depth, > 0); none
// where the depth is below 2^-26 of the scene's largest scaled coordinate `extent`, where a
// direction held in doubles is not resolved (its rounding alone, about 2^-53·extent along the
// depth, would read as 2^-27 and more, up to 10^14 on touching scenes).
std::optional<double> direction_excess(const Q& along, const Q& squared, double extent);
// Why no floating-point method can run where the largest scaled coordinate is `extent`: past
// 2^200 their squared lengths overflow (audit.cpp); "" below.
std::string beyond_doubles(double extent);
// A row that says method `meth` did not run on the scene, and why (AuditRow::not_run).
AuditRow not_run_row(const std::string& scene, const std::string& meth, const Q& eps, const MethodSettings& settings,
                     bool measures, std::string why);

// The audit campaigns run (CampaignArgs::auditor): these baselines' methods and audit_scene.
Auditor baseline_auditor();

}  // namespace scalecert::internal
