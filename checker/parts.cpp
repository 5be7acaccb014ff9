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
        for (size_t k = 0; k < parts.size(); ++k) {
            const std::string wk = w + ".parts[" + std::to_string(k) + "]";
            shape(cx, parts[k], wk, {"vertices"});
            const J& vs = at(parts[k], "vertices");
            cx.claim(vs.is_array() && !vs.empty(), wk + ".vertices is a nonempty list");
            start[i].push_back(sc.P[i].size());
            for (size_t v = 0; v < vs.size(); ++v)
                sc.P[i].push_back(point(cx, vs[v], wk + ".vertices[" + std::to_string(v) + "]"));
        }
        start[i].push_back(sc.P[i].size());
        sc.s[i] = point(cx, at(p, "seed"), w + ".seed");
        sc.scan[i] = std::make_unique<Scan>(cx, sc.P[i], kPoly[i]);
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

std::array<size_t, 2> part_range(Context& cx, const J& j, size_t n, const std::string& where) {
    cx.claim(j.is_array() && j.size() == 2, where + " is [first, last]");
    const size_t a = index(cx, j[0], n, where + "[0]"), b = index(cx, j[1], n, where + "[1]");
    cx.claim(a <= b, where + " has first <= last");
    return {a, b};
}
}  // namespace scalecert_check
