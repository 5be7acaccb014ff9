// Objects made of convex parts (certificates/FORMAT.md, "A compound partition": `scene`, and the
// blocks of part pairs of "A compound partition" and "A compound judgements file"): every part of
// object i scaled about the object's one seed s_i, which need lie in no part.
#pragma once
#include "context.hpp"
#include "scene.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace scalecert_check {
constexpr size_t kMaxCompoundParts = 10000;  // parts an object: scalecert's own limit

// One object made of parts: each part's vertices scanned on their own, over the part's own common
// denominator (so the 16,384-bit limit is a part's, and no part's support value pays for
// another's digits); and its parts of machine-size coordinates (Scan::machine()) once more, one
// array per coordinate holding every such part's vertices in order, so that a block's scan runs
// through memory in order (the parts' own arrays lie wherever they were read: measured 400 ns a
// part out of cache against 18 ns in order).
struct CompoundObject {
    struct Flat {
        size_t begin = 0, end = 0;  // the part's vertices in x (end = begin: not a machine part)
        int bits = 0;               // Scan::bits()
        unsigned long den = 0;      // its D when an unsigned long holds it, else 0
    };
    std::vector<std::shared_ptr<const Scan>> part;
    std::vector<Flat> flat;
    std::vector<int64_t> x[3];
    // flat and x, from part.
    void index(Context& cx);
};

// A scene of two objects made of parts: each object's seed, I1 and I2, and its parts (shared by
// the scenes a claim's poses make: an object without a pose is not copied). Every part spans 3
// dimensions.
struct CompoundScene {
    V3 s[2];
    Q lo[2], hi[2];
    std::shared_ptr<const CompoundObject> obj[2];
    // Parts with radii (FORMAT.md, "Parts with radii"): every part of both objects has one (>= 0),
    // and part k of object i is every point within r[i][k] of its hull. Empty without radii.
    std::vector<Q> r[2];
    bool rounded() const { return !r[0].empty(); }
    size_t parts(int i) const { return obj[i]->part.size(); }
    const Scan& part(int i, size_t k) const { return *obj[i]->part[k]; }
    // The convex scene of part a of P1 and part b of P2 (the objects' seeds, I1 and I2; with radii,
    // theirs): one pair's claims are checked on it, over the pair's joint denominator (scene.hpp).
    Scene pair(Context& cx, size_t a, size_t b) const;
    // max over the vertices v of parts first..last of object i of u·v, for an integer u: each
    // part's maximum u·X/D from its scan, compared across parts by cross-multiplication.
    Q top(Context& cx, int i, const Z3& u, size_t first, size_t last) const;
    // The objects moved by pose[i] (none: as it is, shared), every part's vertices and the seeds.
    CompoundScene posed(Context& cx, const std::array<std::optional<Pose>, 2>& pose) const;
};
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
