// Stage 2: exact convex polyhedra. Faces are true faces (coplanar hull triangles merged), every
// normal a primitive integer vector, every index an index into the input point list.
#pragma once
#include "numeric/exact.hpp"
#include "numeric/predicates.hpp"
#include "numeric/small_int.hpp"

#include <cstdint>
#include <vector>

namespace scalecert::internal {

struct Face {
    Vec3z normal;            // outward, primitive
    Vec3s normal_s{};        // the same in machine integers, when the polyhedron is small()
    std::vector<int> verts;  // true vertices on the face, counter-clockwise seen from outside, smallest index first
};

struct Edge {
    int a, b;    // vertex indices, a < b
    int f0, f1;  // the two faces that meet along the edge
};

struct Face;
// Where a point lies: side −1 strictly inside, 0 on the boundary (face: one holding it), +1
// outside (face: one whose plane it lies strictly beyond).
struct PointPlace {
    int side = -1;
    const Face* face = nullptr;
};

struct Polyhedron {
    std::vector<Vec3q> points;  // input points, as given
    std::vector<int> vertices;  // indices of the extreme points (first copy of duplicates)
    std::vector<Face> faces;
    std::vector<Edge> edges;
    std::vector<std::vector<int>> adj;        // per input index: adjacent vertices (empty for non-vertices)
    std::vector<Vec3z> ipts;                  // points × scale: integers, same order of n·x as points
    Z scale;                                  // lcm of the denominators of the points
    std::vector<Vec3s> ipts_s;                // ipts in machine integers when all |ipts| < 2^29, else empty
    std::vector<std::array<double, 3>> dpts;  // ipts as doubles: a filter for comparisons only
    // Statistics of the predicates this polyhedron decides (support_cmp: argmax's and climb's
    // comparisons, by stage); climb and argmax are called from one thread at a time.
    mutable filter::PredicateStats predicates;
    std::vector<int> start_table;  // cube-map cells (6 × G × G) -> a vertex near the argmax
    int start_g = 0;               // G

    // The vertices maximising n·x (a vertex, an edge's two ends or a face's vertices), sorted,
    // and the maximum value. Hill-climbs the vertex graph, then collects the tied face.
    std::vector<int> argmax(const Vec3z& n, Q* value = nullptr, Z* scaled_value = nullptr) const;
    int start_vertex(
        const std::array<double, 3>& n) const;  // a good vertex to start climbing from (doubles; a hint only)
    int climb(const Vec3z& n) const;            // a vertex maximising n·x (exact decisions, filtered)
    int climb(const Vec3s& n) const;            // the same for |n| < 2^62 on a small() polyhedron
    bool small() const { return !ipts_s.empty(); }
    Q support(const Vec3z& n) const;  // max over vertices of n·x
    bool strictly_inside(const Vec3q& p) const;
    PointPlace place(const Vec3q& p) const;  // exact, in 128-bit integers while they fit
    // For p strictly inside: weights w > 0 on vertices spanning 3 dimensions, Σw = 1, Σ w·v = p
    // (a proof that p is interior), sorted by vertex. From the centroid c of four affinely
    // independent vertices, the ray through p leaves at a point q of some face, a convex
    // combination of one of its fan triangles, and p lies strictly between c and q.
    std::vector<std::pair<int, Q>> interior_weights(const Vec3q& p) const;
};

// Triangles of the convex hull of integer points (CGAL), as index triples oriented outward.
// `given` holds the same points divided by one positive scale (the points as the user wrote
// them). Precondition: pts has 4 affinely independent points.
std::vector<std::array<int, 3>> hull_triangles(const std::vector<Vec3z>& pts, const std::vector<Vec3q>& given);

// Supporting planes of the hull of at most kBrutePoints small integer points, found by testing
// every triple (no CGAL): each with its outward primitive normal and the indices on it, sorted.
// Duplicate points count once (the first copy). Precondition: the points span 3 dimensions.
constexpr size_t kBrutePoints = 16;
struct HullPlane {
    Vec3s normal;
    std::vector<int> on;
};
std::vector<HullPlane> hull_planes_brute(const std::vector<Vec3s>& pts);

// Builds the exact polyhedron. Throws InputError (prefixed with `name`) when the points do not
// span 3 dimensions.
Polyhedron build_polyhedron(const std::vector<Vec3q>& pts, const std::string& name);

}  // namespace scalecert::internal
