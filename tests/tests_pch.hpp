// The headers every test program reads, compiled once (target_precompile_headers).
#pragma once
#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>
#include <gmpxx.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>
#include "certify/certificate.hpp"
#include "geometry/measures.hpp"
