// Objects made of parts with radii (CLAIMS.md, "Objects with a radius", "Parts with radii"): part
// k of object i is every point within ρ·r_k of its hull scaled about the object's seed, and the
// object is the union of its parts (a convex object with a radius is one part). A part pair is
// judged as two objects with a radius (rounded.hpp); the objects
//   - overlap when some pair overlaps, touch when none does and some pair touches, else are apart;
//   - are as far apart as their nearest pair (√E − R least over the pairs, compared exactly).
// A pair whose boxes (each part's box widened by ρr) are apart along an axis, by a double
// computation whose rounding error is bounded, is apart; only the others are judged exactly.
// Every judgement may be asked at poses of the objects (each a [R | t] moving its parts and its
// seed): the parts' points are moved exactly where they are read (PosedPoints), their boxes in
// doubles with the error bounded.
#pragma once
#include "certify/claim.hpp"
#include "certify/rounded.hpp"

#include <memory>

namespace scalecert::internal {

// At most this many part pairs judged exactly in one judgement (their widened boxes meet): past
// it the judgement is refused with one line (docs/manual.md, "Limits").
constexpr long kMaxExactPartPairs = 100000;
// At most this many points in all in the part pairs one judgement judges exactly (each exact pair
// reads its two parts' points, a GJK's scans of them).
constexpr double kMaxExactWork = 5e7;
// At most this many part pairs judged exactly over one run of certify-fp (a rules object).
constexpr long kMaxExactPartPairsInAll = 1000000;

class RoundedParts {
  public:
    // Builds every part (InputError after `name` for a flat part without a radius).
    RoundedParts(const ExactScene& sc, const std::string& name);
    const ExactScene& scene() const { return sc_; }
    const std::string& name() const { return name_; }
    size_t parts(int i) const { return body_[i].size(); }
    const Q& radius(int i, size_t k) const { return radius_[i][k]; }
    // Parts a of P1 and b of P2 as two objects with a radius.
    std::shared_ptr<const RoundedPoints> pair(int a, int b) const;
    // The two parts as a scene of two objects with a radius (their points, seeds and radii).
    ExactScene pair_scene(int a, int b) const;

    using Poses = std::array<std::optional<Pose>, 2>;

    // A pair's hulls' measure and the pair's state at (ρ1, ρ2).
    struct PairState {
        MeasuredDepth hulls;
        Q R;  // ρ1 r_a + ρ2 r_b
        Verdict verdict = Verdict::Separated;
    };
    PairState pair_state(int a, int b, const Q& rho1, const Q& rho2, const Poses& pose = {});

    // The objects' verdict and the pair deciding it (−1, −1 when separated).
    struct Decided {
        Verdict verdict = Verdict::Separated;
        int a = -1, b = -1;
    };
    Decided verdict(const Q& rho1, const Q& rho2, const Poses& pose = {});

    // The objects' distance: the least over the pairs of s·√E − R, the pair's hulls' s and E
    // (hull_signed) and R; the pair attaining it. When the objects meet it is a pair that meets
    // (s√E − R ≤ 0), and the distance is 0.
    struct Nearest {
        int a = -1, b = -1;
        PairState state;
    };
    Nearest nearest(const Q& rho1, const Q& rho2, const Poses& pose = {});

    // The first part of object i within ρ·r_k of x (or within abs more, `near`), −1 for none.
    int locate(int i, const Q& rho, const Vec3q& x, const Q& abs, bool* near, const Poses& pose = {}) const;
    // Part k of object i's box at ρ (at the poses), widened by ρ·r_k: lo[3], hi[3], exact.
    std::array<Q, 6> widened_box(int i, size_t k, const Q& rho, const Poses& pose = {}) const;
    // Part k of object i's hull's extent along n at ρ: max n·x for P1, min for P2.
    Q extent(int i, size_t k, const Vec3q& n, const Q& rho, const Poses& pose = {}) const;

    // A judgement begins: its limits (kMaxExactPartPairs, kMaxExactWork) count from here.
    void start_judgement();
    // A run of claims begins (a rules object): at most kMaxExactPartPairsInAll exact pairs in it.
    void start_run() { run_left_ = kMaxExactPartPairsInAll; }
    void end_run() { run_left_ = -1; }

    // Pairs decided by their boxes, and judged exactly.
    struct Counts {
        long boxed = 0, exact = 0;
    };
    Counts counts() const { return counts_; }

  private:
    ExactScene sc_;
    std::string name_;
    std::vector<std::shared_ptr<const RoundedBody>> body_[2];
    std::vector<Q> radius_[2];
    // The objects in doubles: each part's box (lo[3], hi[3] of its points), its radius and, per
    // axis, a magnitude m such that the box's ends are within 10^-14·m of the exact box's or
    // outside it; the seeds, likewise with magnitudes.
    struct Frame {
        std::vector<std::array<double, 10>> box[2];
        double seed[2][3], seed_mag[2][3];
        // Every part's points in doubles (part k's from off[k] to off[k + 1]), and a magnitude
        // that each coordinate of each is within 10^-14 of, relatively, or below.
        std::vector<D3> pts[2];
        std::vector<size_t> off[2];
        double pts_mag[2] = {0, 0};
        bool safe = true;  // every input (and ρ) 0 or a double within [2^-500, 2^500]: else no filter decides
    };
    Frame base_;
    Frame frame(const Poses& pose) const;  // base_ moved by the poses
    Counts counts_;
    long exact_in_call_ = 0;
    double work_in_call_ = 0;
    long run_left_ = -1;  // exact pairs left in this run (−1: no run's limit)
    // Whether the widened boxes of parts a and b at (ρ1, ρ2) are apart along an axis (proved: the
    // gap in doubles exceeds its rounding error bound); `gap`, when given, gets a lower bound on
    // their Euclidean gap, so on the pair's distance.
    static bool boxes_apart(const Frame& F, int a, int b, double r1, double r2, double* gap = nullptr);
    // Bounds on the pair's distance along the direction u between its boxes' centres, in doubles
    // with their error bounded: `lower` (> 0: the pair is apart) from the parts' supports along u,
    // `upper` from the two points attaining them. −∞ and +∞ where the doubles cannot tell.
    struct Bounds {
        double lower = -INFINITY, upper = INFINITY;
    };
    static Bounds support_bounds(const Frame& F, int a, int b, double r1, double r2);
    void count_exact(int a, int b);  // InputError past the limits above
    // Whether the supports of parts a and b may be scanned: at most kMaxScannedPoints points in one
    // judgement (past it, pairs the boxes cannot part are judged exactly).
    static constexpr size_t kMaxScannedPoints = 50000000;
    size_t scanned_ = 0;
    bool scan(const Frame& F, int a, int b);
};

// The rules on objects made of parts with radii: verdict, separating_plane, witness_point and
// distance on the objects; penetration_depth and signed_distance on one part pair (`parts`), by
// the rules of two objects with a radius.
class RoundedPartsRules final : public ClaimRules {
  public:
    RoundedPartsRules(std::shared_ptr<RoundedParts> parts, const Tolerance& tolerance);
    ~RoundedPartsRules() override;
    Judged judge(const TypedClaim& c, Proof* proof = nullptr) override;
    const ExactScene* parts() const override { return &parts_->scene(); }
    std::optional<std::array<int, 2>> part_pair(const std::optional<std::array<int, 2>>& given,
                                                const std::string& where) const override;
    std::string refusal(ClaimType t) const override;
    std::string certificate(Json entries) const override;

  private:
    std::shared_ptr<RoundedParts> parts_;
};

}  // namespace scalecert::internal
