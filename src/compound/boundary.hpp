// Compounds: the overlap region's boundary, labelled. Each edge of the union's
// rings lies on a side of I1 × I2 or on an edge of some part pair's polygon, whose line is one of
// the pair's half-planes a ρ1 + b ρ2 >= c holding with equality (a = hA(n), b = hB(n), c = n·d):
// there the two parts touch through the contact features that every such normal n picks out. The
// compound's switch points are the ring vertices where that label (the pair, or the pair's tight
// normals: its contact) changes.
//
// Why the labels are right. Along an edge's relative interior the pair's tight normals are those
// whose line holds the edge (a line through an inner point of a polygon edge that bounds a
// half-plane holding the polygon holds the edge). They span the normal cone of the face of
// A(ρ1) ⊕ (−B(ρ2)) that holds the origin in its relative interior; that face is G1 ⊕ (−G2) with
// G1, G2 the faces of the parts that every tight normal picks out (maximisers of n on A, of −n
// on B), and the touching set meets both relative interiors: G1 and G2 are the smallest faces
// holding it (curve/envelope.hpp, piece_contact, makes the same argument on the convex curve). At
// a point the tight normals may span two dimensions (both planes touch: the touching set lies on
// their common line, contact_on_line) or three (a vertex of the sum: vertex against vertex).
#pragma once
#include "compound/region.hpp"
#include "curve/envelope.hpp"

#include <optional>
#include <vector>

namespace scalecert::internal {

// A pair's contact: the smallest faces of its two parts (vertex indices as the parts list their
// points, sorted) that hold the touching set, the label ("FF", "VE", ...) and the tight normals.
struct PairContact {
    size_t pair;  // index into CompoundRegion::pairs
    ContactFeatures contact;
    std::vector<size_t> tight;  // indices into the pair's constraints, ascending
    // Along an edge: the first tight constraint whose line is one (a, b not both 0: a normal
    // whose planes touch at every (ρ1, ρ2), seeds on a face of each part, is tight everywhere
    // and holds no edge), the line that holds the edge.
    size_t line = 0;
};

struct BoundaryEdge {
    Point2q from, to;  // the region on the left
    // On a side of I1 × I2: 0 ρ1 = lo1, 1 ρ1 = hi1, 2 ρ2 = lo2, 3 ρ2 = hi2. Else −1 and `contact`
    // (its constraint `line` holds the edge).
    int bound = -1;
    std::optional<PairContact> contact;
};

struct BoundaryRing {
    size_t piece;                     // index into CompoundRegion::region
    int hole;                         // −1 for the outer ring, else the hole's index
    std::vector<BoundaryEdge> edges;  // from the ring's first vertex, in its order
};

struct CompoundSwitch {
    Point2q at;
    bool pair_change;                   // the pairs on either side differ (else the contact does)
    std::vector<PairContact> contacts;  // every built pair touching at `at`, in pair order
};

struct CompoundBoundary {
    std::vector<BoundaryRing> rings;       // each piece's outer ring, then its holes
    std::vector<CompoundSwitch> switches;  // in ring order
};

// The union's rings (r.region, formed from sc), labelled. Where several pairs' edges hold a piece
// of a ring edge, the first pair (in r.pairs order) labels it.
CompoundBoundary label_boundary(const CompoundRegion& r, const ExactScene& sc);

// The contact of built pair r.pairs[k] at (ρ1, ρ2), where it touches (every half-plane holds, one
// at least with equality); none where it does not touch there.
std::optional<PairContact> pair_contact_at(const CompoundRegion& r, const ExactScene& sc, size_t k, const Point2q& at);

}  // namespace scalecert::internal
