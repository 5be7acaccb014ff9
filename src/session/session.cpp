#include "session/session.hpp"

#include "certify/certificate.hpp"
#include "certify/judgements.hpp"
#include "numeric/limits.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace scalecert::internal {

Session::Session(ExactScene scene, std::string name, Engine engine)
    : Session(std::make_shared<const ExactScene>(std::move(scene)), nullptr, std::move(name), engine) {}

Session::Session(std::shared_ptr<const CompactScene> scene, std::string name, Engine engine)
    : compact_(std::move(scene)), name_(std::move(name)), engine_(engine) {}

Session::Session(std::shared_ptr<const ExactScene> scene, std::shared_ptr<const CompactScene> compact, std::string name,
                 Engine engine)
    : scene_(std::move(scene)), compact_(std::move(compact)), name_(std::move(name)), engine_(engine) {
    if (scene_ && scene_->made_of_parts())
        throw std::logic_error(
            "Session: a scene of parts is not two convex objects (CompoundSession and CompoundJudge take it)");
}

bool Session::plan() {
    if (planned_) return walk_planned_;
    planned_ = true;
    if (engine_ == Engine::Hull) return walk_planned_ = false;
    if (!compact_ && scene_ &&
        (engine_ == Engine::Scan || walk_by_default(scene_->P[0].points.size(), scene_->P[1].points.size())))
        if (auto cs = internal::compact_scene(*scene_)) compact_ = std::make_shared<const CompactScene>(std::move(*cs));
    walk_planned_ =
        compact_ && (engine_ == Engine::Scan || walk_by_default(compact_->P[0].size(), compact_->P[1].size()));
    return walk_planned_;
}

void Session::check() {
    if (plan() && scan_seeds_proved(*compact_)) return;
    hull();
}

void Session::decide() {
    if (decided_) return;
    decided_ = true;
    if (!plan()) return;
    WalkResult r = scan_model(compact_);
    if (r.stop) {
        handover_ = r.stop->text();
        if (std::getenv("SCALECERT_TIMING"))
            std::fprintf(stderr, "scalecert: scan path: %s; the hull path decides\n", handover_.c_str());
        return;
    }
    walk_.emplace(std::move(*r.model));
    walk_curve_ = build_curve(*walk_);
    lap("envelope and curve");
}

bool Session::seeds_coincide() const {
    return compact_ ? compact_->seed[0] == compact_->seed[1] : scene_ && scene_->P[0].seed == scene_->P[1].seed;
}

bool Session::walked() {
    decide();
    return walk_.has_value();
}

const HullModel& Session::hull() {
    if (!hull_) {
        if (hull_source_) {
            if (limit_hull_) refuse_past_the_edge_pair_limit();  // (the library's claims too)
            hull_ = hull_source_();
        } else {
            if (clock_) clock_->restart();
            if (!scene_ && !compact_) throw std::logic_error("Session: no scene and no hull source");
            if (limit_hull_) refuse_past_the_edge_pair_limit();
            hull_ = std::make_shared<const HullModel>(
                hulls_ ? build_model(Model(*hulls_)) : build_model(scene_ ? *scene_ : full_scene(*compact_), name_));
        }
    }
    return *hull_;
}

const Model& Session::hulls() {
    if (hull_) return *hull_;
    // (The library's scenes that do not walk hold their hull model already.)
    if (hull_source_ && !walked()) return hull();
    if (!hulls_) {
        if (!scene_ && !compact_) throw std::logic_error("Session: no scene for the hulls");
        if (clock_) clock_->restart();
        hulls_ = std::make_shared<const Model>(build_hulls(scene_ ? *scene_ : full_scene(*compact_), name_));
        lap("hulls");
    }
    return *hulls_;
}

void Session::refuse_past_the_edge_pair_limit() {
    if (!hulls_) {  // the two hulls alone (hulls() would ask hull() for a scene that does not walk)
        if (!scene_ && !compact_) throw std::logic_error("Session: no scene for the hulls");
        // A hull of n points has at most 3n - 6 edges: under the limit whatever the hulls are.
        double most = 1;
        for (int i = 0; i < 2; ++i)
            most *= 3.0 * static_cast<double>(scene_ ? scene_->P[i].points.size() : compact_->P[i].size());
        if (most <= kMaxEdgePairs) return;
        hulls_ = std::make_shared<const Model>(build_hulls(scene_ ? *scene_ : full_scene(*compact_), name_));
    }
    const Model& h = *hulls_;
    const double pairs = static_cast<double>(h.P[0].edges.size()) * static_cast<double>(h.P[1].edges.size());
    if (pairs > kMaxEdgePairs)
        throw InputError(name_ + ": this claim needs the hull model (every contact line), and its polyhedra have " +
                         std::to_string(h.P[0].edges.size()) + " x " + std::to_string(h.P[1].edges.size()) +
                         " edges, more than 2*10^7 edge pairs (the limit: the lines grow with them)" +
                         (handover_.empty() ? "" : "; the walk handed over: " + handover_));
}

Session::CurveView Session::curve_around(const Q& lo_need, const Q& hi_need) {
    if (walked()) {
        // The window comes from the walked curve's breaks; once the walk proves it, its breaks
        // there are the curve's. A few rounds, each walking wider.
        for (int round = 0; round < 8; ++round) {
            const auto [a, b] = curve_proof_window(walk_curve_, lo_need, hi_need);
            if (sgn(a) <= 0) break;  // from ρ1 = 0: the walk proves no range reaching 0
            if (walk_proves(a, b)) return {*walk_, walk_curve_, walk_->walk_lo, walk_->walk_hi};
            if (!walk_covers(a, b)) break;
        }
    }
    const HullModel& h = hull();
    return {h, hull_curve(), Q(0), std::nullopt};
}

const TouchingCurve& Session::hull_curve() {
    if (!hull_curve_) {
        const Model& m = hull();
        if (clock_) clock_->restart();
        hull_curve_ = build_curve(m);
        lap("envelope and curve");
    }
    return *hull_curve_;
}

const TouchingCurve& Session::curve() { return walked() ? walk_curve_ : hull_curve(); }
const Model& Session::curve_model() {
    if (walked()) return *walk_;
    return hull();
}

bool Session::walk_proves(const Q& lo, const Q& hi) const {
    return walk_ && walk_->walk_lo <= lo && (!walk_->walk_hi || hi <= *walk_->walk_hi);
}

bool Session::walk_covers(const Q& lo, const Q& hi) {
    if (!walked()) return false;
    if (walk_proves(lo, hi)) return true;
    if (sgn(lo) <= 0 || hi < lo) return false;
    WalkResult r = scan_model(compact_, std::make_pair(lo, hi));
    if (r.stop) {
        if (std::getenv("SCALECERT_TIMING"))
            std::fprintf(stderr, "scalecert: scan path over a wider range: %s\n", r.stop->text().c_str());
        return false;
    }
    TouchingCurve c = build_curve(*r.model);
    walk_.emplace(std::move(*r.model));
    walk_curve_ = std::move(c);
    lap("wider walk");
    return walk_proves(lo, hi);
}

Session::Decider Session::decider_for(const std::vector<double>& rho1) {
    if (!rho1.empty() && walked()) {
        const auto [lo, hi] = std::minmax_element(rho1.begin(), rho1.end());
        if (walk_covers(exact_from_double(*lo), exact_from_double(*hi))) return {*walk_, walk_curve_};
    }
    return {hull(), hull_curve()};
}

Verdict Session::verdict(const Q& rho1, const Q& rho2) {
    // Coincident seeds: s lies inside P1(ρ1) and P2(ρ2) for every ρ1, ρ2 > 0 (the walk does not
    // take such scenes; this needs no model at all).
    if (seeds_coincide() && sgn(rho1) > 0 && sgn(rho2) > 0) return Verdict::Overlapping;
    if (walk_covers(rho1, rho1)) return query(*walk_, walk_curve_, rho1, rho2, false).verdict;
    return query(hull(), hull_curve(), rho1, rho2, false).verdict;
}

Q Session::curve_value(const Q& rho1) {
    if (walk_covers(rho1, rho1)) return walk_curve_.env.value(walk_->lines, rho1);
    return hull_curve().env.value(hull().lines, rho1);
}

Session::Certified Session::certified_query(const Q& rho1, const Q& rho2) {
    if (walk_covers(rho1, rho1)) {
        const Model& m = *walk_;
        bool proved = true;
        if (query(m, walk_curve_, rho1, rho2, false).verdict == Verdict::Overlapping) {
            // The witness sits where the ray meets the walked lines' envelope: the true curve only
            // where the walk proved it (walked lines are ≤ the curve everywhere, equal there).
            const auto [t, line] = ray_crossing(m, walk_curve_, rho1, rho2);
            const Q x = t * rho1;
            proved = walk_proves(x, x) && walk_curve_.env.value(m.lines, x) == t * rho2;
        }
        if (proved) return {m, query(m, walk_curve_, rho1, rho2, true)};
        // Overlapping, and the ray meets the curve left of the walk: a touching pair below and
        // left of (ρ1, ρ2) on the walked curve instead, at x < ρ1 with f(x) < ρ2 (f is continuous
        // and f(ρ1) < ρ2, so halving the step towards ρ1 finds one).
        if (m.walk_lo < rho1) {
            Q step = (rho1 - m.walk_lo) / 2;
            for (int k = 0; k < 256; ++k, step /= 2)
                if (walk_curve_.env.value(m.lines, rho1 - step) < rho2) {
                    QueryAnswer r = query(m, walk_curve_, rho1, rho2, false);
                    r.witness = witness_below(m, walk_curve_, rho1 - step);
                    return {m, r};
                }
        }
    }
    const Model& h = hull();
    return {h, query(h, hull_curve(), rho1, rho2, true)};
}

std::string Session::query_text(const Q& rho1, const Q& rho2) {
    const Certified c = certified_query(rho1, rho2);
    return document_text(c.model, query_json(c.model, c.result, seed_weights(c.model)));
}

std::string Session::partition_text() {
    const Model& m = curve_model();
    const TouchingCurve& c = curve();
    const std::string text = document_text(m, partition_json(m, c, build_partition(m, c)));
    lap("partition and output");
    return text;
}

const PointSets& Session::points() {
    if (!points_) {
        if (walked() && walk_->points)
            points_ = walk_->points;  // the walk's trees
        else
            points_ = std::make_shared<HullPoints>(hulls());  // the polyhedra: no contact line needed
    }
    return *points_;
}

// The claim rules' questions, each answered with the least model it needs: the walk where it
// proves the curve, the two hulls (no contact line) for membership and the measures' fallbacks,
// and the hull model only where neither serves, within the edge-pair limit (hull()).
class Session::Models final : public ClaimModels {
  public:
    explicit Models(Session& s) : s_(s) {}
    const HullModel& hull_model() const override { return s_.hull(); }
    const TouchingCurve& hull_curve() const override { return s_.hull_curve(); }
    Verdict verdict(const Q& r1, const Q& r2) const override { return s_.verdict(r1, r2); }
    Q curve_value(const Q& r1) const override { return s_.curve_value(r1); }
    Q growth() const override {
        if (s_.seeds_coincide()) return Q(0);  // every pair overlaps: no model needed
        return s_.curve().growth.value;
    }
    const PointSets& points() const override { return s_.points(); }
    const Model& document() const override { return s_.walked() ? static_cast<const Model&>(*s_.walk_) : s_.hulls(); }
    std::pair<const Model*, QueryAnswer> certified_query(const Q& r1, const Q& r2) const override {
        Certified c = s_.certified_query(r1, r2);
        return {&c.model, std::move(c.result)};
    }
    Json growth_proof() const override {
        if (s_.seeds_coincide()) return Json{{"value", "0"}};  // (judgements.hpp: ρ* = 0 needs no normal)
        return scalecert::internal::growth_proof(s_.curve_model(), s_.curve());
    }
    const Model& hulls() const override { return s_.hulls(); }
    Curve curve_around(const Q& lo, const Q& hi) const override {
        const CurveView v = s_.curve_around(lo, hi);
        return {&v.model, &v.curve, v.lo, v.hi};
    }
    bool member(int i, const Q& rho, const Vec3q& x, Json* proof) const override {
        // A walked scene's trees answer without a hull (CGAL's quickhull is quadratic on points
        // all on the hull, as crossed prisms' are), the distance's rounds unbounded (each adds a
        // point: it always closes); the hulls once built.
        if (!s_.hull_ && !s_.hulls_ && s_.walked() && s_.walk_->points)
            if (const std::optional<bool> in =
                    membership_by_points(*s_.walk_->points, i, rho, x, proof, std::numeric_limits<int>::max()))
                return *in;
        return hull_member(s_.hulls(), i, rho, x, proof);
    }

  private:
    Session& s_;
};

const ClaimModels& Session::claim_models() {
    limit_hull_ = true;
    if (!models_) models_ = std::make_unique<Models>(*this);
    return *models_;
}

Session::~Session() = default;

}  // namespace scalecert::internal
