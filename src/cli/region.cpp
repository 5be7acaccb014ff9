// scalecert region: where two objects made of convex parts overlap in I1 × I2 (issue 22, first
// room): each part pair's exact polygon, their union, and the growth set along ρ1 = ρ2.
#include "common.hpp"
#include "compound/boundary.hpp"
#include "compound/region.hpp"
#include "certify/certificate.hpp"
#include "certify/classify.hpp"
#include "certify/region_certificate.hpp"
#include "compound/locate.hpp"
#include "file_name.hpp"
#include "io/files.hpp"

#include <algorithm>
#include <thread>

namespace scalecert::cli {

using namespace internal;

namespace {
Json ring_json(const std::vector<Point2q>& p) {
    Json a = Json::array();
    for (const Point2q& x : p) a.push_back(Json::array({to_exact_string(x[0]), to_exact_string(x[1])}));
    return a;
}
Json point_json(const Point2q& x) { return Json::array({to_exact_string(x[0]), to_exact_string(x[1])}); }
// A pair's contact: its parts, label, features (vertex indices as each part lists its points),
// tight normals, and the first one's line a rho1 + b rho2 = c (the pair meets on its >= side).
Json contact_json(const CompoundRegion& r, const PairContact& c, bool with_line) {
    const CompoundRegion::Pair& p = r.pairs[c.pair];
    Json j{{"P1_part", p.part1}, {"P2_part", p.part2}, {"contact", c.contact.label},
           {"features", Json{{"P1", c.contact.feat1}, {"P2", c.contact.feat2}}}};
    Json normals = Json::array();
    for (size_t k : c.tight) normals.push_back(normal_json(p.constraints[k].normal));
    j["normals"] = normals;
    if (with_line) {
        const HalfPlane& h = p.constraints[c.tight.front()];
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
            if (e.contact) x["on"] = contact_json(r, *e.contact, true);
            else x["on"] = sides[e.bound];
            edges.push_back(x);
        }
        rings.push_back(Json{{"piece", ring.piece}, {"hole", ring.hole < 0 ? Json(nullptr) : Json(ring.hole)}, {"edges", edges}});
    }
    j["boundary"] = rings;
    Json sw = Json::array();
    for (const CompoundSwitch& s : b.switches) {
        Json cs = Json::array();
        for (const PairContact& c : s.contacts) cs.push_back(contact_json(r, c, false));
        sw.push_back(Json{{"rho1", to_exact_string(s.at[0])}, {"rho2", to_exact_string(s.at[1])},
                          {"change", s.pair_change ? "pair" : "contact"}, {"contacts", cs}});
    }
    j["switch_points"] = sw;
}
}  // namespace

Command add_region(CLI::App& app) {
    struct Args {
        SceneArgs scene;
        std::string out, at, certificate, classify;
        unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand("region", "where objects made of convex parts overlap in I1 x I2: each part pair's exact polygon and their union (JSON)");
    a->scene.add(sub);
    add_out(sub, a->out);
    sub->add_flag("--parts-from-groups", a->scene.opt.parts_from_groups,
                  "read each OBJ mesh of an object (--p1, --p2, or an object's \"mesh\" in SCENE) as a compound: a part per "
                  "'o' or 'g' group, of the vertices its faces name (other mesh formats are refused: they have no groups)");
    sub->add_option("--at", a->at, "also the exact verdict at RHO1,RHO2 (in I1 x I2), with the pair that decides it");
    sub->add_option("--certificate", a->certificate,
                    "also write the certified partition (kind compound_partition): each part pair's overlap polygon with "
                    "witnesses at its corners and the normals that separate the pair outside it, for scalecert-check "
                    "(certificates/FORMAT.md, \"A compound partition\")")
        ->type_name("FILE")
        ->check(file_name());
    sub->add_option("--classify", a->classify,
                    "instead of the region, the exact verdict of each pair of FILE (lines 'rho1 rho2', doubles; '-': standard "
                    "input), one per line, located on a grid over I1 x I2 built once")
        ->type_name("FILE");
    sub->add_option("--threads", a->threads, "threads for --classify (default: all cores)")->check(CLI::Range(1u, 256u));
    example(sub, "Examples:\n  scalecert region tests/data/compound_band.json\n  scalecert region tests/data/compound_band.json --at 7/6,2\n"
                 "  printf '1 2\\n1.5 2\\n' | scalecert region tests/data/compound_band.json --classify -\n"
                 "  scalecert region tests/data/compound_band.json --certificate band.cert.json && scalecert-check band.cert.json");
    return {sub, [a, sub] {
                a->scene.opt.allow_parts = true;
                internal::refuse_outputs_over_inputs({a->out, a->certificate}, {a->scene.path, a->scene.mesh[0], a->scene.mesh[1], a->classify});
                const ExactScene sc = a->scene.load();
                std::vector<Q> x;  // --at, read before the work
                if (sub->count("--at")) {
                    x = number_list(a->at, 2, "--at", a->scene.opt);
                    if (x[0] < sc.lo[0] || x[0] > sc.hi[0] || x[1] < sc.lo[1] || x[1] > sc.hi[1])
                        throw InputError("--at: " + internal::quoted(a->at) + " lies outside I1 x I2");
                }
                std::string pairs_text;  // --classify: read before the work, like --at
                std::vector<double> p1, p2;
                if (sub->count("--classify")) {
                    if (!a->certificate.empty() || !x.empty()) throw InputError("--classify writes verdicts only: not with --certificate or --at");
                    pairs_text = read_input(a->classify.empty() ? "-" : a->classify, "pairs file", kMaxPairsBytes);
                    try {
                        parse_pairs(pairs_text, p1, p2, a->threads);
                    } catch (const InputError& e) {
                        throw InputError(a->classify + ": " + e.what());
                    }
                    for (size_t k = 0; k < p1.size(); ++k)
                        if (Q(p1[k]) < sc.lo[0] || Q(p1[k]) > sc.hi[0] || Q(p2[k]) < sc.lo[1] || Q(p2[k]) > sc.hi[1])
                            throw InputError(a->classify + ": pair " + std::to_string(k + 1) + " lies outside I1 x I2");
                }
                // The union is for the region document only (the certificate and verdicts need none).
                const bool document = !sub->count("--classify");
                const CompoundRegion r = compound_region(sc, a->scene.name(), document);
                if (sub->count("--classify")) {
                    const CompoundLocator L(r, sc.lo, sc.hi, CompoundLocator::grid_for(r));
                    const std::vector<std::int8_t> v = L.classify(p1, p2, a->threads);
                    std::vector<Verdict> out(v.size());
                    for (size_t k = 0; k < v.size(); ++k) out[k] = v[k] == 0 ? Verdict::Separated : v[k] == 1 ? Verdict::Touching : Verdict::Overlapping;
                    emit(verdict_lines(out), a->out);
                    return 0;
                }
                Json j;
                j["format"] = "scalecert-2";
                j["kind"] = "region";
                const auto& hp = r.predicates[filter::Predicate::HalfPlaneSide];
                j["pairs"] = Json{{"total", r.prune.size()}, {"pruned", r.pruned}, {"built", r.built},
                                  {"corner_sides", Json{{"decided_by_filter", hp.filtered}, {"decided_exactly", hp.exact}}}};
                Json pairs = Json::array();
                for (const auto& p : r.pairs)
                    if (!p.polygon.empty()) pairs.push_back(Json{{"P1_part", p.part1}, {"P2_part", p.part2}, {"vertices", ring_json(p.polygon)}});
                j["pair_regions"] = pairs;
                Json region = Json::array();
                for (const RegionPiece& piece : r.region) {
                    Json holes = Json::array();
                    for (const auto& h : piece.holes) holes.push_back(ring_json(h));
                    region.push_back(Json{{"outer", ring_json(piece.outer)}, {"holes", holes}});
                }
                if (r.union_skipped) {
                    j["region"] = nullptr;
                    j["region_note"] = "the union of more than " + std::to_string(kMaxUnionPolygons) +
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
                        thin.push_back(Json{{"P1_part", p.part1}, {"P2_part", p.part2}, {"vertices", ring_json(p.polygon)}});
                j["region_without_area"] = thin;
                Json growth = Json::array();
                for (const auto& iv : r.growth)
                    growth.push_back(Json{{"from", to_exact_string(iv.from)}, {"to", to_exact_string(iv.to)},
                                          {"first_contact", Json{{"P1_part", iv.part1}, {"P2_part", iv.part2}}}});
                j["growth_set"] = growth;
                put_boundary(j, r, sc);
                if (!x.empty()) {
                    const CompoundVerdict v = compound_verdict(r, x[0], x[1]);
                    Json at{{"rho1", to_exact_string(x[0])}, {"rho2", to_exact_string(x[1])}, {"verdict", v.verdict}};
                    if (v.part1 >= 0) at["pair"] = Json{{"P1_part", v.part1}, {"P2_part", v.part2}};
                    j["at"] = at;
                }
                if (a->certificate.empty()) {
                    emit(dump(j), a->out);
                } else {
                    const std::string cert = dump(compound_partition_json(sc, r));
                    if (a->out.empty()) {
                        write_file_atomically(a->certificate, cert);
                        emit(dump(j), a->out);
                    } else {
                        write_files_atomically({{a->certificate, cert}, {a->out, dump(j)}});
                    }
                }
                return 0;
            }};
}

}  // namespace scalecert::cli
