// certify-fp for JSON claims: every output a floating-point collision program produces, checked
// exactly. Squares are compared for distances and depths; no root is taken on the certified path
// (the display doubles of |claimed − exact| use MPFR's correctly rounded square root).
#include "certify/claims.hpp"
#include "certify/certificate.hpp"
#include "certify/compound_judge.hpp"
#include "certify/region_certificate.hpp"
#include "certify/judgements.hpp"
#include "geometry/measures.hpp"
#include "io/strict_json.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>

namespace scalecert::internal {

namespace {

void put_point(Json& o, const std::string& key, const Vec3q& v) {
    o[key] = Json::array({to_exact_string(v[0]), to_exact_string(v[1]), to_exact_string(v[2])});
}

std::string dbl(double d, int digits = 6) {
    char b[40];
    std::snprintf(b, sizeof b, "%.*g", digits, d);
    return b;
}
// "p/q (~d)": the exact value and its nearest double, to `digits` significant digits (the JSON
// claims' report uses 6, the line format's 17).
std::string num(const Q& q, int digits = 6) { return to_exact_string(q) + " (~" + dbl(to_double_rn(q), digits) + ")"; }
std::string ex(const Q& q) { return to_exact_string(q); }
Json ex3(const Vec3q& v) { return Json::array({ex(v[0]), ex(v[1]), ex(v[2])}); }

}  // namespace

// Is x in P_i(ρ) on the exact polyhedra, with its proof.
bool hull_member(const Model& m, int i, const Q& rho, const Vec3q& x, Json* proof) {
    bool inside = false;
    if (proof) *proof = membership_proof(m, i, rho, x, &inside);
    else inside = contains(m, i, rho, x);
    return inside;
}

namespace {

// Reading one claim's fields (every number exact: a JSON number is the double it was read as
// unless exact_decimals) and the tolerance's rules, for the convex and the compound certifier.
class ClaimReader {
public:
    // With `prove`: the last claim run as exact values, and the proof of its judgement.
    std::optional<std::pair<Json, Json>> proof;

protected:
    ClaimReader(const std::string& name, const ClaimOptions& opt, bool prove) : name_(name), opt_(opt), prove_(prove) {}
    std::string name_, where_;
    ClaimOptions opt_;
    bool prove_;  // write the proof of each judgement (certify-fp --certificate)

    [[noreturn]] void fail(const std::string& key, const std::string& what) const {
        throw InputError(where_ + (key.empty() ? "" : "." + key) + ": " + what);
    }
    // The start of every claim: its place for messages, its kind, both in the report.
    std::string begin(const JNode& claim, size_t index, Json& o) {
        proof.reset();
        where_ = name_ + ": claims[" + std::to_string(index) + "]";
        if (claim.kind != JNode::Object) fail("", "expected an object with \"kind\"");
        const std::string kind = str(claim, "kind");
        o["index"] = index;
        o["kind"] = kind;
        return kind;
    }
    void only(const JNode& o, std::initializer_list<const char*> keys) const {
        for (const std::string& k : o.keys)
            if (std::none_of(keys.begin(), keys.end(), [&](const char* x) { return k == x; })) fail(k, "unknown field");
    }
    const JNode& need(const JNode& o, const char* key) const {
        const JNode* n = o.find(key);
        if (!n) fail(key, "missing");
        return *n;
    }
    std::string str(const JNode& o, const char* key) const {
        const JNode& n = need(o, key);
        if (n.kind != JNode::String) fail(key, "expected a string");
        return n.text;
    }
    Q number(const JNode& n, const std::string& key) const {
        if (n.kind != JNode::Number && n.kind != JNode::String) fail(key, "expected a number or a string such as \"3/7\"");
        const bool as_double = !opt_.exact_decimals && n.kind == JNode::Number;
        Q q;
        try {
            q = parse_number(n.text, as_double);
        } catch (const InputError& e) {
            fail(key, e.what());
        }
        return q;
    }
    Q field(const JNode& o, const char* key) const { return number(need(o, key), key); }
    Vec3q point(const JNode& n, const std::string& key) const {
        if (n.kind != JNode::Array || n.items.size() != 3) fail(key, "expected 3 numbers");
        return {number(n.items[0], key), number(n.items[1], key), number(n.items[2], key)};
    }
    std::pair<Q, Q> pair_at(const JNode& o) const {
        const Q r1 = field(o, "rho1"), r2 = field(o, "rho2");
        if (sgn(r1) <= 0) fail("rho1", "scalings must be > 0 (got " + to_exact_string(r1) + ")");
        if (sgn(r2) <= 0) fail("rho2", "scalings must be > 0 (got " + to_exact_string(r2) + ")");
        return {r1, r2};
    }
    std::optional<std::string> label(const JNode& o) const {
        const JNode* n = o.find("contact");
        if (!n) return std::nullopt;
        if (n->kind != JNode::String || n->text.size() != 2 || n->text.find_first_not_of("VEF") != std::string::npos)
            fail("contact", "expected a contact such as \"VE\"");
        return n->text;
    }
    // Within the relative tolerance: |c − e| ≤ tol·|e| (exact).
    bool close(const Q& c, const Q& e) const { return abs(Q(c - e)) <= opt_.tolerance * abs(e); }
    // Claimed c ≥ 0 against an exact square E: (1 − tol)² E ≤ c² ≤ (1 + tol)² E.
    bool close_sq(const Q& c, const Q& E) const {
        if (sgn(c) < 0) return false;
        const Q lo = (1 - opt_.tolerance), hi = (1 + opt_.tolerance);
        const Q c2 = c * c;
        return (sgn(lo) <= 0 || lo * lo * E <= c2) && c2 <= hi * hi * E;
    }
    // A squared length x that cannot be below the exact minimum E (a pair of points in the bodies,
    // the depth along a direction), within the tolerance above it: E ≤ x ≤ (1 + tol)² E.
    bool within_above(const Q& x, const Q& E) const {
        return E <= x && x <= (1 + opt_.tolerance) * (1 + opt_.tolerance) * E;
    }
    // claimed, exact, and the absolute and relative errors (exact, with nearest doubles).
    void errors(Json& o, const Q& claimed, const Q& exact) const {
        put_exact(o, "claimed", claimed);
        put_exact(o, "exact", exact);
        const Q err = abs(Q(claimed - exact));
        put_exact(o, "abs_error", err);
        if (sgn(exact) != 0) put_exact(o, "rel_error", err / abs(exact));
        else o["rel_error"] = nullptr;
    }
    // For a value whose exact square E is known: the error of the squares exactly, and |c − √E|
    // and its relative size as MPFR-rounded doubles.
    void errors_sq(Json& o, const Q& claimed, const Q& E) const {
        put_exact(o, "claimed", claimed);
        put_exact(o, "exact_squared", E);
        put_exact(o, "squared_error", Q(claimed * claimed - E));
        const double d = -sqrt_minus_rn(E, claimed);  // c − √E
        o["abs_error_double"] = std::fabs(d);
        o["rel_error_double"] = sgn(E) ? Json(relative_sqrt_error_rn(E, claimed)) : Json(nullptr);
    }

};

class Certifier : public ClaimReader {
public:
    Certifier(const ClaimModels& models, const std::string& name, const ClaimOptions& opt, bool prove)
        : ClaimReader(name, opt, prove), models_(models) {}

    // How often the exact fallback ran: the distance by CGAL's QP over all vertices, when the
    // proof from the floating-point guess did not close (proved_distance).
    struct Fallbacks { long distance = 0, depth = 0; };
    Fallbacks fallbacks_;

    // One claim: its report object and a one-line text; right or wrong.
    bool run(const JNode& claim, size_t index, Json& o, std::string& text) {
        const std::string kind = begin(claim, index, o);
        if (kind == "verdict") return verdict(claim, o, text);
        if (kind == "growth_distance") return growth(claim, o, text);
        if (kind == "switch_point") return switch_point(claim, o, text);
        if (kind == "curve") return curve(claim, o, text);
        if (kind == "curve_point") return curve_point(claim, o, text);
        if (kind == "separating_plane") return plane(claim, o, text);
        if (kind == "witness_point") return witness(claim, o, text);
        if (kind == "distance") return distance(claim, o, text);
        if (kind == "penetration_depth") return depth(claim, o, text);
        fail("kind", "unknown kind " + quoted(kind) +
                         " (verdict, curve, curve_point, switch_point, growth_distance, separating_plane, witness_point, distance, "
                         "penetration_depth)");
    }

private:
    const ClaimModels& models_;
    // The two exact polyhedra, with no contact line: membership, and the measures' fallbacks.
    const Model& h() const { return models_.hulls(); }
    using Curve = ClaimModels::Curve;
    // The whole curve on the hull model (within the limits: Session::claim_hull).
    Curve whole() const { return {&models_.model(), &models_.curve(), Q(0), std::nullopt}; }
    struct ExactSwitch { Q rho1, rho2; std::string label; };
    std::optional<std::vector<ExactSwitch>> switches_;  // the whole curve's switch points (built on first use)

    // Whether x is in P1(ρ1) and y in P2(ρ2), with their proofs in *proof when given.
    std::pair<bool, bool> members(const Q& r1, const Q& r2, const Vec3q& x, const Vec3q& y, Json* proof) const {
        Json p1, p2;
        const bool a = models_.member(0, r1, x, proof ? &p1 : nullptr), b = models_.member(1, r2, y, proof ? &p2 : nullptr);
        if (proof) *proof = Json{{"P1", std::move(p1)}, {"P2", std::move(p2)}};
        return {a, b};
    }

    bool verdict(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "rho1", "rho2", "verdict"});
        const auto r12 = pair_at(j);
        const Q &r1 = r12.first, &r2 = r12.second;  // (not a structured binding: lambdas below capture them)
        const std::string v = str(j, "verdict");
        if (v != "separated" && v != "touching" && v != "overlapping" && v != "intersecting")
            fail("verdict", "unknown verdict " + quoted(v) + " (separated, touching, overlapping, intersecting)");
        const Verdict e = models_.verdict(r1, r2);
        const bool right = v == "intersecting" ? e != Verdict::Separated : v == verdict_name(e);
        put_exact(o, "rho1", r1);
        put_exact(o, "rho2", r2);
        o["claimed"] = v;
        o["exact"] = verdict_name(e);
        put_exact(o, "rho2_minus_curve", r2 - models_.curve_value(r1));
        text = "verdict at (" + num(r1) + ", " + num(r2) + "): claimed " + v + ", exact " + verdict_name(e);
        if (prove_) {
            const auto [pm, r] = models_.certified_query(r1, r2);
            if (r.verdict != e) throw std::logic_error("certify-fp: the certified verdict and the exact one differ");
            proof.emplace(Json{{"kind", "verdict"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}, {"verdict", v}}, verdict_proof(*pm, r));
        }
        return right;
    }

    bool growth(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "value"});
        const Q g = field(j, "value");
        if (sgn(g) < 0) fail("value", "a growth distance is >= 0 (0 when the seeds coincide)");
        const Q exact = models_.growth();
        errors(o, g, exact);
        text = "growth distance " + num(g) + ": exact " + num(exact);
        if (prove_) {
            Json pr = models_.growth_proof();
            if (pr["value"] != ex(exact)) throw std::logic_error("certify-fp: the proved growth distance and the exact one differ");
            proof.emplace(Json{{"kind", "growth_distance"}, {"value", ex(g)}}, std::move(pr));
        }
        return close(g, exact);
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
            walk_switches_ = switches_of(V);
            return walk_switches_;
        }
        if (!switches_) switches_ = switches_of(V);
        return *switches_;
    }
    std::vector<ExactSwitch> walk_switches_;
    // A claimed scaling: a number > 0 (P(ρ) is a point or reflected otherwise).
    Q scaling(const JNode& n, const std::string& key) const {
        const Q q = number(n, key);
        if (sgn(q) <= 0) fail(key, "scalings must be > 0 (got " + to_exact_string(q) + ")");
        return q;
    }
    std::pair<Q, Q> scaling_pair(const JNode& p, const std::string& key) const {
        if (p.kind != JNode::Array || p.items.size() != 2) fail(key, "expected [rho1, rho2] pairs");
        return {scaling(p.items[0], key), scaling(p.items[1], key)};
    }

    bool switch_point(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "rho1", "rho2", "contact"});
        const auto r12 = pair_at(j);
        const Q &r1 = r12.first, &r2 = r12.second;  // (not a structured binding: lambdas below capture them)
        const std::optional<std::string> lab = label(j);
        // Every ρ1 within the tolerance of the claim's (|x − ρ1| <= tol·x) lies in [lo, hi]: the
        // walk proves the curve over a window holding it; a tolerance of 1 or more needs the whole
        // curve (on to where it reaches ρ2 = 0, past every switch point).
        const Q& tol = opt_.tolerance;
        const Q lo = r1 / (1 + tol);
        const Curve V = tol < 1 ? models_.curve_around(lo, Q(r1 / (1 - tol))) : whole();
        const auto& exs = exact_switches(V);
        put_exact(o, "rho1", r1);
        put_exact(o, "rho2", r2);
        Json claim_json{{"kind", "switch_point"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}};
        if (lab) claim_json["contact"] = *lab;
        if (exs.empty()) {
            o["nearest"] = nullptr;
            if (V.whole()) {
                text = "switch point (" + num(r1) + ", " + num(r2) + "): the exact curve has no switch point at rho1, rho2 > 0";
                // The proof: the whole curve from ρ1 = 0 to past where it reaches ρ2 = 0.
                if (prove_) proof.emplace(std::move(claim_json), curve_proof(*V.model, *V.curve, Q(0), zero_crossing(V)));
            } else {
                text = "switch point (" + num(r1) + ", " + num(r2) + "): the exact curve has no switch point from rho1 = " + num(V.lo_proved) +
                       (V.hi_proved ? " to " + num(*V.hi_proved) : std::string(" on")) + " (the range the walk proved)";
                if (prove_) proof.emplace(std::move(claim_json), curve_proof(*V.model, *V.curve, lo, Q(r1 / (1 - tol))));
            }
            return false;
        }
        // Right when some exact switch point matches (both coordinates within the tolerance, and
        // the contact when claimed): the report names the first that does, else the nearest in ρ1.
        const ExactSwitch* best = nullptr;
        for (const ExactSwitch& s : exs)
            if (close(r1, s.rho1) && close(r2, s.rho2) && (!lab || *lab == s.label)) {
                best = &s;
                break;
            }
        const bool matched = best != nullptr;
        if (!best) {
            best = &exs.front();
            for (const ExactSwitch& s : exs)
                if (abs(Q(s.rho1 - r1)) < abs(Q(best->rho1 - r1))) best = &s;
        }
        Json n;
        put_exact(n, "rho1", best->rho1);
        put_exact(n, "rho2", best->rho2);
        n["contact"] = best->label;
        o["nearest"] = n;
        Json e1, e2;
        errors(e1, r1, best->rho1);
        errors(e2, r2, best->rho2);
        o["rho1_error"] = e1;
        o["rho2_error"] = e2;
        // The proof: the curve over a window holding every ρ1 within the tolerance of the claim's
        // (from ρ1/(1 + tol) to ρ1/(1 − tol), or on to where the curve reaches ρ2 = 0 when tol >= 1).
        if (prove_) {
            const Q hi = tol < 1 ? Q(r1 / (1 - tol)) : std::max(r1, zero_crossing(V));
            proof.emplace(std::move(claim_json), curve_proof(*V.model, *V.curve, lo, hi));
        }
        const bool label_right = !lab || *lab == best->label;
        o["contact_right"] = lab ? Json(label_right) : Json(nullptr);
        text = "switch point (" + num(r1) + ", " + num(r2) + (lab ? ", " + *lab : "") + (matched ? "): matches exact (" : "): nearest exact (") + num(best->rho1) +
               ", " + num(best->rho2) + ", " + best->label + ")";
        return matched;
    }

    // A point of the curve: ρ2 = f(ρ1) > 0, within the tolerance (the line `curve RHO1 RHO2`, exactly).
    bool curve_point(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "rho1", "rho2"});
        const auto r12 = pair_at(j);
        const Q &r1 = r12.first, &r2 = r12.second;  // (not a structured binding: lambdas below capture them)
        const Q f = models_.curve_value(r1);
        put_exact(o, "rho1", r1);
        put_exact(o, "rho2", r2);
        put_exact(o, "curve_rho2", f);
        errors(o, r2, f);
        text = "curve point (" + num(r1) + ", " + num(r2) + "): exact curve at rho1 is " + num(f);
        if (prove_) {
            const Curve V = models_.curve_around(r1, r1);
            proof.emplace(Json{{"kind", "curve_point"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}}, curve_proof(*V.model, *V.curve, r1, r1));
        }
        return sgn(f) > 0 && close(r2, f);
    }

    // The point set for the measures: the cloud's trees on a walked scene (exact for every normal),
    // else the exact polyhedra's vertices.
    const PointSets& points() const { return models_.points(); }
    // The exact distance, proved from the points' supports; CGAL's QP over every hull vertex when
    // the proof does not close (counted).
    ExactDistance exact_distance_of(const Q& r1, const Q& r2) {
        if (std::optional<ProvedDistance> pd = proved_distance(points(), r1, r2)) return pd->d;
        ++fallbacks_.distance;
        return exact_distance(h(), r1, r2);
    }
    // The depth with what proves it (measured_depth); when the distance's proof does not close,
    // from CGAL's exact distance and the EPA on the hull's vertices (counted).
    MeasuredDepth depth_of(const Q& r1, const Q& r2) {
        if (std::optional<MeasuredDepth> d = measured_depth(points(), r1, r2)) return *d;
        ++fallbacks_.depth;
        return depth_from_distance(HullPoints(h()), exact_distance(h(), r1, r2), r1, r2);
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

    // A curve claim: the rules of CLAIMS.md ("Curve claims"), each applied here once.
    bool curve(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "vertices", "pieces", "switch_points"});
        struct Seg { Q x0, y0, x1, y1; std::optional<std::string> label; };
        struct Claimed { Q x, y; };
        std::vector<Seg> segs;
        std::vector<Claimed> claimed_switches;
        const JNode* verts = j.find("vertices");
        const JNode* pieces = j.find("pieces");
        if ((verts != nullptr) == (pieces != nullptr)) fail("", "give \"vertices\" (a polyline) or \"pieces\"");
        if (verts) {
            if (verts->kind != JNode::Array || verts->items.size() < 2) fail("vertices", "expected at least 2 [rho1, rho2] pairs");
            std::vector<std::pair<Q, Q>> v;
            for (const JNode& p : verts->items) v.push_back(scaling_pair(p, "vertices"));
            for (size_t i = 0; i + 1 < v.size(); ++i) {
                if (!(v[i].first < v[i + 1].first)) fail("vertices", "rho1 must increase");
                segs.push_back({v[i].first, v[i].second, v[i + 1].first, v[i + 1].second, std::nullopt});
            }
            // The polyline's own vertices where its slope changes (exactly) are its switch points,
            // unless "switch_points" lists them (a sampled curve would have one at every sample).
            for (size_t i = 1; i + 1 < v.size(); ++i)
                if ((v[i].second - v[i - 1].second) * (v[i + 1].first - v[i].first) !=
                    (v[i + 1].second - v[i].second) * (v[i].first - v[i - 1].first))
                    claimed_switches.push_back({v[i].first, v[i].second});
        } else {
            if (pieces->kind != JNode::Array || pieces->items.empty()) fail("pieces", "expected a list of pieces");
            for (const JNode& p : pieces->items) {
                if (p.kind != JNode::Object) fail("pieces", "expected objects");
                only(p, {"rho1", "slope", "intercept", "contact"});
                const JNode& r = need(p, "rho1");
                if (r.kind != JNode::Array || r.items.size() != 2) fail("pieces.rho1", "expected [from, to]");
                const Q x0 = scaling(r.items[0], "pieces.rho1"), x1 = scaling(r.items[1], "pieces.rho1");
                if (!(x0 < x1)) fail("pieces.rho1", "from < to is required");
                if (!segs.empty() && x0 != segs.back().x1) fail("pieces.rho1", "each piece must start where the one before ends");
                const Q a = field(p, "slope"), b = field(p, "intercept");
                const Q y0 = a * x0 + b, y1 = a * x1 + b;
                if (sgn(y0) <= 0 || sgn(y1) <= 0) fail("pieces", "the piece reaches rho2 <= 0 (scalings must be > 0)");
                if (!segs.empty()) claimed_switches.push_back({x0, segs.back().y1});
                segs.push_back({x0, y0, x1, y1, label(p)});
            }
        }
        const Q lo = segs.front().x0, hi = segs.back().x1;
        Json claim_json{{"kind", "curve"}};  // the claim as read: every number exact
        if (verts) {
            Json v = Json::array({Json::array({ex(segs.front().x0), ex(segs.front().y0)})});
            for (const Seg& s : segs) v.push_back(Json::array({ex(s.x1), ex(s.y1)}));
            claim_json["vertices"] = std::move(v);
        } else {
            Json ps = Json::array();
            for (size_t i = 0; i < segs.size(); ++i) {
                const Seg& s = segs[i];
                const Q a = (s.y1 - s.y0) / (s.x1 - s.x0);
                Json p{{"rho1", Json::array({ex(s.x0), ex(s.x1)})}, {"slope", ex(a)}, {"intercept", ex(s.y0 - a * s.x0)}};
                if (s.label) p["contact"] = *s.label;
                ps.push_back(std::move(p));
            }
            claim_json["pieces"] = std::move(ps);
        }
        if (const JNode* sw = j.find("switch_points")) {
            if (sw->kind != JNode::Array) fail("switch_points", "expected a list of [rho1, rho2]");
            claimed_switches.clear();
            for (const JNode& p : sw->items) {
                const auto [x, y] = scaling_pair(p, "switch_points");
                if (x < lo || x > hi) fail("switch_points", "rho1 = " + to_exact_string(x) + " lies outside the claimed range");
                claimed_switches.push_back({x, y});
            }
            Json cs = Json::array();
            for (const Claimed& p : claimed_switches) cs.push_back(Json::array({ex(p.x), ex(p.y)}));
            claim_json["switch_points"] = std::move(cs);
        }
        // The curve proved over a window around [lo, hi], and around every ρ1 where f takes a
        // claimed end's ρ2 (the horizontal error): walked wider until it is, a few rounds, else
        // the whole curve.
        Curve V = models_.curve_around(lo, hi);
        for (int round = 0; !V.whole(); ++round) {
            Q need_lo = lo, need_hi = hi;
            bool fits = true, whole_needed = false;
            for (const Seg& s : segs)
                for (const Q& y : {s.y0, s.y1}) {
                    const std::optional<Q> x = inverse(V, y);
                    if (x && V.proves(*x)) continue;
                    fits = false;
                    if (!x || sgn(*x) <= 0) whole_needed = true;  // at or before ρ1 = 0 on the walked lines
                    else need_lo = std::min(need_lo, *x), need_hi = std::max(need_hi, *x);
                }
            if (fits) break;
            V = whole_needed || round == 8 ? whole() : models_.curve_around(need_lo, need_hi);
        }
        const TouchingCurve& cv = *V.curve;
        const Model& mv = *V.model;
        if (prove_) proof.emplace(std::move(claim_json), curve_proof(mv, cv, lo, hi));
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
            within = within && close(y, f);
        };
        for (const Seg& s : segs) {
            check_v(s.x0, s.y0);
            check_v(s.x1, s.y1);
            for (const EnvPiece& p : cv.env.pieces)
                if (p.to && *p.to > s.x0 && *p.to < s.x1) check_v(*p.to, s.y0 + (s.y1 - s.y0) * (*p.to - s.x0) / (s.x1 - s.x0));
            for (const auto& [x, y] : {std::pair{s.x0, s.y0}, std::pair{s.x1, s.y1}})
                if (auto xi = inverse(V, y)) max_h = std::max(max_h, Q(abs(Q(*xi - x))));
        }
        // Nothing touches where f ≤ 0; f descends, so it is > 0 on the whole range iff at hi.
        const bool exact_positive = sgn(cv.env.value(mv.lines, hi)) > 0;
        o["exact_rho2_positive_over_range"] = exact_positive;
        put_exact(o, "max_vertical_error", max_v);
        put_exact(o, "max_vertical_error_at_rho1", worst_v_at);
        put_exact(o, "max_horizontal_error", max_h);
        // Switch points: the exact ones in the closed range [lo, hi], each matched with the claimed
        // one nearest to it in ρ1 when that one's nearest exact switch is it. An exact switch
        // strictly inside the range that is not matched is missed; one at an end of the range
        // may go unclaimed. A claimed one not matched is extra; a matched pair must agree in ρ1
        // and ρ2 within the tolerance, or it is misplaced.
        std::vector<const ExactSwitch*> exact;
        for (const ExactSwitch& s : exs)
            if (s.rho1 >= lo && s.rho1 <= hi) exact.push_back(&s);
        auto nearest_claimed = [&](const Q& x) {
            size_t b = 0;
            for (size_t i = 1; i < claimed_switches.size(); ++i)
                if (abs(Q(claimed_switches[i].x - x)) < abs(Q(claimed_switches[b].x - x))) b = i;
            return b;
        };
        auto nearest_exact = [&](const Q& x) {
            size_t b = 0;
            for (size_t i = 1; i < exact.size(); ++i)
                if (abs(Q(exact[i]->rho1 - x)) < abs(Q(exact[b]->rho1 - x))) b = i;
            return b;
        };
        Json missed = Json::array(), extra = Json::array(), misplaced = Json::array();
        std::vector<bool> used(claimed_switches.size(), false);
        for (size_t i = 0; i < exact.size(); ++i) {
            const bool at_end = exact[i]->rho1 == lo || exact[i]->rho1 == hi;
            size_t k = 0;
            if (claimed_switches.empty() || nearest_exact(claimed_switches[k = nearest_claimed(exact[i]->rho1)].x) != i) {
                if (!at_end) missed.push_back(Json::array({to_exact_string(exact[i]->rho1), to_exact_string(exact[i]->rho2)}));
                continue;
            }
            used[k] = true;
            if (!close(claimed_switches[k].x, exact[i]->rho1) || !close(claimed_switches[k].y, exact[i]->rho2)) {
                Json mp;
                put_exact(mp, "exact_rho1", exact[i]->rho1);
                put_exact(mp, "exact_rho2", exact[i]->rho2);
                put_exact(mp, "claimed_rho1", claimed_switches[k].x);
                put_exact(mp, "claimed_rho2", claimed_switches[k].y);
                misplaced.push_back(mp);
            }
        }
        for (size_t k = 0; k < claimed_switches.size(); ++k)
            if (!used[k])
                extra.push_back(Json::array({to_exact_string(claimed_switches[k].x), to_exact_string(claimed_switches[k].y)}));
        o["switch_points_missed"] = missed;
        o["switch_points_extra"] = extra;
        o["switch_points_misplaced"] = misplaced;
        // Labels: the exact contact at each claimed piece's midpoint.
        Json wrong_labels = Json::array();
        for (const Seg& s : segs) {
            if (!s.label) continue;
            const Q mid = (s.x0 + s.x1) / 2;
            // At an exact switch point the contact is the switch point's.
            std::string e = exact_positive ? piece_contact(mv, cv.env.pieces[cv.env.locate(mid)]).label : std::string("none");
            for (const ExactSwitch& sw : exs)
                if (sw.rho1 == mid) e = sw.label;
            if (*s.label != e) {
                Json w;
                put_exact(w, "rho1", mid);
                w["claimed"] = *s.label;
                w["exact"] = e;
                wrong_labels.push_back(w);
            }
        }
        o["wrong_contacts"] = wrong_labels;
        text = "curve of " + std::to_string(segs.size()) + (segs.size() == 1 ? " segment" : " segments") + ": max vertical error " + num(max_v) + ", max horizontal error " +
               num(max_h) + ", switch points missed " + std::to_string(missed.size()) + ", extra " + std::to_string(extra.size()) +
               ", misplaced " + std::to_string(misplaced.size()) + ", wrong contacts " + std::to_string(wrong_labels.size()) +
               (exact_positive ? "" : ", and the exact curve reaches rho2 <= 0 in the claimed range");
        return exact_positive && within && missed.empty() && extra.empty() && misplaced.empty() && wrong_labels.empty();
    }

    bool plane(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "rho1", "rho2", "normal", "offset"});
        const auto r12 = pair_at(j);
        const Q &r1 = r12.first, &r2 = r12.second;  // (not a structured binding: lambdas below capture them)
        const Vec3q n = point(need(j, "normal"), "normal");
        if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0) fail("normal", "the zero vector is not a normal");
        const JNode* off = j.find("offset");
        const auto [c1, c2] = plane_extents(points(), n, r1, r2);
        put_exact(o, "rho1", r1);
        put_exact(o, "rho2", r2);
        put_exact(o, "max_over_P1", c1);  // P1(ρ1) ⊆ {n·x ≤ c1}
        put_exact(o, "min_over_P2", c2);  // P2(ρ2) ⊆ {n·x ≥ c2}
        put_exact(o, "gap", c2 - c1);
        bool right = c1 < c2;
        text = "plane at (" + num(r1) + ", " + num(r2) + "): P1 reaches " + num(c1) + ", P2 starts at " + num(c2);
        if (off) {
            const Q d = number(*off, "offset");
            put_exact(o, "offset_minus_P1", d - c1);
            put_exact(o, "P2_minus_offset", c2 - d);
            right = right && c1 < d && d < c2;
            text += ", offset " + num(d);
        }
        if (prove_) {
            Json cl{{"kind", "separating_plane"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}, {"normal", ex3(n)}};
            if (off) cl["offset"] = ex(number(*off, "offset"));
            proof.emplace(std::move(cl), Json::object());
        }
        return right;
    }

    bool witness(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "rho1", "rho2", "point"});
        const auto r12 = pair_at(j);
        const Q &r1 = r12.first, &r2 = r12.second;  // (not a structured binding: lambdas below capture them)
        const Vec3q x = point(need(j, "point"), "point");
        Json mp;
        const auto [in1, in2] = members(r1, r2, x, x, prove_ ? &mp : nullptr);
        o["in_P1"] = in1;
        o["in_P2"] = in2;
        o["exact_verdict"] = verdict_name(models_.verdict(r1, r2));
        text = "witness point at (" + num(r1) + ", " + num(r2) + "): in P1 " + (in1 ? "yes" : "NO") + ", in P2 " + (in2 ? "yes" : "NO");
        if (prove_) proof.emplace(Json{{"kind", "witness_point"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}, {"point", ex3(x)}}, std::move(mp));
        return in1 && in2;
    }

    bool distance(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "rho1", "rho2", "value", "closest"});
        const auto r12 = pair_at(j);
        const Q &r1 = r12.first, &r2 = r12.second;  // (not a structured binding: lambdas below capture them)
        const Q d = field(j, "value");
        const ExactDistance e = exact_distance_of(r1, r2);
        put_exact(o, "rho1", r1);
        put_exact(o, "rho2", r2);
        errors_sq(o, d, e.squared);
        put_point(o, "exact_closest_P1", e.p1);
        put_point(o, "exact_closest_P2", e.p2);
        bool right = close_sq(d, e.squared);
        o["value_right"] = right;
        text = "distance at (" + num(r1) + ", " + num(r2) + "): claimed " + num(d) + ", exact squared " + num(e.squared) + " (distance ~" + dbl(sqrt_minus_rn(e.squared, Q(0))) + ")";
        Json pc, pp;
        if (prove_) {
            pc = Json{{"kind", "distance"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}, {"value", ex(d)}};
            pp = distance_proof(nullptr, e, r1, r2);
        }
        if (const JNode* cl = j.find("closest")) {
            if (cl->kind != JNode::Array || cl->items.size() != 2) fail("closest", "expected [point on P1, point on P2]");
            const Vec3q p = point(cl->items[0], "closest"), q = point(cl->items[1], "closest");
            const Vec3q pq = sub(q, p);
            const Q sq = dot(pq, pq);
            Json mp;
            const auto [in1, in2] = members(r1, r2, p, q, prove_ ? &mp : nullptr);
            o["closest_in_P1"] = in1;
            o["closest_in_P2"] = in2;
            put_exact(o, "closest_squared_distance", sq);
            const bool ok = in1 && in2 && within_above(sq, e.squared);
            o["closest_right"] = ok;
            right = right && ok;
            if (prove_) {
                pc["closest"] = Json::array({ex3(p), ex3(q)});
                pp["closest"] = std::move(mp);
            }
        }
        if (prove_) proof.emplace(std::move(pc), std::move(pp));
        return right;
    }

    bool depth(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "rho1", "rho2", "value", "direction"});
        const auto r12 = pair_at(j);
        const Q &r1 = r12.first, &r2 = r12.second;  // (not a structured binding: lambdas below capture them)
        const Q d = field(j, "value");
        // The exact squared depth (−1 when separated) and a minimising direction, with its proof.
        const MeasuredDepth md = depth_of(r1, r2);
        ExactDepth e{Q(-1), md.normal};
        if (md.state == MeasuredDepth::Touching) e.squared = 0;
        if (md.state == MeasuredDepth::Overlapping) e.squared = md.depth->squared;
        put_exact(o, "rho1", r1);
        put_exact(o, "rho2", r2);
        Json pc, pp;
        if (prove_) {
            pc = Json{{"kind", "penetration_depth"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}, {"value", ex(d)}};
            pp = depth_proof(nullptr, md, r1, r2);
        }
        if (sgn(e.squared) < 0) {
            o["exact_verdict"] = "separated";
            put_exact(o, "claimed", d);
            text = "penetration depth at (" + num(r1) + ", " + num(r2) + "): claimed " + num(d) + ", but the pair is separated";
            if (const JNode* dir = j.find("direction"); dir && prove_) pc["direction"] = ex3(point(*dir, "direction"));
            if (prove_) proof.emplace(std::move(pc), std::move(pp));
            return false;
        }
        errors_sq(o, d, e.squared);
        o["exact_direction"] = Json::array({e.direction[0].get_str(), e.direction[1].get_str(), e.direction[2].get_str()});
        bool right = close_sq(d, e.squared);
        o["value_right"] = right;
        text = "penetration depth at (" + num(r1) + ", " + num(r2) + "): claimed " + num(d) + ", exact squared " + num(e.squared) + " (depth ~" + dbl(sqrt_minus_rn(e.squared, Q(0))) + ")";
        if (const JNode* dir = j.find("direction")) {
            const Vec3q n = point(*dir, "direction");
            if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0) fail("direction", "the zero vector is not a direction");
            // Moving P2 by the depth along n separates them exactly iff n attains the minimum.
            const Q along = directional_depth_squared(points(), n, r1, r2);
            put_exact(o, "depth_squared_along_direction", along);
            const bool ok = within_above(along, e.squared);
            o["direction_right"] = ok;
            right = right && ok;
            if (prove_) pc["direction"] = ex3(n);
        }
        if (prove_) proof.emplace(std::move(pc), std::move(pp));
        return right;
    }
};

}  // namespace

// The claims on two compounds (CLAIMS.md, "Objects made of parts"): verdicts, separating planes,
// witness points and distances, judged by CompoundJudge at any (ρ1, ρ2) > 0.
class CompoundCertifier : public ClaimReader {
public:
    CompoundCertifier(CompoundJudge& judge, const std::string& name, const ClaimOptions& opt, bool prove)
        : ClaimReader(name, opt, prove), j_(judge) {}

    bool run(const JNode& claim, size_t index, Json& o, std::string& text) {
        const std::string kind = begin(claim, index, o);
        if (kind == "verdict") return verdict(claim, o, text);
        if (kind == "separating_plane") return plane(claim, o, text);
        if (kind == "witness_point") return witness(claim, o, text);
        if (kind == "distance") return distance(claim, o, text);
        if (kind == "curve" || kind == "curve_point" || kind == "switch_point" || kind == "growth_distance" || kind == "penetration_depth")
            fail("kind", quoted(kind) + " is a claim on two convex objects; on objects made of parts certify-fp takes verdict, "
                         "separating_plane, witness_point and distance (the region and its growth set: scalecert region)");
        fail("kind", "unknown kind " + quoted(kind) + " (on objects made of parts: verdict, separating_plane, witness_point, distance)");
    }

    // The line format's 'RHO1 RHO2 VERDICT'.
    bool verdict_line(const Q& r1, const Q& r2, const std::string& v, Json& o, std::string& text) {
        proof.reset();
        Json p;
        const CompoundJudge::Verdict e = j_.verdict(r1, r2, prove_ ? &p : nullptr);
        const bool right = v == "intersecting" ? e.verdict > 0 : v == name_of(e.verdict);
        o["claim"] = v;
        put_exact(o, "rho1", r1);
        put_exact(o, "rho2", r2);
        o["exact"] = name_of(e.verdict);
        o["pair"] = pair_json(e);
        text = "(" + num(r1, 17) + ", " + num(r2, 17) + ") claimed " + v + ": exact " + name_of(e.verdict);
        if (prove_) proof.emplace(Json{{"kind", "verdict"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}, {"verdict", v}}, std::move(p));
        return right;
    }

private:
    CompoundJudge& j_;
    static const char* name_of(int v) { return v == 2 ? "overlapping" : v == 1 ? "touching" : "separated"; }
    static Json pair_json(const CompoundJudge::Verdict& e) { return e.part1 < 0 ? Json(nullptr) : Json::array({e.part1, e.part2}); }

    bool verdict(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "rho1", "rho2", "verdict"});
        const auto [r1, r2] = pair_at(j);
        const std::string v = str(j, "verdict");
        if (v != "separated" && v != "touching" && v != "overlapping" && v != "intersecting")
            fail("verdict", "unknown verdict " + quoted(v) + " (separated, touching, overlapping, intersecting)");
        const bool right = verdict_line(r1, r2, v, o, text);
        o.erase("claim");
        o["claimed"] = v;
        text = "verdict at (" + num(r1) + ", " + num(r2) + "): claimed " + v + ", exact " + o["exact"].get<std::string>();
        return right;
    }

    bool plane(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "rho1", "rho2", "normal", "offset"});
        const auto [r1, r2] = pair_at(j);
        const Vec3q n = point(need(j, "normal"), "normal");
        if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0) fail("normal", "the zero vector is not a normal");
        const JNode* off = j.find("offset");
        const auto [c1, c2] = j_.plane_extents(n, r1, r2);
        put_exact(o, "rho1", r1);
        put_exact(o, "rho2", r2);
        put_exact(o, "max_over_P1", c1);
        put_exact(o, "min_over_P2", c2);
        put_exact(o, "gap", c2 - c1);
        bool right = c1 < c2;
        text = "plane at (" + num(r1) + ", " + num(r2) + "): P1 reaches " + num(c1) + ", P2 starts at " + num(c2);
        Json cl{{"kind", "separating_plane"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}, {"normal", ex3(n)}};
        if (off) {
            const Q d = number(*off, "offset");
            put_exact(o, "offset_minus_P1", d - c1);
            put_exact(o, "P2_minus_offset", c2 - d);
            right = right && c1 < d && d < c2;
            text += ", offset " + num(d);
            cl["offset"] = ex(d);
        }
        if (prove_) proof.emplace(std::move(cl), Json::object());
        return right;
    }

    // Is x in object i at ρ: the part holding it (or −1), its proof in *p.
    int in(int i, const Q& rho, const Vec3q& x, Json& o, const char* key, Json* p) {
        const int k = j_.locate(i, rho, x, p);
        o[key] = k >= 0 ? Json(k) : Json(false);
        return k;
    }

    bool witness(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "rho1", "rho2", "point"});
        const auto [r1, r2] = pair_at(j);
        const Vec3q x = point(need(j, "point"), "point");
        Json p1, p2;
        const int k1 = in(0, r1, x, o, "in_P1_part", prove_ ? &p1 : nullptr), k2 = in(1, r2, x, o, "in_P2_part", prove_ ? &p2 : nullptr);
        o["exact_verdict"] = name_of(j_.verdict(r1, r2).verdict);
        text = "witness point at (" + num(r1) + ", " + num(r2) + "): in P1 " + (k1 >= 0 ? "part " + std::to_string(k1) : "NO") + ", in P2 " +
               (k2 >= 0 ? "part " + std::to_string(k2) : "NO");
        if (prove_) proof.emplace(Json{{"kind", "witness_point"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}, {"point", ex3(x)}}, Json{{"P1", p1}, {"P2", p2}});
        return k1 >= 0 && k2 >= 0;
    }

    bool distance(const JNode& j, Json& o, std::string& text) {
        only(j, {"kind", "rho1", "rho2", "value", "closest"});
        const auto [r1, r2] = pair_at(j);
        const Q d = field(j, "value");
        Json pp;
        const CompoundJudge::Distance e = j_.distance(r1, r2, prove_ ? &pp : nullptr);
        put_exact(o, "rho1", r1);
        put_exact(o, "rho2", r2);
        errors_sq(o, d, e.squared);
        put_point(o, "exact_closest_P1", e.p1);
        put_point(o, "exact_closest_P2", e.p2);
        o["exact_pair"] = Json::array({e.part1, e.part2});
        bool right = close_sq(d, e.squared);
        o["value_right"] = right;
        text = "distance at (" + num(r1) + ", " + num(r2) + "): claimed " + num(d) + ", exact squared " + num(e.squared) + " (distance ~" +
               dbl(sqrt_minus_rn(e.squared, Q(0))) + ", parts " + std::to_string(e.part1) + " and " + std::to_string(e.part2) + ")";
        Json pc{{"kind", "distance"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}, {"value", ex(d)}};
        if (const JNode* cl = j.find("closest")) {
            if (cl->kind != JNode::Array || cl->items.size() != 2) fail("closest", "expected [point on P1, point on P2]");
            const Vec3q p = point(cl->items[0], "closest"), q = point(cl->items[1], "closest");
            const Vec3q pq = sub(q, p);
            const Q sq = dot(pq, pq);
            Json m1, m2;
            const int k1 = in(0, r1, p, o, "closest_in_P1_part", prove_ ? &m1 : nullptr);
            const int k2 = in(1, r2, q, o, "closest_in_P2_part", prove_ ? &m2 : nullptr);
            put_exact(o, "closest_squared_distance", sq);
            const bool ok = k1 >= 0 && k2 >= 0 && within_above(sq, e.squared);
            o["closest_right"] = ok;
            right = right && ok;
            pc["closest"] = Json::array({ex3(p), ex3(q)});
            pp["closest"] = Json{{"P1", m1}, {"P2", m2}};
        }
        if (prove_) proof.emplace(std::move(pc), std::move(pp));
        return right;
    }
};

namespace {
// The report of n claims, `bad` of them wrong: JSON {"claims", "tolerance" (JSON claims only),
// "right", "wrong"}, or the claims' text lines and a summary line.
// (fallbacks >= 0: JSON claims' "exact_fallbacks", how often the exact fallback ran.)
std::string report(Json arr, const std::string& text, long n, long bad, bool json, const Q* tolerance, long* wrong, long* count,
                   long fallbacks = -1, long fallbacks_depth = 0) {
    if (wrong) *wrong = bad;
    if (count) *count = n;
    if (json) {
        Json j;
        j["claims"] = std::move(arr);
        if (tolerance) put_exact(j, "tolerance", *tolerance);
        j["right"] = n - bad;
        j["wrong"] = bad;
        if (fallbacks >= 0) j["exact_fallbacks"] = Json{{"distance", fallbacks}, {"depth", fallbacks_depth}};
        return dump(j);
    }
    return text + "claims: " + std::to_string(n) + ", right: " + std::to_string(n - bad) + ", wrong: " + std::to_string(bad) + "\n";
}

// A number of the line format, read as a JSON claim's number is (parse_number): the double a
// decimal names (a floating-point program's output means the double it held), or with
// exact_decimals the decimal as written; a fraction p/q is exact.
Q read_number(const std::string& t, bool exact_decimals, const std::string& where) {
    try {
        return parse_number(t, !exact_decimals);
    } catch (const InputError& e) {
        throw InputError(where + ": " + e.what());
    }
}
// A line's RHO1 RHO2, each > 0; a refusal names the one at fault.
std::pair<Q, Q> read_scalings(const std::string& a, const std::string& b, bool exact_decimals, const std::string& where) {
    const Q r1 = read_number(a, exact_decimals, where + ": rho1"), r2 = read_number(b, exact_decimals, where + ": rho2");
    if (sgn(r1) <= 0) throw InputError(where + ": rho1: scalings must be > 0 (got " + to_exact_string(r1) + ")");
    if (sgn(r2) <= 0) throw InputError(where + ": rho2: scalings must be > 0 (got " + to_exact_string(r2) + ")");
    return {r1, r2};
}
}  // namespace

static Json entry(size_t index, Json claim, bool right, Json proof) {
    return Json{{"index", index}, {"claim", std::move(claim)}, {"right", right}, {"proof", std::move(proof)}};
}

std::string certify_claim_lines(const ClaimModels& models, const std::string& claims, const std::string& name,
                                bool exact_decimals, bool json, long* wrong, long* count, std::string* certificate) {
    Json entries = Json::array();
    std::optional<std::pair<Json, Json>> proof;
    std::istringstream in(claims);
    std::string line, text;
    Json arr = Json::array();
    long n = 0, bad = 0;
    for (long no = 1; std::getline(in, line); ++no) {
        auto hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        std::istringstream ls(line);
        std::vector<std::string> w;
        for (std::string t; ls >> t;) w.push_back(t);
        if (w.empty()) continue;
        const std::string where = name + ": line " + std::to_string(no);
        Json o;
        o["line"] = no;
        bool right = false;
        std::string detail;
        proof.reset();
        if (w[0] == "curve" && w.size() == 3) {
            const auto [r1, r2] = read_scalings(w[1], w[2], exact_decimals, where);
            Q f = models.curve_value(r1);
            right = f == r2;
            o["claim"] = "curve";
            put_exact(o, "rho1", r1);
            put_exact(o, "rho2", r2);
            put_exact(o, "curve_rho2", f);
            put_exact(o, "rho2_minus_curve", r2 - f);
            detail = "curve point (" + w[1] + ", " + w[2] + "): exact curve at rho1 is " + num(f, 17) + ", off by " + num(r2 - f, 17);
            if (certificate) {
                const ClaimModels::Curve V = models.curve_around(r1, r1);
                proof.emplace(Json{{"kind", "curve_point"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}}, curve_proof(*V.model, *V.curve, r1, r1));
            }
        } else if (w[0] == "growth" && w.size() == 2) {
            Q g = read_number(w[1], exact_decimals, where);
            if (sgn(g) < 0) throw InputError(where + ": a growth distance is >= 0 (0 when the seeds coincide)");
            const Q exact_g = models.growth();
            right = g == exact_g;
            o["claim"] = "growth";
            put_exact(o, "claimed", g);
            put_exact(o, "exact", exact_g);
            detail = "growth distance " + w[1] + ": exact " + num(exact_g, 17) + ", off by " + num(g - exact_g, 17);
            if (certificate) proof.emplace(Json{{"kind", "growth_distance"}, {"value", ex(g)}}, models.growth_proof());
        } else if (w.size() == 3) {
            const auto [r1, r2] = read_scalings(w[0], w[1], exact_decimals, where);
            const std::string& v = w[2];
            if (v != "separated" && v != "touching" && v != "overlapping" && v != "intersecting")
                throw InputError(where + ": unknown verdict " + quoted(v) + " (separated, touching, overlapping, intersecting)");
            Verdict e = models.verdict(r1, r2);
            std::string en = verdict_name(e);
            right = v == "intersecting" ? e != Verdict::Separated : v == en;
            Q f = models.curve_value(r1);
            o["claim"] = v;
            put_exact(o, "rho1", r1);
            put_exact(o, "rho2", r2);
            o["exact"] = en;
            put_exact(o, "rho2_minus_curve", r2 - f);
            detail = "(" + w[0] + ", " + w[1] + ") claimed " + v + ": exact " + en + ", rho2 - curve = " + num(r2 - f, 17);
            if (certificate) {
                const auto [pm, r] = models.certified_query(r1, r2);
                if (r.verdict != e) throw std::logic_error("certify-fp: the certified verdict and the exact one differ");
                proof.emplace(Json{{"kind", "verdict"}, {"rho1", ex(r1)}, {"rho2", ex(r2)}, {"verdict", v}}, verdict_proof(*pm, r));
            }
        } else {
            throw InputError(where + ": expected 'RHO1 RHO2 VERDICT', 'curve RHO1 RHO2' or 'growth RHO'");
        }
        if (proof) entries.push_back(entry(static_cast<size_t>(no), std::move(proof->first), right, std::move(proof->second)));  // by line number
        ++n;
        bad += !right;
        o["right"] = right;
        arr.push_back(o);
        text += std::string(right ? "right  " : "WRONG  ") + detail + "\n";
    }
    if (n == 0) throw InputError(name + ": no claims (expected 'RHO1 RHO2 VERDICT', 'curve RHO1 RHO2' or 'growth RHO' lines)");
    if (certificate) *certificate = judgements_text(models.document(), Q(0), std::move(entries));
    return report(std::move(arr), text, n, bad, json, nullptr, wrong, count);
}

ClaimModels ClaimModels::of(const HullModel& m, const TouchingCurve& c) {
    auto points = std::make_shared<HullPoints>(m);
    return {[&m]() -> const HullModel& { return m; },
            [&c]() -> const TouchingCurve& { return c; },
            [&m, &c](const Q& r1, const Q& r2) { return query(m, c, r1, r2, false).verdict; },
            [&m, &c](const Q& r1) { return c.env.value(m.lines, r1); },
            [&c] { return c.growth.value; },
            [points]() -> const PointSets& { return *points; },
            [&m]() -> const Model& { return m; },
            [&m, &c](const Q& r1, const Q& r2) { return std::pair<const Model*, QueryAnswer>{&m, query(m, c, r1, r2, true)}; },
            [&m, &c] { return scalecert::internal::growth_proof(m, c); },
            [&m]() -> const Model& { return m; },
            [&m, &c](const Q&, const Q&) { return ClaimModels::Curve{&m, &c, Q(0), std::nullopt}; },
            [&m](int i, const Q& rho, const Vec3q& x, Json* proof) { return hull_member(m, i, rho, x, proof); }};
}

namespace {
// A JSON claims file ({"format": "scalecert-claims-1", "claims": [...]}): its root, checked.
JNode claims_root(const std::string& claims, const std::string& name) {
    JNode root;
    try {
        root = parse_strict_json(claims);
    } catch (const JsonError& e) {
        throw InputError(name + ": malformed JSON near byte " + std::to_string(e.pos) + ": " + e.what);
    }
    const JNode* format = root.find("format");
    const JNode* list = root.find("claims");
    if (!format || format->kind != JNode::String || format->text != "scalecert-claims-1")
        throw InputError(name + ": format: expected \"scalecert-claims-1\"");
    for (const std::string& k : root.keys)
        if (k != "format" && k != "claims") throw InputError(name + ": " + k + ": unknown field");
    if (!list || list->kind != JNode::Array || list->items.empty()) throw InputError(name + ": claims: expected a non-empty list");
    return root;
}

// Every claim of the list through the certifier: the report's entries (arr), the judgements with
// their proofs (entries, when proving) and the text; the number of wrong claims.
template <class Cert>
long run_claims(Cert& cert, const JNode& list, bool prove, Json& arr, Json& entries, std::string& text) {
    long bad = 0;
    for (size_t i = 0; i < list.items.size(); ++i) {
        Json o;
        std::string line;
        const bool right = cert.run(list.items[i], i, o, line);
        if (prove) {
            if (!cert.proof) throw std::logic_error("certify-fp: a judgement without its proof");
            entries.push_back(entry(i, std::move(cert.proof->first), right, std::move(cert.proof->second)));
        }
        o["right"] = right;
        bad += !right;
        arr.push_back(o);
        text += std::string(right ? "right  " : "WRONG  ") + line + "\n";
    }
    return bad;
}

bool is_json(const std::string& claims, const ClaimOptions& opt, const std::string& name) {
    if (sgn(opt.tolerance) < 0) throw InputError("tolerance: must be >= 0 (got " + to_exact_string(opt.tolerance) + ")");
    const size_t first = claims.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && claims[first] == '{') return true;
    if (sgn(opt.tolerance) != 0) throw InputError(name + ": a tolerance applies to JSON claims (scalecert-claims-1) only");
    return false;
}
}  // namespace

std::string certify_fp(const ClaimModels& models, const std::string& claims, const std::string& name, const ClaimOptions& opt,
                       long* wrong, long* count, std::string* certificate) {
    if (!is_json(claims, opt, name)) return certify_claim_lines(models, claims, name, opt.exact_decimals, opt.json, wrong, count, certificate);
    const JNode root = claims_root(claims, name);
    const JNode& list = *root.find("claims");
    Certifier cert(models, name, opt, certificate != nullptr);
    Json arr = Json::array(), entries = Json::array();
    std::string text;
    const long bad = run_claims(cert, list, certificate != nullptr, arr, entries, text);
    if (certificate) *certificate = judgements_text(models.document(), opt.tolerance, std::move(entries));
    return report(std::move(arr), text, static_cast<long>(list.items.size()), bad, opt.json, &opt.tolerance, wrong, count,
                  cert.fallbacks_.distance, cert.fallbacks_.depth);
}

std::string certify_fp(CompoundJudge& judge, const std::string& claims, const std::string& name, const ClaimOptions& opt, long* wrong,
                       long* count, std::string* certificate) {
    CompoundCertifier cert(judge, name, opt, certificate != nullptr);
    Json arr = Json::array(), entries = Json::array();
    std::string text;
    long n = 0, bad = 0;
    const bool json = is_json(claims, opt, name);
    if (json) {
        const JNode root = claims_root(claims, name);
        const JNode& list = *root.find("claims");
        bad = run_claims(cert, list, certificate != nullptr, arr, entries, text);
        n = static_cast<long>(list.items.size());
    } else {
        // Lines: 'RHO1 RHO2 VERDICT' only (a curve and a growth distance are claims on convex objects).
        std::istringstream in(claims);
        std::string line;
        for (long no = 1; std::getline(in, line); ++no) {
            if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
            std::istringstream ls(line);
            std::vector<std::string> w;
            for (std::string t; ls >> t;) w.push_back(t);
            if (w.empty()) continue;
            const std::string where = name + ": line " + std::to_string(no);
            if (w.size() != 3 || w[0] == "curve")
                throw InputError(where + ": expected 'RHO1 RHO2 VERDICT' (on objects made of parts, verdict lines only: a curve and a "
                                         "growth distance are claims on convex objects)");
            const auto [r1, r2] = read_scalings(w[0], w[1], opt.exact_decimals, where);
            const std::string& v = w[2];
            if (v != "separated" && v != "touching" && v != "overlapping" && v != "intersecting")
                throw InputError(where + ": unknown verdict " + quoted(v) + " (separated, touching, overlapping, intersecting)");
            Json o;
            o["line"] = no;
            std::string detail;
            const bool right = cert.verdict_line(r1, r2, v, o, detail);
            if (certificate) entries.push_back(entry(static_cast<size_t>(no), std::move(cert.proof->first), right, std::move(cert.proof->second)));
            ++n;
            bad += !right;
            o["right"] = right;
            arr.push_back(o);
            text += std::string(right ? "right  " : "WRONG  ") + detail + "\n";
        }
        if (n == 0) throw InputError(name + ": no claims (expected 'RHO1 RHO2 VERDICT' lines)");
    }
    if (certificate) *certificate = compound_judgements_text(judge.scene(), json ? opt.tolerance : Q(0), std::move(entries));
    return report(std::move(arr), text, n, bad, opt.json, json ? &opt.tolerance : nullptr, wrong, count);
}

}  // namespace scalecert::internal
