// The JSON scene reader on any bytes, and for the scenes it accepts (small ones), the whole
// pipeline: its partition certificate must pass the checker. The compact reader must agree with
// the strict one, and the scan path's curve with the hull path's. A scene of objects made of
// parts goes through the compound path: the region with its labelled boundary, whose contact
// edges must be touching at their middles, and its certificate, which the checker must accept.
#include "fuzz_common.hpp"

#include "certify/region_certificate.hpp"
#include "compound/boundary.hpp"

namespace {
void compound(const scalecert::internal::ExactScene& sc) {
    using namespace scalecert::internal;
    CompoundRegion r;
    try {
        r = compound_region(sc, "fuzz.json");
    } catch (const InputError&) {
        return;
    }
    const CompoundBoundary b = label_boundary(r, sc);
    for (const BoundaryRing& ring : b.rings)
        for (const BoundaryEdge& e : ring.edges) {
            if (!e.contact) continue;
            const Point2q mid{(e.from[0] + e.to[0]) / 2, (e.from[1] + e.to[1]) / 2};
            if (compound_verdict(r, mid[0], mid[1]).verdict != Verdict::Touching)
                fuzz::finding("a labelled contact edge of the compound region is not touching at its middle");
        }
    for (const CompoundSwitch& s : b.switches)
        if (s.contacts.empty()) fuzz::finding("a compound switch point with no pair touching there");
    (void)compound_region_json(sc, r);
    fuzz::must_pass_checker(dump(compound_partition_json(sc, r)), "compound partition");
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    scalecert::internal::ReadOptions opt;
    opt.allow_off_files = false;  // no file names from fuzzed text
    opt.allow_parts = true;
    opt.numbers = size > 0 && (data[0] & 1) ? scalecert::Numbers::Double : scalecert::Numbers::Exact;
    // The compact reader must give the strict reader's scene or nothing, under either reading.
    const auto fast = scalecert::internal::parse_scene_fast(text.data(), text.size(), opt.numbers);
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
            if (!(back.P[i].points == sc.P[i].points && back.P[i].seed == sc.P[i].seed &&
                  back.P[i].seed_given == sc.P[i].seed_given && back.lo[i] == sc.lo[i] && back.hi[i] == sc.hi[i]))
                fuzz::finding("the compact scene reader reads another scene than the strict reader");
    }
    if (!sc.P[0].parts.empty() || !sc.P[1].parts.empty()) {
        if (fuzz::total_points(sc) <= 64 && sc.P[0].parts.size() <= 8 && sc.P[1].parts.size() <= 8) compound(sc);
        return 0;
    }
    scalecert::internal::HullModel m;
    scalecert::internal::TouchingCurve c;
    if (fuzz::total_points(sc) <= 40 && fuzz::certify(sc, &m, &c)) fuzz::scan_agrees(sc, m, c);
    return 0;
}
