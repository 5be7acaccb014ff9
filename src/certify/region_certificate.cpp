// The compound partition certificate (region_certificate.hpp).
#include "certify/region_certificate.hpp"

#include "certify/compound_judge.hpp"
#include "certify/query.hpp"
#include "compound/boundary.hpp"
#include "numeric/parallel.hpp"

#include <map>
#include <stdexcept>
#include <tuple>

namespace scalecert::internal {

std::string compound_judgements_text(const ExactScene& sc, const Q& tolerance, const Q& abs_tolerance,
                                     Json judgements) {
    Json j;
    j["format"] = "scalecert-2";
    j["kind"] = "compound_judgements";
    if (sgn(abs_tolerance) > 0) j["abs_tolerance"] = to_exact_string(abs_tolerance);
    j["tolerance"] = to_exact_string(tolerance);
    j["judgements"] = std::move(judgements);
    j["scene"] = compound_scene_json(sc);
    return dump(j);
}

namespace {

// An entry's polygon and its witnesses (o's last three members: named first, then filled, so that
// no member is copied as the object grows).
void polygon_json(Json& o, const std::vector<Point2q>& poly, Json witnesses) {
    for (const char* key : {"vertices", "vertices_double", "witnesses"}) o[key] = nullptr;
    Json v = Json::array(), d = Json::array();
    for (const Point2q& p : poly) {
        v.push_back(Json::array({to_exact_string(p[0]), to_exact_string(p[1])}));
        d.push_back(Json::array({to_double_rn(p[0]), to_double_rn(p[1])}));
    }
    o["vertices"] = std::move(v);
    o["vertices_double"] = std::move(d);
    o["witnesses"] = std::move(witnesses);
}

// Blocks of pruned pairs apart along the same axis on the same side: runs along P2 in each row,
// a run extended down the rows while the next row has the same run. Each block is one entry with
// the normal ±e_c: every pair in it has part 1's swept box below (or above) part 2's along c, so
// the maximum over the block's P1 parts lies below the minimum over its P2 parts.
struct Block {
    int a0, a1, b0, b1, axis, side;
};
std::vector<Block> pruned_blocks(const CompoundRegion& r) {
    const int m = static_cast<int>(r.parts[0].size()), n = static_cast<int>(r.parts[1].size());
    auto code = [&](int a, int b) {
        return r.prune[static_cast<size_t>(a) * static_cast<size_t>(n) + static_cast<size_t>(b)];
    };
    std::vector<Block> done;
    std::map<std::tuple<int, int, int>, size_t> open;  // (b0, b1, code) -> block reaching the previous row
    for (int a = 0; a < m; ++a) {
        std::map<std::tuple<int, int, int>, size_t> next;
        for (int b = 0; b < n;) {
            const int k = code(a, b);
            if (!k) {
                ++b;
                continue;
            }
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
        Json e{{"P1_parts", range_json(b.a0, b.a1)},
               {"P2_parts", range_json(b.b0, b.b1)},
               {"normals", Json::array({normal_json(nrm)})}};
        polygon_json(e, {}, Json::array());
        entries.push_back({{b.a0, b.b0}, std::move(e)});
    }
    // The built pairs' entries with their witnesses, on every core (each pair's in its slot; the
    // tasks only read the parts).
    std::vector<Json> built(r.pairs.size());
    const unsigned threads =
        static_cast<unsigned>(std::min<size_t>(default_threads(), std::max<size_t>(1, r.pairs.size() / 8)));
    std::vector<long> missed(threads, 0);
    parallel_tasks(r.pairs.size(), threads, [&](unsigned t, size_t k) {
        const CompoundRegion::Pair& p = r.pairs[k];
        const Polyhedron &A = r.parts[0][static_cast<size_t>(p.part1)], &B = r.parts[1][static_cast<size_t>(p.part2)];
        Json wit = Json::array();
        for (const Point2q& v : p.polygon)
            wit.push_back(witness_object(pair_common_point(A, B, s1, s2, v[0], v[1], missed[t])));
        Json normals = Json::array();
        for (size_t f : p.fence) normals.push_back(normal_json(p.constraints[f].normal));
        Json e{{"P1_parts", range_json(p.part1, p.part1)},
               {"P2_parts", range_json(p.part2, p.part2)},
               {"normals", std::move(normals)}};
        polygon_json(e, p.polygon, std::move(wit));
        built[k] = std::move(e);
    });
    for (long x : missed) fallbacks += x;
    for (size_t k = 0; k < r.pairs.size(); ++k)
        entries.push_back({{r.pairs[k].part1, r.pairs[k].part2}, std::move(built[k])});
    std::sort(entries.begin(), entries.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    // Every key first, in the document's order: filling them in then moves the large arrays, where
    // inserting a key would copy those already in (the object is a vector of members, whose
    // elements a reallocation copies).
    Json j;
    for (const char* key : {"format", "kind", "pairs", "growth_set", "statistics", "scene"}) j[key] = nullptr;
    j["format"] = "scalecert-2";
    j["kind"] = "compound_partition";
    Json pairs = Json::array();
    for (auto& e : entries) pairs.push_back(std::move(e.second));
    j["pairs"] = std::move(pairs);
    Json growth = Json::array();
    for (const auto& iv : r.growth) {
        Json g;
        put_exact(g, "from", iv.from);
        put_exact(g, "to", iv.to);
        g["first_contact"] = Json{{"P1_part", iv.part1}, {"P2_part", iv.part2}};
        growth.push_back(g);
    }
    j["growth_set"] = std::move(growth);
    j["statistics"] = Json{{"pairs", r.prune.size()},
                           {"pruned", r.pruned},
                           {"built", r.built},
                           {"entries", entries.size()},
                           {"witness_fallbacks", fallbacks}};
    j["scene"] = compound_scene_json(sc);
    return j;
}

Json range_json(int from, int to) { return Json::array({from, to}); }

void put_part_name(Json& o, const std::string& key, const PolyInput& in, int k) {
    if (k < 0) return;
    const std::string& n = part_name(in, static_cast<size_t>(k));
    if (!n.empty()) o[key + "_name"] = n;
}

Json part_pair_json(const ExactScene& sc, int a, int b) {
    Json j;
    const int k[2] = {a, b};
    for (int i = 0; i < 2; ++i) {
        const std::string key = i ? "P2_part" : "P1_part";
        j[key] = k[i];
        put_part_name(j, key, sc.P[i], k[i]);
    }
    return j;
}

namespace {
Json ring_json(const std::vector<Point2q>& p) {
    Json a = Json::array();
    for (const Point2q& x : p) a.push_back(Json::array({to_exact_string(x[0]), to_exact_string(x[1])}));
    return a;
}
// A pair's entry with its polygon's vertices.
Json with_vertices(Json pair, const std::vector<Point2q>& polygon) {
    pair["vertices"] = ring_json(polygon);
    return pair;
}
Json point_json(const Point2q& x) { return Json::array({to_exact_string(x[0]), to_exact_string(x[1])}); }
// A pair's contact: its parts, label, features (vertex indices as each part lists its points),
// tight normals, and the line a rho1 + b rho2 = c that holds the edge (the pair meets on its >= side).
Json contact_json(const ExactScene& sc, const CompoundRegion& r, const PairContact& c, bool with_line) {
    const CompoundRegion::Pair& p = r.pairs[c.pair];
    Json j = part_pair_json(sc, p.part1, p.part2);
    j["contact"] = c.contact.label;
    j["features"] = Json{{"P1", c.contact.feat1}, {"P2", c.contact.feat2}};
    Json normals = Json::array();
    for (size_t k : c.tight) normals.push_back(normal_json(p.constraints[k].normal));
    j["normals"] = normals;
    if (with_line) {
        const HalfPlane& h = p.constraints[c.line];
        j["line"] = Json{{"a", to_exact_string(h.a)}, {"b", to_exact_string(h.b)}, {"c", to_exact_string(h.c)}};
    }
    return j;
}
void put_boundary(Json& j, const CompoundRegion& r, const ExactScene& sc) {
    if (r.union_skipped) {
        j["boundary"] = nullptr;
        j["switch_points"] = nullptr;
        return;
    }
    static const char* const sides[4] = {"rho1 = I1.lo", "rho1 = I1.hi", "rho2 = I2.lo", "rho2 = I2.hi"};
    const CompoundBoundary b = label_boundary(r, sc);
    Json rings = Json::array();
    for (const BoundaryRing& ring : b.rings) {
        Json edges = Json::array();
        for (const BoundaryEdge& e : ring.edges) {
            Json x{{"from", point_json(e.from)}, {"to", point_json(e.to)}};
            if (e.contact)
                x["on"] = contact_json(sc, r, *e.contact, true);
            else
                x["on"] = sides[e.bound];
            edges.push_back(x);
        }
        rings.push_back(
            Json{{"piece", ring.piece}, {"hole", ring.hole < 0 ? Json(nullptr) : Json(ring.hole)}, {"edges", edges}});
    }
    j["boundary"] = rings;
    Json sw = Json::array();
    for (const CompoundSwitch& s : b.switches) {
        Json cs = Json::array();
        for (const PairContact& c : s.contacts) cs.push_back(contact_json(sc, r, c, false));
        sw.push_back(Json{{"rho1", to_exact_string(s.at[0])},
                          {"rho2", to_exact_string(s.at[1])},
                          {"change", s.pair_change ? "pair" : "contact"},
                          {"contacts", cs}});
    }
    j["switch_points"] = sw;
}
}  // namespace

Json compound_region_json(const ExactScene& sc, const CompoundRegion& r, const std::optional<std::array<Q, 2>>& at) {
    Json j;
    j["format"] = "scalecert-2";
    j["kind"] = "region";
    const auto& hp = r.predicates[filter::Predicate::HalfPlaneSide];
    j["pairs"] = Json{{"total", r.prune.size()},
                      {"pruned", r.pruned},
                      {"built", r.built},
                      {"corner_sides", Json{{"decided_by_filter", hp.filtered}, {"decided_exactly", hp.exact}}}};
    Json pairs = Json::array();
    for (const auto& p : r.pairs)
        if (!p.polygon.empty()) pairs.push_back(with_vertices(part_pair_json(sc, p.part1, p.part2), p.polygon));
    j["pair_regions"] = pairs;
    Json region = Json::array();
    for (const RegionPiece& piece : r.region) {
        Json holes = Json::array();
        for (const auto& h : piece.holes) holes.push_back(ring_json(h));
        region.push_back(Json{{"outer", ring_json(piece.outer)}, {"holes", holes}});
    }
    if (r.union_skipped) {
        j["region"] = nullptr;
        j["region_note"] =
            "the union of more than " + std::to_string(kMaxUnionPolygons) +
            " pair polygons with area is not formed (its cost grows with their crossings): the region is the union "
            "of pair_regions";
    } else {
        j["region"] = region;
    }
    // Meeting sets without area (a pair that only touches, along a segment or at a point)
    // are part of the region too; the union above is of the polygons with area.
    Json thin = Json::array();
    for (const auto& p : r.pairs)
        if (!p.polygon.empty() && p.polygon.size() < 3)
            thin.push_back(with_vertices(part_pair_json(sc, p.part1, p.part2), p.polygon));
    j["region_without_area"] = thin;
    // Each interval's first contact: the pair that meets at its start, with its contact there
    // (null when it already overlaps there: the interval starts on the rectangle's edge).
    Json growth = Json::array();
    for (const auto& iv : r.growth) {
        Json first = part_pair_json(sc, iv.part1, iv.part2);
        first["contact"] = nullptr;
        for (size_t k = 0; k < r.pairs.size(); ++k)
            if (r.pairs[k].part1 == iv.part1 && r.pairs[k].part2 == iv.part2)
                if (const auto c = pair_contact_at(r, sc, k, {iv.from, iv.from})) {
                    first["contact"] = c->contact.label;
                    first["features"] = Json{{"P1", c->contact.feat1}, {"P2", c->contact.feat2}};
                }
        growth.push_back(
            Json{{"from", to_exact_string(iv.from)}, {"to", to_exact_string(iv.to)}, {"first_contact", first}});
    }
    j["growth_set"] = growth;
    put_boundary(j, r, sc);
    if (at) {
        const CompoundVerdict v = compound_verdict(r, (*at)[0], (*at)[1]);
        Json a{{"rho1", to_exact_string((*at)[0])},
               {"rho2", to_exact_string((*at)[1])},
               {"verdict", verdict_name(v.verdict)}};
        if (v.part1 >= 0) a["pair"] = part_pair_json(sc, v.part1, v.part2);
        j["at"] = a;
    }
    return j;
}

}  // namespace scalecert::internal
