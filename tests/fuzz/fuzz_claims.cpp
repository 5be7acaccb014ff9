// certify-fp's claims reader on any bytes, against the tetrahedron-on-a-box scene (its curve
// derived by hand in test_hand_curves), once with I1 = [1/2, 2] and once with I1 = [1/2, 3/4], so
// that curve claims reach beyond I1 and across its switch point (1, 2) outside it. Oracle: a curve
// or switch point claim judged right (no tolerance) must touch at each claimed point by the brute
// force (tests/support.hpp: no hull, no envelope): at its vertices, piece ends and midpoints.
#include "fuzz_common.hpp"
#include "baselines/audit.hpp"
#include "certify/claims.hpp"
#include "certify/compound_judge.hpp"
#include "session/session.hpp"

#include <nlohmann/json.hpp>

namespace {
using namespace scalecert::internal;
struct Fixed {
    ExactScene sc;
    HullModel m;
    TouchingCurve c;
    explicit Fixed(const char* i1) {
        sc = parse_scene_text(std::string(
                                  R"({"P1": {"vertices": [[2,0,2],[-2,2,5],[-1,-2,6],[2,0,7]], "seed": [0,0,"9/2"]},
                "P2": {"vertices": [[-1,-1,-1],[1,-1,-1],[-1,1,-1],[1,1,-1],[-1,-1,1],[1,-1,1],[-1,1,1],[1,1,1]],
                "seed": [0,0,0]},
                "I1": )") + i1 + R"(, "I2": [1, 4]})",
                              "tetra_box", "");
        m = build_model(sc);
        c = build_curve(m);
    }
};

// A number as the claims reader takes it (exact decimals and p/q), or none.
std::optional<Q> exact_of(const nlohmann::json& j) {
    try {
        if (j.is_string()) return parse_number(j.get<std::string>(), Numbers::Exact);
        if (j.is_number()) return parse_number(j.dump(), Numbers::Exact);
    } catch (const InputError&) {}
    return std::nullopt;
}

void must_touch(const Fixed& f, const test::Brute& b, const Q& x, const Q& y, const std::string& what) {
    if (b.classify(f.sc, x, y) != 0)
        fuzz::finding("a " + what + " claim judged right is not touching at (" + x.get_str() + ", " + y.get_str() +
                      ") by brute force");
}

// The points a right curve or switch point claim says are on the curve.
void check_right_claims(const Fixed& f, const test::Brute& b, const std::string& text, const std::string& report) {
    nlohmann::json in, out;
    try {
        in = nlohmann::json::parse(text);
        out = nlohmann::json::parse(report);
    } catch (const nlohmann::json::exception&) {
        return;
    }
    if (!in.is_object() || !in.contains("claims") || !in["claims"].is_array())
        return;  // (text with a NUL can parse as "1")
    for (const auto& r : out["claims"]) {
        if (!r["right"].get<bool>()) continue;
        const auto& cl = in["claims"][r["index"].get<size_t>()];
        const std::string kind = r["kind"];
        if (kind == "switch_point") {
            if (auto x = exact_of(cl["rho1"]), y = exact_of(cl["rho2"]); x && y) must_touch(f, b, *x, *y, kind);
        } else if (kind == "curve" && cl.contains("vertices")) {
            std::optional<std::pair<Q, Q>> prev;
            for (const auto& v : cl["vertices"]) {
                auto x = exact_of(v[0]), y = exact_of(v[1]);
                if (!x || !y) return;
                must_touch(f, b, *x, *y, kind);
                if (prev)
                    must_touch(f, b, (prev->first + *x) / 2, (prev->second + *y) / 2, kind + " (a segment's midpoint)");
                prev = {{*x, *y}};
            }
        } else if (kind == "curve") {
            for (const auto& p : cl["pieces"]) {
                auto x0 = exact_of(p["rho1"][0]), x1 = exact_of(p["rho1"][1]), a = exact_of(p["slope"]),
                     c = exact_of(p["intercept"]);
                if (!x0 || !x1 || !a || !c) return;
                for (const Q& x : {*x0, *x1, Q((*x0 + *x1) / 2)}) must_touch(f, b, x, *a * x + *c, kind);
            }
        }
    }
}
}  // namespace

// The band of tests/data/compound_band.json (two boxes either side of P1's seed, a box between):
// claims on objects made of parts, each certificate checked by the checker in the same process.
// Oracle: every certificate the engine writes is valid.
void compound_claims(const std::string& text) {
    static const ExactScene band = [] {
        ReadOptions opt;
        opt.allow_parts = true;
        return parse_scene_text(
            R"({"P1": {"parts": [
            {"vertices": [[2,-1,-1],[3,-1,-1],[2,1,-1],[3,1,-1],[2,-1,1],[3,-1,1],[2,1,1],[3,1,1]]},
            {"vertices": [[-3,-1,-1],[-2,-1,-1],[-3,1,-1],[-2,1,-1],[-3,-1,1],[-2,-1,1],[-3,1,1],[-2,1,1]]}],
            "seed": [0, 0, 0]},
            "P2": {"vertices": [[4,-1,-1],[5,-1,-1],[4,1,-1],[5,1,-1],[4,-1,1],[5,-1,1],[4,1,1],[5,1,1]],
            "seed": ["9/2", 0, 0]},
            "I1": [1, 4], "I2": [1, 3]})",
            "band", "", opt);
    }();
    static CompoundJudge judge(band, "band");
    for (const Q& abs : {Q(0), Q(1, 1000)})  // exact, and at an absolute tolerance
        try {
            long wrong = -1;
            std::string certificate;
            ClaimOptions opt{Numbers::Double, Q(0), true};
            opt.abs_tolerance = abs;
            const std::string out = certify_fp(judge, text, "fuzz.claims", opt, &wrong, nullptr, &certificate);
            if (wrong < 0 || out.empty()) fuzz::finding("certify_fp on parts returned no report");
            fuzz::must_pass_checker(certificate, "compound judgements certificate");
        } catch (const InputError&) {}
}

// Crossed 40-gon prisms (tests/support.hpp), whose Minkowski sum has O(n^2) facets: the same
// claims judged on the walk (a fresh session each input, the engine forced to the walk) and on
// the hull model. Oracle: the same judgement for every claim, the same refusal, and a valid
// certificate from the walk; the same with an absolute tolerance.
void walk_claims(const std::string& text) {
    static const ExactScene prisms = test::crossed_prism_scene(40);
    static const HullModel hm = build_model(prisms);
    static const TouchingCurve hc = build_curve(hm);
    for (int run = 0; run < 3; ++run) {  // lines, JSON, JSON at an absolute tolerance
        const bool json = run > 0;
        ClaimOptions opt{Numbers::Double, Q(0), json};
        if (run == 2) opt.abs_tolerance = Q(1, 1000);
        std::string hull_out, walk_out, cert, hull_err, walk_err;
        long wrong = -1;
        try {
            hull_out = certify_fp(HullClaimModels(hm, hc), text, "fuzz.claims", opt, &wrong);
        } catch (const InputError& e) {
            hull_err = e.what();
        }
        try {
            Session s(prisms, "fuzz.claims", Engine::Scan);
            walk_out = certify_fp(s.claim_models(), text, "fuzz.claims", opt, &wrong, nullptr, &cert);
        } catch (const InputError& e) {
            walk_err = e.what();
        }
        if (hull_err.empty() != walk_err.empty())
            fuzz::finding("the walk and the hull model disagree on refusing: '" + hull_err + "' / '" + walk_err + "'");
        if (!hull_err.empty()) continue;
        if (json) {
            const nlohmann::json h = nlohmann::json::parse(hull_out), w = nlohmann::json::parse(walk_out);
            for (size_t i = 0; i < h["claims"].size(); ++i)
                if (h["claims"][i]["right"] != w["claims"][i]["right"])
                    fuzz::finding("claim " + std::to_string(i) +
                                  " judged differently on the walk and on the hull model");
        } else if (hull_out != walk_out) {
            fuzz::finding("the line format's report differs between the walk and the hull model");
        }
        fuzz::must_pass_checker(cert, "judgements certificate from the walk");
    }
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static Fixed wide(R"(["1/2", 2])"), narrow(R"(["1/2", "3/4"])");
    static test::Brute brute(wide.sc);  // the same polyhedra and seeds in both
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (const Fixed* f : {&wide, &narrow})
        for (bool bin : {false, true})
            for (bool json : {false, true}) {
                try {
                    long wrong = -1;
                    std::string out = certify_fp(f->m, f->c, text, "fuzz.claims",
                                                 bin ? Numbers::Exact : Numbers::Double, json, &wrong);
                    if (wrong < 0 || out.empty()) fuzz::finding("certify_fp returned no report");
                    if (json && !bin) check_right_claims(*f, brute, text, out);
                } catch (const InputError&) {}
            }
    compound_claims(text);
    walk_claims(text);
    return 0;
}
