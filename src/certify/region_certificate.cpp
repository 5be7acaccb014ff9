// The compound partition certificate (region_certificate.hpp).
#include "certify/region_certificate.hpp"

#include "geometry/gjk.hpp"
#include "certify/query.hpp"
#include "numeric/parallel.hpp"

#include <map>
#include <stdexcept>
#include <tuple>

namespace scalecert::internal {

namespace {
Json points_json(const std::vector<Vec3q>& pts) {
    Json a = Json::array();
    for (const Vec3q& v : pts) a.push_back(Json::array({to_exact_string(v[0]), to_exact_string(v[1]), to_exact_string(v[2])}));
    return a;
}

// The scene with every object as a list of parts (a plain object is one part).
Json compound_scene_json(const ExactScene& sc) {
    Json s;
    const char* names[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        const PolyInput& in = sc.P[i];
        Json parts = Json::array();
        if (in.parts.empty()) parts.push_back(Json{{"vertices", points_json(in.points)}});
        for (const std::vector<Vec3q>& p : in.parts) parts.push_back(Json{{"vertices", points_json(p)}});
        s[names[i]] = Json{{"parts", parts}, {"seed", Json::array({to_exact_string(in.seed[0]), to_exact_string(in.seed[1]), to_exact_string(in.seed[2])})}};
    }
    for (int i = 0; i < 2; ++i) s[i == 0 ? "I1" : "I2"] = Json::array({to_exact_string(sc.lo[i]), to_exact_string(sc.hi[i])});
    return s;
}

// A common point of A(ρ1) and B(ρ2) (hm holds the two parts and the seeds), weights indexed into
// each part's own point list: an exact LP over the few vertices a double GJK names, else over all
// the parts' vertices. The LP decides; GJK only proposes (its simplex may miss a touching face).
Witness pair_witness(const HullModel& hm, const Q& r1, const Q& r2, long& fallbacks) {
    const GjkGuess g = gjk_guess(hm, r1.get_d(), r2.get_d());
    if (!g.v1.empty() && !g.v2.empty()) {
        if (std::optional<Witness> w = try_witness(hm, r1, r2, g.v1, g.v2)) return std::move(*w);
        ++fallbacks;
    }
    return make_witness(hm, r1, r2, hm.P[0].vertices, hm.P[1].vertices, false);
}

Json polygon_json(Json& o, const std::vector<Point2q>& poly) {
    Json v = Json::array(), d = Json::array();
    for (const Point2q& p : poly) {
        v.push_back(Json::array({to_exact_string(p[0]), to_exact_string(p[1])}));
        d.push_back(Json::array({to_double_rn(p[0]), to_double_rn(p[1])}));
    }
    o["vertices"] = v;
    o["vertices_double"] = d;
    return o;
}

Json range_json(int from, int to) { return Json::array({from, to}); }

// Blocks of pruned pairs apart along the same axis on the same side: runs along P2 in each row,
// a run extended down the rows while the next row has the same run. Each block is one entry with
// the normal ±e_c: every pair in it has part 1's swept box below (or above) part 2's along c, so
// the maximum over the block's P1 parts lies below the minimum over its P2 parts.
struct Block { int a0, a1, b0, b1, axis, side; };
std::vector<Block> pruned_blocks(const CompoundRegion& r) {
    const int m = static_cast<int>(r.parts[0].size()), n = static_cast<int>(r.parts[1].size());
    auto code = [&](int a, int b) { return r.prune[static_cast<size_t>(a) * static_cast<size_t>(n) + static_cast<size_t>(b)]; };
    std::vector<Block> done;
    std::map<std::tuple<int, int, int>, size_t> open;  // (b0, b1, code) -> block reaching the previous row
    for (int a = 0; a < m; ++a) {
        std::map<std::tuple<int, int, int>, size_t> next;
        for (int b = 0; b < n;) {
            const int k = code(a, b);
            if (!k) { ++b; continue; }
            int e = b + 1;
            while (e < n && code(a, e) == k) ++e;
            const auto key = std::make_tuple(b, e - 1, k);
            const auto it = open.find(key);
            if (it != open.end()) {
                done[it->second].a1 = a;
                next[key] = it->second;
            } else {
                done.push_back({a, a, b, e - 1, (k - 1) / 2, (k - 1) % 2 ? 1 : -1});
                next[key] = done.size() - 1;
            }
            b = e;
        }
        open = std::move(next);
    }
    return done;
}
}  // namespace

Json compound_partition_json(const ExactScene& sc, const CompoundRegion& r) {
    const Vec3q &s1 = sc.P[0].seed, &s2 = sc.P[1].seed;
    // Entries in (first P1 part, first P2 part) order: built pairs one each, pruned blocks.
    std::vector<std::pair<std::pair<int, int>, Json>> entries;
    long fallbacks = 0;  // witnesses the GJK's vertices did not hold
    for (const Block& b : pruned_blocks(r)) {
        Vec3z nrm{Z(0), Z(0), Z(0)};
        nrm[static_cast<size_t>(b.axis)] = b.side;
        Json e{{"P1_parts", range_json(b.a0, b.a1)}, {"P2_parts", range_json(b.b0, b.b1)}, {"normals", Json::array({normal_json(nrm)})}};
        polygon_json(e, {});
        e["witnesses"] = Json::array();
        entries.push_back({{b.a0, b.b0}, std::move(e)});
    }
    // The witnesses, on every core (each pair's in its slot; each task copies its two parts).
    std::vector<std::vector<Witness>> witnesses(r.pairs.size());
    const unsigned threads = static_cast<unsigned>(std::min<size_t>(default_threads(), std::max<size_t>(1, r.pairs.size() / 8)));
    std::vector<long> missed(threads, 0);
    parallel_tasks(r.pairs.size(), threads, [&](unsigned t, size_t k) {
        const CompoundRegion::Pair& p = r.pairs[k];
        if (p.polygon.empty()) return;
        HullModel hm;  // the two parts and the seeds, for the GJK guess
        hm.P[0] = r.parts[0][static_cast<size_t>(p.part1)];
        hm.P[1] = r.parts[1][static_cast<size_t>(p.part2)];
        hm.s[0] = s1;
        hm.s[1] = s2;
        for (const Point2q& v : p.polygon) witnesses[k].push_back(pair_witness(hm, v[0], v[1], missed[t]));
    });
    for (long x : missed) fallbacks += x;
    for (size_t k = 0; k < r.pairs.size(); ++k) {
        const CompoundRegion::Pair& p = r.pairs[k];
        Json normals = Json::array();
        for (size_t f : p.fence) normals.push_back(normal_json(p.constraints[f].normal));
        Json e{{"P1_parts", range_json(p.part1, p.part1)}, {"P2_parts", range_json(p.part2, p.part2)}, {"normals", normals}};
        polygon_json(e, p.polygon);
        Json wit = Json::array();
        for (const Witness& w : witnesses[k]) wit.push_back(witness_object(w));
        e["witnesses"] = wit;
        entries.push_back({{p.part1, p.part2}, std::move(e)});
    }
    std::sort(entries.begin(), entries.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    Json j;
    j["format"] = "scalecert-2";
    j["kind"] = "compound_partition";
    Json pairs = Json::array();
    for (auto& e : entries) pairs.push_back(std::move(e.second));
    j["pairs"] = pairs;
    Json growth = Json::array();
    for (const auto& iv : r.growth) {
        Json g;
        put_exact(g, "from", iv.from);
        put_exact(g, "to", iv.to);
        g["first_contact"] = Json{{"P1_part", iv.part1}, {"P2_part", iv.part2}};
        growth.push_back(g);
    }
    j["growth_set"] = growth;
    j["statistics"] = Json{{"pairs", r.prune.size()}, {"pruned", r.pruned}, {"built", r.built}, {"entries", entries.size()}, {"witness_fallbacks", fallbacks}};
    j["scene"] = compound_scene_json(sc);
    return j;
}

}  // namespace scalecert::internal
