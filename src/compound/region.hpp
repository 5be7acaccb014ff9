// Compounds: the overlap region of two objects made of convex parts, all
// parts of an object scaled about the object's one seed, in I1 × I2.
//
// For parts A of object 1 and B of object 2, with d = s2 − s1, hA(n) = max over A of n·(v − s1)
// and hB(n) = max over B of −n·(w − s2): A(ρ1) = s1 + ρ1(A − s1) reaches n·s1 + ρ1 hA(n) along
// n, and B(ρ2) starts at n·s2 − ρ2 hB(n), so the normal n separates them iff
// n·d > ρ1 hA(n) + ρ2 hB(n). For ρ1, ρ2 > 0 the normal fan of ρ1 A ⊕ (−ρ2 B) is that of A ⊕ (−B):
// two convex polytopes are apart iff one of its facet normals separates them. So the pair meets
// exactly on R_AB = {(ρ1, ρ2) : ρ1 hA(n) + ρ2 hB(n) >= n·d for every facet normal n of A ⊕ (−B)},
// a convex polygon; hA and hB may be negative or zero, as the seed need not lie in a part. The
// objects meet where some pair does: on the union of the R_AB, which need not be monotone (two
// parts on either side of a seed move apart as it grows: a band).
#pragma once
#include "geometry/polygon2.hpp"
#include "geometry/polyhedron.hpp"
#include "io/scene.hpp"
#include "numeric/limits.hpp"

#include <optional>
#include <cstdint>

#include <array>
#include <vector>

namespace scalecert::internal {

using Point2q = Pt2;  // (ρ1, ρ2)

// a ρ1 + b ρ2 >= c: where a facet normal n of A ⊕ (−B) does not separate the pair
// (a = hA(n), b = hB(n), c = n·d).
struct HalfPlane {
    Q a, b, c;
    Vec3z normal;
    double ad = 0, bd = 0, cd = 0;  // a, b, c by filter::region_double, for predicate 8
    // The sign of a x + b y − c at (x, y), given also as doubles (xd, yd: region_double, or the
    // doubles themselves when x and y are doubles): predicate 8, exactly when its filter cannot tell.
    int side(const Q& x, const Q& y, double xd, double yd, filter::PredicateStats& st) const {
        return filter::half_plane_side(
            ad, bd, cd, xd, yd, [&] { return sgn(Q(a * x + b * y - c)); }, st);
    }
};

// One part pair's overlap set in the rectangle I1 × I2 (lo, hi: ρ1's and ρ2's ranges): a convex
// polygon, counter-clockwise from its lowest (then leftmost) corner, without repeated or collinear
// corners; empty, a point or a segment where the set is. And every facet normal's half-plane.
// `fence`: constraints that cut the rectangle to exactly the polygon (indices into `constraints`,
// ascending), none of them redundant given the others. So every point of the rectangle outside
// the polygon is separated by the normal of a fence constraint it violates: the pair's
// certificate (region_certificate.hpp).
struct PairRegion {
    std::vector<Point2q> polygon;
    std::vector<HalfPlane> constraints;
    std::vector<size_t> fence;
};
PairRegion pair_region(const Polyhedron& A, const Polyhedron& B, const Vec3q& s1, const Vec3q& s2, const Q lo[2],
                       const Q hi[2], filter::PredicateStats* stats = nullptr);

// The facet normals of A ⊕ (−B) (the Gauss-map overlay of contact_lines.hpp), primitive.
std::vector<Vec3z> minkowski_facet_normals(const Polyhedron& A, const Polyhedron& B);
// Their half-planes for parts A of the object with seed s1 and B of the one with seed s2, in the
// normals' order (a, b, c and their doubles).
std::vector<HalfPlane> pair_constraints(const Polyhedron& A, const Polyhedron& B, const Vec3q& s1, const Vec3q& s2);

// The union of convex polygons with area (CGAL's Boolean set operations on exact rationals):
// its connected pieces, each an outer boundary (counter-clockwise) and its holes (clockwise),
// every vertex list from its lowest, then leftmost, corner; the pieces in that corner's order.
struct RegionPiece {
    std::vector<Point2q> outer;
    std::vector<std::vector<Point2q>> holes;
};
std::vector<RegionPiece> union_of(const std::vector<std::vector<Point2q>>& convex);

// The region of a scene whose objects may be compounds (PolyInput::parts; a plain object is one
// part): every part pair, those whose swept bounding boxes over I1 and I2 are apart pruned before
// any exact work (they cannot meet anywhere in the rectangle), the others' polygons; their union;
// and the growth set, where the objects meet on ρ1 = ρ2: intervals of ρ, each with the pair that
// meets first. Parts in messages: "P1.parts[k]", with the name of a named one (part_label).
// Throws InputError for a flat part.
struct CompoundRegion {
    struct Pair {
        int part1, part2;
        std::vector<Point2q> polygon;        // empty when apart in the rectangle
        std::vector<HalfPlane> constraints;  // every facet normal's half-plane
        std::vector<size_t> fence;           // PairRegion::fence
    };
    std::vector<Polyhedron> parts[2];  // each object's parts (a plain object: itself)
    std::vector<Pair> pairs;           // the built pairs, part1-major
    // For every part pair (part1-major, a byte each): 0 when built, else 1 + 2c + (s > 0) when
    // pruned, c the axis on which the swept boxes are apart and s = +1 when part 1's lies below
    // (normal e_c), −1 when above (normal −e_c).
    std::vector<std::uint8_t> prune;
    std::vector<RegionPiece> region;  // the union of the polygons with area (when formed)
    bool union_skipped = false;       // asked for, but more than kMaxUnionPolygons polygons
    struct Interval {
        Q from, to;
        int part1, part2;  // the pair meeting at `from`
    };
    std::vector<Interval> growth;  // in increasing ρ, disjoint
    long pruned = 0, built = 0;
    filter::PredicateStats predicates;  // half_plane_side: the corners' sides, by stage
};
// Each object's parts as polyhedra (a plain object: itself), appended to parts[i]; InputError
// past kMaxPartPairs and for a flat part ("NAME: P1.parts[k]: ...", or "P1.parts[k] ('foot')").
void build_parts(const ExactScene& sc, const std::string& name, std::vector<Polyhedron> (&parts)[2]);
// Its vertices' least and largest coordinate along each axis.
std::array<std::array<Q, 2>, 3> bounding_box(const Polyhedron& P);

// Throws InputError, before the pair polygons, past the limits below (manual.md "Limits"), for a
// zero-width range (the region is a set of the plane) and for a flat part.
constexpr std::size_t kMaxPartPairs = 10000000;     // part pairs in all (a byte each, a box test each)
constexpr std::size_t kMaxBuiltPairs = 20000;       // pairs whose swept boxes meet (each built exactly)
constexpr double kMaxEdgePairWork = kMaxEdgePairs;  // over the built pairs, Σ edges(A) × edges(B)
// The union (`region`) is formed only when asked and of at most kMaxUnionPolygons polygons with
// area: its cost grows with the crossings of their boundaries, up to the square of their edges
// (1,545 crossing strips took 47 s and 1.7 GB, and more ran out of
// memory inside CGAL). Past the limit `region` stays empty and union_skipped is set.
constexpr std::size_t kMaxUnionPolygons = 1000;
CompoundRegion compound_region(const ExactScene& sc, const std::string& name, bool with_union = true);

// The objects at (ρ1, ρ2) in I1 × I2, exactly: overlapping when some built pair's every half-plane
// holds strictly (their interiors meet: the parts have interiors), touching when some pair's hold
// with equality somewhere and none overlaps, else separated (a pruned pair cannot meet in the
// rectangle). With the first pair that decides it (none when separated).
struct CompoundVerdict {
    Verdict verdict = Verdict::Separated;
    int part1 = -1, part2 = -1;
};
CompoundVerdict compound_verdict(const CompoundRegion& r, const Q& rho1, const Q& rho2);

}  // namespace scalecert::internal
