// Judgements on two compounds at one scaling pair: the exact verdict, the
// distance (the least over the part pairs), a point's membership and a plane's extents, each at
// any (ρ1, ρ2) > 0 (inside I1 × I2 or not) and each with its proof for scalecert-check
// (certificates/FORMAT.md, "A compound judgements file").
//
// Parts A of object 1 and B of object 2 scale about their object's seed. At one (ρ1, ρ2) a pair is
//   - apart when its scaled bounding boxes are apart along an axis (exact; that axis separates),
//   - else judged by the facet normals n of A ⊕ (−B): the least of ρ1 hA(n) + ρ2 hB(n) − n·d is
//     < 0 (separated by n), 0 (touching: n separates weakly) or > 0 (overlapping: the interiors
//     meet), as in region.hpp.
// The objects overlap when some pair does (the union's interiors meet iff two parts' interiors
// do: an open set meets the parts' boundaries in a set of measure zero), touch when no pair
// overlaps and some pair meets, else are separated.
#pragma once
#include "certify/certificate.hpp"
#include "certify/query.hpp"
#include "compound/region.hpp"
#include "geometry/measures.hpp"

#include <map>
#include <memory>
#include <optional>

namespace scalecert::internal {

// A common point of A(ρ1) and B(ρ2), parts of the objects with seeds s1 and s2, weights indexed
// into each part's own point list: exact elimination on a double GJK's final simplex, else an
// exact LP over the few vertices it names, else over all the parts' vertices (counted in
// `fallbacks`). The exact stages decide; GJK only proposes. Reads the parts only (no support
// query), so threads may share them.
Witness pair_common_point(const Polyhedron& A, const Polyhedron& B, const Vec3q& s1, const Vec3q& s2, const Q& rho1,
                          const Q& rho2, long& fallbacks);
// The same with the two parts and the seeds in hm.
Witness pair_common_point(const HullModel& hm, const Q& rho1, const Q& rho2, long& fallbacks);

class ScaledParts;  // one object's parts' boxes at one ρ: ends enclosed in doubles, exact on demand

// At most this many blocks in all the proofs of one run (about 100 bytes each in the file): past
// it certify-fp --certificate is refused with one line (docs/manual.md, "Limits").
constexpr double kMaxCertificateBlocks = 1e6;

class CompoundJudge {
  public:
    // Builds every part's hull (InputError for a flat part, named "NAME: P1.parts[k]").
    CompoundJudge(const ExactScene& sc, const std::string& name);
    ~CompoundJudge();
    const ExactScene& scene() const { return sc_; }
    size_t parts(int i) const { return parts_[i].size(); }
    const Polyhedron& part(int i, size_t k) const { return parts_[i][k]; }

    // The exact verdict and the deciding pair (−1 when separated). With
    // `proof`: {"verdict", and by verdict "blocks" (separated, touching), "pair" and "witness"
    // (touching: a common point of that pair) or "pair" and "interior" (overlapping: a point
    // inside both parts, every listed weight > 0 on points spanning 3 dimensions)}.
    CompoundVerdict verdict(const Q& rho1, const Q& rho2, Json* proof = nullptr);

    // The exact squared distance between the objects (the least over the part pairs; 0 when they
    // meet) with closest points p ∈ P1(ρ1), q ∈ P2(ρ2) and their parts. With `proof`: {"squared",
    // "pair", "P1", "P2" (the closest points' weights in their parts), and when squared > 0
    // "apart": blocks whose normals u each hold gap(u)² ≥ squared·|u|² over the block}.
    struct Distance {
        Q squared;
        Vec3q p1, p2;
        int part1 = -1, part2 = -1;
    };
    Distance distance(const Q& rho1, const Q& rho2, Json* proof = nullptr);

    // Is x in object i scaled by ρ? The first part holding it (−1 if none). With `proof`:
    // {"part", "in": weights} or {"out": [a normal per part, whose plane x lies beyond]}.
    int locate(int i, const Q& rho, const Vec3q& x, Json* proof = nullptr) const;
    // For x in no part: the first part within `abs` (> 0) of it (−1 if none). With `proof`:
    // {"part", "near": weights of that part's point nearest x} or {"out": [a normal per part,
    // along which x lies more than abs beyond it]} (judgements.hpp, near_proof).
    int near(int i, const Q& rho, const Vec3q& x, const Q& abs, Json* proof = nullptr) const;

    // The depth of parts a of P1 and b of P2 at (ρ1, ρ2), as for two convex objects (measures.hpp,
    // measured_depth: the parts scaled about their objects' seeds). With `proof`: depth_proof's
    // (judgements.hpp), over the two parts' own points.
    MeasuredDepth pair_depth(int a, int b, const Q& rho1, const Q& rho2, Json* proof = nullptr);
    // The squared directional depth of that pair along n (directional_depth_squared).
    Q pair_directional_depth(int a, int b, const Vec3q& n, const Q& rho1, const Q& rho2);

    // max over P1(ρ1) of n·x and min over P2(ρ2) of n·x: over every part's vertices.
    std::pair<Q, Q> plane_extents(const Vec3q& n, const Q& rho1, const Q& rho2) const;

    // Statistics: pairs judged by their boxes, by their facet normals, exact distances; box
    // comparisons (one axis of two boxes, in doubles, exactly when they cannot tell, or one pair's
    // gap in doubles) and the slabs of a double GJK's direction tried on a pair (distances).
    struct Counts {
        long boxed = 0, judged = 0, distances = 0, box_comparisons = 0, slabs = 0;
    };
    Counts counts() const { return counts_; }
    // A budget on the work from here on: past `judgements` more pairs judged by their facet
    // normals or tried with a slab (judged + slabs), `distances` more exact distances, or
    // `comparisons` more box comparisons, the judgement in progress throws InputError(message).
    void set_budget(long judgements, long distances, long comparisons, std::string message);
    void clear_budget() { budget_.reset(); }

  private:
    using Box = std::array<std::array<Q, 2>, 3>;
    struct PairCache;
    friend class ScaledParts;
    ExactScene sc_;
    std::string name_;
    std::vector<Polyhedron> parts_[2];
    std::vector<Box> unit_[2];  // each part's own box (unscaled), and last the box of them all
    std::vector<std::array<std::array<double, 2>, 3>> unit_d_[2];  // their ends by region_double
    double seed_d_[2][3];                                          // the seeds by region_double
    Vec3q d_;                                                      // s2 − s1
    filter::PredicateStats predicates_;                            // half_plane_side: the pairs' constraints
    std::map<std::pair<int, int>, std::unique_ptr<PairCache>> cache_;
    double edge_work_ = 0;  // over the pairs judged exactly: Σ edges(A) × edges(B), within kMaxEdgePairWork
    size_t blocks_ = 0;     // blocks written into proofs so far
    void check_blocks(size_t more) const;  // InputError past kMaxCertificateBlocks
    Counts counts_;
    std::optional<std::array<long, 3>> budget_;  // the most judged + slabs, distances, box comparisons
    std::string budget_message_;
    void check_budget() const;  // InputError past the budget

    Box scaled_box(int i, size_t k, const Q& rho) const;  // k = parts(i): the box of them all
    PairCache& pair(int a, int b);
    // −1 separated (strictly), 0 touching, +1 overlapping, with a normal for ≤ 0.
    int pair_sign(int a, int b, const Q& rho1, const Q& rho2, ScaledParts& X, ScaledParts& Y, int* code, Vec3q* normal,
                  int prefer = -1);
    // Does the slab of a double GJK's direction between parts a and b, rounded to an integer
    // normal N and proved exactly, hold gap(N) > 0 and gap(N)² >= E·|N|²? N then in `normal`.
    bool slab_at_least(int a, int b, const Q& rho1, const Q& rho2, const Q& E, Vec3z* normal);
};

}  // namespace scalecert::internal
