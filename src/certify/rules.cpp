// The rules of certificates/CLAIMS.md on typed claims, each applied once. Squares are compared
// for distances and depths: no root is taken.
#include "certify/claim.hpp"
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
    }
    return "";
}

const char* claimed_name(Claimed v) {
    switch (v) {
    case Claimed::Separated: return verdict_name(Verdict::Separated);
    case Claimed::Touching: return verdict_name(Verdict::Touching);
    case Claimed::Overlapping: return verdict_name(Verdict::Overlapping);
    case Claimed::Intersecting: return "intersecting";  // the one claimed verdict that is not an exact one
    }
    return "";
}

std::optional<Claimed> claimed_of(const std::string& name) {
    for (Claimed v : {Claimed::Separated, Claimed::Touching, Claimed::Overlapping, Claimed::Intersecting})
        if (name == claimed_name(v)) return v;
    return std::nullopt;
}

bool verdict_matches(Claimed claimed, Verdict exact) {
    switch (claimed) {
    case Claimed::Separated: return exact == Verdict::Separated;
    case Claimed::Touching: return exact == Verdict::Touching;
    case Claimed::Overlapping: return exact == Verdict::Overlapping;
    case Claimed::Intersecting: return exact != Verdict::Separated;
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

namespace {
// A plane claim's rule (CLAIMS.md): c1 = max over P1(ρ1) of n·x, c2 = min over P2(ρ2). Exact: the
// plane separates strictly (the offset strictly between). Within abs: each body lies within abs of
// its side, c1 − o ≤ abs·|n| and o − c2 ≤ abs·|n| (with no offset, for some o: c1 − c2 ≤ 2·abs·|n|).
bool plane_right(const Tolerance& tol, const Q& c1, const Q& c2, const Vec3q& n, const std::optional<Q>& offset) {
    if (sgn(tol.abs) == 0) return c1 < c2 && (!offset || (c1 < *offset && *offset < c2));
    const Q N = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (!offset) return tol.within_abs(c1 - c2, 4 * N);
    return tol.within_abs(c1 - *offset, N) && tol.within_abs(*offset - c2, N);
}
}  // namespace

namespace {
std::string ex(const Q& q) { return to_exact_string(q); }
Json ex3(const Vec3q& v) { return Json::array({ex(v[0]), ex(v[1]), ex(v[2])}); }
Json ex_pair(const Q& a, const Q& b) { return Json::array({ex(a), ex(b)}); }
Vec3q diff(const Vec3q& a, const Vec3q& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Q dot3(const Vec3q& a, const Vec3q& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
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
    default: break;
    }
    return j;
}
}  // namespace

// ---- two convex objects ----------------------------------------------------------------------

namespace {
// The depth rule (CLAIMS.md, penetration_depth) on a measured depth md: wrong for a separated
// pair; else the value against the exact depth, and a claimed direction n by the squared depth
// along it, along(n) (moving P2 that far along n separates them exactly iff n attains the least).
void depth_rule(const TypedClaim& c, const MeasuredDepth& md, const Tolerance& tol, Judged& g,
                const std::function<Q(const Vec3q&)>& along) {
    auto& d = g.set<DepthJudged>();
    if (md.state == Verdict::Separated) {
        d.separated = Verdict::Separated;
        g.right = false;
        return;
    }
    d.exact_squared = md.state == Verdict::Touching ? Q(0) : md.depth->squared;
    d.exact_direction = md.normal;
    d.value_right = tol.close_sq(c.value, *d.exact_squared);
    g.right = *d.value_right;
    if (c.direction) {
        d.along = along(*c.direction);
        d.direction_right = tol.within_above(d.along, *d.exact_squared);
        g.right = g.right && *d.direction_right;
    }
}
}  // namespace

struct ConvexRules::Impl {
    Impl(const ClaimModels& m, const Tolerance& tolerance) : models(m), tol(tolerance) {}
    const ClaimModels& models;
    Tolerance tol;
    long distance_fallbacks = 0, depth_fallbacks = 0;
    using Curve = ClaimModels::Curve;
    std::optional<std::vector<ExactSwitch>> switches;  // the whole curve's switch points (built on first use)
    std::vector<ExactSwitch> walk_switches;

    // The two exact polyhedra, with no contact line: the measures' fallbacks.
    const Model& hulls() const { return models.hulls(); }
    // The whole curve on the hull model (within the limits: Session::claim_hull).
    Curve whole() const { return {&models.hull_model(), &models.hull_curve(), Q(0), std::nullopt}; }
    // The point set for the measures: the cloud's trees on a walked scene (exact for every
    // normal), else the exact polyhedra's vertices.
    const PointSets& points() const { return posed ? *posed : models.points(); }
    // A claim at poses (CLAIMS.md, "Poses") is judged by the same rules from support queries on
    // the moved points (PosedPoints: no model is built for the pose), each proof a support proof
    // that the checker verifies on the moved vertices: a verdict's is its depth's. The proved
    // distances' rounds are unbounded there (each adds a point: they always close).
    const PosedPoints* posed = nullptr;
    static constexpr int kAll = std::numeric_limits<int>::max();
    // Is x in P_i(ρ)? With its proof when asked.
    bool member(int i, const Q& rho, const Vec3q& x, Json* proof) const {
        if (!posed) return models.member(i, rho, x, proof);
        const std::optional<bool> in = membership_by_points(*posed, i, rho, x, proof, kAll);
        if (!in) throw std::logic_error("certify-fp: a posed membership did not close");
        return *in;
    }
    // The exact verdict; at poses, the depth's.
    Verdict exact_verdict(const Q& r1, const Q& r2) {
        if (!posed) return models.verdict(r1, r2);
        return depth_of(r1, r2).state;
    }

    // Whether x is in P1(ρ1) and y in P2(ρ2) (or, at an absolute tolerance, within it of them),
    // with their proofs in *proof when given. `known`: the exact closest points, with their
    // weights when known: a claimed point within the tolerance of its body's is near at once.
    // m.in1, m.in2 (and m.near1, m.near2: outside, within the tolerance).
    void members(const Q& r1, const Q& r2, const Vec3q& x, const Vec3q& y, Membership& g, Json* proof,
                 const ExactDistance* known = nullptr) const {
        auto one = [&](int i, const Q& r, const Vec3q& v, Json* pj, bool& near) {
            near = false;
            if (sgn(tol.abs) > 0 && known) {
                const auto& w = i == 0 ? known->w1 : known->w2;
                const Vec3q d = diff(v, i == 0 ? known->p1 : known->p2);
                if (!w.empty() && dot3(d, d) <= tol.abs * tol.abs) {
                    // Near its body's closest point; in the body, it is said to be in it. Beyond
                    // the slab between the closest points (u = p2 − p1: max over P1 of u·y is
                    // u·p1, min over P2 is u·p2) it is outside at once; else it is placed exactly.
                    const Vec3q u = diff(known->p2, known->p1);
                    const Q along = i == 0 ? Q(dot3(u, v) - dot3(u, known->p1)) : Q(dot3(u, known->p2) - dot3(u, v));
                    near = sgn(known->squared) > 0 && sgn(along) > 0 ? true : !member(i, r, v, nullptr);
                    if (pj) *pj = Json{{"near", weights_json(w)}};
                    return true;
                }
            }
            if (member(i, r, v, pj)) return true;
            near = sgn(tol.abs) > 0 && near_proof(points(), i, r, v, tol.abs, pj);
            return near;
        };
        Json p1, p2;
        g.in1 = one(0, r1, x, proof ? &p1 : nullptr, g.near1);
        g.in2 = one(1, r2, y, proof ? &p2 : nullptr, g.near2);
        if (proof) *proof = Json{{"P1", std::move(p1)}, {"P2", std::move(p2)}};
    }

    // The exact switch points where V proves the curve: every break of ρ2 = f(ρ1) at ρ1 > 0
    // with ρ2 > 0, inside I1 or not, with its contact (on the whole curve: built once).
    std::vector<ExactSwitch> switches_of(const Curve& V) const {
        std::vector<ExactSwitch> out;
        const auto& P = V.curve->env.pieces;
        for (size_t k = 0; k + 1 < P.size(); ++k) {
            const Q& x = *P[k].to;
            const ContactLine &L = V.model->lines[P[k].line], &R = V.model->lines[P[k + 1].line];
            const Q y = L.at(x);
            if (sgn(x) <= 0 || !V.proves(x)) continue;
            if (sgn(y) <= 0) break;  // f descends: nothing touches from here on
            out.push_back({x, y, contact_at(*V.model, L, R, x, y).label});
        }
        return out;
    }
    const std::vector<ExactSwitch>& exact_switches(const Curve& V) {
        if (!V.whole()) {
            walk_switches = switches_of(V);
            return walk_switches;
        }
        if (!switches) switches = switches_of(V);
        return *switches;
    }

    // The exact distance, proved from the points' supports; CGAL's QP over every hull vertex when
    // the proof does not close (counted).
    ExactDistance exact_distance_of(const Q& r1, const Q& r2) {
        if (posed) {
            const std::optional<ProvedDistance> pd = proved_distance(*posed, r1, r2, kAll);
            if (!pd) throw std::logic_error("certify-fp: a posed distance did not close");
            return pd->d;
        }
        if (std::optional<ProvedDistance> pd = proved_distance(points(), r1, r2)) return pd->d;
        ++distance_fallbacks;
        return exact_distance(hulls(), r1, r2);
    }
    // The depth with what proves it (measured_depth); when the distance's proof does not close,
    // from CGAL's exact distance and the EPA on the hull's vertices (counted).
    MeasuredDepth depth_of(const Q& r1, const Q& r2) {
        if (posed) {
            const std::optional<MeasuredDepth> md = measured_depth(*posed, r1, r2, kAll);
            if (!md) throw std::logic_error("certify-fp: a posed depth did not close");
            return *md;
        }
        if (std::optional<MeasuredDepth> d = measured_depth(points(), r1, r2)) return *d;
        ++depth_fallbacks;
        return depth_from_distance(HullPoints(hulls()), exact_distance(hulls(), r1, r2), r1, r2);
    }

    // Where the curve reaches ρ2 = 0: on its last piece (it goes on as one line from there).
    static Q zero_crossing(const Curve& V) {
        const ContactLine& L = V.model->lines[V.curve->env.pieces.back().line];
        return std::max(Q(0), Q(-L.intercept / L.slope));
    }

    // ρ1 with f(ρ1) = y (f is strictly decreasing), or none outside f's range over ρ1 ≥ 0; f as
    // V has it (the exact curve where V proves it).
    static std::optional<Q> inverse(const Curve& V, const Q& y) {
        for (const EnvPiece& p : V.curve->env.pieces) {
            const ContactLine& L = V.model->lines[p.line];
            const Q x = (y - L.intercept) / L.slope;
            if (x >= p.from && (!p.to || x <= *p.to)) return x;
        }
        return std::nullopt;
    }

    void verdict(const TypedClaim& c, Judged& g, Proof* proof) {
        auto& d = g.set<VerdictJudged>();
        if (posed && !proof) {
            // Without a certificate, the verdict alone where a few support queries prove it.
            if (const std::optional<Verdict> v = proved_verdict(*posed, c.rho1, c.rho2)) {
                d.exact = *v;
                g.right = verdict_matches(c.verdict, d.exact);
                return;
            }
        }
        if (posed) {
            const MeasuredDepth md = depth_of(c.rho1, c.rho2);
            d.exact = md.state;
            g.right = verdict_matches(c.verdict, d.exact);
            if (proof) proof->proof = Json{{"depth", depth_proof(nullptr, md, c.rho1, c.rho2)}};
            return;
        }
        const Verdict e = models.verdict(c.rho1, c.rho2);
        g.right = verdict_matches(c.verdict, e);
        d.exact = e;
        d.rho2_minus_curve = c.rho2 - models.curve_value(c.rho1);
        if (proof) {
            const auto [pm, r] = models.certified_query(c.rho1, c.rho2);
            if (r.verdict != e) throw std::logic_error("certify-fp: the certified verdict and the exact one differ");
            proof->proof = verdict_proof(*pm, r);
        }
    }

    void growth(const TypedClaim& c, Judged& g, Proof* proof) {
        auto& d = g.set<GrowthJudged>();
        d.exact = models.growth();
        g.right = tol.close(c.value, d.exact);
        if (proof) {
            proof->proof = models.growth_proof();
            if (proof->proof["value"] != ex(d.exact))
                throw std::logic_error("certify-fp: the proved growth distance and the exact one differ");
        }
    }

    void curve_point(const TypedClaim& c, Judged& g, Proof* proof) {
        auto& d = g.set<CurvePointJudged>();
        d.exact = models.curve_value(c.rho1);
        g.right = sgn(d.exact) > 0 && tol.close(c.rho2, d.exact);
        if (proof) {
            const Curve V = models.curve_around(c.rho1, c.rho1);
            proof->proof = curve_proof(*V.model, *V.curve, c.rho1, c.rho1);
        }
    }

    void switch_point(const TypedClaim& c, Judged& g, Proof* proof) {
        auto& d = g.set<SwitchPointJudged>();
        const Q &r1 = c.rho1, &r2 = c.rho2, &t = tol.rel;
        // Every ρ1 within the tolerance of the claim's (|x − ρ1| <= tol·x) lies in [lo, hi]: the
        // walk proves the curve over a window holding it; a tolerance of 1 or more needs the whole
        // curve (on to where it reaches ρ2 = 0, past every switch point).
        const Q lo = r1 / (1 + t);
        const Curve V = t < 1 ? models.curve_around(lo, Q(r1 / (1 - t))) : whole();
        const auto& exs = exact_switches(V);
        d.window_whole = V.whole();
        d.window_lo = V.lo_proved;
        d.window_hi = V.hi_proved;
        if (exs.empty()) {
            // The proof: the whole curve from ρ1 = 0 to past where it reaches ρ2 = 0, or the window.
            if (proof) {
                proof->proof = V.whole() ? curve_proof(*V.model, *V.curve, Q(0), zero_crossing(V))
                                         : curve_proof(*V.model, *V.curve, lo, Q(r1 / (1 - t)));
            }
            g.right = false;
            return;
        }
        // Right when some exact switch point matches (both coordinates within the tolerance, and
        // the contact when claimed): the judgement names the first that does, else the nearest in ρ1.
        const ExactSwitch* best = nullptr;
        for (const ExactSwitch& s : exs)
            if (tol.close(r1, s.rho1) && tol.close(r2, s.rho2) && (!c.contact || *c.contact == s.label)) {
                best = &s;
                break;
            }
        d.matched = best != nullptr;
        if (!best) {
            best = &exs.front();
            for (const ExactSwitch& s : exs)
                if (abs(Q(s.rho1 - r1)) < abs(Q(best->rho1 - r1))) best = &s;
        }
        d.nearest = *best;
        // The proof: the curve over a window holding every ρ1 within the tolerance of the claim's
        // (from ρ1/(1 + tol) to ρ1/(1 − tol), or on to where the curve reaches ρ2 = 0 when tol >= 1).
        if (proof) {
            const Q hi = t < 1 ? Q(r1 / (1 - t)) : std::max(r1, zero_crossing(V));
            proof->proof = curve_proof(*V.model, *V.curve, lo, hi);
        }
        if (c.contact) d.contact_right = *c.contact == best->label;
        g.right = d.matched;
    }

    // A curve claim: the rules of CLAIMS.md ("Curve claims").
    void curve(const TypedClaim& c, Judged& g, Proof* proof) {
        auto& d = g.set<CurveJudged>();
        const ClaimedCurve& k = *c.curve;
        const auto& segs = k.segments;
        const Q lo = segs.front().x0, hi = segs.back().x1;
        // The curve proved over a window around [lo, hi], and around every ρ1 where f takes a
        // claimed end's ρ2 (the horizontal error): walked wider until it is, a few rounds, else
        // the whole curve.
        Curve V = models.curve_around(lo, hi);
        for (int round = 0; !V.whole(); ++round) {
            Q need_lo = lo, need_hi = hi;
            bool fits = true, whole_needed = false;
            for (const CurveSegment& s : segs)
                for (const Q& y : {s.y0, s.y1}) {
                    const std::optional<Q> x = inverse(V, y);
                    if (x && V.proves(*x)) continue;
                    fits = false;
                    if (!x || sgn(*x) <= 0)
                        whole_needed = true;  // at or before ρ1 = 0 on the walked lines
                    else
                        need_lo = std::min(need_lo, *x), need_hi = std::max(need_hi, *x);
                }
            if (fits) break;
            V = whole_needed || round == 8 ? whole() : models.curve_around(need_lo, need_hi);
        }
        const TouchingCurve& cv = *V.curve;
        const Model& mv = *V.model;
        if (proof) proof->proof = curve_proof(mv, cv, lo, hi);
        // Vertical error: on a stretch where the claim and f are both linear, so is their
        // difference (and so are the tolerance's bounds), so the claimed ends and the exact
        // breaks inside each segment suffice.
        const auto& exs = exact_switches(V);
        Q max_v = 0, max_h = 0, worst_v_at = lo;
        bool within = true;
        auto check_v = [&](const Q& x, const Q& y) {
            const Q f = cv.env.value(mv.lines, x);
            const Q e = abs(Q(y - f));
            if (e > max_v) max_v = e, worst_v_at = x;
            within = within && tol.close(y, f);
        };
        for (const CurveSegment& s : segs) {
            check_v(s.x0, s.y0);
            check_v(s.x1, s.y1);
            for (const EnvPiece& p : cv.env.pieces)
                if (p.to && *p.to > s.x0 && *p.to < s.x1)
                    check_v(*p.to, s.y0 + (s.y1 - s.y0) * (*p.to - s.x0) / (s.x1 - s.x0));
            for (const auto& [x, y] : {std::pair{s.x0, s.y0}, std::pair{s.x1, s.y1}})
                if (auto xi = inverse(V, y)) max_h = std::max(max_h, Q(abs(Q(*xi - x))));
        }
        // Nothing touches where f ≤ 0; f descends, so it is > 0 on the whole range iff at hi.
        d.exact_positive = sgn(cv.env.value(mv.lines, hi)) > 0;
        d.max_vertical = max_v;
        d.max_vertical_at = worst_v_at;
        d.max_horizontal = max_h;
        // Switch points: the exact ones in the closed range [lo, hi], each matched with the claimed
        // one nearest to it in ρ1 when that one's nearest exact switch is it. An exact switch
        // strictly inside the range that is not matched is missed; one at an end of the range
        // may go unclaimed. A claimed one not matched is extra; a matched pair must agree in ρ1
        // and ρ2 within the tolerance, or it is misplaced.
        const auto& claimed = k.switches;
        std::vector<const ExactSwitch*> exact;
        for (const ExactSwitch& s : exs)
            if (s.rho1 >= lo && s.rho1 <= hi) exact.push_back(&s);
        auto nearest_claimed = [&](const Q& x) {
            size_t b = 0;
            for (size_t i = 1; i < claimed.size(); ++i)
                if (abs(Q(claimed[i].first - x)) < abs(Q(claimed[b].first - x))) b = i;
            return b;
        };
        auto nearest_exact = [&](const Q& x) {
            size_t b = 0;
            for (size_t i = 1; i < exact.size(); ++i)
                if (abs(Q(exact[i]->rho1 - x)) < abs(Q(exact[b]->rho1 - x))) b = i;
            return b;
        };
        std::vector<bool> used(claimed.size(), false);
        for (size_t i = 0; i < exact.size(); ++i) {
            const bool at_end = exact[i]->rho1 == lo || exact[i]->rho1 == hi;
            size_t n = 0;
            if (claimed.empty() || nearest_exact(claimed[n = nearest_claimed(exact[i]->rho1)].first) != i) {
                if (!at_end) d.missed.push_back({exact[i]->rho1, exact[i]->rho2});
                continue;
            }
            used[n] = true;
            if (!tol.close(claimed[n].first, exact[i]->rho1) || !tol.close(claimed[n].second, exact[i]->rho2))
                d.misplaced.push_back({exact[i]->rho1, exact[i]->rho2, claimed[n].first, claimed[n].second});
        }
        for (size_t n = 0; n < claimed.size(); ++n)
            if (!used[n]) d.extra.push_back(claimed[n]);
        // Contacts: the exact contact at each claimed piece's midpoint.
        for (const CurveSegment& s : segs) {
            if (!s.contact) continue;
            const Q mid = (s.x0 + s.x1) / 2;
            // At an exact switch point the contact is the switch point's.
            std::string e =
                d.exact_positive ? piece_contact(mv, cv.env.pieces[cv.env.locate(mid)]).label : std::string("none");
            for (const ExactSwitch& sw : exs)
                if (sw.rho1 == mid) e = sw.label;
            if (*s.contact != e) d.wrong_contacts.push_back({mid, *s.contact, e});
        }
        g.right = d.exact_positive && within && d.missed.empty() && d.extra.empty() && d.misplaced.empty() &&
                  d.wrong_contacts.empty();
    }

    void plane(const TypedClaim& c, Judged& g, Proof* proof) {
        auto& d = g.set<PlaneJudged>();
        std::tie(d.c1, d.c2) = plane_extents(points(), c.normal, c.rho1, c.rho2);
        g.right = plane_right(tol, d.c1, d.c2, c.normal, c.offset);
        if (proof) proof->proof = Json::object();
    }

    void witness(const TypedClaim& c, Judged& g, Proof* proof) {
        auto& d = g.set<WitnessJudged>();
        Json mp;
        members(c.rho1, c.rho2, c.point, c.point, d, proof ? &mp : nullptr);
        d.exact_verdict = exact_verdict(c.rho1, c.rho2);
        g.right = d.in1 && d.in2;
        if (proof) proof->proof = std::move(mp);
    }

    void distance(const TypedClaim& c, Judged& g, Proof* proof) {
        auto& d = g.set<DistanceJudged>();
        const ExactDistance e = exact_distance_of(c.rho1, c.rho2);
        d.exact_squared = e.squared;
        d.exact_p1 = e.p1;
        d.exact_p2 = e.p2;
        d.value_right = tol.close_sq(c.value, e.squared);
        g.right = d.value_right;
        if (proof) proof->proof = distance_proof(nullptr, e, c.rho1, c.rho2);
        if (c.closest) {
            const auto& [p, q] = *c.closest;
            const Vec3q pq = diff(q, p);
            d.closest_squared = dot3(pq, pq);
            Json mp;
            members(c.rho1, c.rho2, p, q, d, proof ? &mp : nullptr, &e);
            d.closest_right = d.in1 && d.in2 && tol.within_above(d.closest_squared, e.squared, 2);
            g.right = g.right && *d.closest_right;
            if (proof) proof->proof["closest"] = std::move(mp);
        }
    }

    void depth(const TypedClaim& c, Judged& g, Proof* proof) {
        // The exact squared depth (none when separated) and a minimising direction, with its proof.
        const MeasuredDepth md = depth_of(c.rho1, c.rho2);
        if (proof) proof->proof = depth_proof(nullptr, md, c.rho1, c.rho2);
        depth_rule(c, md, tol, g,
                   [&](const Vec3q& n) { return directional_depth_squared(points(), n, c.rho1, c.rho2); });
    }
};

ConvexRules::ConvexRules(const ClaimModels& models, const Tolerance& tolerance)
    : ClaimRules(tolerance), impl_(new Impl(models, tolerance)) {}
ConvexRules::~ConvexRules() = default;
std::optional<std::array<long, 2>> ConvexRules::fallbacks() const {
    return std::array<long, 2>{impl_->distance_fallbacks, impl_->depth_fallbacks};
}
std::string ConvexRules::certificate(Json entries) const {
    return judgements_text(impl_->models.document(), tol_.rel, tol_.abs, std::move(entries));
}

namespace {
// A part pair {part of P1, part of P2} checked against the objects' part counts.
void check_part_pair(const std::array<int, 2>& pair, const size_t counts[2], const std::string& where) {
    for (size_t k = 0; k < 2; ++k)
        if (pair[k] < 0 || static_cast<size_t>(pair[k]) >= counts[k])
            throw InputError(where + ".parts[" + std::to_string(k) + "]: P" + std::to_string(k + 1) + " has " +
                             std::to_string(counts[k]) + (counts[k] == 1 ? " part" : " parts") + " (numbered from 0)");
}
}  // namespace

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

Judged ConvexRules::judge(const TypedClaim& c, Proof* proof) {
    Judged g;
    if (proof) proof->claim = exact_claim_json(c);
    if (no_answer(c, proof)) return g;
    std::optional<PosedPoints> at;  // the points moved by the claim's poses, for its judgement
    if (c.posed()) {
        if (c.type != ClaimType::Verdict && c.type != ClaimType::Plane && c.type != ClaimType::Witness &&
            c.type != ClaimType::Distance && c.type != ClaimType::Depth)
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
    case ClaimType::Verdict: {
        auto& jd = g.set<VerdictJudged>();
        const CompoundVerdict e = judge_.verdict(c.rho1, c.rho2, p);
        jd.exact = e.verdict;
        g.part1 = e.part1;
        g.part2 = e.part2;
        g.right = verdict_matches(c.verdict, jd.exact);
        break;
    }
    case ClaimType::Plane: {
        auto& jd = g.set<PlaneJudged>();
        std::tie(jd.c1, jd.c2) = judge_.plane_extents(c.normal, c.rho1, c.rho2);
        g.right = plane_right(tol_, jd.c1, jd.c2, c.normal, c.offset);
        if (p) *p = Json::object();
        break;
    }
    case ClaimType::Witness: {
        auto& jd = g.set<WitnessJudged>();
        Json p1, p2;
        jd.in_part1 = place(0, c.rho1, c.point, p ? &p1 : nullptr, &jd.near1);
        jd.in_part2 = place(1, c.rho2, c.point, p ? &p2 : nullptr, &jd.near2);
        jd.in1 = jd.in_part1 >= 0;
        jd.in2 = jd.in_part2 >= 0;
        jd.exact_verdict = judge_.verdict(c.rho1, c.rho2).verdict;
        g.right = jd.in1 && jd.in2;
        if (p) *p = Json{{"P1", std::move(p1)}, {"P2", std::move(p2)}};
        break;
    }
    case ClaimType::Distance: {
        auto& jd = g.set<DistanceJudged>();
        Json pp;
        const CompoundJudge::Distance e = judge_.distance(c.rho1, c.rho2, p ? &pp : nullptr);
        jd.exact_squared = e.squared;
        jd.exact_p1 = e.p1;
        jd.exact_p2 = e.p2;
        g.part1 = e.part1;
        g.part2 = e.part2;
        jd.value_right = tol_.close_sq(c.value, e.squared);
        g.right = jd.value_right;
        if (c.closest) {
            const auto& [a, b] = *c.closest;
            const Vec3q ab = diff(b, a);
            jd.closest_squared = dot3(ab, ab);
            Json m1, m2;
            // At an absolute tolerance, a claimed point within it of the exact closest point of its
            // object (in part k, with its weights in the distance's proof) is near at once.
            auto at = [&](int i, const Vec3q& x, Json* pj, bool* near) {
                const Vec3q d = diff(x, i == 0 ? e.p1 : e.p2);
                const int k = i == 0 ? e.part1 : e.part2;
                const Q& rho = i == 0 ? c.rho1 : c.rho2;
                if (sgn(tol_.abs) > 0 && k >= 0 && dot3(d, d) <= tol_.abs * tol_.abs) {
                    if (pj) *pj = Json{{"part", k}, {"near", pp[i == 0 ? "P1" : "P2"]}};
                    *near = judge_.locate(i, rho, x) < 0;  // in some part, it is said to be in it
                    return k;
                }
                return place(i, rho, x, pj, near);
            };
            jd.in_part1 = at(0, a, p ? &m1 : nullptr, &jd.near1);
            jd.in_part2 = at(1, b, p ? &m2 : nullptr, &jd.near2);
            jd.in1 = jd.in_part1 >= 0;
            jd.in2 = jd.in_part2 >= 0;
            jd.closest_right = jd.in1 && jd.in2 && tol_.within_above(jd.closest_squared, e.squared, 2);
            g.right = g.right && *jd.closest_right;
            if (p) pp["closest"] = Json{{"P1", std::move(m1)}, {"P2", std::move(m2)}};
        }
        if (p) *p = std::move(pp);
        break;
    }
    case ClaimType::Depth: {
        // One part pair's depth, by the rule for two convex objects (the parts scaled about their
        // objects' seeds); its proof that rule's, over the two parts' own points.
        if (!c.parts) throw std::logic_error("PartsRules: a depth with no part pair");
        const int a = (*c.parts)[0], b = (*c.parts)[1];
        g.part1 = a;
        g.part2 = b;
        const MeasuredDepth md = judge_.pair_depth(a, b, c.rho1, c.rho2, p);
        depth_rule(c, md, tol_, g,
                   [&](const Vec3q& n) { return judge_.pair_directional_depth(a, b, n, c.rho1, c.rho2); });
        break;
    }
    default: break;
    }
    return g;
}

}  // namespace scalecert::internal
