// Headers most of the checker's files read, compiled once (target_precompile_headers). Only
// third-party and standard headers: each source still includes what it uses.
#pragma once
#include <gmpxx.h>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>
