// Shared by the libFuzzer targets (tools/fuzz.sh): the oracles that turn a wrong answer into a
// crash libFuzzer reports. The checker is linked in from its own library, scalecert_check_core
// (it shares no code with the engine; here both live in one process only to compare them).
#pragma once
#include "certify/certificate.hpp"
#include "certify/classify.hpp"
#include "curve/scan.hpp"
#include "../support.hpp"

#include "../../checker/check.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace fuzz {
using namespace scalecert::internal;

[[noreturn]] inline void finding(const std::string& what) {
    std::fprintf(stderr, "FUZZ FINDING: %s\n", what.c_str());
    std::fflush(stderr);
    __builtin_trap();
}

// The checker must accept what the engine writes.
inline void must_pass_checker(const std::string& text, const std::string& what) {
    std::string msg;
    if (scalecert_check::check_text(text, msg) != 0) finding("the checker rejects the engine's " + what + ": " + msg);
}

// For a small scene the engine accepts: the curve, the partition and its certificate, which the
// checker must accept. Returns false when the engine refuses the scene (InputError).
inline bool certify(const ExactScene& sc, HullModel* out_model = nullptr, TouchingCurve* out_curve = nullptr) {
    HullModel m;
    try {
        m = build_model(sc);
    } catch (const InputError&) {
        return false;
    }
    TouchingCurve c = build_curve(m);
    must_pass_checker(dump(partition_json(m, c, build_partition(m, c))), "partition");
    if (out_curve) *out_curve = c;
    if (out_model) *out_model = std::move(m);
    return true;
}

// The scan path on a scene the hull path accepted: where it decides, its curve document must
// be the hull path's byte for byte, but for the engine statistics.
inline void scan_agrees(const ExactScene& sc, const Model& hm, const TouchingCurve& hc) {
    auto cs = compact_scene(sc);
    if (!cs) return;
    auto without_model = [](const Model& m, const TouchingCurve& c) {
        Json j = curve_json(m, c);
        j.erase("model");
        return dump(j);
    };
    const WalkResult r = scan_model(std::make_shared<CompactScene>(std::move(*cs)));
    if (r.model && without_model(*r.model, build_curve(*r.model)) != without_model(hm, hc))
        finding("the scan path's curve differs from the hull path's");
}

inline size_t total_points(const ExactScene& sc) { return sc.P[0].points.size() + sc.P[1].points.size(); }
}  // namespace fuzz
