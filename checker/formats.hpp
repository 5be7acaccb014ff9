// The five kinds of certificate scalecert-check reads, one module each (certificates/FORMAT.md):
//   partition.cpp            "Fields of a partition file", "Why a file that passes proves the partition"
//   query.cpp                a query answer (the end of "Why a file that passes proves the partition")
//   judgements.cpp           "A judgements file" (rounded.cpp: its "Objects with a radius")
//   compound_partition.cpp   "A compound partition"
//   compound_judgements.cpp  "A compound judgements file"
// Each takes the whole file's JSON value, checks every claim (Invalid at the first that fails,
// Unreadable past the work limit), and may set cx.summary.
#pragma once
#include "context.hpp"

#include <array>
#include <string>
#include <vector>

namespace scalecert_check {
struct Scene;
struct Line;

void check_partition(Context& cx, const J& c);
void check_query(Context& cx, const J& c);
void check_judgements(Context& cx, const J& c);
void check_compound_partition(Context& cx, const J& c);
void check_compound_judgements(Context& cx, const J& c);

// The certificate of verdict v (separated, touching or overlapping) at (r1, r2) > 0: a query
// answer's "certificate", which a judgement of a verdict carries too.
void check_verdict(Context& cx, const Scene& sc, const Q& r1, const Q& r2, const std::string& v, const J& cert);

// The overlap region I1 × I2 ∩ {ρ2 >= curve} of a partition, from its verified pieces (rect: the
// rectangle I1 × I2 in written form).
std::vector<P2> overlap_region(const Scene& sc, const std::vector<P2>& rect, const std::vector<Line>& lines,
                               const std::vector<std::array<Q, 2>>& ranges);
}  // namespace scalecert_check
