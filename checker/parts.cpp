#include "parts.hpp"

#include "json.hpp"
#include "numbers.hpp"

#include <numeric>

namespace scalecert_check {
CompoundScene read_compound_scene(Context& cx, const J& sj) {
    CompoundScene cs;
    Scene& sc = cs.sc;
    std::vector<size_t>(&start)[2] = cs.start;
    shape(cx, sj, "scene", {"P1", "P2", "I1", "I2"});
    for (int i = 0; i < 2; ++i) {
        const std::string w = std::string("scene.") + kPoly[i];
        const J& p = at(sj, kPoly[i]);
        shape(cx, p, w, {"parts", "seed"});
        const J& parts = at(p, "parts");
        cx.claim(parts.is_array() && !parts.empty(), w + ".parts is a nonempty list");
        if (parts.size() > kMaxCompoundParts)
            throw Unreadable{w + " has more than " + std::to_string(kMaxCompoundParts) +
                             " parts (scalecert's own limit)"};
        Vertices v;
        for (size_t k = 0; k < parts.size(); ++k) {
            const std::string wk = w + ".parts[" + std::to_string(k) + "]";
            shape(cx, parts[k], wk, {"vertices"});
            const J& vs = at(parts[k], "vertices");
            cx.claim(Vertices::is_list(cx, vs) && Vertices::length(cx, vs) > 0, wk + ".vertices is a nonempty list");
            start[i].push_back(v.size());
            v.add(cx, vs, wk + ".vertices");
        }
        start[i].push_back(v.size());
        read_seed(cx, sc, i, p, w, v);
    }
    sc.prepare(cx);
    read_ranges(cx, sc, sj);
    // Each part spans 3 dimensions, as scalecert requires of its input (the claims would hold for
    // flat parts too: the file states a scene the engine reads).
    for (int i = 0; i < 2; ++i)
        for (size_t k = 0; k + 1 < start[i].size(); ++k) {
            std::vector<int> idx(start[i][k + 1] - start[i][k]);
            std::iota(idx.begin(), idx.end(), static_cast<int>(start[i][k]));
            cx.claim(affine_dim(cx, sc, i, idx) == 3,
                     std::string("scene.") + kPoly[i] + ".parts[" + std::to_string(k) + "] spans 3 dimensions");
        }
    return cs;
}

namespace {
// [first, last] of a part range, 0 <= first <= last < n.
std::array<size_t, 2> part_range(Context& cx, const J& j, size_t n, const std::string& where) {
    cx.claim(j.is_array() && j.size() == 2, where + " is [first, last]");
    const size_t a = index(cx, j[0], n, where + "[0]"), b = index(cx, j[1], n, where + "[1]");
    cx.claim(a <= b, where + " has first <= last");
    return {a, b};
}
}  // namespace

PairCover::PairCover(Context& cx, size_t m, size_t n) : m_(m), n_(n) {
    cx.spend(static_cast<double>(m) * static_cast<double>(n) / 8);
    covered_.assign(m * n, false);
}

std::array<std::array<size_t, 2>, 2> PairCover::next(Context& cx, const J& entry, const std::string& w,
                                                     const char* noun) {
    const std::array<size_t, 2> ra = part_range(cx, at(entry, "P1_parts"), m_, w + ".P1_parts"),
                                rb = part_range(cx, at(entry, "P2_parts"), n_, w + ".P2_parts");
    cx.claim(blocks_ == 0 || std::array<size_t, 2>{ra[0], rb[0]} > previous_,
             w + " comes after the " + noun + " before it (by first P1 part, then first P2 part)");
    ++blocks_;
    previous_ = {ra[0], rb[0]};
    cx.spend(static_cast<double>(ra[1] - ra[0] + 1) * static_cast<double>(rb[1] - rb[0] + 1));
    for (size_t a = ra[0]; a <= ra[1]; ++a)
        for (size_t b = rb[0]; b <= rb[1]; ++b) {
            if (covered_[a * n_ + b])  // (the message only when it fails: a block may cover 10^8 pairs)
                cx.claim(false,
                         w + " covers the pair (" + std::to_string(a) + ", " + std::to_string(b) + ") a second time");
            covered_[a * n_ + b] = true;
            ++count_;
        }
    return {ra, rb};
}

void PairCover::complete(Context& cx, const std::string& what) const {
    cx.claim(count_ == m_ * n_, what + " (" + std::to_string(count_) + " of " + std::to_string(m_ * n_) + ")");
}
}  // namespace scalecert_check
