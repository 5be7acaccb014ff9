#include "session/engine.hpp"

#include "certify/certificate.hpp"
#include "certify/rounded.hpp"
#include "certify/rounded_parts.hpp"
#include "geometry/measures.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

namespace scalecert::internal {

namespace {

// A contact as the public API has it, from the curve's label ("VE") and features.
scalecert::Contact contact_of(const std::string& label, const std::vector<int>& f1, const std::vector<int>& f2) {
    auto index = [](char c) {
        switch (c) {
        case 'V': return 0;
        case 'E': return 1;
        case 'F': return 2;
        }
        throw std::logic_error("unknown feature letter");
    };
    if (label.size() != 2) throw std::logic_error("contact label of two letters expected");
    return {static_cast<scalecert::ContactKind>(3 * index(label[0]) + index(label[1])), f1, f2};
}

// Two convex objects: the session's walk or hull model answers.
class ConvexEngine final : public SceneEngine {
  public:
    explicit ConvexEngine(SceneSource src) : exact_(std::move(src.exact)), name_(std::move(src.name)) {
        session_ = exact_ ? std::make_unique<Session>(exact_, std::move(src.compact), name_, src.engine)
                          : std::make_unique<Session>(std::move(src.compact), name_, src.engine);
        if (src.hull) session_->set_hull_source(std::move(src.hull));
        if (src.clock) session_->set_clock(src.clock);
    }
    void check() override { session_->check(); }
    std::shared_ptr<const CompactScene> compact() override { return session_->compact_scene(); }
    void prepare() override { public_curve(); }
    bool convex() const override { return true; }
    Verdict verdict(const Q& r1, const Q& r2) override { return session_->verdict(r1, r2); }
    scalecert::QueryResult query(const Q& r1, const Q& r2) override {
        // The walk where it proves the curve at ρ1 (as the query document), else the hull model.
        const Session::Certified c = session_->certified_query(r1, r2);
        const QueryAnswer& r = c.result;
        scalecert::QueryResult out{r.verdict, std::nullopt, std::nullopt};
        if (r.plane)
            out.plane =
                scalecert::Plane{to_q(c.model.lines[r.plane->line].normal), r.plane->c1, r.plane->c2, r.plane->offset};
        if (r.witness) out.common = scalecert::CommonPoint{r.witness->rho1, r.witness->rho2, r.witness->point};
        return out;
    }
    std::string verdict_document(const Q& r1, const Q& r2) override { return session_->query_text(r1, r2); }
    std::string partition_document() override { return session_->partition_text(); }
    std::vector<Verdict> classify(const std::vector<double>& rho1, const std::vector<double>& rho2, unsigned threads,
                                  const std::string&, std::optional<StageCounts>* counts) override {
        const Session::Decider d = session_->decider_for(rho1);
        FastCurve f(d.model, d.curve);
        std::vector<Verdict> out;
        const StageCounts sc = classify_batch(f, rho1, rho2, out, threads);
        if (counts) *counts = sc;
        return out;
    }
    std::pair<Q, Q> plane_extents(const Vec3q& n, const Q& r1, const Q& r2) override {
        // Support queries over the points: no hull model.
        return internal::plane_extents(session_->points(), n, r1, r2);
    }
    std::unique_ptr<ClaimRules> rules(const Tolerance& tolerance) override {
        return std::make_unique<ConvexRules>(session_->claim_models(), tolerance);
    }
    GoldenAnswers golden(const GoldenPoints& points) override {
        const ClaimModels& models = session_->claim_models();
        return golden_answers(exact_scene(), session_->curve_model(), session_->curve(), models, points);
    }
    CompoundSession& region() override {
        if (!region_) region_ = std::make_unique<CompoundSession>(exact_scene(), name_);
        return *region_;
    }
    Session& convex_session(const std::string&) override { return *session_; }
    const scalecert::Curve& curve(const std::string&) override { return public_curve(); }

  private:
    const ExactScene& exact_scene() {
        if (!exact_) exact_ = std::make_shared<const ExactScene>(full_scene(*session_->compact_scene()));
        return *exact_;
    }
    const scalecert::Curve& public_curve() {
        if (curve_) return *curve_;
        const TouchingCurve& c = session_->curve();
        const Model& m = session_->curve_model();
        scalecert::Curve out;
        for (const CurvePiece& p : c.pieces) {
            const ContactLine& L = m.lines[c.env.pieces[p.env].line];
            std::optional<scalecert::Contact> k;
            if (!p.contact.label.empty()) k = contact_of(p.contact.label, p.contact.feat1, p.contact.feat2);
            out.pieces.push_back({p.from, p.to, L.slope, L.intercept, to_q(L.normal), k});
        }
        for (const CurveSwitch& s : c.switches) {
            std::optional<scalecert::Contact> k;
            if (!s.contact.label.empty()) k = contact_of(s.contact.label, s.contact.feat1, s.contact.feat2);
            out.switches.push_back({s.rho1, s.rho2, k});
        }
        out.growth = {c.growth.value, c.growth.in_rectangle};
        return curve_.emplace(std::move(out));
    }
    std::shared_ptr<const ExactScene> exact_;
    std::string name_;
    std::unique_ptr<Session> session_;
    std::unique_ptr<CompoundSession> region_;
    std::optional<scalecert::Curve> curve_;
};

// Objects made of parts: the region, and the part pairs' judge for any pair.
class PartsEngine final : public SceneEngine {
  public:
    explicit PartsEngine(SceneSource src) : exact_(std::move(src.exact)), name_(std::move(src.name)) {}
    void check() override {}  // each part's hull is built (and checked) where it is first needed
    std::shared_ptr<const CompactScene> compact() override { return nullptr; }
    void prepare() override {}
    bool convex() const override { return false; }
    Verdict verdict(const Q& r1, const Q& r2) override { return session().judge().verdict(r1, r2).verdict; }
    scalecert::QueryResult query(const Q& r1, const Q& r2) override {
        return {verdict(r1, r2), std::nullopt, std::nullopt};
    }
    std::string verdict_document(const Q& r1, const Q& r2) override { return session().verdict_certificate(r1, r2); }
    std::string partition_document() override { return dump(session().partition_json()); }
    std::vector<Verdict> classify(const std::vector<double>& rho1, const std::vector<double>& rho2, unsigned threads,
                                  const std::string& source, std::optional<StageCounts>*) override {
        // Located on the region's grid (pairs in I1 × I2).
        return session().classify(rho1, rho2, threads, source);
    }
    std::pair<Q, Q> plane_extents(const Vec3q& n, const Q& r1, const Q& r2) override {
        return session().judge().plane_extents(n, r1, r2);
    }
    std::unique_ptr<ClaimRules> rules(const Tolerance& tolerance) override {
        return std::make_unique<PartsRules>(session().judge(), tolerance);
    }
    GoldenAnswers golden(const GoldenPoints& points) override {
        // The region document, with queries where the meeting set ends.
        Json doc = session().region_json();
        return golden_answers_parts(session().region(true), session().judge(), std::move(doc), points);
    }
    CompoundSession& region() override { return session(); }
    Session& convex_session(const std::string& refusal) override { throw InputError(refusal); }
    const scalecert::Curve& curve(const std::string& refusal) override { throw InputError(refusal); }

  private:
    // The region's session, made on first use (a scene is validated without one).
    CompoundSession& session() {
        if (!session_) session_.emplace(*exact_, name_);
        return *session_;
    }
    std::shared_ptr<const ExactScene> exact_;
    std::string name_;
    std::optional<CompoundSession> session_;
};

// The engines of objects with a radius, each verdict at its own exact pair: one judgements file
// of a verdict claim, the exact verdict, by `rules`.
std::string one_verdict_document(ClaimRules& rules, const Q& r1, const Q& r2, Verdict v, const std::string& name) {
    TypedClaim c;
    c.type = ClaimType::Verdict;
    c.rho1 = r1;
    c.rho2 = r2;
    c.verdict = v == Verdict::Separated  ? Claimed::Separated
                : v == Verdict::Touching ? Claimed::Touching
                                         : Claimed::Overlapping;
    Json entries = Json::array();
    judge_claim(rules, c, 0, name, &entries);
    return rules.certificate(std::move(entries));
}
// classify: each pair's doubles at their exact values (finite and > 0), one verdict a pair.
template <class F>
std::vector<Verdict> classify_each(const std::vector<double>& rho1, const std::vector<double>& rho2,
                                   const std::string& source, F verdict) {
    std::vector<Verdict> out;
    out.reserve(rho1.size());
    for (size_t k = 0; k < rho1.size(); ++k) {
        if (!(std::isfinite(rho1[k]) && rho1[k] > 0 && std::isfinite(rho2[k]) && rho2[k] > 0))
            throw InputError(source + ": pair " + std::to_string(k) + ": scalings must be finite and > 0");
        out.push_back(verdict(exact_from_double(rho1[k]), exact_from_double(rho2[k])));
    }
    return out;
}
[[noreturn]] void refuse_rounded_plane(const std::string& name) {
    throw InputError(name +
                     ": objects with a radius reach past their hulls by ρ·r·|n| along a normal n, which is "
                     "not rational: certify-fp's separating_plane judges planes on them");
}

// Two convex objects with radii (not both 0): verdicts and claims at any pair, from the hulls'
// proved measures (rounded.hpp). Their touching set is curved: no curve, partition, region or
// golden data yet, each refused in one line.
class RoundedEngine final : public SceneEngine {
  public:
    explicit RoundedEngine(SceneSource src) : exact_(std::move(src.exact)), name_(std::move(src.name)) {}
    void check() override { points(); }
    std::shared_ptr<const CompactScene> compact() override { return nullptr; }
    void prepare() override { points(); }
    bool convex() const override { return false; }
    Verdict verdict(const Q& r1, const Q& r2) override {
        const RoundedPoints& S = points();
        const auto [rank, flat] = S.difference_span(S);
        return rounded_verdict(hull_measure(S, rank, flat, r1, r2),
                               r1 * exact_->P[0].radius + r2 * exact_->P[1].radius);
    }
    scalecert::QueryResult query(const Q& r1, const Q& r2) override {
        return {verdict(r1, r2), std::nullopt, std::nullopt};
    }
    // A judgements file of one verdict claim, the exact verdict (FORMAT.md, "Objects with a radius").
    std::string verdict_document(const Q& r1, const Q& r2) override {
        points();
        RoundedRules rules(exact_, points_, Tolerance{});
        return one_verdict_document(rules, r1, r2, verdict(r1, r2), name_);
    }
    std::string partition_document() override { throw InputError(refused("the partition")); }
    std::vector<Verdict> classify(const std::vector<double>& rho1, const std::vector<double>& rho2, unsigned,
                                  const std::string& source, std::optional<StageCounts>*) override {
        return classify_each(rho1, rho2, source, [this](const Q& r1, const Q& r2) { return verdict(r1, r2); });
    }
    std::pair<Q, Q> plane_extents(const Vec3q&, const Q&, const Q&) override { refuse_rounded_plane(name_); }
    std::unique_ptr<ClaimRules> rules(const Tolerance& tolerance) override {
        points();
        return std::make_unique<RoundedRules>(exact_, points_, tolerance);
    }
    GoldenAnswers golden(const GoldenPoints& p) override { return rounded_golden(*exact_, points(), p); }
    CompoundSession& region() override { throw InputError(refused("the region")); }
    Session& convex_session(const std::string&) override {
        throw InputError(refused("the touching curve (with its segments and the grid search)"));
    }
    const scalecert::Curve& curve(const std::string&) override { throw InputError(refused("the touching curve")); }

  private:
    const RoundedPoints& points() {
        if (!points_) {
            auto S = std::make_shared<const RoundedPoints>(*exact_, name_);
            check_rounded(*exact_, *S, name_);
            points_ = std::move(S);
        }
        return *points_;
    }
    std::string refused(const std::string& what) const {
        return name_ + ": " + what +
               " is not built for objects with a radius (their touching set is curved); query, classify and "
               "certify-fp answer at any pair";
    }
    std::shared_ptr<const ExactScene> exact_;
    std::string name_;
    std::shared_ptr<const RoundedPoints> points_;
};

// Objects made of parts with radii (a convex object beside them is one part): verdicts, claims with
// their certificates, and golden samples at any pair (rounded_parts.hpp); no curve, partition or
// region yet, each refused in one line.
class RoundedPartsEngine final : public SceneEngine {
  public:
    explicit RoundedPartsEngine(SceneSource src) : exact_(std::move(src.exact)), name_(std::move(src.name)) {}
    void check() override { judge(); }
    std::shared_ptr<const CompactScene> compact() override { return nullptr; }
    void prepare() override { judge(); }
    bool convex() const override { return false; }
    Verdict verdict(const Q& r1, const Q& r2) override { return judge().verdict(r1, r2).verdict; }
    scalecert::QueryResult query(const Q& r1, const Q& r2) override {
        return {verdict(r1, r2), std::nullopt, std::nullopt};
    }
    // A compound judgements file of one verdict claim, the exact verdict (FORMAT.md, "Parts with radii").
    std::string verdict_document(const Q& r1, const Q& r2) override {
        judge();
        RoundedPartsRules rules(judge_, Tolerance{});
        return one_verdict_document(rules, r1, r2, verdict(r1, r2), name_);
    }
    std::string partition_document() override { throw InputError(refused("the partition")); }
    std::vector<Verdict> classify(const std::vector<double>& rho1, const std::vector<double>& rho2, unsigned,
                                  const std::string& source, std::optional<StageCounts>*) override {
        return classify_each(rho1, rho2, source, [this](const Q& r1, const Q& r2) { return verdict(r1, r2); });
    }
    std::pair<Q, Q> plane_extents(const Vec3q&, const Q&, const Q&) override { refuse_rounded_plane(name_); }
    std::unique_ptr<ClaimRules> rules(const Tolerance& tolerance) override {
        judge();
        return std::make_unique<RoundedPartsRules>(judge_, tolerance);
    }
    GoldenAnswers golden(const GoldenPoints& points) override {
        RoundedParts& J = judge();
        return sampled_golden(
            *exact_, [&J](const Q& r1, const Q& r2) { return J.verdict(r1, r2).verdict; },
            [&J](const Q& r1, const Q& r2) {
                // Apart: the nearest pair; else the pair deciding the verdict (its signed distance <= 0).
                const RoundedParts::Decided d = J.verdict(r1, r2);
                int a = d.a, b = d.b;
                RoundedParts::PairState st;
                if (d.verdict == Verdict::Separated) {
                    RoundedParts::Nearest n = J.nearest(r1, r2);
                    a = n.a, b = n.b, st = std::move(n.state);
                } else {
                    st = J.pair_state(a, b, r1, r2);
                }
                const auto [s, E] = hull_signed(st.hulls);
                return GoldenValue{d.verdict, s, E, st.R, a, b};
            },
            points);
    }
    CompoundSession& region() override { throw InputError(refused("the region")); }
    Session& convex_session(const std::string&) override {
        throw InputError(refused("the touching curve (with its segments and the grid search)"));
    }
    const scalecert::Curve& curve(const std::string&) override { throw InputError(refused("the touching curve")); }

  private:
    RoundedParts& judge() {
        if (!judge_) judge_ = std::make_shared<RoundedParts>(*exact_, name_);
        return *judge_;
    }
    std::string refused(const std::string& what) const {
        return name_ + ": " + what +
               " is not built for objects made of parts with radii; query, classify and certify-fp answer at any "
               "pair";
    }
    std::shared_ptr<const ExactScene> exact_;
    std::string name_;
    std::shared_ptr<RoundedParts> judge_;
};

}  // namespace

std::unique_ptr<SceneEngine> open_engine(SceneSource source) {
    if (source.exact && source.exact->rounded() && source.exact->made_of_parts())
        return std::make_unique<RoundedPartsEngine>(std::move(source));
    if (source.exact && source.exact->rounded()) return std::make_unique<RoundedEngine>(std::move(source));
    if (source.exact && source.exact->made_of_parts()) return std::make_unique<PartsEngine>(std::move(source));
    return std::make_unique<ConvexEngine>(std::move(source));
}

std::unique_ptr<SceneEngine> open_engine(std::shared_ptr<const ExactScene> scene, std::string name) {
    SceneSource src;
    src.exact = std::move(scene);
    src.name = std::move(name);
    return open_engine(std::move(src));
}

}  // namespace scalecert::internal
