// The one orchestration layer: a scene as read (by the strict reader, or in machine integers by
// the compact one), the engine chosen in one place, the hull model built at most once, the curve
// cached. The command's handlers and the library's Analysis (and so Python) go through it.
//
// Engines. The walk (scan.hpp) finds the curve's lines without a hull, and proves the curve over
// a range of ρ1 that holds I1 and the growth distance; where it meets what it does not handle it
// hands over to the hull model, and the reason is kept. The hull model (polyhedra, every contact
// line) serves what needs all vertices or the whole curve: certificates, partitions, distances,
// depths, planes, and verdicts outside the walked range.
#pragma once
#include "certify/claims.hpp"
#include "certify/query.hpp"
#include "curve/scan.hpp"
#include "numeric/timing.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace scalecert::internal {

// Which engine builds the curve: Auto takes the walk when walk_by_default (scan.hpp: from 2,000
// points, both polyhedra together, or 250,000 as their product) and the scene is held in
// integers; Scan always tries it first, Hull never.
enum class Engine { Auto, Scan, Hull };

class Session {
  public:
    // `name` prefixes the hull model's geometric errors ("FILE: P1: ..."). A compact scene may be
    // null only with the strict one given; given both, they hold the same scene (the compact one
    // as plan() would make it, e.g. another session's compact_scene()).
    Session(ExactScene scene, std::string name, Engine engine = Engine::Auto);
    Session(std::shared_ptr<const CompactScene> scene, std::string name, Engine engine = Engine::Auto);
    Session(std::shared_ptr<const ExactScene> scene, std::shared_ptr<const CompactScene> compact, std::string name,
            Engine engine = Engine::Auto);
    ~Session();
    // Not copied nor moved: its claim models refer to it.
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;
    // Laps for SCALECERT_TIMING (optional; must outlive the session's work).
    void set_clock(StageClock* clock) { clock_ = clock; }
    // A hull model built elsewhere and shared (the library's Scene builds it once for all its
    // analyses); by default the session builds its own.
    void set_hull_source(std::function<std::shared_ptr<const HullModel>()> source) { hull_source_ = std::move(source); }

    // The curve and the model it came from: the walk's, or the hull model's.
    const TouchingCurve& curve();
    const Model& curve_model();
    bool walked();                                             // the curve came from the walk
    const std::string& handover() const { return handover_; }  // why the walk handed over ("" if it did not)
    // The hull model and its curve over all ρ1 > 0, built on first use. Once claim_models() was
    // called, a hull model this session builds itself is refused (InputError, before any line is
    // built) when its polyhedra's edge pairs pass kMaxEdgePairs (limits.hpp).
    const HullModel& hull();
    // The two exact polyhedra and seeds, with no contact line (build_hulls): what membership,
    // closest points and the exact distance's fallback need. The hull model's when it is built.
    const Model& hulls();
    const TouchingCurve& hull_curve();
    // The exact verdict at (ρ1, ρ2), ρ1, ρ2 > 0: on the walk where it proved the curve, else on
    // the hull model.
    Verdict verdict(const Q& rho1, const Q& rho2);
    // The curve's ρ2 at ρ1 > 0, likewise.
    Q curve_value(const Q& rho1);
    // Whether the walk proved the curve at every ρ1 in [lo, hi] (false on the hull path). When it
    // walked I1 but not all of [lo, hi], it walks again over the wider range first (output-sensitive,
    // as the first walk; queries outside I1 need it): false only if that walk hands over too. The
    // wider walk replaces the first in place (its curve over I1 is the same, its statistics not).
    bool walk_covers(const Q& lo, const Q& hi);
    // The model and curve that decide every pair whose ρ1 is among `rho1` (doubles, read
    // exactly): the walk's where it proved the curve at all of them, else the hull model's.
    struct Decider {
        const Model& model;
        const TouchingCurve& curve;
    };
    Decider decider_for(const std::vector<double>& rho1);
    // The curve proved over curve_proof's window around [lo_need, hi_need] (judgements.hpp):
    // the walk's, walking wider until it proves the window (a few rounds), else the hull model's
    // (within the limits of hull()). `proved` is where that curve is the exact one.
    struct CurveView {
        const Model& model;
        const TouchingCurve& curve;
        Q lo;                 // proved for ρ1 >= lo (0 on the hull model)
        std::optional<Q> hi;  // and up to hi (none: unbounded)
        bool proves(const Q& x) const { return x >= lo && (!hi || x <= *hi); }
    };
    CurveView curve_around(const Q& lo_need, const Q& hi_need);
    // Certificates (certificate.hpp): on the walk when it proved what they rest on, else on the
    // hull model. A query answer needs the curve at ρ1 and, when overlapping, where the ray
    // t·(ρ1, ρ2) meets it; a partition needs it over I1, which the walk always covers.
    struct Certified {
        const Model& model;
        QueryAnswer result;
    };
    Certified certified_query(const Q& rho1, const Q& rho2);
    std::string query_text(const Q& rho1, const Q& rho2);  // document_text(query_json(...))
    std::string partition_text();                          // document_text(partition_json(...))
    // What claims are checked against (claims.hpp): verdicts and curve values as verdict() and
    // curve_value() give them, the hull model for what needs every vertex.
    const ClaimModels& claim_models();
    // The points for the measures (measures.hpp): on a walked scene their trees, with no hull
    // (CloudPoints, built on first use); else the hull model's vertices.
    const PointSets& points();
    const std::string& name() const { return name_; }
    bool hull_built() const { return hull_ != nullptr; }
    // The scene's geometry checked as this session's engine will read it, without building the
    // curve: where the walk will be tried, its seeds proved inside by a few extreme points
    // (scan_seeds_proved); otherwise, or when they are not, the hull model built (its errors: flat
    // points, a seed outside, as InputError). The library's Scene calls it on construction.
    void check();
    // The scene in machine integers, as the engine decided (null when the walk is not tried).
    std::shared_ptr<const CompactScene> compact_scene() {
        plan();
        return compact_;
    }

  private:
    // The one choice of engine: whether the walk is tried (the scene then in machine integers,
    // compact_), by Engine and walk_by_default. decide() runs the walk when it is.
    bool plan();
    bool planned_ = false, walk_planned_ = false;
    void decide();
    bool seeds_coincide() const;             // every pair overlaps: s lies inside P1(ρ1) and P2(ρ2)
    void refuse_past_the_edge_pair_limit();  // InputError when the hulls' edge pairs pass kMaxEdgePairs
    bool limit_hull_ = false;                // set by claim_models()
    void lap(const char* what) {
        if (clock_) clock_->lap(what);
    }
    std::shared_ptr<const ExactScene> scene_;
    std::shared_ptr<const CompactScene> compact_;
    std::string name_;
    Engine engine_;
    StageClock* clock_ = nullptr;
    std::function<std::shared_ptr<const HullModel>()> hull_source_;
    bool decided_ = false;
    std::optional<WalkModel> walk_;
    TouchingCurve walk_curve_;
    // Proved by the walk as it stands (walk_covers without walking wider).
    bool walk_proves(const Q& lo, const Q& hi) const;
    std::string handover_;
    std::shared_ptr<const HullModel> hull_;
    std::shared_ptr<const Model> hulls_;  // build_hulls's, when no hull model was built
    std::optional<TouchingCurve> hull_curve_;
    std::shared_ptr<const PointSets> points_;
    class Models;
    std::unique_ptr<Models> models_;  // claim_models()
};

}  // namespace scalecert::internal
