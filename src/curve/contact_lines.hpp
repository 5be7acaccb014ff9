// Stage 3: the contact lines. One line per facet normal n of Q1 ⊕ (−Q2) (faces of P1, faces of P2,
// crossing Gauss-map arcs of edge pairs): the pair is separated by the plane of normal n iff
//   n·d > ρ1·h1(n) + ρ2·h2(n),  i.e.  ρ2 < (n·d − ρ1·h1)/h2  =  slope·ρ1 + intercept.
#pragma once
#include "geometry/bodies.hpp"
#include "io/int_points.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace scalecert::internal {

class PointSets;  // geometry/point_sets.hpp

struct ContactLine {
    Vec3z normal;                   // primitive, pointing from P1 towards P2
    Q h1, h2, nd;                   // h1 = max n·(v−s1), h2 = max −n·(w−s2), nd = n·d; h1, h2 > 0
    Q slope, intercept;             // slope = −h1/h2 < 0, intercept = nd/h2
    std::vector<int> feat1, feat2;  // contact features: maximisers of n on P1, of −n on P2
    std::string contact;            // "FV", "VF", "EE", "FF", "FE", "EF"
    Q at(const Q& rho1) const { return slope * rho1 + intercept; }
};

// "V", "E" or "F" for a feature of 1, 2 or more vertices.
char feature_letter(size_t n_vertices);

struct LineStats {
    std::uint64_t face_normals = 0, edge_pairs_tested = 0, arc_crossings = 0, distinct_normals = 0;
    std::uint64_t dominated_lines = 0;  // facet normals whose lines were certainly dominated
    filter::PredicateStats predicates;  // arc_side (Gauss-arc sign tests) and dominated_line, by stage
};

// What the scan path did (scan.hpp): engine statistics, reported in its curve's "model".
struct ScanStats {
    std::uint64_t support_queries = 0;  // exact support queries
    // scan_support: points whose double value was formed and ruled out (filtered), candidates
    // then formed exactly (exact)
    filter::PredicateStats predicates;
    std::uint64_t lp_solves = 0, lp_rows = 0;  // the start: exact LPs and their final size
    std::uint64_t gift_wrap_steps = 0, pieces_walked = 0;
};

// A curve's model: the contact lines over the two bodies (on the scan path the bodies' polyhedra
// are empty: its points are in `scan`).
struct Model : Bodies {
    std::vector<ContactLine> lines;  // sorted by normal
    LineStats stats;
    // The scan path's points (scan.hpp); null on the hull path.
    std::shared_ptr<const CompactScene> scan;
    ScanStats scan_stats;
    // The scan path's points behind the walk's trees, kept for the measures (CloudPoints).
    std::shared_ptr<const PointSets> points;
    // The scan path's proof covers ρ1 in [walk_lo, walk_hi] (none: unbounded): there the walked
    // lines' envelope is the whole curve. Outside it, it is only a lower bound.
    Q walk_lo;
    std::optional<Q> walk_hi;
    // Point k of polyhedron i as given, on either path.
    Vec3q pt(int i, size_t k) const { return scan ? scan->P[i].point(k) : P[i].points[k]; }
};

// The two engines' models, each accepted only where it is valid. What both hold (lines, seeds,
// the scene's ranges) serves the curve, queries, the partition and the documents, which take a
// Model. The hull model (build_model) also holds the exact polyhedra and every contact line:
// what needs them (planes, distances, depths, segments, facet normals) takes a HullModel. The
// walk's model (scan_model) has no polyhedra: its points are in `scan`.
struct HullModel : Model {};
struct WalkModel : Model {};

// The indices of the lines y = a[i]·x + b[i] not certainly dominated by another (larger slope and
// larger intercept: strictly below it for every x ≥ 0). a, b approximate exact values to within
// 10^-14 relative (or are not finite); a line is dropped only when margins of 10^-12 prove it.
std::vector<size_t> undominated(const std::vector<double>& a, const std::vector<double>& b);

// The exact polyhedra and the seeds of a scene, checked as build_model checks them, with no contact
// line: what membership, distances and depths need (Model::P built, Model::lines empty). Cheap
// next to the lines, whose count can grow with the product of the two polyhedra's edges.
Model build_hulls(const ExactScene& scene);
Model build_hulls(const ExactScene& scene, const std::string& name);  // errors prefixed by `name`
// The hull model from those: every contact line added.
HullModel build_model(Model&& hulls);

// Builds the exact polyhedra, checks the seeds, and enumerates the contact lines: every facet
// normal of the Minkowski sum is found; lines certainly dominated (never on the touching curve,
// never deciding a query) are dropped before their exact values are computed.
HullModel build_model(const ExactScene& scene);
// The same, with its errors (flat points, a seed outside) prefixed by `name` ("FILE: ...").
HullModel build_model(const ExactScene& scene, const std::string& name);

// Every facet normal of Q1 ⊕ (−Q2), primitive and sorted, the dominated ones included (Model::lines
// keeps only those that can be on the curve). Recomputed on each call.
std::vector<Vec3z> all_facet_normals(const HullModel& m);
// The same for two polyhedra held elsewhere (a compound's part pair: no copy).
std::vector<Vec3z> all_facet_normals(const Polyhedron& P1, const Polyhedron& P2);

// The line of normal n (any nonzero direction, not necessarily a facet normal of the sum):
// support values, features and the line, computed by scanning the polyhedra.
ContactLine line_for_normal(const HullModel& m, const Vec3z& n);
// The line of normal n from its contact features (maximisers, sorted) and the maxima of n·x over
// P1's and of −n·x over P2's points times their scales.
ContactLine make_line(const Model& m, const Vec3z& n, std::vector<int> feat1, std::vector<int> feat2, const Z& sup1,
                      const Z& sup2);

}  // namespace scalecert::internal
