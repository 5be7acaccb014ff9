// Floating-point baselines, behind one interface: classify (ρ1, ρ2), and where a method can,
// estimate the touching curve. They read the scene as doubles (the nearest double to each exact
// coordinate), as a floating-point program would. Nothing here is on the certified path.
#pragma once
#include "campaign/audit_table.hpp"
#include "curve/contact_lines.hpp"

#include <cmath>
#include <array>
#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace scalecert::internal::fp {

using D3 = std::array<double, 3>;
struct Polytope {
    std::vector<D3> pts;
    D3 seed;
};
struct FpScene {
    Polytope P[2];
    double lo[2], hi[2];
    MethodSettings settings;  // the methods' own settings, which each reads where it runs
};
FpScene to_fp(const ExactScene& s);

inline bool finite(const D3& p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }
// The largest |coordinate| of the points scaled about `seed` by up to `hi`, or `so_far` if larger.
inline double scaled_extent(const std::vector<D3>& pts, const D3& seed, double hi, double so_far = 0) {
    for (const D3& p : pts)
        for (int k = 0; k < 3; ++k) so_far = std::max(so_far, std::fabs(seed[k]) + hi * std::fabs(p[k] - seed[k]));
    return so_far;
}

// What a method measures besides its verdict, as its API returns it: the distance between
// separated bodies (with closest points where it gives them), or the penetration depth of
// overlapping ones with the direction in which translating P2 by the depth makes them touch.
struct Measure {
    double value = 0;
    bool depth = false;  // a penetration depth, else a distance
    std::optional<D3> direction;
    std::optional<std::array<D3, 2>> closest;  // on P1, on P2
};

// Objects made of parts: a contact the method reports on one part pair (FCL's and Bullet's
// compound queries report one or more per colliding pair): the part of P1 and of P2, the depth,
// and the direction in which translating P2's part by the depth makes the two parts touch.
struct PartContact {
    int part1 = 0, part2 = 0;
    double depth = 0;
    D3 direction{};
};

// The deepest of the contacts of each part pair, in the pairs' order.
inline std::vector<PartContact> deepest_per_pair(const std::vector<PartContact>& all) {
    std::map<std::pair<int, int>, PartContact> deepest;
    for (const PartContact& c : all) {
        auto [at, fresh] = deepest.emplace(std::make_pair(c.part1, c.part2), c);
        if (!fresh && c.depth > at->second.depth) at->second = c;
    }
    std::vector<PartContact> out;
    for (const auto& kv : deepest) out.push_back(kv.second);
    return out;
}

// classify: +1 separated, 0 touching (only methods that can say so), −1 intersecting (a collision
// query's "colliding": overlapping or touching), −2 strictly overlapping (only a program's own
// claims say so): AuditRow::Said.
class Method {
  public:
    virtual ~Method() = default;
    virtual std::string name() const = 0;
    virtual int classify(double r1, double r2) const = 0;
    // The distance (separated = true) or the penetration depth, where the method's API gives it.
    virtual std::optional<Measure> measure(double /*r1*/, double /*r2*/, bool /*separated*/) const {
        return std::nullopt;
    }
    // Objects made of parts: the contacts the method's collision query reports, the deepest per
    // part pair; none where its API gives none.
    virtual std::vector<PartContact> contacts(double /*r1*/, double /*r2*/) const { return {}; }
};

// libccd's GJK and MPR on the two scaled vertex sets (support function per polytope).
std::unique_ptr<Method> make_libccd_gjk(const FpScene& s);
std::unique_ptr<Method> make_libccd_mpr(const FpScene& s);
// scalecert's own contact lines evaluated in plain double, no filter: h1, h2 recomputed in
// double from the double vertices for each of the engine's normals.
std::unique_ptr<Method> make_double_envelope(const Model& m, const FpScene& s);

// FCL's collide() on Convex shapes (GJK via libccd, or FCL's own GJK), and Bullet's
// btGjkEpaSolver2::Distance on btConvexHullShape (collision margin 0).
std::unique_ptr<Method> make_fcl(const Model& m, const FpScene& s, bool libccd);
std::unique_ptr<Method> make_bullet(const FpScene& s);

// The paper's node test: any pair of triangulated faces intersecting (double precision).
std::unique_ptr<Method> make_paper_tritri(const Model& m, const FpScene& s);
bool triangles_intersect(const std::array<D3, 3>& a, const std::array<D3, 3>& b);

// The method of that name (libccd-gjk, libccd-mpr, fcl-gjk-libccd, fcl-gjk-indep,
// bullet-gjk-epa, paper-tritri, double-envelope); none for an unknown name.
std::unique_ptr<Method> make_method(const std::string& name, const Model& m, const FpScene& s);
// Those names, in that order.
std::vector<std::string> method_names();

// ---- Objects made of convex parts ---------------------------------------------------------------
// Each object's parts as doubles (the nearest double to each exact coordinate), each part with its
// exact hull's faces (indices into its own points, as given), all scaled about the object's seed.
// A plain (convex) object is one part.
struct CompoundFp {
    struct Part {
        std::vector<D3> pts;
        std::vector<std::vector<int>> faces;
    };
    std::vector<Part> parts[2];
    D3 seed[2];
    double lo[2], hi[2];
    MethodSettings settings;  // as FpScene's
};
// The compound methods (their verdicts: the objects collide when any part pair does):
//   bullet-compound      Bullet's btCompoundShape of btConvexHullShape children (margin 0), each
//                        child's local scaling set to ρ about the seed, queried by
//                        btCollisionWorld::contactPairTest: a contact at distance < 0 overlapping,
//                        = 0 touching, none (or > 0) separated. Distance: btGjkEpaSolver2::Distance,
//                        the least over the child pairs.
//   fcl-compound-libccd, fcl-compound-indep
//                        FCL's fcl::Convex parts in two DynamicAABBTreeCollisionManagers, one per
//                        object, rebuilt at each (ρ1, ρ2); manager1->collide(manager2) with the
//                        default callback (libccd's GJK or FCL's own); distance: manager1->distance.
//   libccd-gjk-parts     libccd's GJK looped over every part pair, stopping at the first that meets.
std::unique_ptr<Method> make_compound_method(const std::string& name, const CompoundFp& s);
std::vector<std::string> compound_method_names();
// The settings a method of that name runs with (MethodSettings, by option name): its rows record them.
// Without `measures` (audit --no-measures, the grid) those only its distances and depths read (libccd's
// EPA tolerance, MPR's iteration limit, FCL's distance tolerance) are left out.
std::vector<std::pair<std::string, double>> settings_of(const std::string& method, const MethodSettings& s,
                                                        bool measures = true);
// The FCL and Bullet ones, from the module (fcl_bullet.cpp): kind 0 Bullet, 1 FCL with libccd's
// GJK, 2 FCL with its own GJK.
std::unique_ptr<Method> make_fcl_bullet_compound(const CompoundFp& s, int kind);

// ---- Objects with a radius -------------------------------------------------------------------
// Each object as doubles (CLAIMS.md, "Objects with a radius"): the hull of its points, scaled about
// its seed by ρ, with every point within ρr of it. Its shape says how the libraries that have one
// hold it: a sphere (its points one point), a capsule (its points on one line: the extreme two its
// ends), or a hull (any other, with or without a radius). Shape and ends are decided exactly.
struct RoundedFp {
    enum class Shape { Sphere, Capsule, Hull };
    struct Object {
        std::vector<D3> pts;  // the nearest doubles
        D3 seed;
        double radius = 0;     // r's nearest double
        bool rounded = false;  // r > 0 (decided exactly)
        Shape shape = Shape::Hull;
        std::array<int, 2> ends{};  // a sphere's point (both), a capsule's two ends
        // A hull of points spanning 3 dimensions: its exact hull's faces (indices into pts).
        std::vector<std::vector<int>> faces;
    };
    Object P[2];
    double lo[2], hi[2];
    MethodSettings settings;
};
// libccd's GJK and MPR on the objects, their support inflated as the engines collide them: the
// scaled hull's support point plus ρr·d/|d| along the direction d asked (libccd's support callback).
std::unique_ptr<Method> make_rounded_libccd(const RoundedFp& s, bool mpr);
// The FCL and Bullet ones, from the module (fcl_bullet.cpp): kind 0 Bullet, 1 FCL with libccd's
// GJK, 2 FCL with its own GJK. FCL only where each object is a sphere, a capsule or a hull
// without a radius (rounded_fcl_why_not).
std::unique_ptr<Method> make_rounded_fcl_bullet(const RoundedFp& s, int kind);
// Why FCL cannot hold the objects ("" when it can): it has no convex shape with a radius.
std::string rounded_fcl_why_not(const RoundedFp& s);

// The paper's pipeline: classify an n × n grid over I1 × I2; in each column, the touching ρ2 is
// estimated by `bisections` rounds of bisection between the last separated and the first
// overlapping node, repeated `repeats` times from jittered brackets and averaged (Section 3.2).
// With `exhaustive`, every node is classified, as in the paper's exhaustive search (Section 2.3.2);
// without, a column stops at its first overlapping node (the region above the curve overlaps,
// so the estimates are the same; only the cost differs).
struct GridCurve {
    std::vector<double> rho1, rho2;  // one estimate per column where the column changes state
    long classifications = 0;
};
GridCurve grid_search(const Method& method, const FpScene& s, int n, int bisections = 0, int repeats = 1,
                      bool exhaustive = false);

}  // namespace scalecert::internal::fp
