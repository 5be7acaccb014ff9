// The OFF reader on any bytes; a polyhedron it accepts is paired with a cube and certified.
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    scalecert::Scene sc;
    try {
        sc.P[0].points = scalecert::parse_off_text(text, "fuzz.off");
    } catch (const scalecert::InputError&) {
        return 0;
    }
    if (sc.P[0].points.size() < 4 || sc.P[0].points.size() > 40) return 0;
    using scalecert::Q;
    for (int k = 0; k < 8; ++k) sc.P[1].points.push_back({Q(40 + (k & 1)), Q((k >> 1) & 1), Q((k >> 2) & 1)});
    for (int i = 0; i < 2; ++i) {
        scalecert::Vec3q c{Q(0), Q(0), Q(0)};
        for (const auto& v : sc.P[i].points) for (int k = 0; k < 3; ++k) c[k] += v[k];
        for (int k = 0; k < 3; ++k) c[k] /= Q(static_cast<long>(sc.P[i].points.size()));
        sc.P[i].seed = c;
        sc.lo[i] = Q(1, 2);
        sc.hi[i] = Q(3);
    }
    fuzz::certify(sc);
    return 0;
}
