// Audits of floating-point collision code against the exact engine: per-method error and speed
// tables (the rows of campaign/audit_table.hpp).
#pragma once
#include "baselines/baselines.hpp"
#include "campaign/campaign.hpp"

namespace scalecert::internal {

// Runs every method on the scene: random pairs plus pairs at relative distances 2^-k above and
// below the curve; and the grid search at each resolution in grid_ns.
// With by_distance, also the wrong-verdict counts on 15 verticals at relative distances 2^-4 …
// 2^-52 above and below the curve (their own 390 pairs; the other counts are unchanged).
std::vector<AuditRow> audit_scene(const std::string& name, const ExactScene& s, const Q& eps,
                                  const std::vector<std::string>& methods, const std::vector<int>& grid_ns,
                                  bool by_distance = false, bool measures = true);
// The audit campaigns run (CampaignArgs::auditor): these baselines' methods and audit_scene.
Auditor baseline_auditor();

}  // namespace scalecert::internal
