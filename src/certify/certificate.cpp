#include "certify/certificate.hpp"
#include "certify/model_points.hpp"

#include "curve/closed_forms.hpp"
#include "geometry/witness.hpp"

#include <algorithm>
#include <iterator>

#include <mpfr.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <cstdio>
#include <fstream>

namespace scalecert::internal {

namespace {
const char* kFormat = "scalecert-2";

// An exact value and, in `key_double`, its nearest double.
void put(Json& o, const std::string& key, const Q& q) {
    o[key] = to_exact_string(q);
    o[key + "_double"] = to_double_rn(q);
}
void put(Json& o, const std::string& key, const std::vector<Q>& qs) {
    Json a = Json::array(), b = Json::array();
    for (const Q& q : qs) a.push_back(to_exact_string(q)), b.push_back(to_double_rn(q));
    o[key] = std::move(a);
    o[key + "_double"] = std::move(b);
}
void put(Json& o, const std::string& key, const Vec3q& v) { put(o, key, std::vector<Q>(v.begin(), v.end())); }
Json ints(const Vec3z& v) { return Json::array({v[0].get_str(), v[1].get_str(), v[2].get_str()}); }
Json weights(const std::vector<std::pair<int, Q>>& w) {
    Json a = Json::array();
    for (const auto& [i, q] : w) a.push_back(Json::array({i, to_exact_string(q)}));
    return a;
}
Json features(const std::vector<int>& f1, const std::vector<int>& f2) { return Json{{"P1", f1}, {"P2", f2}}; }

// Seeds strictly inside: strictly positive weights on vertices spanning 3 dimensions.
Json seed_interior_json(const SeedWeights& s) {
    Json seeds;
    const char* names[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) seeds[names[i]] = weights(s.w[i]);
    return seeds;
}

Json witness_json(const Witness& w) {
    Json j;
    put(j, "rho1", w.rho1);
    put(j, "rho2", w.rho2);
    put(j, "point", w.point);
    j["P1"] = weights(w.w1);
    j["P2"] = weights(w.w2);
    return j;
}

Json piece_json(const Model& m, const TouchingCurve& c, const CurvePiece& p, bool certificate) {
    const EnvPiece& e = c.env.pieces[p.env];
    const ContactLine& L = m.lines[e.line];
    Json j;
    put(j, "rho1", std::vector<Q>{p.from, p.to});
    put(j, "slope", L.slope);
    put(j, "intercept", L.intercept);
    if (p.contact.label.empty()) {
        j["contact"] = nullptr;  // ρ2 ≤ 0 all along the piece: nothing touches
    } else {
        j["contact"] = p.contact.label;
        j["features"] = features(p.contact.feat1, p.contact.feat2);
    }
    j["closed_form"] = closed_form_line(m, L).formula;
    j["normal"] = ints(L.normal);
    if (certificate) {
        put(j, "h1", L.h1);
        put(j, "h2", L.h2);
        j["support_vertices"] = Json{{"P1", L.feat1.front()}, {"P2", L.feat2.front()}};
    }
    // The other normals with the piece's line that cut its maximisers down to the contact
    // features, each one that shrinks them (a face's proper face has lower dimension, so at most
    // two per polyhedron): the checker scans every vertex for each, so it takes at most four.
    if (e.same.size() > 1) {
        Json also = Json::array();
        std::vector<int> G[2] = {L.feat1, L.feat2};
        for (size_t k : e.same) {
            if (k == e.line) continue;
            bool shrinks = false;
            for (int i = 0; i < 2; ++i) {
                const std::vector<int>& f = i ? m.lines[k].feat2 : m.lines[k].feat1;
                std::vector<int> both;
                std::set_intersection(G[i].begin(), G[i].end(), f.begin(), f.end(), std::back_inserter(both));
                if (both.size() < G[i].size()) shrinks = true, G[i] = std::move(both);
            }
            if (shrinks) also.push_back(ints(m.lines[k].normal));
        }
        if (!also.empty()) j["same_line_normals"] = also;
    }
    return j;
}

Json switch_json(const CurveSwitch& s) {
    Json j;
    put(j, "rho1", s.rho1);
    put(j, "rho2", s.rho2);
    if (s.contact.label.empty()) {
        j["contact"] = nullptr;  // ρ2 ≤ 0: outside the scaling domain, nothing touches
    } else {
        j["contact"] = s.contact.label;
        j["features"] = features(s.contact.feat1, s.contact.feat2);
    }
    j["equation"] = s.equation;
    return j;
}

Json curve_body(const Model& m, const TouchingCurve& c, bool certificate) {
    Json j;
    j["format"] = kFormat;
    j["kind"] = certificate ? "partition" : "curve";
    Json pieces = Json::array();
    for (const CurvePiece& p : c.pieces) pieces.push_back(piece_json(m, c, p, certificate));
    j["pieces"] = pieces;
    Json sw = Json::array();
    for (const CurveSwitch& s : c.switches) sw.push_back(switch_json(s));
    j["switch_points"] = sw;
    put(j, "growth_distance", c.growth.value);
    j["growth_distance_in_rectangle"] = c.growth.in_rectangle;
    if (sgn(c.growth.value) == 0) j["growth_distance_note"] = "the seeds coincide: every scaling pair overlaps";
    j["model"] = points_of(m).engine_json(m);
    return j;
}
}  // namespace

void put_exact(Json& o, const std::string& key, const Q& q) { put(o, key, q); }
void put_exact(Json& o, const std::string& key, const std::vector<Q>& qs) { put(o, key, qs); }
void put_exact(Json& o, const std::string& key, const Vec3q& v) { put(o, key, v); }
Json document_scene(const Model& m) { return points_of(m).scene_json(m); }

Json curve_json(const Model& m, const TouchingCurve& c) { return curve_body(m, c, false); }

Json weights_json(const std::vector<std::pair<int, Q>>& w) { return weights(w); }
Json witness_object(const Witness& w) { return witness_json(w); }
Json normal_json(const Vec3z& n) { return ints(n); }

Json query_certificate_json(const Model& m, const QueryAnswer& r) {
    Json cert;
    if (r.plane) {
        const PlaneCert& p = *r.plane;
        const ContactLine& L = m.lines[p.line];
        Json pl;
        pl["normal"] = ints(L.normal);
        put(pl, "offset", p.offset);
        put(pl, "P1_max", p.c1);
        put(pl, "P2_min", p.c2);
        pl["support_vertices"] = Json{{"P1", p.support1}, {"P2", p.support2}};
        pl["contact"] = L.contact;
        cert["plane"] = pl;
    }
    if (r.witness) cert["witness"] = witness_json(*r.witness);
    return cert;
}

Json seed_interior(const SeedWeights& seeds) { return seed_interior_json(seeds); }

Json query_json(const Model& m, const QueryAnswer& r, const SeedWeights& seeds) {
    Json j;
    j["format"] = kFormat;
    j["kind"] = "query";
    j["verdict"] = verdict_name(r.verdict);
    put(j, "rho1", r.rho1);
    put(j, "rho2", r.rho2);
    j["certificate"] = query_certificate_json(m, r);
    j["seed_interior"] = seed_interior_json(seeds);
    j["scene"] = points_of(m).scene_json(m);
    return j;
}

namespace {
// Adds to a document holding c's "pieces" and "switch_points" their witnesses, and "curve_ends".
void put_curve_witnesses(Json& j, const Model& m, const TouchingCurve& c, const CurveWitnesses& p) {
    for (size_t k = 0; k < c.pieces.size(); ++k)
        if (p.piece_witnesses[k]) j["pieces"][k]["contact_witness"] = witness_json(*p.piece_witnesses[k]);
    for (size_t k = 0; k < c.pieces.size(); ++k)
        if (p.zero_witnesses[k]) j["pieces"][k]["zero_witness"] = witness_json(*p.zero_witnesses[k]);
    for (size_t k = 0, w = 0; k < c.switches.size(); ++k)
        if (sgn(c.switches[k].rho2) > 0) j["switch_points"][k]["witness"] = witness_json(p.switch_witnesses[w++]);
    Json ends = Json::array();
    for (int e = 0; e < 2; ++e) {
        const CurvePiece& cp = e == 0 ? c.pieces.front() : c.pieces.back();
        Q x = e == 0 ? cp.from : cp.to;
        Json end;
        put(end, "rho1", x);
        put(end, "rho2", m.lines[c.env.pieces[cp.env].line].at(x));
        if (p.end_witness[e]) end["witness"] = witness_json(*p.end_witness[e]);
        ends.push_back(end);
    }
    j["curve_ends"] = ends;
}
}  // namespace

Json curve_proof_json(const Model& m, const TouchingCurve& c, const CurveWitnesses& w) {
    Json j;
    put(j, "rho1", std::vector<Q>{c.pieces.front().from, c.pieces.back().to});
    Json pieces = Json::array();
    for (const CurvePiece& p : c.pieces) pieces.push_back(piece_json(m, c, p, true));
    j["pieces"] = pieces;
    Json sw = Json::array();
    for (const CurveSwitch& s : c.switches) sw.push_back(switch_json(s));
    j["switch_points"] = sw;
    put_curve_witnesses(j, m, c, w);
    return j;
}

Json partition_json(const Model& m, const TouchingCurve& c, const Partition& p) {
    Json j = curve_body(m, c, true);
    put_curve_witnesses(j, m, c, p);
    Json g;
    if (p.growth_witness) {
        const ContactLine& L = m.lines[c.env.pieces[c.growth.env].line];
        g["normal"] = ints(L.normal);
        put(g, "h1", L.h1);
        put(g, "h2", L.h2);
        g["witness"] = witness_json(*p.growth_witness);
    } else {
        g["seeds_coincide"] = true;
    }
    j["growth_distance_certificate"] = g;
    Json regions;
    auto poly = [](const std::vector<Pt2>& v) {
        Json a = Json::array(), b = Json::array();
        for (const Pt2& x : v) {
            a.push_back(Json::array({to_exact_string(x[0]), to_exact_string(x[1])}));
            b.push_back(Json::array({to_double_rn(x[0]), to_double_rn(x[1])}));
        }
        return std::make_pair(a, b);
    };
    auto [ov, ovd] = poly(p.overlap);
    Json wit = Json::array();
    for (const Witness& w : p.overlap_witnesses) wit.push_back(witness_json(w));
    regions["overlap"] = Json{{"vertices", ov}, {"vertices_double", ovd}, {"witnesses", wit}};
    Json seps = Json::array();
    for (const SeparatedRegion& r : p.separated) {
        auto [a, b] = poly(r.verts);
        seps.push_back(Json{{"piece", r.piece}, {"vertices", a}, {"vertices_double", b}});
    }
    regions["separated"] = seps;
    j["regions"] = regions;
    j["seed_interior"] = seed_interior_json(p.seeds);
    j["scene"] = points_of(m).scene_json(m);
    return j;
}

std::string document_text(const Model& m, const Json& j) { return points_of(m).document_text(m, dump(j)); }

}  // namespace scalecert::internal
