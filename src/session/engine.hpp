// The one engine interface the front doors hold: the library's Analysis (and so Python), each
// command's handler and golden data ask it for verdicts, documents, claim rules and golden
// answers. Two convex objects are one implementation (the walk or the hull model, chosen by
// Session::plan), objects made of parts another (their region and part-pair judge); open_engine
// chooses. What only one kind has (the convex curve and its segments, the region's polygons) is
// asked for by name and refused by the others with the front door's words. (The audits run each
// kind's own floating-point methods against that kind's exact answers: baselines/.)
#pragma once
#include "certify/claim.hpp"
#include "certify/classify.hpp"
#include "certify/golden.hpp"
#include "session/compound_session.hpp"
#include "session/session.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace scalecert::internal {

class SceneEngine {
  public:
    virtual ~SceneEngine() = default;
    // The scene's geometry checked as this engine will read it, without building the curve
    // (Session::check on two convex objects; parts are checked where their hulls are built).
    virtual void check() = 0;
    // The scene in machine integers where the engine walks (null otherwise): shared with later
    // engines of the same scene.
    virtual std::shared_ptr<const CompactScene> compact() = 0;
    // Builds now what every answer needs (a convex scene's curve), so that its errors come first.
    virtual void prepare() = 0;
    // Two convex objects: the scene has the paper's curve, its switch points and growth distance.
    virtual bool convex() const = 0;
    // The exact verdict at (ρ1, ρ2) > 0.
    virtual Verdict verdict(const Q& rho1, const Q& rho2) = 0;
    // The verdict with its evidence (a plane, a common point) where the engine has them.
    virtual scalecert::QueryResult query(const Q& rho1, const Q& rho2) = 0;
    // scalecert query --json: the verdict's certificate (FORMAT.md: a query, or on parts a
    // compound judgements file of one verdict claim).
    virtual std::string verdict_document(const Q& rho1, const Q& rho2) = 0;
    // scalecert partition: the certified partition of I1 × I2.
    virtual std::string partition_document() = 0;
    // The exact verdicts of doubles' exact values (> 0, finite), on `threads` threads; `source`
    // names the pairs in errors. *counts, when given, gets how many were decided by the filter
    // and how many exactly, where the engine counts them (else it stays empty).
    virtual std::vector<Verdict> classify(const std::vector<double>& rho1, const std::vector<double>& rho2,
                                          unsigned threads, const std::string& source,
                                          std::optional<StageCounts>* counts) = 0;
    // max over P1(ρ1) of n·x and min over P2(ρ2), every part of each (check_plane).
    virtual std::pair<Q, Q> plane_extents(const Vec3q& n, const Q& rho1, const Q& rho2) = 0;
    // The claim rules of this kind of object, at these tolerances (they refer to the engine).
    virtual std::unique_ptr<ClaimRules> rules(const Tolerance& tolerance) = 0;
    // Golden data's answers (golden.hpp): near the curve, or where the region's meeting set ends.
    virtual GoldenAnswers golden(const GoldenPoints& points) = 0;
    // Where the objects meet in I1 × I2, pair polygon by pair polygon (both kinds).
    virtual CompoundSession& region() = 0;
    // What is defined for two convex objects only (the curve, segments, the grid baseline): the
    // session; on other kinds InputError(refusal), the front door's words for what answers instead.
    virtual Session& convex_session(const std::string& refusal) = 0;
    // The public curve over I1 (scalecert.hpp), built once; InputError(refusal) likewise.
    virtual const scalecert::Curve& curve(const std::string& refusal) = 0;
};

// A scene as read, and how its engine is to be made.
struct SceneSource {
    // The scene read exactly; may be null when `compact` holds it (two convex objects read
    // straight into machine integers), and is then made from it when asked for.
    std::shared_ptr<const ExactScene> exact;
    std::shared_ptr<const CompactScene> compact;
    std::string name;  // prefixes the geometric errors ("FILE: P1: ...")
    Engine engine = Engine::Auto;
    // A hull model built elsewhere and shared (the library's Scene builds it once for all its
    // analyses); none: the engine builds its own.
    std::function<std::shared_ptr<const HullModel>()> hull;
    StageClock* clock = nullptr;  // SCALECERT_TIMING laps
};

// The one place that chooses the engine for a scene: objects made of parts get the region's,
// two convex objects the session's (which then chooses the walk or the hull model).
std::unique_ptr<SceneEngine> open_engine(SceneSource source);
// The same for a scene read exactly, its own hull model, the engine chosen as Engine::Auto.
std::unique_ptr<SceneEngine> open_engine(std::shared_ptr<const ExactScene> scene, std::string name);

}  // namespace scalecert::internal
