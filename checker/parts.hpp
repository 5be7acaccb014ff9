// Objects made of convex parts (certificates/FORMAT.md, "A compound partition": `scene`, and the
// blocks of part pairs of "A compound partition" and "A compound judgements file"): every part of
// object i scaled about the object's one seed s_i, which need lie in no part.
#pragma once
#include "context.hpp"
#include "scene.hpp"

#include <array>
#include <string>
#include <vector>

namespace scalecert_check {
constexpr size_t kMaxCompoundParts = 10000;  // parts an object: scalecert's own limit

// A scene of two objects made of parts: each object's parts, their vertices held as one list
// (part k: [start[k], start[k + 1])), every part spanning 3 dimensions.
struct CompoundScene {
    Scene sc;
    std::vector<size_t> start[2];
    size_t parts(int i) const { return start[i].size() - 1; }
    // The vertices of parts first..last of object i, ascending.
    std::vector<int> verts(int i, size_t first, size_t last) const {
        std::vector<int> v;
        for (size_t k = start[i][first]; k < start[i][last + 1]; ++k) v.push_back(static_cast<int>(k));
        return v;
    }
};
// The scene object of a compound certificate: P1 and P2 as `parts` (at most kMaxCompoundParts an
// object, else unreadable) and `seed`, I1 and I2.
CompoundScene read_compound_scene(Context& cx, const J& sj);

// [first, last] of a part range, 0 <= first <= last < n.
std::array<size_t, 2> part_range(Context& cx, const J& j, size_t n, const std::string& where);
}  // namespace scalecert_check
