// A mesh reader (OFF, OBJ, PLY, STL: the first byte chooses) on any bytes; a polyhedron it
// accepts is paired with a cube and certified. For OFF, the compact reader must agree.
#include "fuzz_common.hpp"
#include "io/mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const scalecert::internal::MeshFormat f = static_cast<scalecert::internal::MeshFormat>(data[0] % 4);
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    // For OFF, the compact reader must give the full reader's points or nothing, under the
    // reading the first byte chooses (decimals as doubles, or as written).
    scalecert::internal::ReadOptions opt;
    opt.numbers = data[0] & 4 ? scalecert::Numbers::Double : scalecert::Numbers::Exact;
    const auto fast = f == scalecert::internal::MeshFormat::Off ? scalecert::internal::parse_off_fast(text, opt.numbers)
                                                                : std::nullopt;
    scalecert::internal::ExactScene sc;
    try {
        sc.P[0].points = scalecert::internal::parse_mesh(text, f, "fuzz.mesh", opt);
    } catch (const scalecert::internal::InputError&) {
        if (fast) fuzz::finding("the compact OFF reader accepts what the full reader refuses");
        return 0;
    }
    if (fast && !(scalecert::internal::q_points(*fast) == sc.P[0].points))
        fuzz::finding("the compact OFF reader reads other points");
    if (sc.P[0].points.size() < 4 || sc.P[0].points.size() > 40) return 0;
    using scalecert::internal::Q;
    for (int k = 0; k < 8; ++k) sc.P[1].points.push_back({Q(40 + (k & 1)), Q((k >> 1) & 1), Q((k >> 2) & 1)});
    for (int i = 0; i < 2; ++i) {
        sc.lo[i] = Q(1, 2);
        sc.hi[i] = Q(3);
    }
    scalecert::internal::finish_scene(sc, "fuzz");  // the mean seeds
    fuzz::certify(sc);
    return 0;
}
