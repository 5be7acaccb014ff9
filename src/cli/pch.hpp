// Headers every subcommand's file reads, compiled once (target_precompile_headers).
#pragma once
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include "cli/common.hpp"
