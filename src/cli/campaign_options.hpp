// The options of golden and audit, shared by scalecert and scalecert-mpi (same names, same checks).
#pragma once
#include "campaign/campaign.hpp"

#include <CLI/CLI.hpp>

namespace scalecert::cli {

// --numbers double|float32|exact (the public Numbers), on every command that reads numbers.
// --numbers double|float32|exact (and its earlier name --binary-doubles); the --numbers option.
CLI::Option* add_numbers(CLI::App* sub, Numbers& numbers);
void add_golden_options(CLI::App* sub, internal::CampaignArgs& a);
void add_audit_options(CLI::App* sub, internal::CampaignArgs& a);

}  // namespace scalecert::cli
