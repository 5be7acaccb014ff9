// certify-fp: the JSON and line formats of claims read into typed claims (claim.hpp), judged by
// the rules (rules.cpp), and their reports written (JSON or text; the display doubles of
// |claimed − exact| use MPFR's correctly rounded square root).
#include "certify/claims.hpp"
#include "certify/claim.hpp"
#include "certify/certificate.hpp"
#include "certify/compound_judge.hpp"
#include "certify/region_certificate.hpp"
#include "certify/report.hpp"
#include "certify/judgements.hpp"
#include "geometry/measures.hpp"
#include "io/strict_json.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <sstream>

namespace scalecert::internal {

using namespace report_parts;

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
        : name_(name), numbers_(numbers), parts_(parts != nullptr), rounded_(parts && parts->rounded()) {
        if (parts)
            for (int i = 0; i < 2; ++i) count_[i] = std::max<size_t>(1, parts->P[i].parts.size());
    }

    TypedClaim read(const JNode& claim, size_t index) {
        where_ = name_ + ": claims[" + std::to_string(index) + "]";
        if (claim.kind != JNode::Object) fail("", "expected an object with \"kind\"");
        const std::string kind = str(claim, "kind");
        const std::optional<ClaimType> t = type_of(kind);
        // On parts with radii a signed distance is a contact of one part pair, as a depth is.
        if (parts_ && (!t || !(PartsRules::takes(*t) || (rounded_ && *t == ClaimType::SignedDistance)))) {
            const std::string kinds = std::string("verdict, separating_plane, witness_point, distance") +
                                      (rounded_ ? ", penetration_depth and signed_distance" : " and penetration_depth");
            if (t)
                fail("kind", in_quotes(kind) +
                                 " is a claim on two convex objects; on objects made of parts certify-fp " + "takes " +
                                 kinds +
                                 (rounded_ ? " (the region is not built for parts with radii)"
                                           : " (the region and its growth set: scalecert region)"));
            fail("kind", "unknown kind " + in_quotes(kind) + " (on objects made of parts: " + kinds + ")");
        }
        if (!t)
            fail("kind", "unknown kind " + in_quotes(kind) +
                             " (verdict, curve, curve_point, switch_point, growth_distance, separating_plane, "
                             "witness_point, distance, "
                             "penetration_depth, signed_distance)");
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
                fail("verdict", "unknown verdict " + in_quotes(v) +
                                    " (separated, touching, overlapping, intersecting, not_overlapping)");
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
        case ClaimType::SignedDistance: {
            only(claim, {"kind", "rho1", "rho2", "parts", "value", "at_least", "below", "pose1", "pose2"});
            pair_at(claim, c);
            part_pair(claim, c);
            poses(claim, c);
            const JNode* v = claim.find("value");
            const JNode* lo = claim.find("at_least");
            const JNode* hi = claim.find("below");
            if ((v != nullptr) + (lo != nullptr) + (hi != nullptr) != 1)
                fail("", "give one of \"value\", \"at_least\" and \"below\" (the signed distance, or a bound)");
            c.bound = v ? TypedClaim::Bound::Value : lo ? TypedClaim::Bound::AtLeast : TypedClaim::Bound::Below;
            answer(v ? *v : lo ? *lo : *hi, v ? "value" : lo ? "at_least" : "below", c, c.value);
            break;
        }
        }
        return c;
    }

  private:
    std::string name_, where_;
    Numbers numbers_;
    bool parts_, rounded_;      // objects made of parts, with radii
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

    // A depth's or a signed distance's "parts": [k, j], the pair of parts it speaks of (a contact).
    // Needed on objects made of parts, where the depth of the objects is not defined; on two convex
    // objects only [0, 0].
    void part_pair(const JNode& claim, TypedClaim& c) const {
        const JNode* n = claim.find("parts");
        if (!n) {
            if (parts_)
                fail("parts", std::string("missing: a ") +
                                  (c.type == ClaimType::Depth ? "penetration depth" : "signed distance") +
                                  " on objects made of parts is a contact of one part pair, "
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
              ClaimType::Plane, ClaimType::Witness, ClaimType::Distance, ClaimType::Depth, ClaimType::SignedDistance})
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

// A JSON claim's report object (beside its index and kind) and its text line; `parts`: the scene
// when the claim was on objects made of parts, else null.
void describe_claim(const TypedClaim& c, const Judged& g, const ExactScene* parts, Json& o, std::string& text) {
    if (!c.no_answer.empty()) {
        // The scaling pair it was asked at, where that is a question and not the answer.
        const bool asked =
            c.type != ClaimType::Growth && c.type != ClaimType::Curve && c.type != ClaimType::SwitchPoint;
        if (asked && c.type != ClaimType::CurvePoint)
            put_rhos(o, c);
        else if (c.type == ClaimType::CurvePoint)
            put_exact(o, "rho1", c.rho1);
        o["no_answer"] = c.no_answer;
        o["reason"] = c.no_answer_reason;
        // A contact names its part pair, answered or not.
        std::string of;
        if (parts && c.parts) {
            const int a = (*c.parts)[0], b = (*c.parts)[1];
            put_part_pair(o, "parts", *parts, a, b);
            of = " of " + parts_named(*parts, a, b);
        }
        text =
            std::string(type_name(c.type)) + of +
            (asked ? c.type == ClaimType::CurvePoint ? " at rho1 = " + num(c.rho1) : " at " + at(c) : std::string()) +
            ": " + c.no_answer + " is " + c.no_answer_reason + ": no answer";
        return;
    }
    std::visit(
        [&](const auto& d) {
            if constexpr (std::is_same_v<std::decay_t<decltype(d)>, std::monostate>)
                throw std::logic_error("certify-fp: a judgement with no kind");
            else
                describe(c, d, g, parts, o, text);
        },
        g.of);
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
                             " (separated, touching, overlapping, intersecting, not_overlapping)");
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
    std::visit(
        [&](const auto& d) {
            using K = std::decay_t<decltype(d)>;
            if constexpr (std::is_same_v<K, VerdictJudged> || std::is_same_v<K, CurvePointJudged> ||
                          std::is_same_v<K, GrowthJudged>)
                describe_line(c, d, g, parts, w, o, text);
            else
                throw std::logic_error("certify-fp: a line of another kind");
        },
        g.of);
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
    auto one = [&](const TypedClaim& c, size_t index, const std::string& where, Json& o, auto&& describe_it) {
        const Judged g = judge_claim(rules, c, index, where, prove ? &r.entries : nullptr);
        std::string line;
        describe_it(g, line);
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
            if (const std::string why = rules.refusal(c.type); !why.empty())
                throw InputError(name + ": claims[" + std::to_string(i) + "].kind: " + in_quotes(type_name(c.type)) +
                                 ": " + why);
            Json o;
            o["index"] = i;
            o["kind"] = type_name(c.type);
            one(c, i, name + ": claims[" + std::to_string(i) + "]", o,
                [&](const Judged& g, std::string& line) { describe_claim(c, g, parts, o, line); });
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
        if (const std::string why = rules.refusal(c.type); !why.empty())
            throw InputError(name + ": line " + std::to_string(no) + ": " +
                             (c.type == ClaimType::Growth ? "growth" : "curve") + ": " + why);
        Json o;
        o["line"] = no;
        // The certificate's entries are numbered by line.
        one(c, static_cast<size_t>(no), name + ": line " + std::to_string(no), o,
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
