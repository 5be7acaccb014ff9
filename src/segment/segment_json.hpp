// A segment in the documents: scalecert curve --segment and query --segment (certificates/FORMAT.md,
// "Segments"): what the segment adds to the curve and to a query answer.
#pragma once
#include "certify/certificate.hpp"
#include "segment/segment.hpp"

namespace scalecert::internal {

// Adds the segment, t1/t2 pieces, the t-plane curve, the contact loci and the hull faces (for
// figures) to a curve document.
void add_segment_json(Json& j, const HullModel& m, const TouchingCurve& c, const Segment& s);
// Adds t1, t2 and the directional gap to a query document.
void add_query_segment_json(Json& j, const Segment& s, const Q& rho1, const Q& rho2);
// |v2 − v1|·g to the nearest double (MPFR at 256 bits, then rounded).
double scaled_length(const Vec3q& v1, const Vec3q& v2, const Q& g);

}  // namespace scalecert::internal
