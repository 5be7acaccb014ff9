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
    // Part k of object i as [base, count) of the object's vertices.
    std::array<size_t, 2> part(int i, size_t k) const { return {start[i][k], start[i][k + 1] - start[i][k]}; }
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

// Blocks of part pairs, {"P1_parts": [a0, a1], "P2_parts": [b0, b1], ...} (P1 parts a0..a1 ×
// P2 parts b0..b1), listed in increasing (a0, b0) order, that must cover every pair of the
// m × n exactly once: a bit a pair (10^8 at most), counted.
class PairCover {
  public:
    PairCover(Context& cx, size_t m, size_t n);
    // The block of `entry` (named w; `noun` names an entry in messages): its part ranges, after
    // the block before it, covering no pair a second time.
    std::array<std::array<size_t, 2>, 2> next(Context& cx, const J& entry, const std::string& w, const char* noun);
    // Every pair covered; `what` begins the message.
    void complete(Context& cx, const std::string& what) const;

  private:
    size_t m_, n_, count_ = 0, blocks_ = 0;
    std::vector<bool> covered_;
    std::array<size_t, 2> previous_{0, 0};
};
}  // namespace scalecert_check
