// certify-fp: the JSON and line formats of claims read into typed claims (claim.hpp), judged by
// the rules (rules.cpp), and their reports written (JSON or text; the display doubles of
// |claimed − exact| use MPFR's correctly rounded square root).
#include "certify/claims.hpp"
#include "certify/claim.hpp"
#include "certify/certificate.hpp"
#include "certify/compound_judge.hpp"
#include "certify/region_certificate.hpp"
#include "certify/judgements.hpp"
#include "geometry/measures.hpp"
#include "io/strict_json.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <sstream>

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

}  // namespace

// Is x in P_i(ρ) on the exact polyhedra, with its proof.
bool hull_member(const Model& m, int i, const Q& rho, const Vec3q& x, Json* proof) {
    bool inside = false;
    if (proof)
        *proof = membership_proof(m, i, rho, x, &inside);
    else
        inside = contains(m, i, rho, x);
    return inside;
}

namespace {

// ---- reading: JSON claims into typed claims ----------------------------------------------------

// Reads one claim of a scalecert-claims-1 list into a TypedClaim: every field checked, every
// number exact (a JSON number is the binary value ClaimOptions::numbers reads). On objects
// made of parts (`parts`) only the types PartsRules takes.
class ClaimReader {
  public:
    // parts: the scene of objects made of parts, or none for two convex objects.
    ClaimReader(const std::string& name, Numbers numbers, const ExactScene* parts)
        : name_(name), numbers_(numbers), parts_(parts != nullptr) {
        if (parts)
            for (int i = 0; i < 2; ++i) count_[i] = std::max<size_t>(1, parts->P[i].parts.size());
    }

    TypedClaim read(const JNode& claim, size_t index) {
        where_ = name_ + ": claims[" + std::to_string(index) + "]";
        if (claim.kind != JNode::Object) fail("", "expected an object with \"kind\"");
        const std::string kind = str(claim, "kind");
        const std::optional<ClaimType> t = type_of(kind);
        if (parts_ && (!t || !PartsRules::takes(*t))) {
            if (t)
                fail("kind",
                     in_quotes(kind) +
                         " is a claim on two convex objects; on objects made of parts certify-fp takes verdict, "
                         "separating_plane, witness_point, distance and penetration_depth (the region and its "
                         "growth set: scalecert region)");
            fail("kind", "unknown kind " + in_quotes(kind) +
                             " (on objects made of parts: verdict, separating_plane, witness_point, distance, "
                             "penetration_depth)");
        }
        if (!t)
            fail("kind", "unknown kind " + in_quotes(kind) +
                             " (verdict, curve, curve_point, switch_point, growth_distance, separating_plane, "
                             "witness_point, distance, "
                             "penetration_depth)");
        TypedClaim c;
        c.type = *t;
        switch (c.type) {
        case ClaimType::Verdict: {
            only(claim, {"kind", "rho1", "rho2", "verdict", "pose1", "pose2"});
            pair_at(claim, c);
            poses(claim, c);
            const std::string v = str(claim, "verdict");
            const std::optional<Claimed> cv = claimed_of(v);
            if (!cv)
                fail("verdict",
                     "unknown verdict " + in_quotes(v) + " (separated, touching, overlapping, intersecting)");
            c.verdict = *cv;
            break;
        }
        case ClaimType::Growth:
            only(claim, {"kind", "value"});
            if (answer(need(claim, "value"), "value", c, c.value) && sgn(c.value) < 0)
                fail("value", "a growth distance is >= 0 (0 when the seeds coincide)");
            break;
        case ClaimType::SwitchPoint:  // both scalings are the program's answer
            only(claim, {"kind", "rho1", "rho2", "contact"});
            for (const char* k : {"rho1", "rho2"}) {
                Q& r = k[3] == '1' ? c.rho1 : c.rho2;
                if (answer(need(claim, k), k, c, r) && sgn(r) <= 0)
                    fail(k, "scalings must be > 0 (got " + to_exact_string(r) + ")");
            }
            c.contact = label(claim);
            break;
        case ClaimType::CurvePoint:  // ρ2 is the program's answer
            only(claim, {"kind", "rho1", "rho2"});
            c.rho1 = field(claim, "rho1");
            if (sgn(c.rho1) <= 0) fail("rho1", "scalings must be > 0 (got " + to_exact_string(c.rho1) + ")");
            if (answer(need(claim, "rho2"), "rho2", c, c.rho2) && sgn(c.rho2) <= 0)
                fail("rho2", "scalings must be > 0 (got " + to_exact_string(c.rho2) + ")");
            break;
        case ClaimType::Curve: c.curve = std::make_shared<const ClaimedCurve>(curve(claim)); break;
        case ClaimType::Plane:
            only(claim, {"kind", "rho1", "rho2", "normal", "offset", "pose1", "pose2"});
            pair_at(claim, c);
            poses(claim, c);
            if (answer_point(need(claim, "normal"), "normal", c, c.normal) && is_zero(c.normal))
                set_no_answer(c, "normal", "the zero vector");
            if (const JNode* off = claim.find("offset")) answer(*off, "offset", c, c.offset.emplace());
            break;
        case ClaimType::Witness:
            only(claim, {"kind", "rho1", "rho2", "point", "pose1", "pose2"});
            pair_at(claim, c);
            poses(claim, c);
            answer_point(need(claim, "point"), "point", c, c.point);
            break;
        case ClaimType::Distance:
            only(claim, {"kind", "rho1", "rho2", "value", "closest", "pose1", "pose2"});
            pair_at(claim, c);
            poses(claim, c);
            answer(need(claim, "value"), "value", c, c.value);
            if (const JNode* cl = claim.find("closest")) {
                std::array<Vec3q, 2>& pq = c.closest.emplace();
                if (cl->kind == JNode::Null)
                    set_no_answer(c, "closest", "not two points");
                else if (cl->kind != JNode::Array || cl->items.size() != 2)
                    fail("closest", "expected [point on P1, point on P2]");
                else
                    answer_point(cl->items[0], "closest", c, pq[0]) && answer_point(cl->items[1], "closest", c, pq[1]);
            }
            break;
        case ClaimType::Depth:
            only(claim, {"kind", "rho1", "rho2", "parts", "value", "direction", "pose1", "pose2"});
            pair_at(claim, c);
            part_pair(claim, c);
            poses(claim, c);
            answer(need(claim, "value"), "value", c, c.value);
            if (const JNode* dir = claim.find("direction"))
                if (answer_point(*dir, "direction", c, c.direction.emplace()) && is_zero(*c.direction))
                    set_no_answer(c, "direction", "the zero vector");
            break;
        }
        return c;
    }

  private:
    std::string name_, where_;
    Numbers numbers_;
    bool parts_;
    size_t count_[2] = {1, 1};  // parts of P1 and of P2 (a convex object is one part)

    // "pose1", "pose2": the objects at poses, each three rows [r1, r2, r3, t] of numbers (read as
    // the claims' numbers are), R nonsingular. A pose is the program's question, not its answer:
    // a non-number in it is bad input.
    void poses(const JNode& claim, TypedClaim& c) const {
        for (size_t i = 0; i < 2; ++i) {
            const std::string key = i ? "pose2" : "pose1";
            const JNode* n = claim.find(key.c_str());
            if (!n) continue;
            if (n->kind != JNode::Array || n->items.size() != 3)
                fail(key, "expected 3 rows [r1, r2, r3, t] (the matrix [R | t])");
            Pose& m = c.pose[i].emplace();
            for (size_t r = 0; r < 3; ++r) {
                const JNode& row = n->items[r];
                const std::string wr = key + "[" + std::to_string(r) + "]";
                if (row.kind != JNode::Array || row.items.size() != 4) fail(wr, "expected 4 numbers [r1, r2, r3, t]");
                for (size_t k = 0; k < 4; ++k) m[r][k] = number(row.items[k], wr + "[" + std::to_string(k) + "]");
            }
            if (pose_singular(m)) fail(key, "its 3x3 part R is singular (determinant 0): the object would be flat");
        }
    }

    // A depth's "parts": [k, j], the pair of parts it speaks of (a contact). Needed on objects made
    // of parts, where the depth of the objects is not defined; on two convex objects only [0, 0].
    void part_pair(const JNode& claim, TypedClaim& c) const {
        const JNode* n = claim.find("parts");
        if (!n) {
            if (parts_)
                fail("parts",
                     "missing: a penetration depth on objects made of parts is a contact of one part pair, "
                     "\"parts\": [part of P1, part of P2] (numbered from 0)");
            return;
        }
        if (n->kind != JNode::Array || n->items.size() != 2)
            fail("parts", "expected [part of P1, part of P2] (numbered from 0)");
        std::array<int, 2> k{};
        for (size_t i = 0; i < 2; ++i) {
            const JNode& x = n->items[i];
            const std::string w = "parts[" + std::to_string(i) + "]";
            if ((x.kind != JNode::Number && x.kind != JNode::String) || x.text.empty() ||
                x.text.find_first_not_of("0123456789") != std::string::npos || x.text.size() > 9)
                fail(w, "expected a part number (0, 1, ...)");
            const size_t v = std::stoul(x.text);
            if (v >= count_[i])
                fail(w, "P" + std::to_string(i + 1) + " has " + std::to_string(count_[i]) +
                            (count_[i] == 1 ? " part" : " parts") + " (numbered from 0)");
            k[i] = static_cast<int>(v);
        }
        if (parts_) c.parts = k;
    }

    static bool is_zero(const Vec3q& v) { return sgn(v[0]) == 0 && sgn(v[1]) == 0 && sgn(v[2]) == 0; }
    static std::optional<ClaimType> type_of(const std::string& kind) {
        for (ClaimType t :
             {ClaimType::Verdict, ClaimType::Curve, ClaimType::CurvePoint, ClaimType::SwitchPoint, ClaimType::Growth,
              ClaimType::Plane, ClaimType::Witness, ClaimType::Distance, ClaimType::Depth})
            if (kind == type_name(t)) return t;
        return std::nullopt;
    }
    [[noreturn]] void fail(const std::string& key, const std::string& what) const {
        throw InputError(where_ + (key.empty() ? "" : "." + key) + ": " + what);
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
        if (n.kind != JNode::Number && n.kind != JNode::String)
            fail(key, "expected a number or a string such as \"3/7\"");
        Q q;
        try {
            q = parse_number(n.text, n.kind == JNode::Number ? numbers_ : Numbers::Exact);
        } catch (const InputError& e) {
            fail(key, e.what());
        }
        return q;
    }
    Q field(const JNode& o, const char* key) const { return number(need(o, key), key); }
    // A number the program computed, into q: a non-number there (null, NaN, ±Infinity) makes the
    // claim no answer (false returned, q untouched).
    static bool non_number(const JNode& n) {
        return n.kind == JNode::Null ||
               (n.kind == JNode::Number && (n.text == "NaN" || n.text == "Infinity" || n.text == "-Infinity"));
    }
    static void set_no_answer(TypedClaim& c, const std::string& key, const char* reason) {
        if (!c.no_answer.empty()) return;  // the first one found is named
        c.no_answer = key;
        c.no_answer_reason = reason;
    }
    bool answer(const JNode& n, const std::string& key, TypedClaim& c, Q& q) const {
        if (non_number(n)) {
            set_no_answer(c, key, "not a number");
            return false;
        }
        q = number(n, key);
        return true;
    }
    // The same for a point: null, or any coordinate a non-number.
    bool answer_point(const JNode& n, const std::string& key, TypedClaim& c, Vec3q& p) const {
        if (n.kind == JNode::Null ||
            (n.kind == JNode::Array && std::any_of(n.items.begin(), n.items.end(), non_number))) {
            if (n.kind == JNode::Null || n.items.size() == 3) {
                set_no_answer(c, key, "not a number");
                return false;
            }
        }
        p = point(n, key);
        return true;
    }
    Vec3q point(const JNode& n, const std::string& key) const {
        if (n.kind != JNode::Array || n.items.size() != 3) fail(key, "expected 3 numbers");
        return {number(n.items[0], key), number(n.items[1], key), number(n.items[2], key)};
    }
    void pair_at(const JNode& o, TypedClaim& c) const {
        c.rho1 = field(o, "rho1");
        c.rho2 = field(o, "rho2");
        if (sgn(c.rho1) <= 0) fail("rho1", "scalings must be > 0 (got " + to_exact_string(c.rho1) + ")");
        if (sgn(c.rho2) <= 0) fail("rho2", "scalings must be > 0 (got " + to_exact_string(c.rho2) + ")");
    }
    std::optional<std::string> label(const JNode& o) const {
        const JNode* n = o.find("contact");
        if (!n) return std::nullopt;
        if (n->kind != JNode::String || n->text.size() != 2 || n->text.find_first_not_of("VEF") != std::string::npos)
            fail("contact", "expected a contact such as \"VE\"");
        return n->text;
    }
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

    ClaimedCurve curve(const JNode& j) const {
        only(j, {"kind", "vertices", "pieces", "switch_points"});
        ClaimedCurve k;
        auto& segs = k.segments;
        const JNode* verts = j.find("vertices");
        const JNode* pieces = j.find("pieces");
        if ((verts != nullptr) == (pieces != nullptr)) fail("", "give \"vertices\" (a polyline) or \"pieces\"");
        k.as_vertices = verts != nullptr;
        if (verts) {
            if (verts->kind != JNode::Array || verts->items.size() < 2)
                fail("vertices", "expected at least 2 [rho1, rho2] pairs");
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
                    k.switches.push_back(v[i]);
        } else {
            if (pieces->kind != JNode::Array || pieces->items.empty()) fail("pieces", "expected a list of pieces");
            for (const JNode& p : pieces->items) {
                if (p.kind != JNode::Object) fail("pieces", "expected objects");
                only(p, {"rho1", "slope", "intercept", "contact"});
                const JNode& r = need(p, "rho1");
                if (r.kind != JNode::Array || r.items.size() != 2) fail("pieces.rho1", "expected [from, to]");
                const Q x0 = scaling(r.items[0], "pieces.rho1"), x1 = scaling(r.items[1], "pieces.rho1");
                if (!(x0 < x1)) fail("pieces.rho1", "from < to is required");
                if (!segs.empty() && x0 != segs.back().x1)
                    fail("pieces.rho1", "each piece must start where the one before ends");
                const Q a = field(p, "slope"), b = field(p, "intercept");
                const Q y0 = a * x0 + b, y1 = a * x1 + b;
                if (sgn(y0) <= 0 || sgn(y1) <= 0) fail("pieces", "the piece reaches rho2 <= 0 (scalings must be > 0)");
                if (!segs.empty()) k.switches.push_back({x0, segs.back().y1});
                segs.push_back({x0, y0, x1, y1, label(p)});
            }
        }
        if (const JNode* sw = j.find("switch_points")) {
            if (sw->kind != JNode::Array) fail("switch_points", "expected a list of [rho1, rho2]");
            k.switches.clear();
            k.switches_listed = true;
            const Q lo = segs.front().x0, hi = segs.back().x1;
            for (const JNode& p : sw->items) {
                const auto [x, y] = scaling_pair(p, "switch_points");
                if (x < lo || x > hi)
                    fail("switch_points", "rho1 = " + to_exact_string(x) + " lies outside the claimed range");
                k.switches.push_back({x, y});
            }
        }
        return k;
    }
};

// ---- writing: the report of a judgement ---------------------------------------------------------

// claimed, exact, and the absolute and relative errors (exact, with nearest doubles).
void errors(Json& o, const Q& claimed, const Q& exact) {
    put_exact(o, "claimed", claimed);
    put_exact(o, "exact", exact);
    const Q err = abs(Q(claimed - exact));
    put_exact(o, "abs_error", err);
    if (sgn(exact) != 0)
        put_exact(o, "rel_error", err / abs(exact));
    else
        o["rel_error"] = nullptr;
}
// For a value whose exact square E is known: the error of the squares exactly, and |c − √E|
// and its relative size as MPFR-rounded doubles.
void errors_sq(Json& o, const Q& claimed, const Q& E) {
    put_exact(o, "claimed", claimed);
    put_exact(o, "exact_squared", E);
    put_exact(o, "squared_error", Q(claimed * claimed - E));
    const double d = -sqrt_minus_rn(E, claimed);  // c − √E
    o["abs_error_double"] = std::fabs(d);
    o["rel_error_double"] = sgn(E) ? Json(relative_sqrt_error_rn(E, claimed)) : Json(nullptr);
}
// (ρ1, ρ2), and which objects are at poses.
std::string at(const TypedClaim& c) {
    const char* posed = c.pose[0] && c.pose[1] ? " with P1 and P2 at poses"
                        : c.pose[0]            ? " with P1 at a pose"
                        : c.pose[1]            ? " with P2 at a pose"
                                               : "";
    return "(" + num(c.rho1) + ", " + num(c.rho2) + ")" + posed;
}
// A point's part on an object made of parts: its number, or false when no part holds it.
Json part_or_false(int k) { return k >= 0 ? Json(k) : Json(false); }
// After part k of object i in a text line: " ('foot')", its name, or "" when it has none.
std::string name_of(const ExactScene& sc, int i, int k) { return part_name_suffix(sc.P[i], static_cast<size_t>(k)); }
// Part k of object i in a text line: "part 3", "part 3 ('foot')" when it has a name, "NO" for none.
std::string part_or_no(const ExactScene& sc, int i, int k, bool near = false) {
    return k < 0 ? "NO" : (near ? "within LEN of part " : "part ") + std::to_string(k) + name_of(sc, i, k);
}
// A membership for the text line: "yes", "within LEN" (outside, within the absolute tolerance), "NO".
const char* yes_near_no(bool in, bool near) { return !in ? "NO" : near ? "within LEN" : "yes"; }
// o[key] = true beside o[in_key] for a point outside its body but within the absolute tolerance.
void put_near(Json& o, const char* key, bool near) {
    if (near) o[key] = true;
}
// A part pair [a, b] as o[key], and beside it o[key + "_names"], [name or null, name or null], when
// either part has a name (null for the pair itself: no pair).
void put_part_pair(Json& o, const std::string& key, const ExactScene& sc, int a, int b) {
    if (a < 0) {
        o[key] = nullptr;
        return;
    }
    o[key] = Json::array({a, b});
    const std::string &n1 = part_name(sc.P[0], static_cast<size_t>(a)),
                      &n2 = part_name(sc.P[1], static_cast<size_t>(b));
    if (!n1.empty() || !n2.empty())
        o[key + "_names"] = Json::array({n1.empty() ? Json(nullptr) : Json(n1), n2.empty() ? Json(nullptr) : Json(n2)});
}

// A JSON claim's report object (beside its index and kind) and its text line; `parts`: the scene
// when the claim was on objects made of parts, else null.
void describe(const TypedClaim& c, const Judged& g, const ExactScene* parts, Json& o, std::string& text) {
    auto rhos = [&] {
        put_exact(o, "rho1", c.rho1);
        put_exact(o, "rho2", c.rho2);
        for (size_t i = 0; i < 2; ++i)
            if (c.pose[i]) o[i ? "pose2" : "pose1"] = exact_claim_json(c)[i ? "pose2" : "pose1"];
    };
    if (!c.no_answer.empty()) {
        // The scaling pair it was asked at, where that is a question and not the answer.
        const bool asked =
            c.type != ClaimType::Growth && c.type != ClaimType::Curve && c.type != ClaimType::SwitchPoint;
        if (asked && c.type != ClaimType::CurvePoint)
            rhos();
        else if (c.type == ClaimType::CurvePoint)
            put_exact(o, "rho1", c.rho1);
        o["no_answer"] = c.no_answer;
        o["reason"] = c.no_answer_reason;
        // A contact names its part pair, answered or not.
        std::string of;
        if (parts && c.parts) {
            const int a = (*c.parts)[0], b = (*c.parts)[1];
            put_part_pair(o, "parts", *parts, a, b);
            of = " of parts " + std::to_string(a) + name_of(*parts, 0, a) + " and " + std::to_string(b) +
                 name_of(*parts, 1, b);
        }
        text =
            std::string(type_name(c.type)) + of +
            (asked ? c.type == ClaimType::CurvePoint ? " at rho1 = " + num(c.rho1) : " at " + at(c) : std::string()) +
            ": " + c.no_answer + " is " + c.no_answer_reason + ": no answer";
        return;
    }
    switch (c.type) {
    case ClaimType::Verdict: {
        const auto& d = std::get<VerdictJudged>(g.of);
        rhos();
        if (parts) {
            o["exact"] = verdict_name(d.exact);
            put_part_pair(o, "pair", *parts, g.part1, g.part2);
            o["claimed"] = claimed_name(c.verdict);
        } else {
            o["claimed"] = claimed_name(c.verdict);
            o["exact"] = verdict_name(d.exact);
            if (!c.posed()) put_exact(o, "rho2_minus_curve", d.rho2_minus_curve);  // no curve at a pose
        }
        text = "verdict at " + at(c) + ": claimed " + claimed_name(c.verdict) + ", exact " + verdict_name(d.exact);
        return;
    }
    case ClaimType::Growth: {
        const auto& d = std::get<GrowthJudged>(g.of);
        errors(o, c.value, d.exact);
        text = "growth distance " + num(c.value) + ": exact " + num(d.exact);
        return;
    }
    case ClaimType::SwitchPoint: {
        const auto& d = std::get<SwitchPointJudged>(g.of);
        rhos();
        const std::string head = "switch point " + at(c);
        if (!d.nearest) {
            o["nearest"] = nullptr;
            if (d.window_whole)
                text = head + ": the exact curve has no switch point at rho1, rho2 > 0";
            else
                text = head + ": the exact curve has no switch point from rho1 = " + num(d.window_lo) +
                       (d.window_hi ? " to " + num(*d.window_hi) : std::string(" on")) + " (the range the walk proved)";
            return;
        }
        const ExactSwitch& b = *d.nearest;
        Json n;
        put_exact(n, "rho1", b.rho1);
        put_exact(n, "rho2", b.rho2);
        n["contact"] = b.label;
        o["nearest"] = n;
        Json e1, e2;
        errors(e1, c.rho1, b.rho1);
        errors(e2, c.rho2, b.rho2);
        o["rho1_error"] = e1;
        o["rho2_error"] = e2;
        o["contact_right"] = d.contact_right ? Json(*d.contact_right) : Json(nullptr);
        text = "switch point (" + num(c.rho1) + ", " + num(c.rho2) + (c.contact ? ", " + *c.contact : "") +
               (d.matched ? "): matches exact (" : "): nearest exact (") + num(b.rho1) + ", " + num(b.rho2) + ", " +
               b.label + ")";
        return;
    }
    case ClaimType::CurvePoint: {
        const auto& d = std::get<CurvePointJudged>(g.of);
        rhos();
        put_exact(o, "curve_rho2", d.exact);
        errors(o, c.rho2, d.exact);
        text = "curve point " + at(c) + ": exact curve at rho1 is " + num(d.exact);
        return;
    }
    case ClaimType::Curve: {
        const auto& d = std::get<CurveJudged>(g.of);
        o["exact_rho2_positive_over_range"] = d.exact_positive;
        put_exact(o, "max_vertical_error", d.max_vertical);
        put_exact(o, "max_vertical_error_at_rho1", d.max_vertical_at);
        put_exact(o, "max_horizontal_error", d.max_horizontal);
        auto pairs = [](const std::vector<std::pair<Q, Q>>& v) {
            Json a = Json::array();
            for (const auto& [x, y] : v) a.push_back(Json::array({to_exact_string(x), to_exact_string(y)}));
            return a;
        };
        o["switch_points_missed"] = pairs(d.missed);
        o["switch_points_extra"] = pairs(d.extra);
        Json mp = Json::array();
        for (const CurveJudged::Misplaced& m : d.misplaced) {
            Json j;
            put_exact(j, "exact_rho1", m.exact_rho1);
            put_exact(j, "exact_rho2", m.exact_rho2);
            put_exact(j, "claimed_rho1", m.claimed_rho1);
            put_exact(j, "claimed_rho2", m.claimed_rho2);
            mp.push_back(j);
        }
        o["switch_points_misplaced"] = mp;
        Json wl = Json::array();
        for (const CurveJudged::WrongContact& w : d.wrong_contacts) {
            Json j;
            put_exact(j, "rho1", w.rho1);
            j["claimed"] = w.claimed;
            j["exact"] = w.exact;
            wl.push_back(j);
        }
        o["wrong_contacts"] = wl;
        const size_t n = c.curve->segments.size();
        text = "curve of " + std::to_string(n) + (n == 1 ? " segment" : " segments") + ": max vertical error " +
               num(d.max_vertical) + ", max horizontal error " + num(d.max_horizontal) + ", switch points missed " +
               std::to_string(d.missed.size()) + ", extra " + std::to_string(d.extra.size()) + ", misplaced " +
               std::to_string(d.misplaced.size()) + ", wrong contacts " + std::to_string(d.wrong_contacts.size()) +
               (d.exact_positive ? "" : ", and the exact curve reaches rho2 <= 0 in the claimed range");
        return;
    }
    case ClaimType::Plane: {
        const auto& d = std::get<PlaneJudged>(g.of);
        rhos();
        put_exact(o, "max_over_P1", d.c1);  // P1(ρ1) ⊆ {n·x ≤ c1}
        put_exact(o, "min_over_P2", d.c2);  // P2(ρ2) ⊆ {n·x ≥ c2}
        put_exact(o, "gap", d.c2 - d.c1);
        text = "plane at " + at(c) + ": P1 reaches " + num(d.c1) + ", P2 starts at " + num(d.c2);
        if (c.offset) {
            put_exact(o, "offset_minus_P1", *c.offset - d.c1);
            put_exact(o, "P2_minus_offset", d.c2 - *c.offset);
            text += ", offset " + num(*c.offset);
        }
        return;
    }
    case ClaimType::Witness: {
        const auto& d = std::get<WitnessJudged>(g.of);
        if (parts) {
            o["in_P1_part"] = part_or_false(d.in_part1);
            put_part_name(o, "in_P1_part", parts->P[0], d.in_part1);
            o["in_P2_part"] = part_or_false(d.in_part2);
            put_part_name(o, "in_P2_part", parts->P[1], d.in_part2);
            text = "witness point at " + at(c) + ": in P1 " + part_or_no(*parts, 0, d.in_part1, d.near1) + ", in P2 " +
                   part_or_no(*parts, 1, d.in_part2, d.near2);
        } else {
            o["in_P1"] = d.in1;
            o["in_P2"] = d.in2;
            text = "witness point at " + at(c) + ": in P1 " + yes_near_no(d.in1, d.near1) + ", in P2 " +
                   yes_near_no(d.in2, d.near2);
        }
        put_near(o, "near_P1", d.near1);
        put_near(o, "near_P2", d.near2);
        o["exact_verdict"] = verdict_name(d.exact_verdict);
        return;
    }
    case ClaimType::Distance: {
        const auto& d = std::get<DistanceJudged>(g.of);
        rhos();
        errors_sq(o, c.value, d.exact_squared);
        put_point(o, "exact_closest_P1", d.exact_p1);
        put_point(o, "exact_closest_P2", d.exact_p2);
        if (parts) put_part_pair(o, "exact_pair", *parts, g.part1, g.part2);
        o["value_right"] = d.value_right;
        text = "distance at " + at(c) + ": claimed " + num(c.value) + ", exact squared " + num(d.exact_squared) +
               " (distance ~" + dbl(sqrt_minus_rn(d.exact_squared, Q(0))) +
               (parts ? ", parts " + std::to_string(g.part1) + name_of(*parts, 0, g.part1) + " and " +
                            std::to_string(g.part2) + name_of(*parts, 1, g.part2)
                      : std::string()) +
               ")";
        if (c.closest) {
            if (parts) {
                o["closest_in_P1_part"] = part_or_false(d.in_part1);
                put_part_name(o, "closest_in_P1_part", parts->P[0], d.in_part1);
                o["closest_in_P2_part"] = part_or_false(d.in_part2);
                put_part_name(o, "closest_in_P2_part", parts->P[1], d.in_part2);
            } else {
                o["closest_in_P1"] = d.in1;
                o["closest_in_P2"] = d.in2;
            }
            put_near(o, "closest_near_P1", d.near1);
            put_near(o, "closest_near_P2", d.near2);
            if (d.near1 || d.near2) text += ", closest points within LEN of their bodies";
            put_exact(o, "closest_squared_distance", d.closest_squared);
            o["closest_right"] = *d.closest_right;
            // Wrong points: the line says so, and why (CLAIMS.md, "a closest pair").
            if (!*d.closest_right) {
                std::string why;
                if (!d.in1) why = "the first point is not in P1";
                if (!d.in2) why += std::string(why.empty() ? "" : "; ") + "the second point is not in P2";
                if (why.empty())
                    why = d.near1 || d.near2 ? "each is in or within LEN of its body, but they lie farther apart than "
                                               "the distance allows"
                                             : "each is in its body, but they lie farther apart than the distance";
                text += std::string(d.value_right ? ", but" : ", and") + " the closest points are wrong (" + why + ")";
            }
        }
        return;
    }
    case ClaimType::Depth: {
        const auto& d = std::get<DepthJudged>(g.of);
        rhos();
        // On parts, the contact's part pair, named in the line.
        std::string of;
        if (parts && c.parts) {
            put_part_pair(o, "parts", *parts, g.part1, g.part2);
            of = " of parts " + std::to_string(g.part1) + name_of(*parts, 0, g.part1) + " and " +
                 std::to_string(g.part2) + name_of(*parts, 1, g.part2);
        }
        if (!d.exact_squared) {
            o["exact_verdict"] = verdict_name(Verdict::Separated);
            put_exact(o, "claimed", c.value);
            text = "penetration depth" + of + " at " + at(c) + ": claimed " + num(c.value) + ", but the " +
                   (of.empty() ? "pair is" : "parts are") + " separated";
            return;
        }
        errors_sq(o, c.value, *d.exact_squared);
        o["exact_direction"] = Json::array(
            {d.exact_direction[0].get_str(), d.exact_direction[1].get_str(), d.exact_direction[2].get_str()});
        o["value_right"] = *d.value_right;
        text = "penetration depth" + of + " at " + at(c) + ": claimed " + num(c.value) + ", exact squared " +
               num(*d.exact_squared) + " (depth ~" + dbl(sqrt_minus_rn(*d.exact_squared, Q(0))) + ")";
        if (c.direction) {
            put_exact(o, "depth_squared_along_direction", d.along);
            o["direction_right"] = *d.direction_right;
            if (*d.value_right && !*d.direction_right) text += ", but the direction is wrong";
        }
        return;
    }
    }
}

// ---- the line format ------------------------------------------------------------------------------

// A number of the line format, read as a JSON claim's number is (parse_number): the binary value
// a decimal names under `numbers` (a floating-point program's output means the value it held), or
// under Exact the decimal as written; a fraction p/q is exact.
Q read_number(const std::string& t, Numbers numbers, const std::string& where) {
    try {
        return parse_number(t, numbers);
    } catch (const InputError& e) {
        throw InputError(where + ": " + e.what());
    }
}
// A line's RHO1 RHO2, each > 0; a refusal names the one at fault.
std::pair<Q, Q> read_scalings(const std::string& a, const std::string& b, Numbers numbers, const std::string& where) {
    const Q r1 = read_number(a, numbers, where + ": rho1"), r2 = read_number(b, numbers, where + ": rho2");
    if (sgn(r1) <= 0) throw InputError(where + ": rho1: scalings must be > 0 (got " + to_exact_string(r1) + ")");
    if (sgn(r2) <= 0) throw InputError(where + ": rho2: scalings must be > 0 (got " + to_exact_string(r2) + ")");
    return {r1, r2};
}

// What printf writes for a non-finite double (any case, any sign): no answer.
bool non_number_word(std::string w) {
    if (!w.empty() && (w[0] == '-' || w[0] == '+')) w.erase(0, 1);
    std::transform(w.begin(), w.end(), w.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return w == "nan" || w == "inf" || w == "infinity";
}

// One line's claim, typed: 'RHO1 RHO2 VERDICT', and on convex objects 'curve RHO1 RHO2' (a curve
// point, exactly) and 'growth RHO'.
TypedClaim read_line(const std::vector<std::string>& w, Numbers numbers, bool parts, const std::string& where) {
    TypedClaim c;
    if (parts && (w.size() != 3 || w[0] == "curve"))
        throw InputError(where +
                         ": expected 'RHO1 RHO2 VERDICT' (on objects made of parts, verdict lines only: a curve and a "
                         "growth distance are claims on convex objects)");
    if (w[0] == "curve" && w.size() == 3) {
        c.type = ClaimType::CurvePoint;
        if (non_number_word(w[2])) {  // ρ2 is the program's answer
            c.rho1 = read_scalings(w[1], "1", numbers, where).first;
            c.no_answer = "rho2", c.no_answer_reason = "not a number";
        } else {
            std::tie(c.rho1, c.rho2) = read_scalings(w[1], w[2], numbers, where);
        }
    } else if (w[0] == "growth" && w.size() == 2) {
        c.type = ClaimType::Growth;
        if (non_number_word(w[1])) {
            c.no_answer = "value", c.no_answer_reason = "not a number";
            return c;
        }
        c.value = read_number(w[1], numbers, where);
        if (sgn(c.value) < 0) throw InputError(where + ": a growth distance is >= 0 (0 when the seeds coincide)");
    } else if (w.size() == 3) {
        c.type = ClaimType::Verdict;
        std::tie(c.rho1, c.rho2) = read_scalings(w[0], w[1], numbers, where);
        const std::optional<Claimed> v = claimed_of(w[2]);
        if (!v)
            throw InputError(where + ": unknown verdict " + in_quotes(w[2]) +
                             " (separated, touching, overlapping, intersecting)");
        c.verdict = *v;
    } else {
        throw InputError(where + ": expected 'RHO1 RHO2 VERDICT', 'curve RHO1 RHO2' or 'growth RHO'");
    }
    return c;
}

// A line's report object (beside its line number) and text; w: the line's words as written.
void describe_line(const TypedClaim& c, const Judged& g, const ExactScene* parts, const std::vector<std::string>& w,
                   Json& o, std::string& text) {
    if (!c.no_answer.empty()) {
        o["claim"] = c.type == ClaimType::Growth ? "growth" : "curve";
        if (c.type == ClaimType::CurvePoint) put_exact(o, "rho1", c.rho1);
        o["no_answer"] = c.no_answer;
        o["reason"] = c.no_answer_reason;
        text = (c.type == ClaimType::Growth ? "growth distance " + w[1] : "curve point (" + w[1] + ", " + w[2] + ")") +
               ": " + c.no_answer + " is " + c.no_answer_reason + ": no answer";
        return;
    }
    switch (c.type) {
    case ClaimType::CurvePoint: {
        o["claim"] = "curve";
        put_exact(o, "rho1", c.rho1);
        put_exact(o, "rho2", c.rho2);
        const Q& f = std::get<CurvePointJudged>(g.of).exact;
        put_exact(o, "curve_rho2", f);
        put_exact(o, "rho2_minus_curve", c.rho2 - f);
        text = "curve point (" + w[1] + ", " + w[2] + "): exact curve at rho1 is " + num(f, 17) + ", off by " +
               num(c.rho2 - f, 17);
        return;
    }
    case ClaimType::Growth: {
        o["claim"] = "growth";
        put_exact(o, "claimed", c.value);
        const Q& e = std::get<GrowthJudged>(g.of).exact;
        put_exact(o, "exact", e);
        text = "growth distance " + w[1] + ": exact " + num(e, 17) + ", off by " + num(c.value - e, 17);
        return;
    }
    default: {
        const VerdictJudged& d = std::get<VerdictJudged>(g.of);
        const std::string v = claimed_name(c.verdict), e = verdict_name(d.exact);
        o["claim"] = v;
        put_exact(o, "rho1", c.rho1);
        put_exact(o, "rho2", c.rho2);
        o["exact"] = e;
        if (parts) {
            put_part_pair(o, "pair", *parts, g.part1, g.part2);
            text = "(" + num(c.rho1, 17) + ", " + num(c.rho2, 17) + ") claimed " + v + ": exact " + e;
        } else {
            put_exact(o, "rho2_minus_curve", d.rho2_minus_curve);
            text = "(" + w[0] + ", " + w[1] + ") claimed " + v + ": exact " + e +
                   ", rho2 - curve = " + num(d.rho2_minus_curve, 17);
        }
        return;
    }
    }
}

// ---- the runs ---------------------------------------------------------------------------------------

// The report of n claims, `bad` of them wrong: JSON {"claims", "tolerance" (JSON claims only),
// "right", "wrong"}, or the claims' text lines and a summary line.
// (fallbacks >= 0: JSON claims' "exact_fallbacks", how often the exact fallback ran.)
std::string report(Json arr, const std::string& text, long n, long bad, bool json, const ClaimOptions* tolerance,
                   long* wrong, long* count, long fallbacks = -1, long fallbacks_depth = 0) {
    if (wrong) *wrong = bad;
    if (count) *count = n;
    if (json) {
        Json j;
        j["claims"] = std::move(arr);
        if (tolerance) put_exact(j, "tolerance", tolerance->tolerance);
        if (tolerance && sgn(tolerance->abs_tolerance) > 0) put_exact(j, "abs_tolerance", tolerance->abs_tolerance);
        j["right"] = n - bad;
        j["wrong"] = bad;
        if (fallbacks >= 0) j["exact_fallbacks"] = Json{{"distance", fallbacks}, {"depth", fallbacks_depth}};
        return dump(j);
    }
    // The tolerances, when any is not 0, as the checker shows them.
    std::string tols;
    if (tolerance && sgn(tolerance->tolerance) != 0) tols += ", tolerance " + to_exact_string(tolerance->tolerance);
    if (tolerance && sgn(tolerance->abs_tolerance) != 0)
        tols += ", abs_tolerance " + to_exact_string(tolerance->abs_tolerance);
    return text + "claims: " + std::to_string(n) + ", right: " + std::to_string(n - bad) +
           ", wrong: " + std::to_string(bad) + tols + "\n";
}

Json entry(size_t index, Proof&& p, bool right) {
    return Json{{"index", index}, {"claim", std::move(p.claim)}, {"right", right}, {"proof", std::move(p.proof)}};
}

// A JSON claims file ({"format": "scalecert-claims-1", "claims": [...]}): its root, checked.
JNode claims_root(const std::string& claims, const std::string& name) {
    JNode root;
    try {
        root = parse_strict_json(claims, true);
    } catch (const JsonError& e) {
        throw InputError(name + ": malformed JSON near byte " + std::to_string(e.pos) + ": " + e.what);
    }
    const JNode* format = root.find("format");
    const JNode* list = root.find("claims");
    if (!format || format->kind != JNode::String || format->text != "scalecert-claims-1")
        throw InputError(name + ": format: expected \"scalecert-claims-1\"");
    for (const std::string& k : root.keys)
        if (k != "format" && k != "claims") throw InputError(name + ": " + k + ": unknown field");
    if (!list || list->kind != JNode::Array) throw InputError(name + ": claims: expected a list");
    return root;
}

bool is_json(const std::string& claims, const ClaimOptions& opt, const std::string& name) {
    if (sgn(opt.tolerance) < 0)
        throw InputError("tolerance: must be >= 0 (got " + to_exact_string(opt.tolerance) + ")");
    if (sgn(opt.abs_tolerance) < 0)
        throw InputError("abs_tolerance: must be >= 0 (got " + to_exact_string(opt.abs_tolerance) + ")");
    const size_t first = claims.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && claims[first] == '{') return true;
    if (sgn(opt.tolerance) != 0 || sgn(opt.abs_tolerance) != 0)
        throw InputError(name + ": a tolerance applies to JSON claims (scalecert-claims-1) only");
    return false;
}

// Every claim of a file, read into types and judged by `rules`: the
// report, the certificate's entries (when proving), the counts.
struct Run {
    Json arr = Json::array(), entries = Json::array();
    std::string text;
    long n = 0, bad = 0;
};
Run run_claims(ClaimRules& rules, const std::string& claims, const std::string& name, const ClaimOptions& opt,
               bool json, const ExactScene* parts, bool prove) {
    Run r;
    auto one = [&](const TypedClaim& c, size_t index, Json& o, auto&& describe_it) {
        Proof p;
        const Judged g = rules.judge(c, prove ? &p : nullptr);
        std::string line;
        describe_it(g, line);
        if (prove) r.entries.push_back(entry(index, std::move(p), g.right));
        o["right"] = g.right;
        ++r.n;
        r.bad += !g.right;
        // Only the report asked for is kept (a million claims: 80 MB of lines, not gigabytes of both).
        if (opt.json)
            r.arr.push_back(std::move(o));
        else
            r.text += std::string(g.right ? "right  " : "WRONG  ") + line + "\n";
    };
    if (json) {
        const JNode root = claims_root(claims, name);
        ClaimReader reader(name, opt.numbers, parts);
        for (size_t i = 0; i < root.find("claims")->items.size(); ++i) {
            const TypedClaim c = reader.read(root.find("claims")->items[i], i);
            Json o;
            o["index"] = i;
            o["kind"] = type_name(c.type);
            try {
                one(c, i, o, [&](const Judged& g, std::string& line) { describe(c, g, parts, o, line); });
            } catch (const InputError& e) {  // a limit met while judging it (a pose's moved points)
                if (!c.posed()) throw;
                throw InputError(name + ": claims[" + std::to_string(i) + "]." + e.what());
            }
        }
        return r;
    }
    std::istringstream in(claims);
    std::string line;
    for (long no = 1; std::getline(in, line); ++no) {
        if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::istringstream ls(line);
        std::vector<std::string> w;
        for (std::string t; ls >> t;) w.push_back(t);
        if (w.empty()) continue;
        const TypedClaim c = read_line(w, opt.numbers, parts != nullptr, name + ": line " + std::to_string(no));
        Json o;
        o["line"] = no;
        // The certificate's entries are numbered by line.
        one(c, static_cast<size_t>(no), o,
            [&](const Judged& g, std::string& text) { describe_line(c, g, parts, w, o, text); });
    }
    return r;
}
}  // namespace

JNode read_claims_root(const std::string& claims, const std::string& name) { return claims_root(claims, name); }

TypedClaim read_claim(const JNode& claim, size_t index, const std::string& name, Numbers numbers) {
    return ClaimReader(name, numbers, nullptr).read(claim, index);
}

std::string certify_fp(ClaimRules& rules, const std::string& claims, const std::string& name, const ClaimOptions& opt,
                       long* wrong, long* count, std::string* certificate) {
    const bool json = is_json(claims, opt, name);
    const Run r = run_claims(rules, claims, name, opt, json, rules.parts(), certificate != nullptr);
    if (certificate) *certificate = rules.certificate(std::move(r.entries));
    const std::optional<std::array<long, 2>> fb = json ? rules.fallbacks() : std::nullopt;
    return report(std::move(r.arr), r.text, r.n, r.bad, opt.json, json ? &opt : nullptr, wrong, count,
                  fb ? (*fb)[0] : -1, fb ? (*fb)[1] : 0);
}

std::string certify_fp(const ClaimModels& models, const std::string& claims, const std::string& name,
                       const ClaimOptions& opt, long* wrong, long* count, std::string* certificate) {
    ConvexRules rules(models, {opt.tolerance, opt.abs_tolerance});
    return certify_fp(rules, claims, name, opt, wrong, count, certificate);
}

std::string certify_fp(CompoundJudge& judge, const std::string& claims, const std::string& name,
                       const ClaimOptions& opt, long* wrong, long* count, std::string* certificate) {
    PartsRules rules(judge, {opt.tolerance, opt.abs_tolerance});
    return certify_fp(rules, claims, name, opt, wrong, count, certificate);
}

HullClaimModels::HullClaimModels(const HullModel& m, const TouchingCurve& c)
    : m_(m), c_(c), points_(std::make_shared<HullPoints>(m)) {}
Verdict HullClaimModels::verdict(const Q& r1, const Q& r2) const { return query(m_, c_, r1, r2, false).verdict; }
Q HullClaimModels::curve_value(const Q& r1) const { return c_.env.value(m_.lines, r1); }
std::pair<const Model*, QueryAnswer> HullClaimModels::certified_query(const Q& r1, const Q& r2) const {
    return {&m_, query(m_, c_, r1, r2, true)};
}
Json HullClaimModels::growth_proof() const { return scalecert::internal::growth_proof(m_, c_); }
bool HullClaimModels::member(int i, const Q& rho, const Vec3q& x, Json* proof) const {
    return hull_member(m_, i, rho, x, proof);
}

}  // namespace scalecert::internal
