// certify-fp's claims reader on any bytes, against the tetrahedron-on-a-box scene (its curve
// derived by hand in test_hand_curves).
#include "fuzz_common.hpp"
#include "scalecert/audit.hpp"

namespace {
struct Fixed {
    scalecert::internal::Model m;
    scalecert::internal::Curve c;
    Fixed() {
        scalecert::internal::Scene sc = scalecert::internal::parse_scene_text(
            R"({"P1": {"vertices": [[2,0,2],[-2,2,5],[-1,-2,6],[2,0,7]], "seed": [0,0,"9/2"]},
                "P2": {"vertices": [[-1,-1,-1],[1,-1,-1],[-1,1,-1],[1,1,-1],[-1,-1,1],[1,-1,1],[-1,1,1],[1,1,1]], "seed": [0,0,0]},
                "I1": ["1/2", 2], "I2": [1, 4]})", "tetra_box", "");
        m = scalecert::internal::build_model(sc);
        c = scalecert::internal::build_curve(m);
    }
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static Fixed f;
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (bool bin : {false, true})
        for (bool json : {false, true}) {
            try {
                long wrong = -1;
                std::string out = scalecert::internal::certify_fp(f.m, f.c, text, "fuzz.claims", bin, json, &wrong);
                if (wrong < 0 || out.empty()) fuzz::finding("certify_fp returned no report");
            } catch (const scalecert::internal::InputError&) {
            }
        }
    return 0;
}
