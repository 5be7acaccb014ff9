// The JSON scene reader on any bytes, and for the scenes it accepts (small ones), the whole
// pipeline: its partition certificate must pass the checker. The compact reader must agree with
// the strict one, and the scan path's curve with the hull path's.
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    scalecert::internal::ReadOptions opt;
    opt.allow_off_files = false;  // no file names from fuzzed text
    opt.binary_doubles = size > 0 && (data[0] & 1);
    // The compact reader (exact decimals only) must give the strict reader's scene or nothing.
    const auto fast = opt.binary_doubles ? std::nullopt : scalecert::internal::parse_scene_fast(text.data(), text.size());
    scalecert::internal::ExactScene sc;
    try {
        sc = scalecert::internal::parse_scene_text(text, "fuzz.json", "", opt);
    } catch (const scalecert::internal::InputError&) {
        if (fast) fuzz::finding("the compact scene reader accepts what the strict reader refuses");
        return 0;
    }
    if (fast) {
        const scalecert::internal::ExactScene back = scalecert::internal::full_scene(*fast);
        for (int i = 0; i < 2; ++i)
            if (!(back.P[i].points == sc.P[i].points && back.P[i].seed == sc.P[i].seed && back.P[i].seed_given == sc.P[i].seed_given &&
                  back.lo[i] == sc.lo[i] && back.hi[i] == sc.hi[i]))
                fuzz::finding("the compact scene reader reads another scene than the strict reader");
    }
    scalecert::internal::HullModel m;
    scalecert::internal::TouchingCurve c;
    if (fuzz::total_points(sc) <= 40 && fuzz::certify(sc, &m, &c)) fuzz::scan_agrees(sc, m, c);
    return 0;
}
