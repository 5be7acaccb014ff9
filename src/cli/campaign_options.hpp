// The options of golden and audit, shared by scalecert and scalecert-mpi (same names, same checks).
#pragma once
#include "campaign/campaign.hpp"

#include <CLI/CLI.hpp>

namespace scalecert::cli {

void add_golden_options(CLI::App* sub, internal::CampaignArgs& a);
void add_audit_options(CLI::App* sub, internal::CampaignArgs& a);

}  // namespace scalecert::cli
