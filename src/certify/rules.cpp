// The claim rules' frame (claim.hpp): claimed verdicts, tolerances, the claim as certificates state
// it, and each object kind's dispatch to the rules of kinds/. Squares are compared for distances
// and depths: no root is taken.
#include "certify/claim.hpp"
#include "certify/rules_impl.hpp"
#include "certify/compound_judge.hpp"
#include "certify/judgements.hpp"
#include "certify/region_certificate.hpp"
#include "geometry/measures.hpp"

#include <functional>
#include <limits>
#include <algorithm>

namespace scalecert::internal {

const char* type_name(ClaimType t) {
    switch (t) {
    case ClaimType::Verdict: return "verdict";
    case ClaimType::Curve: return "curve";
    case ClaimType::CurvePoint: return "curve_point";
    case ClaimType::SwitchPoint: return "switch_point";
    case ClaimType::Growth: return "growth_distance";
    case ClaimType::Plane: return "separating_plane";
    case ClaimType::Witness: return "witness_point";
    case ClaimType::Distance: return "distance";
    case ClaimType::Depth: return "penetration_depth";
    case ClaimType::SignedDistance: return "signed_distance";
    }
    return "";
}

const char* claimed_name(Claimed v) {
    switch (v) {
    case Claimed::Separated: return verdict_name(Verdict::Separated);
    case Claimed::Touching: return verdict_name(Verdict::Touching);
    case Claimed::Overlapping: return verdict_name(Verdict::Overlapping);
    case Claimed::Intersecting: return "intersecting";  // the claimed verdicts that are not exact ones
    case Claimed::NotOverlapping: return "not_overlapping";
    }
    return "";
}

std::optional<Claimed> claimed_of(const std::string& name) {
    for (Claimed v :
         {Claimed::Separated, Claimed::Touching, Claimed::Overlapping, Claimed::Intersecting, Claimed::NotOverlapping})
        if (name == claimed_name(v)) return v;
    return std::nullopt;
}

bool verdict_matches(Claimed claimed, Verdict exact) {
    switch (claimed) {
    case Claimed::Separated: return exact == Verdict::Separated;
    case Claimed::Touching: return exact == Verdict::Touching;
    case Claimed::Overlapping: return exact == Verdict::Overlapping;
    case Claimed::Intersecting: return exact != Verdict::Separated;
    case Claimed::NotOverlapping: return exact != Verdict::Overlapping;
    }
    return false;
}

bool Tolerance::close(const Q& c, const Q& e) const {
    const Q d = c - e;
    return (sgn(d) < 0 ? Q(-d) : d) <= rel * (sgn(e) < 0 ? Q(-e) : e);
}

int sign_minus_sqrt(const Q& a, const Q& k, const Q& E) {
    const int sk = sgn(E) == 0 ? 0 : sgn(k);  // the sign of k·√E
    if (sk == 0) return sgn(a);
    if (sgn(a) != sk) return sgn(a) > sk ? 1 : -1;
    const int m = cmp(a * a, k * k * E);  // |a| against |k|·√E
    return sk > 0 ? m : -m;
}

bool Tolerance::close_sq(const Q& c, const Q& E) const {
    if (sgn(abs) > 0) return sign_minus_sqrt(c - abs, 1 + rel, E) <= 0 && sign_minus_sqrt(c + abs, 1 - rel, E) >= 0;
    if (sgn(c) < 0) return false;
    const Q lo = (1 - rel), hi = (1 + rel);
    const Q c2 = c * c;
    return (sgn(lo) <= 0 || lo * lo * E <= c2) && c2 <= hi * hi * E;
}

bool Tolerance::within_above(const Q& x, const Q& E, int apart) const {
    const Q k = 1 + rel;
    if (sgn(abs) == 0) return E <= x && x <= k * k * E;
    // √x ≤ k√E + m, m = apart·abs: x ≤ k²E + m² + 2km√E.
    const Q m = apart * abs;
    return sign_minus_sqrt(x - k * k * E - m * m, 2 * k * m, E) <= 0;
}

bool Tolerance::within_abs(const Q& x, const Q& N) const { return sign_minus_sqrt(x, abs, N) <= 0; }

bool Tolerance::close_signed(const Q& c, int s, const Q& E) const {
    // c − abs − rel√E ≤ s√E ≤ c + abs + rel√E, each side one sign_minus_sqrt.
    return sign_minus_sqrt(c - abs, s + rel, E) <= 0 && sign_minus_sqrt(c + abs, s - rel, E) >= 0;
}

std::optional<Judged::Surd> Judged::exact_value() const {
    const Q R = radii ? Q((*radii)[0] + (*radii)[1]) : Q(0);
    if (const auto* d = get<DistanceJudged>()) {
        if (sgn(R) == 0) return Surd{1, d->exact_squared, Q(0)};
        return d->exact_squared > R * R ? Surd{1, d->exact_squared, Q(-R)} : Surd{0, Q(0), Q(0)};
    }
    if (const auto* d = get<DepthJudged>()) {
        if (!d->exact_squared) return std::nullopt;
        return Surd{d->root_sign, *d->exact_squared, R};
    }
    if (const auto* d = get<SignedDistanceJudged>()) return Surd{d->root(), d->exact_squared, Q(-R)};
    return std::nullopt;
}

bool Tolerance::close_value(const Q& c, int s, const Q& E, const Q& k) const {
    // σ the sign of x, |x| = σ·s·√E + σ·k; each side of |c − x| ≤ abs + rel·|x| one sign_minus_sqrt.
    const int sigma = sign_minus_sqrt(k, Q(-s), E);
    const Q rs = rel * sigma;
    return sign_minus_sqrt(c - k - abs - rs * k, s * (1 + rs), E) <= 0 &&
           sign_minus_sqrt(k - c - abs - rs * k, -s * (1 - rs), E) <= 0;
}

int sign_two_sqrts(const Q& a, const Q& b, const Q& A, const Q& c, const Q& E) {
    const int su = sign_minus_sqrt(a, Q(-b), A);  // u = a + b√A
    const int sv = sgn(E) == 0 ? 0 : sgn(c);      // v = c√E
    if (su == 0 || sv == 0 || su == sv) return su != 0 ? su : sv;
    // Opposite signs: the larger of |u|, |v|; u² − v² = a² + b²A − c²E + 2ab√A.
    const int t = sign_minus_sqrt(a * a + b * b * A - c * c * E, Q(-2 * a * b), A);
    return t == 0 ? 0 : t > 0 ? su : sv;
}

namespace {
std::string ex(const Q& q) { return to_exact_string(q); }
Json ex3(const Vec3q& v) { return Json::array({ex(v[0]), ex(v[1]), ex(v[2])}); }
Json ex_pair(const Q& a, const Q& b) { return Json::array({ex(a), ex(b)}); }
}  // namespace

namespace {
Json exact_fields_json(const TypedClaim& c);
}  // namespace

// The field with no answer is null (a zero normal or direction stays as it was written).
Json exact_claim_json(const TypedClaim& c) {
    Json j = exact_fields_json(c);
    if (!c.no_answer.empty() && c.no_answer_reason != std::string("the zero vector")) j[c.no_answer] = nullptr;
    return j;
}

namespace {
Json exact_fields_json(const TypedClaim& c) {
    Json j{{"kind", type_name(c.type)}};
    switch (c.type) {
    case ClaimType::Growth: j["value"] = ex(c.value); return j;
    case ClaimType::Curve: {
        const ClaimedCurve& k = *c.curve;
        const auto& S = k.segments;
        if (k.as_vertices) {
            Json v = Json::array({ex_pair(S.front().x0, S.front().y0)});
            for (const CurveSegment& s : S) v.push_back(ex_pair(s.x1, s.y1));
            j["vertices"] = std::move(v);
        } else {
            Json ps = Json::array();
            for (const CurveSegment& s : S) {
                const Q a = (s.y1 - s.y0) / (s.x1 - s.x0);
                Json p{{"rho1", ex_pair(s.x0, s.x1)}, {"slope", ex(a)}, {"intercept", ex(s.y0 - a * s.x0)}};
                if (s.contact) p["contact"] = *s.contact;
                ps.push_back(std::move(p));
            }
            j["pieces"] = std::move(ps);
        }
        if (k.switches_listed) {
            Json cs = Json::array();
            for (const auto& [x, y] : k.switches) cs.push_back(ex_pair(x, y));
            j["switch_points"] = std::move(cs);
        }
        return j;
    }
    default: break;
    }
    j["rho1"] = ex(c.rho1);
    j["rho2"] = ex(c.rho2);
    for (size_t i = 0; i < 2; ++i)
        if (c.pose[i]) {
            Json m = Json::array();
            for (const auto& row : *c.pose[i])
                m.push_back(Json::array({ex(row[0]), ex(row[1]), ex(row[2]), ex(row[3])}));
            j[i ? "pose2" : "pose1"] = std::move(m);
        }
    switch (c.type) {
    case ClaimType::Verdict: j["verdict"] = claimed_name(c.verdict); break;
    case ClaimType::SwitchPoint:
        if (c.contact) j["contact"] = *c.contact;
        break;
    case ClaimType::Plane:
        j["normal"] = ex3(c.normal);
        if (c.offset) j["offset"] = ex(*c.offset);
        break;
    case ClaimType::Witness: j["point"] = ex3(c.point); break;
    case ClaimType::Distance:
        j["value"] = ex(c.value);
        if (c.closest) j["closest"] = Json::array({ex3((*c.closest)[0]), ex3((*c.closest)[1])});
        break;
    case ClaimType::Depth:
        if (c.parts) j["parts"] = Json::array({(*c.parts)[0], (*c.parts)[1]});
        j["value"] = ex(c.value);
        if (c.direction) j["direction"] = ex3(*c.direction);
        break;
    case ClaimType::SignedDistance:
        if (c.parts) j["parts"] = Json::array({(*c.parts)[0], (*c.parts)[1]});
        j[c.bound == TypedClaim::Bound::Value     ? "value"
          : c.bound == TypedClaim::Bound::AtLeast ? "at_least"
          : c.bound == TypedClaim::Bound::AtMost  ? "at_most"
                                                  : "below"] = ex(c.value);
        break;
    default: break;
    }
    return j;
}
}  // namespace

// ---- two convex objects ----------------------------------------------------------------------

ConvexRules::ConvexRules(const ClaimModels& models, const Tolerance& tolerance)
    : ClaimRules(tolerance), impl_(new Impl(models, tolerance)) {}
ConvexRules::~ConvexRules() = default;
std::optional<std::array<long, 2>> ConvexRules::fallbacks() const {
    return std::array<long, 2>{impl_->distance_fallbacks, impl_->depth_fallbacks};
}
std::string ConvexRules::certificate(Json entries) const {
    return judgements_text(impl_->models.document(), tol_.rel, tol_.abs, std::move(entries));
}

void check_part_pair(const std::array<int, 2>& pair, const size_t counts[2], const std::string& where) {
    for (size_t k = 0; k < 2; ++k)
        if (pair[k] < 0 || static_cast<size_t>(pair[k]) >= counts[k])
            throw InputError(where + ".parts[" + std::to_string(k) + "]: P" + std::to_string(k + 1) + " has " +
                             std::to_string(counts[k]) + (counts[k] == 1 ? " part" : " parts") + " (numbered from 0)");
}

std::optional<std::array<int, 2>> ConvexRules::part_pair(const std::optional<std::array<int, 2>>& given,
                                                         const std::string& where) const {
    const size_t one[2] = {1, 1};
    if (given) check_part_pair(*given, one, where);
    return std::nullopt;
}

namespace {
// A claim with no answer in it is wrong; its proof names the field (FORMAT.md).
bool no_answer(const TypedClaim& c, Proof* proof) {
    if (c.no_answer.empty()) return false;
    if (proof) proof->proof = Json{{"no_answer", c.no_answer}};
    return true;
}
}  // namespace

Judged judge_claim(ClaimRules& rules, const TypedClaim& c, size_t index, const std::string& where, Json* entries) {
    Proof p;
    Judged g;
    try {
        g = rules.judge(c, entries ? &p : nullptr);
    } catch (const InputError& e) {
        if (!c.posed()) throw;
        throw InputError(where + "." + e.what());
    }
    if (entries)
        entries->push_back(
            Json{{"index", index}, {"claim", std::move(p.claim)}, {"right", g.right}, {"proof", std::move(p.proof)}});
    return g;
}

Judged ConvexRules::judge(const TypedClaim& c, Proof* proof) {
    Judged g;
    if (proof) proof->claim = exact_claim_json(c);
    if (no_answer(c, proof)) return g;
    std::optional<PosedPoints> at;  // the points moved by the claim's poses, for its judgement
    if (c.posed()) {
        if (c.type != ClaimType::Verdict && c.type != ClaimType::Plane && c.type != ClaimType::Witness &&
            c.type != ClaimType::Distance && c.type != ClaimType::Depth && c.type != ClaimType::SignedDistance)
            throw std::logic_error("certify-fp: a pose on a claim of the curve");
        at.emplace(impl_->models.points(), c.pose);
    }
    impl_->posed = at ? &*at : nullptr;
    struct Reset {
        const PosedPoints*& p;
        ~Reset() { p = nullptr; }
    } reset{impl_->posed};
    switch (c.type) {
    case ClaimType::Verdict: impl_->verdict(c, g, proof); break;
    case ClaimType::Growth: impl_->growth(c, g, proof); break;
    case ClaimType::CurvePoint: impl_->curve_point(c, g, proof); break;
    case ClaimType::SwitchPoint: impl_->switch_point(c, g, proof); break;
    case ClaimType::Curve: impl_->curve(c, g, proof); break;
    case ClaimType::Plane: impl_->plane(c, g, proof); break;
    case ClaimType::Witness: impl_->witness(c, g, proof); break;
    case ClaimType::Distance: impl_->distance(c, g, proof); break;
    case ClaimType::Depth: impl_->depth(c, g, proof); break;
    case ClaimType::SignedDistance: impl_->signed_distance(c, g, proof); break;
    }
    return g;
}

// ---- two objects made of parts ---------------------------------------------------------------

PartsRules::PartsRules(CompoundJudge& judge, const Tolerance& tolerance) : ClaimRules(tolerance), judge_(judge) {}
PartsRules::~PartsRules() = default;
const ExactScene* PartsRules::parts() const { return &judge_.scene(); }
std::optional<std::array<int, 2>> PartsRules::part_pair(const std::optional<std::array<int, 2>>& given,
                                                        const std::string& where) const {
    // A contact of one part pair: the objects' depth is not defined.
    if (!given)
        throw InputError(where +
                         ".parts: missing: a penetration depth on objects made of parts is a contact of "
                         "one part pair (parts = {part of P1, part of P2})");
    const ExactScene& sc = judge_.scene();
    const size_t counts[2] = {std::max<size_t>(1, sc.P[0].parts.size()), std::max<size_t>(1, sc.P[1].parts.size())};
    check_part_pair(*given, counts, where);
    return given;
}
std::string PartsRules::certificate(Json entries) const {
    return compound_judgements_text(judge_.scene(), tol_.rel, tol_.abs, std::move(entries));
}

CompoundJudge& PartsRules::posed(const std::array<std::optional<Pose>, 2>& pose) {
    std::string key;
    for (const auto& p : pose) {
        key += p ? "[" : "-";
        if (p)
            for (const auto& row : *p)
                for (const Q& x : row) key += to_exact_string(x) + ",";
    }
    std::unique_ptr<CompoundJudge>& j = posed_[key];
    if (!j) {
        ExactScene sc = judge_.scene();
        for (size_t i = 0; i < 2; ++i)
            if (pose[i]) {
                sc.P[i].seed_given = true;  // the seed moves with the object
                apply_pose(*pose[i], sc.P[i], std::string("claim pose") + (i ? "2" : "1"));
            }
        j = std::make_unique<CompoundJudge>(sc, "poses");
    }
    return *j;
}

std::string PartsRules::refusal(ClaimType t) const {
    if (takes(t)) return {};
    return "a claim on two convex objects; on objects made of parts certify-fp takes verdict, separating_plane, "
           "witness_point, distance and penetration_depth (a signed distance: on parts with radii, of one part pair)";
}

bool PartsRules::takes(ClaimType t) {
    return t == ClaimType::Verdict || t == ClaimType::Plane || t == ClaimType::Witness || t == ClaimType::Distance ||
           t == ClaimType::Depth;
}

int PartsRules::place(int i, const Q& rho, const Vec3q& x, Json* proof, bool* near) const {
    const int k = judge_.locate(i, rho, x, proof);
    *near = false;
    if (k >= 0 || sgn(tol_.abs) == 0) return k;
    const int n = judge_.near(i, rho, x, tol_.abs, proof);
    *near = n >= 0;
    return n;
}

Judged PartsRules::judge(const TypedClaim& c, Proof* proof) {
    if (!takes(c.type)) throw std::logic_error("PartsRules: a claim on two convex objects");
    Judged g;
    Json* p = proof ? &proof->proof : nullptr;
    if (proof) proof->claim = exact_claim_json(c);
    if (no_answer(c, proof)) return g;
    if (c.posed()) {  // the same rules on the scene moved by the poses
        TypedClaim bare = c;
        bare.pose = {};
        PartsRules at(posed(c.pose), tol_);
        g = at.judge(bare, proof);
        if (proof) proof->claim = exact_claim_json(c);
        return g;
    }
    switch (c.type) {
    case ClaimType::Verdict: judge_verdict(c, g, p); break;
    case ClaimType::Plane: judge_plane(c, g, p); break;
    case ClaimType::Witness: judge_witness(c, g, p); break;
    case ClaimType::Distance: judge_distance(c, g, p); break;
    case ClaimType::Depth: judge_depth(c, g, p); break;
    default: break;
    }
    return g;
}

}  // namespace scalecert::internal
