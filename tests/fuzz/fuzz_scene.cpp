// The JSON scene reader on any bytes, and for the scenes it accepts (small ones), the whole
// pipeline: its partition certificate must pass the checker.
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    scalecert::internal::ReadOptions opt;
    opt.allow_off_files = false;  // no file names from fuzzed text
    opt.binary_doubles = size > 0 && (data[0] & 1);
    scalecert::internal::Scene sc;
    try {
        sc = scalecert::internal::parse_scene_text(text, "fuzz.json", "", opt);
    } catch (const scalecert::internal::InputError&) {
        return 0;
    }
    if (fuzz::total_points(sc) <= 40) fuzz::certify(sc);
    return 0;
}
