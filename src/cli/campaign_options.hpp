// The options of golden and audit, shared by scalecert and scalecert-mpi (same names, same checks).
#pragma once
#include "campaign/campaign.hpp"

#include <CLI/CLI.hpp>

namespace scalecert::cli {

// --numbers double|float32|exact (the public Numbers, and its earlier name --binary-doubles), on
// every command that reads numbers; the --numbers option.
CLI::Option* add_numbers(CLI::App* sub, Numbers& numbers);
// An integer option's check: decimal digits only (a '-' first where lo < 0), from lo to hi. Unlike
// CLI::Range it sees the word as given, so " 1" or "1 " is refused, not trimmed to 1.
CLI::Validator whole_number(long long lo, long long hi);
void add_golden_options(CLI::App* sub, internal::CampaignArgs& a);
void add_audit_options(CLI::App* sub, internal::CampaignArgs& a);

}  // namespace scalecert::cli
