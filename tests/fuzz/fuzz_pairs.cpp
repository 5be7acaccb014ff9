// The pairs reader of `classify` on any bytes, on one and on two threads: the same pairs, bit for
// bit, or the same error.
#include "fuzz_common.hpp"

#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::vector<double> a1, a2, b1, b2;
    std::string ea, eb;
    try {
        scalecert::internal::parse_pairs(text, a1, a2, 1);
    } catch (const scalecert::internal::InputError& e) {
        ea = e.what();
    }
    try {
        scalecert::internal::parse_pairs(text, b1, b2, 2);
    } catch (const scalecert::internal::InputError& e) {
        eb = e.what();
    }
    if (ea != eb) fuzz::finding("pairs: 1 and 2 threads disagree: '" + ea + "' / '" + eb + "'");
    if (!ea.empty()) return 0;
    if (a1.size() != b1.size() || std::memcmp(a1.data(), b1.data(), a1.size() * sizeof(double)) ||
        std::memcmp(a2.data(), b2.data(), a2.size() * sizeof(double)))
        fuzz::finding("pairs: 1 and 2 threads read different pairs");
    for (size_t i = 0; i < a1.size(); ++i)
        if (!(a1[i] > 0 && a2[i] > 0 && std::isfinite(a1[i]) && std::isfinite(a2[i])))
            fuzz::finding("pairs: a pair that is not finite and > 0 was accepted");
    return 0;
}
