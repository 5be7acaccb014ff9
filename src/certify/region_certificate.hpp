// Stage 7 for compounds: the certified partition of I1 × I2 for two objects made of
// convex parts (kind "compound_partition", certificates/FORMAT.md "A compound partition").
//
// The objects meet at (ρ1, ρ2) iff some part pair does, so the file certifies each pair's meeting
// set M in the rectangle on its own, and the union needs no further proof: a point lies in the
// overlap region iff it lies in some pair's M. A pair's entry lists a few facet normals (its
// fence: PairRegion::fence) whose half-planes ρ1 hA(n) + ρ2 hB(n) >= n·d cut the rectangle to
// exactly M: outside M one of them fails, and that normal separates the pair there. M's corners
// carry witnesses (common points), so by convexity the pair meets on all of M. Pairs that meet
// nowhere in the rectangle need no corners; those pruned by their swept boxes share one entry per
// block of parts apart along the same axis (one normal for the block's union of vertices), so the
// file grows with the pairs that can meet, not with all pairs.
#pragma once
#include "certify/certificate.hpp"
#include "compound/region.hpp"

#include <array>
#include <optional>

namespace scalecert::internal {

// The compound judgements document (kind "compound_judgements", FORMAT.md): certify-fp's proofs on
// objects made of parts, as text.
std::string compound_judgements_text(const ExactScene& sc, const Q& tolerance, const Q& abs_tolerance, Json judgements);

// The certificate of r, the region of scene sc (compound_region(sc, ...)).
Json compound_partition_json(const ExactScene& sc, const CompoundRegion& r);

// A part pair for documents: {"P1_part": a, "P2_part": b}, each index followed by its part's name
// ("P1_part_name") when it has one.
Json part_pair_json(const ExactScene& sc, int a, int b);
// Beside o[key], part k of object in (k < 0: none): o[key + "_name"], its name, when it has one.
void put_part_name(Json& o, const std::string& key, const PolyInput& in, int k);
// A range of part indices [from, to] as the certificates write it.
Json range_json(int from, int to);

// The region document (kind "region", docs/manual.md "region"): the pairs' counts and polygons,
// their union (r formed with it) with its boundary labelled and its switch points, the pairs that
// meet without area, the growth set, and with `at` the exact verdict there (in I1 × I2).
Json compound_region_json(const ExactScene& sc, const CompoundRegion& r,
                          const std::optional<std::array<Q, 2>>& at = std::nullopt);

}  // namespace scalecert::internal
