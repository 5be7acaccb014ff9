// The checker on any bytes (seeded with the bundled certificates and query answers). It must
// never crash, and what it accepts must be true: for an accepted file, the engine recomputes the
// answer for the scene stored in it and every claim compared here must agree.
#include "fuzz_common.hpp"
#include "certify/claims.hpp"
#include "certify/compound_judge.hpp"
#include "compound/region.hpp"

#include <map>

namespace {
using J = nlohmann::json;
using namespace scalecert::internal;

// The scene of an accepted compound file, as the engine reads it (a finding if it cannot).
ExactScene compound_scene_of(const J& c) {
    ReadOptions opt;
    opt.allow_parts = true;
    opt.allow_off_files = false;
    try {
        return parse_scene_text(c.at("scene").dump(), "scene", "", opt);
    } catch (const InputError& e) {
        fuzz::finding(std::string("the checker accepted a compound scene the engine cannot read: ") + e.what());
    }
}

// An accepted compound partition: the engine's region for the stored scene must have exactly the
// file's meeting polygons (pair by pair) and growth set.
void compare_compound_with_engine(const J& c) {
    const ExactScene sc = compound_scene_of(c);
    CompoundRegion r;
    try {
        r = compound_region(sc, "scene", false);
    } catch (const InputError&) {
        return;  // past the engine's limits (a zero-width range, too many pairs): nothing to compare
    }
    std::map<std::pair<int, int>, J> engine, file;
    auto ring = [](const std::vector<Point2q>& p) {
        J a = J::array();
        for (const Point2q& x : p) a.push_back(J::array({to_exact_string(x[0]), to_exact_string(x[1])}));
        return a;
    };
    for (const auto& p : r.pairs)
        if (!p.polygon.empty()) engine[{p.part1, p.part2}] = ring(p.polygon);
    for (const J& e : c.at("pairs"))
        if (!e.at("vertices").empty())
            file[{e.at("P1_parts")[0].get<int>(), e.at("P2_parts")[0].get<int>()}] = e.at("vertices");
    if (engine != file) fuzz::finding("the checker accepted a compound partition whose polygons are not the engine's");
    const J& gs = c.at("growth_set");
    if (gs.size() != r.growth.size()) fuzz::finding("the checker accepted a wrong compound growth set");
    for (size_t k = 0; k < r.growth.size(); ++k)
        if (gs[k].at("from").get<std::string>() != to_exact_string(r.growth[k].from) ||
            gs[k].at("to").get<std::string>() != to_exact_string(r.growth[k].to))
            fuzz::finding("the checker accepted a wrong compound growth interval");
}

// The options certify-fp judged a judgements file's claims with: its tolerance and, when it has
// one, its absolute tolerance (the checker has accepted both as exact numbers).
ClaimOptions options_of(const J& c) {
    auto q = [](const J& j) {
        Q v(j.get<std::string>());
        v.canonicalize();
        return v;
    };
    ClaimOptions o{Numbers::Exact, q(c.at("tolerance")), true};
    if (c.contains("abs_tolerance")) o.abs_tolerance = q(c.at("abs_tolerance"));
    return o;
}

// An accepted compound judgements file: the engine, on the stored scene, claims and tolerances,
// must give every judgement the file states.
void compare_compound_judgements_with_engine(const J& c) {
    const ExactScene sc = compound_scene_of(c);
    J doc{{"format", "scalecert-claims-1"}, {"claims", J::array()}};
    for (const J& e : c.at("judgements")) doc["claims"].push_back(e.at("claim"));
    std::string report;
    try {
        CompoundJudge judge(sc, "scene");
        long wrong = 0;
        report = certify_fp(judge, doc.dump(), "fuzz", options_of(c), &wrong);
    } catch (const InputError& e) {
        const std::string what = e.what();
        if (what.find("the limit") != std::string::npos) return;  // past the engine's limits: nothing to compare
        fuzz::finding("the checker accepted compound claims the engine refuses: " + what);
    }
    const J r = J::parse(report);
    for (size_t k = 0; k < c.at("judgements").size(); ++k)
        if (r.at("claims")[k].at("right") != c.at("judgements")[k].at("right"))
            fuzz::finding("the checker accepted a wrong compound judgement at " + std::to_string(k));
}

void compare_with_engine(const J& c) {
    if (c.at("kind") == "compound_partition") return compare_compound_with_engine(c);
    if (c.at("kind") == "compound_judgements") return compare_compound_judgements_with_engine(c);
    ExactScene sc;
    try {
        sc = parse_scene_text(c.at("scene").dump(), "scene", "");
    } catch (const InputError& e) {
        fuzz::finding(std::string("the checker accepted a scene the engine cannot read: ") + e.what());
    }
    HullModel m;
    try {
        m = build_model(sc);
    } catch (const InputError&) {
        return;  // a seed the engine's own (stricter) checks refuse, or a limit: nothing to compare
    }
    TouchingCurve cv = build_curve(m);
    auto exact = [](const J& j) { return j.get<std::string>(); };
    if (c.at("kind") == "query") {
        Q r1(exact(c.at("rho1"))), r2(exact(c.at("rho2")));
        if (verdict_name(query(m, cv, r1, r2, false).verdict) != c.at("verdict").get<std::string>())
            fuzz::finding("the checker accepted a wrong verdict");
        return;
    }
    if (c.at("kind") == "judgements") {  // every judgement stated must be the engine's for its claim
        J doc{{"format", "scalecert-claims-1"}, {"claims", J::array()}};
        for (const J& e : c.at("judgements")) doc["claims"].push_back(e.at("claim"));
        long wrong = 0;
        std::string report;
        try {
            report = certify_fp(HullClaimModels(m, cv), doc.dump(), "fuzz", options_of(c), &wrong);
        } catch (const InputError& e) {
            fuzz::finding(std::string("the checker accepted claims the engine refuses: ") + e.what());
        }
        const J r = J::parse(report);
        for (size_t k = 0; k < c.at("judgements").size(); ++k)
            if (r.at("claims")[k].at("right") != c.at("judgements")[k].at("right"))
                fuzz::finding("the checker accepted a wrong judgement at " + std::to_string(k));
        return;
    }
    if (exact(c.at("growth_distance")) != to_exact_string(cv.growth.value))
        fuzz::finding("the checker accepted a wrong growth distance");
    const J& pieces = c.at("pieces");
    if (pieces.size() != cv.pieces.size()) fuzz::finding("the checker accepted a wrong number of pieces");
    for (size_t k = 0; k < pieces.size(); ++k) {
        const ContactLine& L = m.lines[cv.env.pieces[cv.pieces[k].env].line];
        if (exact(pieces[k].at("slope")) != to_exact_string(L.slope) ||
            exact(pieces[k].at("intercept")) != to_exact_string(L.intercept) ||
            exact(pieces[k].at("rho1")[1]) != to_exact_string(cv.pieces[k].to))
            fuzz::finding("the checker accepted a wrong piece " + std::to_string(k));
        if (pieces[k].at("contact").get<std::string>() != L.contact)
            fuzz::finding("the checker accepted a wrong piece contact");
    }
    for (size_t k = 0; k < cv.switches.size(); ++k) {
        const J& sw = c.at("switch_points")[k];
        const std::string want = cv.switches[k].contact.label;
        if (sw.at("contact").is_null() ? !want.empty() : sw.at("contact").get<std::string>() != want)
            fuzz::finding("the checker accepted a wrong switch contact at " + std::to_string(k));
    }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::string msg;
    if (scalecert_check::check_text(text, msg) != 0) return 0;
    compare_with_engine(scalecert_check::parse_strict(text));
    return 0;
}
