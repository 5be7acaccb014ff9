#include "certify/rounded.hpp"

#include "certify/certificate.hpp"
#include "certify/judgements.hpp"
#include "io/json.hpp"

#include <limits>

namespace scalecert::internal {

const char* const kRoundedKinds =
    "on objects with a radius certify-fp takes verdict, separating_plane, witness_point, distance, "
    "penetration_depth and signed_distance, at pairs and at poses, and growth_distance (their touching set is "
    "curved: the curve, its points and switch points are not judged yet)";

namespace {
constexpr int kAll = std::numeric_limits<int>::max();

// Adds v to an independent set of at most 3 integer vectors when it is independent of them.
void extend_basis(std::vector<Vec3z>& b, const Vec3z& v) {
    if (b.size() == 3 || is_zero(v)) return;
    if (b.empty()) return b.push_back(v);
    if (b.size() == 1) {
        if (!is_zero(cross(b[0], v))) b.push_back(v);
        return;
    }
    if (sgn(dotz(cross(b[0], b[1]), v)) != 0) b.push_back(v);
}

// A nonzero integer vector orthogonal to the span of b (fewer than 3 vectors).
Vec3z orthogonal_to(const std::vector<Vec3z>& b) {
    if (b.size() == 2) return primitive(cross(b[0], b[1]));
    if (b.empty()) return Vec3z{Z(0), Z(0), Z(1)};
    for (int a = 0; a < 3; ++a) {
        Vec3z e{Z(0), Z(0), Z(0)};
        e[a] = 1;
        const Vec3z n = cross(b[0], e);
        if (!is_zero(n)) return primitive(n);
    }
    throw std::logic_error("orthogonal_to: a zero basis vector");
}

// The span of the differences of object i's points in S (at most 3 vectors).
std::vector<Vec3z> span_of(const PointSets& S, int i, size_t count) {
    std::vector<Vec3z> b;
    const Vec3z z0 = S.zpoint(i, 0);
    for (size_t k = 1; k < count && b.size() < 3; ++k) extend_basis(b, sub(S.zpoint(i, static_cast<int>(k)), z0));
    return b;
}
}  // namespace

std::shared_ptr<const RoundedBody> rounded_body(const std::vector<Vec3q>& points, const Vec3q& seed, const Q& radius,
                                                const std::string& label) {
    auto o = std::make_shared<RoundedBody>();
    o->pts = points;
    o->seed = seed;
    o->scale = 1;
    for (const Vec3q& v : o->pts)
        for (const Q& c : v) lcm_into(o->scale, Z(c.get_den()));
    o->zpts.reserve(o->pts.size());
    o->dpts.reserve(o->pts.size());
    for (const Vec3q& v : o->pts) {
        o->zpts.push_back({over(v[0], o->scale), over(v[1], o->scale), over(v[2], o->scale)});
        o->dpts.push_back({to_double_rn(v[0]), to_double_rn(v[1]), to_double_rn(v[2])});
    }
    for (size_t k = 1; k < o->zpts.size() && o->basis.size() < 3; ++k)
        extend_basis(o->basis, sub(o->zpts[k], o->zpts[0]));
    if (o->basis.size() == 3)
        o->hull.emplace(build_polyhedron(o->pts, label));
    else if (sgn(radius) <= 0)
        throw InputError(label + ": its points span no volume (they lie " +
                         (o->basis.size() == 2   ? "in a plane"
                          : o->basis.size() == 1 ? "on a line"
                                                 : "at one point") +
                         ") and it has no radius > 0");
    return o;
}

RoundedPoints::RoundedPoints(const ExactScene& sc, const std::string& name)
    : RoundedPoints(rounded_body(sc.P[0].points, sc.P[0].seed, sc.P[0].radius, name + ": P1"),
                    rounded_body(sc.P[1].points, sc.P[1].seed, sc.P[1].radius, name + ": P2")) {}

RoundedPoints::RoundedPoints(std::shared_ptr<const RoundedBody> a, std::shared_ptr<const RoundedBody> b)
    : obj_{std::move(a), std::move(b)} {
    std::vector<Vec3z> both = obj_[0]->basis;
    for (const Vec3z& v : obj_[1]->basis) extend_basis(both, v);
    rank_ = static_cast<int>(both.size());
    if (rank_ < 3) flat_normal_ = orthogonal_to(both);
}

int RoundedPoints::argmax(int i, const Vec3z& n) const {
    const RoundedBody& o = *obj_[i];
    if (o.hull) return o.hull->argmax(n).front();
    int best = 0;
    Z bv = dotz(n, o.zpts[0]);
    for (size_t k = 1; k < o.zpts.size(); ++k) {
        Z v = dotz(n, o.zpts[k]);
        if (v > bv) bv = std::move(v), best = static_cast<int>(k);
    }
    return best;
}

int RoundedPoints::dargmax(int i, const D3& d) const {
    const RoundedBody& o = *obj_[i];
    if (o.hull) {
        // A hill climb over the hull's vertex graph in doubles (a guess for the double GJK, which
        // the exact stages check): from the cube map's vertex, to any neighbour higher along d.
        const Polyhedron& P = *o.hull;
        auto along = [&](int k) {
            const auto& x = P.dpts[static_cast<size_t>(k)];
            return d[0] * x[0] + d[1] * x[1] + d[2] * x[2];
        };
        int cur = P.start_vertex({d[0], d[1], d[2]});
        double cv = along(cur);
        for (bool moved = true; moved;) {
            moved = false;
            for (int nb : P.adj[static_cast<size_t>(cur)])
                if (const double v = along(nb); v > cv) cv = v, cur = nb, moved = true;
        }
        return cur;
    }
    int best = 0;
    double bv = -INFINITY;
    auto consider = [&](int k) {
        const D3& x = o.dpts[static_cast<size_t>(k)];
        const double t = d[0] * x[0] + d[1] * x[1] + d[2] * x[2];
        if (t > bv) bv = t, best = k;
    };
    for (size_t k = 0; k < o.dpts.size(); ++k) consider(static_cast<int>(k));
    return best;
}

std::pair<int, Vec3z> RoundedPoints::difference_span(const PointSets& S) const {
    if (&S == this) return {rank_, flat_normal_};
    if (obj_[0]->hull || obj_[1]->hull) return {3, Vec3z{}};
    // At poses the hulls turn apart: the span of the moved points.
    std::vector<Vec3z> both = span_of(S, 0, obj_[0]->pts.size());
    for (const Vec3z& v : span_of(S, 1, obj_[1]->pts.size())) extend_basis(both, v);
    if (both.size() == 3) return {3, Vec3z{}};
    return {static_cast<int>(both.size()), orthogonal_to(both)};
}

MeasuredDepth hull_measure(const PointSets& S, int rank, const Vec3z& flat, const Q& rho1, const Q& rho2) {
    if (rank == 3) {
        std::optional<MeasuredDepth> md = measured_depth(S, rho1, rho2, kAll);
        if (!md) throw std::logic_error("hull_measure: the depth did not close");
        // Apart by a plane alone (the EPA's, when the doubles saw them meet): the radii need the
        // hulls' distance, proved.
        if (md->state == Verdict::Separated && md->distance.w1.empty()) {
            const std::optional<ProvedDistance> pd = proved_distance(S, rho1, rho2, kAll);
            if (!pd || sgn(pd->d.squared) <= 0) throw std::logic_error("hull_measure: a separating plane, no distance");
            md->distance = pd->d;
        }
        return *md;
    }
    const std::optional<ProvedDistance> pd = proved_distance(S, rho1, rho2, kAll);
    if (!pd) throw std::logic_error("hull_measure: the distance did not close");
    if (sgn(pd->d.squared) > 0) return depth_from_distance(S, pd->d, rho1, rho2);
    // A flat difference holds the origin on its boundary: h_M(flat) = 0.
    MeasuredDepth m;
    m.state = Verdict::Touching;
    m.normal = flat;
    m.distance = pd->d;
    return m;
}

std::pair<int, Q> hull_signed(const MeasuredDepth& h) {
    switch (h.state) {
    case Verdict::Separated: return {1, h.distance.squared};
    case Verdict::Touching: return {0, Q(0)};
    case Verdict::Overlapping: return {-1, h.depth->squared};
    }
    return {0, Q(0)};
}

Verdict rounded_verdict(const MeasuredDepth& h, const Q& R) {
    if (h.state != Verdict::Separated) return sgn(R) > 0 ? Verdict::Overlapping : h.state;
    const int c = cmp(h.distance.squared, R * R);
    return c > 0 ? Verdict::Separated : c == 0 ? Verdict::Touching : Verdict::Overlapping;
}

void check_rounded(const ExactScene& sc, const RoundedPoints& S, const std::string& name) {
    for (int i = 0; i < 2; ++i) {
        const PolyInput& in = sc.P[i];
        const std::string which = i == 0 ? "P1" : "P2";
        const ExactDistance d = point_to_body(S, i, Q(1), in.seed);
        // Scaling about the seed keeps it where it is: interior at ρ = 1 is interior at every ρ.
        const bool interior = sgn(in.radius) > 0 ? d.squared < in.radius * in.radius
                                                 : sgn(d.squared) == 0 && S.strictly_inside(i, in.seed);
        if (!interior)
            throw InputError(name + ": " + which + ": the seed " +
                             (sgn(in.radius) > 0 ? "is not within less than the radius of the hull of the points"
                                                 : "is not strictly inside the hull of the points") +
                             " (it must lie in the object's interior)");
    }
}

bool RoundedPoints::strictly_inside(int i, const Vec3q& x) const {
    return obj_[i]->hull && obj_[i]->hull->strictly_inside(x);
}

std::vector<std::pair<int, Q>> RoundedPoints::interior_weights(int i, const Vec3q& x) const {
    if (!obj_[i]->hull) throw std::logic_error("RoundedPoints::interior_weights: a flat object");
    return obj_[i]->hull->interior_weights(x);
}

// ---- the rules ---------------------------------------------------------------------------------

RoundedRules::RoundedRules(std::shared_ptr<const ExactScene> scene, std::shared_ptr<const RoundedPoints> points,
                           const Tolerance& tolerance)
    : ClaimRules(tolerance), scene_(std::move(scene)), points_(std::move(points)) {}
RoundedRules::~RoundedRules() = default;

std::string RoundedRules::refusal(ClaimType t) const {
    switch (t) {
    case ClaimType::Verdict:
    case ClaimType::Plane:
    case ClaimType::Witness:
    case ClaimType::Distance:
    case ClaimType::Depth:
    case ClaimType::SignedDistance:
    case ClaimType::Growth: return {};
    default: return kRoundedKinds;
    }
}

std::optional<std::array<int, 2>> RoundedRules::part_pair(const std::optional<std::array<int, 2>>& given,
                                                          const std::string& where) const {
    if (given && ((*given)[0] != 0 || (*given)[1] != 0))
        throw InputError(where + ".parts: P1 and P2 have 1 part each (numbered from 0)");
    return std::nullopt;
}

bool rounded_member(const PointSets& S, int i, const Q& rho, const Q& m, const Vec3q& x, const Tolerance& tol,
                    bool& near, Json* proof) {
    const ExactDistance d = point_to_body(S, i, rho, x);
    near = false;
    if (d.squared <= m * m) {
        if (proof) *proof = Json{{"within", weights_json(d.w1)}};
        return true;
    }
    if (sgn(tol.abs) > 0 && sign_minus_sqrt(m + tol.abs, Q(1), d.squared) >= 0) {
        near = true;
        if (proof) *proof = Json{{"near", weights_json(d.w1)}};
        return true;
    }
    if (proof) *proof = Json{{"out", normal_json(primitive(sub(d.p2, d.p1)))}};
    return false;
}

bool rounded_plane_right(const Tolerance& tol, const Q& c1, const Q& c2, const Q& m1, const Q& m2, const Vec3q& n,
                         const std::optional<Q>& offset) {
    const Q N = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (sgn(tol.abs) == 0) {
        if (!offset) return sign_minus_sqrt(c2 - c1, m1 + m2, N) > 0;
        return sign_minus_sqrt(*offset - c1, m1, N) > 0 && sign_minus_sqrt(c2 - *offset, m2, N) > 0;
    }
    if (!offset) return sign_minus_sqrt(c1 - c2, 2 * tol.abs - m1 - m2, N) <= 0;
    return sign_minus_sqrt(c1 - *offset, tol.abs - m1, N) <= 0 && sign_minus_sqrt(*offset - c2, tol.abs - m2, N) <= 0;
}

Json rounded_hulls_proof(const MeasuredDepth& md, const Q& rho1, const Q& rho2) {
    return md.state == Verdict::Separated ? Json{{"distance", distance_proof(nullptr, md.distance, rho1, rho2)}}
                                          : Json{{"depth", depth_proof(nullptr, md, rho1, rho2)}};
}
namespace {
Json hulls_proof(const MeasuredDepth& md, const TypedClaim& c) { return rounded_hulls_proof(md, c.rho1, c.rho2); }
}  // namespace

Judged RoundedRules::judge(const TypedClaim& c, Proof* proof) {
    Judged g;
    if (proof) proof->claim = exact_claim_json(c);
    if (c.type == ClaimType::Growth) {
        if (!c.no_answer.empty()) {
            if (proof) proof->proof = Json{{"no_answer", c.no_answer}};
            return g;
        }
        if (!growth_) growth_ = rounded_growth(*scene_, *points_);
        const QuadSurd& x = growth_->rho;
        auto& d = g.set<GrowthJudged>();
        d.surd = x;
        // ρ* = sgn(b)·√(b²c) + a against the claimed value, within REL (LEN applies to no scaling).
        const Tolerance rel{tol_.rel, Q(0)};
        g.right = rel.close_value(c.value, sgn(x.b), Q(x.b * x.b * Q(x.c)), x.a);
        if (proof) proof->proof = growth_->proof;
        return g;
    }
    const Q m1 = c.rho1 * scene_->P[0].radius, m2 = c.rho2 * scene_->P[1].radius, R = m1 + m2;
    g.radii = std::array<Q, 2>{m1, m2};
    if (!c.no_answer.empty()) {
        if (proof) proof->proof = Json{{"no_answer", c.no_answer}};
        return g;
    }
    std::optional<PosedPoints> at;
    if (c.posed()) at.emplace(*points_, c.pose);
    const PointSets& S = at ? static_cast<const PointSets&>(*at) : *points_;
    auto measure = [&] {
        const auto [rank, flat] = points_->difference_span(S);
        return hull_measure(S, rank, flat, c.rho1, c.rho2);
    };
    switch (c.type) {
    case ClaimType::Verdict: {
        const MeasuredDepth md = measure();
        auto& d = g.set<VerdictJudged>();
        d.exact = rounded_verdict(md, R);
        g.right = verdict_matches(c.verdict, d.exact);
        if (proof) proof->proof = hulls_proof(md, c);
        break;
    }
    case ClaimType::SignedDistance: {
        const MeasuredDepth md = measure();
        auto& d = g.set<SignedDistanceJudged>();
        d.exact = rounded_verdict(md, R);
        const auto [s, E] = hull_signed(md);
        d.root_sign = s;
        d.exact_squared = E;
        switch (c.bound) {  // the value s√E − R
        case TypedClaim::Bound::Value: g.right = tol_.close_value(c.value, s, E, Q(-R)); break;
        case TypedClaim::Bound::AtLeast: g.right = sign_minus_sqrt(c.value - tol_.abs + R, Q(s), E) <= 0; break;
        case TypedClaim::Bound::Below: g.right = sign_minus_sqrt(c.value + tol_.abs + R, Q(s), E) > 0; break;
        case TypedClaim::Bound::AtMost: g.right = sign_minus_sqrt(c.value + tol_.abs + R, Q(s), E) >= 0; break;
        }
        if (proof) proof->proof = hulls_proof(md, c);
        break;
    }
    case ClaimType::Distance: {
        const std::optional<ProvedDistance> pd = proved_distance(S, c.rho1, c.rho2, kAll);
        if (!pd) throw std::logic_error("RoundedRules: the distance did not close");
        const ExactDistance& e = pd->d;
        auto& d = g.set<DistanceJudged>();
        d.exact_squared = e.squared;
        d.exact_p1 = e.p1;
        d.exact_p2 = e.p2;
        // √E − R when the objects are apart (E > R²), else 0.
        const bool apart = e.squared > R * R;
        // A length: at LEN = 0 one below 0 is wrong, as on plain polyhedra (Tolerance::close_sq).
        d.value_right =
            (sgn(tol_.abs) > 0 || sgn(c.value) >= 0) &&
            (apart ? tol_.close_value(c.value, 1, e.squared, Q(-R)) : tol_.close_value(c.value, 0, Q(0), Q(0)));
        g.right = d.value_right;
        Json mp;
        if (c.closest) {
            const auto& [p, q] = *c.closest;
            const Vec3q pq = sub(q, p);
            d.closest_squared = pq[0] * pq[0] + pq[1] * pq[1] + pq[2] * pq[2];
            Json j1, j2;
            d.in1 = rounded_member(S, 0, c.rho1, m1, p, tol_, d.near1, proof ? &j1 : nullptr);
            d.in2 = rounded_member(S, 1, c.rho2, m2, q, tol_, d.near2, proof ? &j2 : nullptr);
            // |q − p| ≤ (1 + rel)·(√E − R) + 2·abs apart; ≤ 2·abs when the objects meet.
            const Q k = 1 + tol_.rel;
            const bool near_enough =
                apart ? sign_two_sqrts(k * R - 2 * tol_.abs, Q(1), d.closest_squared, Q(-k), e.squared) <= 0
                      : d.closest_squared <= 4 * tol_.abs * tol_.abs;
            d.closest_right = d.in1 && d.in2 && near_enough;
            g.right = g.right && *d.closest_right;
            if (proof) mp = Json{{"P1", std::move(j1)}, {"P2", std::move(j2)}};
        }
        if (proof) {
            proof->proof = distance_proof(nullptr, e, c.rho1, c.rho2);
            if (c.closest) proof->proof["closest"] = std::move(mp);
        }
        break;
    }
    case ClaimType::Depth: {
        const MeasuredDepth md = measure();
        auto& d = g.set<DepthJudged>();
        if (proof) proof->proof = hulls_proof(md, c);
        if (rounded_verdict(md, R) == Verdict::Separated) {
            d.separated = Verdict::Separated;
            g.right = false;
            break;
        }
        // The depth R − s√E (the hulls' depth + R, or R − their distance).
        const auto [s, E] = hull_signed(md);
        d.root_sign = -s;
        d.exact_squared = E;
        d.exact_direction = md.normal;
        d.value_right = (sgn(tol_.abs) > 0 || sgn(c.value) >= 0) && tol_.close_value(c.value, -s, E, R);
        g.right = *d.value_right;
        if (c.direction) {
            // Along u the objects part after t(u) + R, t(u) = h_M(u)/|u| the hulls' (signed): right
            // when that is at most (1 + rel)·depth + abs (it is never less than the depth).
            d.along = directional_depth_squared(S, *c.direction, c.rho1, c.rho2);
            const Q k = 1 + tol_.rel;
            d.direction_right = sign_two_sqrts(R - k * R - tol_.abs, Q(sgn(d.along)), abs(d.along), Q(k * s), E) <= 0;
            g.right = g.right && *d.direction_right;
        }
        break;
    }
    case ClaimType::Plane: {
        auto& d = g.set<PlaneJudged>();
        std::tie(d.c1, d.c2) = plane_extents(S, c.normal, c.rho1, c.rho2);
        g.right = rounded_plane_right(tol_, d.c1, d.c2, m1, m2, c.normal, c.offset);
        if (proof) proof->proof = Json::object();
        break;
    }
    case ClaimType::Witness: {
        auto& d = g.set<WitnessJudged>();
        Json j1, j2;
        d.in1 = rounded_member(S, 0, c.rho1, m1, c.point, tol_, d.near1, proof ? &j1 : nullptr);
        d.in2 = rounded_member(S, 1, c.rho2, m2, c.point, tol_, d.near2, proof ? &j2 : nullptr);
        if (c.with_verdict) d.exact_verdict = rounded_verdict(measure(), R);
        g.right = d.in1 && d.in2;
        if (proof) proof->proof = Json{{"P1", std::move(j1)}, {"P2", std::move(j2)}};
        break;
    }
    default: throw std::logic_error("RoundedRules: a claim of the curve");
    }
    return g;
}

std::string RoundedRules::certificate(Json entries) const {
    Json j;
    j["format"] = "scalecert-2";
    j["kind"] = "judgements";
    if (sgn(tol_.abs) > 0) j["abs_tolerance"] = to_exact_string(tol_.abs);
    j["tolerance"] = to_exact_string(tol_.rel);
    j["judgements"] = std::move(entries);
    // Each seed interior: with a radius, a point of the hull nearer than r ({"within": weights});
    // without, weights of hull vertices spanning 3 dimensions, as for any object.
    Json seeds;
    for (int i = 0; i < 2; ++i) {
        const PolyInput& in = scene_->P[i];
        seeds[i ? "P2" : "P1"] = sgn(in.radius) > 0
                                     ? Json{{"within", weights_json(point_to_body(*points_, i, Q(1), in.seed).w1)}}
                                     : weights_json(points_->interior_weights(i, in.seed));
    }
    j["seed_interior"] = std::move(seeds);
    j["scene"] = scene_json(*scene_);
    return dump(j);
}

}  // namespace scalecert::internal

namespace scalecert::internal {

namespace {
std::string fraction_columns(const Q& q) { return q.get_num().get_str() + "," + q.get_den().get_str(); }
}  // namespace

GoldenAnswers rounded_golden(const ExactScene& sc, const RoundedPoints& S, const GoldenPoints& points) {
    const std::pair<int, Vec3z> span = S.difference_span(S);  // (a lambda may not capture a binding)
    auto state = [&](const Q& r1, const Q& r2) {
        const MeasuredDepth md = hull_measure(S, span.first, span.second, r1, r2);
        const Q R = r1 * sc.P[0].radius + r2 * sc.P[1].radius;
        const auto [s, E] = hull_signed(md);
        return GoldenValue{rounded_verdict(md, R), s, E, R};
    };
    return sampled_golden(
        sc, [&](const Q& r1, const Q& r2) { return state(r1, r2).verdict; }, state, points);
}

GoldenAnswers sampled_golden(const ExactScene& sc, const std::function<Verdict(const Q&, const Q&)>& verdict,
                             const std::function<GoldenValue(const Q&, const Q&)>& state, const GoldenPoints& points) {
    validate(points);
    const bool parts = sc.made_of_parts();
    const char* value_key = parts ? "pair_signed_distance" : "signed_distance";
    const Q &lo1 = sc.lo[0], &hi1 = sc.hi[0], &lo2 = sc.lo[1], &hi2 = sc.hi[1];
    Json samples = Json::array(), queries = Json::array();
    std::string csv =
        std::string("rho1,rho2,where,verdict_at_doubles,") + value_key + (parts ? ",part1,part2" : "") + "\n";
    std::string rcsv = std::string(
                           "rho1_num,rho1_den,rho2_num,rho2_den,where,verdict,hulls_sign,hulls_squared_num,"
                           "hulls_squared_den,radius_sum_num,radius_sum_den") +
                       (parts ? ",part1,part2" : "") + "\n";
    const int V = lo1 == hi1 ? 1 : points.verticals;
    for (int k = 0; k < V; ++k) {
        const Q x = V == 1 ? lo1 : Q(lo1 + (hi1 - lo1) * k / (V - 1));
        Json sample{{"rho1", to_exact_string(x)}};
        const Verdict at_lo = verdict(x, lo2), at_hi = verdict(x, hi2);
        if (at_lo != Verdict::Separated || at_hi == Verdict::Separated) {
            // The set does not cross ρ1 × I2 inside it: say which side of it I2 lies.
            sample["crosses"] = false;
            sample["verdict_at_lo2"] = verdict_name(at_lo);
            sample["verdict_at_hi2"] = verdict_name(at_hi);
            samples.push_back(std::move(sample));
            continue;
        }
        // Bisection: a separated, b not; 60 halvings of I2 (or the touching pair, found exactly).
        Q a = lo2, b = hi2;
        std::optional<Q> on;
        for (int step = 0; step < 60 && !on; ++step) {
            const Q m = (a + b) / 2;
            const Verdict v = verdict(x, m);
            if (v == Verdict::Touching) on = m;
            (v == Verdict::Separated ? a : b) = m;
        }
        sample["crosses"] = true;
        sample["below"] = to_exact_string(a);  // separated
        sample["above"] = to_exact_string(b);  // not separated
        if (on) sample["touching"] = to_exact_string(*on);
        const Q y = on ? *on : Q((a + b) / 2);
        // The pairs near it: on it (the midpoint, or the touching pair), then 2^-k of each
        // coordinate above, below, right and left, each in I1 × I2.
        std::vector<std::pair<std::string, std::pair<Q, Q>>> near{{"on", {x, y}}};
        for (int o : points.offsets) {
            const std::string e = " 2^-" + std::to_string(o);
            const Q dy = y / Q(Z(1) << o), dx = x / Q(Z(1) << o);
            near.push_back({"above" + e, {x, y + dy}});
            near.push_back({"below" + e, {x, y - dy}});
            near.push_back({"right" + e, {x + dx, y}});
            near.push_back({"left" + e, {x - dx, y}});
        }
        for (const auto& [where, p] : near) {
            const auto& [qx, qy] = p;
            if (qx < lo1 || qx > hi1 || qy < lo2 || qy > hi2) continue;
            const double dx = double_in(qx, lo1, hi1), dy = double_in(qy, lo2, hi2);
            const Q ex = exact_from_double(dx), ey = exact_from_double(dy);
            const GoldenValue g = state(ex, ey);
            const Verdict v = g.verdict;
            const int s = g.s;
            const Q &E = g.E, &R = g.R;
            const double value = s == 0 || sgn(E) == 0 ? to_double_rn(Q(-R))
                                 : s > 0               ? sqrt_minus_rn(E, R)
                                                       : -sqrt_minus_rn(E, Q(-R));
            queries.push_back(Json{{"rho1", to_exact_string(ex)},
                                   {"rho2", to_exact_string(ey)},
                                   {"rho1_double", dx},
                                   {"rho2_double", dy},
                                   {"where", where},
                                   {"near", to_exact_string(x)},
                                   {"verdict_at_doubles", verdict_name(v)},
                                   {value_key, Json{{"hulls_sign", s},
                                                    {"hulls_squared", to_exact_string(E)},
                                                    {"radius_sum", to_exact_string(R)},
                                                    {"value_double", value}}}});
            const std::string pair_columns = parts ? "," + std::to_string(g.a) + "," + std::to_string(g.b) : "";
            if (parts) queries.back()[value_key]["pair"] = Json::array({g.a, g.b});
            char buf[160];
            std::snprintf(buf, sizeof buf, "%.17g,%.17g,", dx, dy);
            char val[40];
            std::snprintf(val, sizeof val, "%.17g", value);
            csv += std::string(buf) + where + "," + verdict_name(v) + "," + val + pair_columns + "\n";
            rcsv += fraction_columns(ex) + "," + fraction_columns(ey) + "," + where + "," + verdict_name(v) + "," +
                    std::to_string(s) + "," + fraction_columns(E) + "," + fraction_columns(R) + pair_columns + "\n";
        }
        samples.push_back(std::move(sample));
    }
    Json doc{{"format", "scalecert-2"},
             {"kind", "touching_samples"},
             {"scene", scene_file_json(sc)},
             {"samples", std::move(samples)}};
    return {std::move(doc), std::move(queries), std::move(csv), std::move(rcsv)};
}

}  // namespace scalecert::internal
