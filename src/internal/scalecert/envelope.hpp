// Stage 4: the touching curve ρ2 = f(ρ1) = max over contact lines, over all ρ1 ≥ 0, and its
// restriction to I1 with switch points and the growth distance.
#pragma once
#include "scalecert/contact_lines.hpp"

#include <optional>

namespace scalecert::internal {

struct EnvPiece {
    size_t line;                 // representative line (smallest normal among identical lines)
    std::vector<size_t> same;    // every line identical to it (same slope and intercept)
    Q from;                      // left end (0 for the first piece)
    std::optional<Q> to;         // right end; none for the last piece (extends to +∞)
};

struct Envelope {
    std::vector<EnvPiece> pieces;  // in increasing ρ1, covering [0, ∞)
    // Index of the piece whose closed range holds x; at a breakpoint, the piece to its right.
    size_t locate(const Q& x) const;
    Q value(const std::vector<ContactLine>& lines, const Q& x) const;
};

Envelope upper_envelope(const std::vector<ContactLine>& lines);

struct Contact {
    std::vector<int> feat1, feat2;
    std::string label;  // e.g. "VE"
};

struct CurvePiece {
    Q from, to;
    size_t env;  // index into Envelope::pieces
};

struct SwitchPoint {
    Q rho1, rho2;
    size_t left, right;  // indices into Curve::pieces
    Contact contact;
    std::string equation;  // which closed form of the paper's Appendix gives ρ1
};

struct GrowthDistance {
    Q value;
    size_t env;  // envelope piece holding it
    bool in_rectangle;
};

struct Curve {
    Envelope env;
    std::vector<CurvePiece> pieces;  // over I1
    std::vector<SwitchPoint> switches;
    GrowthDistance growth;
};

// The contact at a switch point (ρ1, ρ2) between neighbouring pieces on lines L and R: the
// smallest face of each polyhedron holding the touching set (a vertex or an edge: both planes
// touch, so the touching set lies on their common line).
Contact contact_at(const Model& m, const ContactLine& L, const ContactLine& R, const Q& rho1, const Q& rho2);

Curve build_curve(const Model& m);

}  // namespace scalecert::internal
