// Scene families with a degeneracy parameter ε (exact rationals), for golden data and audits.
#pragma once
#include "io/scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace scalecert::internal {

// A small deterministic generator (same seed, same numbers on every platform).
class Rng {
  public:
    explicit Rng(std::uint64_t seed) : s_(seed * 0x9E3779B97F4A7C15ull + 1) {}
    std::uint64_t next();
    long uniform(long lo, long hi);  // inclusive
  private:
    std::uint64_t s_;
};

const std::vector<std::string>& family_names();

// The failure atlas (audit --atlas): a family per class of failure users report, each with the ε
// values (ε = 2^-k) that span the class, and the public thread it comes from.
struct AtlasClass {
    std::string family;
    std::vector<int> ks;  // ε = 2^-k for each k
    std::string thread;
};
const std::vector<AtlasClass>& atlas_classes();
std::string family_description(const std::string& name);

// Scene `index` of family `name` at degeneracy ε (ε > 0; smaller is more degenerate).
// Throws InputError for an unknown family.
ExactScene make_family_scene(const std::string& name, const Q& eps, Rng& rng);

}  // namespace scalecert::internal
