// Stage 4: the touching curve ρ2 = f(ρ1) = max over contact lines, over all ρ1 ≥ 0, and its
// restriction to I1 with switch points and the growth distance. Where the envelope reaches
// ρ2 = 0 (P2(0) is the seed, on P1's boundary) the curve goes on as one line: below ρ2 = 0
// nothing touches, and the envelope there would describe no contact.
#pragma once
#include "curve/contact_lines.hpp"

#include <functional>
#include <optional>

namespace scalecert::internal {

struct EnvPiece {
    size_t line;               // representative line (smallest normal among identical lines)
    std::vector<size_t> same;  // every line identical to it (same slope and intercept)
    Q from;                    // left end (0 for the first piece)
    std::optional<Q> to;       // right end; none for the last piece (extends to +∞)
};

struct Envelope {
    std::vector<EnvPiece> pieces;  // in increasing ρ1, covering [0, ∞); none starts below ρ2 = 0
    // Index of the piece whose closed range holds x; at a breakpoint, the piece to its right.
    size_t locate(const Q& x) const;
    Q value(const std::vector<ContactLine>& lines, const Q& x) const;
};

Envelope upper_envelope(const std::vector<ContactLine>& lines);

struct ContactFeatures {
    std::vector<int> feat1, feat2;
    std::string label;  // e.g. "VE"
};

struct CurvePiece {
    Q from, to;
    size_t env;               // index into Envelope::pieces
    ContactFeatures contact;  // piece_contact of its envelope piece; empty label if ρ2 ≤ 0 all along it
};

struct CurveSwitch {
    Q rho1, rho2;
    size_t left, right;  // indices into TouchingCurve::pieces
    ContactFeatures contact;
    std::string equation;  // which closed form of the paper's Appendix gives ρ1
};

struct Growth {
    Q value;
    size_t env;  // envelope piece holding it
    bool in_rectangle;
};

struct TouchingCurve {
    Envelope env;
    std::vector<CurvePiece> pieces;  // over I1
    std::vector<CurveSwitch> switches;
    Growth growth;
};

// The contact where planes of two independent normals both touch: A[i] the vertices of P_i that
// maximise both (their common face, −n for P2), u the cross product of the normals (the common
// line's direction), scaled(i, k) vertex k of P_i scaled about its seed to its ρ_i.
ContactFeatures contact_on_line(const Vec3z& u, const std::vector<int> A[2],
                                const std::function<Vec3q(int, int)>& scaled);
// The contact at a switch point (ρ1, ρ2) between neighbouring pieces on lines L and R: the
// smallest face of each polyhedron holding the touching set (a vertex or an edge: both planes
// touch, so the touching set lies on their common line).
ContactFeatures contact_at(const Model& m, const ContactLine& L, const ContactLine& R, const Q& rho1, const Q& rho2);

// The contact along an envelope piece: the smallest faces of P1(ρ1) and P2(ρ2) that hold their
// touching set, the same at every inner point of the piece with ρ2 > 0. Every normal whose line is
// the piece's (EnvPiece::same, all of them) touches there, so the touching set T lies in each one's
// maximisers and in their intersections G1, G2 (faces). And T = G1 ∩ G2 meets both relative
// interiors: the face of the Minkowski sum holding the origin in its relative interior is the
// difference of the faces that the normals in its normal cone pick out, i.e. of G2 and G1. So G_i
// is the smallest face holding T. The label follows from the vertex counts of G1 and G2.
ContactFeatures piece_contact(const Model& m, const EnvPiece& e);
// A ρ1 of the curve piece with ρ2 > 0 (the middle of that part): where its contact is witnessed.
// None when ρ2 ≤ 0 all along it (nothing touches there).
std::optional<Q> contact_rho1(const Model& m, const TouchingCurve& c, const CurvePiece& p);

TouchingCurve build_curve(const Model& m);
// Sets c.pieces and c.switches to the curve over [lo, hi] (0 ≤ lo ≤ hi) from c.env: build_curve's
// restriction to I1, and the window a judgement's proof covers (certify/judgements.hpp).
void restrict_curve(const Model& m, TouchingCurve& c, const Q& lo, const Q& hi);

}  // namespace scalecert::internal
