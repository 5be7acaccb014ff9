// The typed claim core: a claim (TypedClaim) is judged by typed rules into a Judged, with its
// proof when asked. Every front end reads its own form into a TypedClaim and writes its own form
// from the Judged: the JSON and line formats (claims.cpp), the C++ API (api.cpp) and numpy
// (python/module.cpp, through the C++ API). The rules are those of certificates/CLAIMS.md, each
// applied once, for convex objects (ConvexRules) and objects made of parts (PartsRules): each
// claim kind's rules and report in its own file of kinds/.
#pragma once
#include "certify/claims.hpp"
#include "io/strict_json.hpp"

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace scalecert::internal {

enum class ClaimType {
    Verdict,
    Curve,
    CurvePoint,
    SwitchPoint,
    Growth,
    Plane,
    Witness,
    Distance,
    Depth,
    SignedDistance
};
const char* type_name(ClaimType t);  // the JSON kind: "verdict", "curve", ..., "penetration_depth", "signed_distance"

// A claimed verdict: the three exact ones, or intersecting (= not separated): the public type.
using Claimed = scalecert::ClaimedVerdict;
const char* claimed_name(Claimed v);
std::optional<Claimed> claimed_of(const std::string& name);
bool verdict_matches(Claimed claimed, Verdict exact);

// A claimed curve: segments over increasing ρ1, contiguous, each with its contact when claimed.
struct CurveSegment {
    Q x0, y0, x1, y1;
    std::optional<std::string> contact;
};
struct ClaimedCurve {
    std::vector<CurveSegment> segments;
    bool as_vertices = true;                // written as a polyline ("vertices"), else "pieces"
    std::vector<std::pair<Q, Q>> switches;  // its switch points (listed, or where its slope changes)
    bool switches_listed = false;           // given as "switch_points"
};

// One claim, every number exact: the fields its type uses.
struct TypedClaim {
    ClaimType type = ClaimType::Verdict;
    Q rho1 = 1, rho2 = 1;                  // all but Growth and Curve
    Claimed verdict = Claimed::Separated;  // Verdict
    Vec3q normal{};                        // Plane (nonzero)
    std::optional<Q> offset;               // Plane
    Vec3q point{};                         // Witness
    Q value = 0;                           // Growth, Distance, Depth, SignedDistance
    // SignedDistance: the value claimed is the signed distance, or a bound on it: at least the
    // value, or below it (what "no contact within the margin" and "a contact" say).
    // AtMost (value or below it, never read from a claims file) is what a MuJoCo contact says of
    // the margin: MuJoCo reports one at dist = margin, and says none there too (CLAIMS.md).
    enum class Bound { Value, AtLeast, Below, AtMost } bound = Bound::Value;
    std::optional<std::array<Vec3q, 2>> closest;  // Distance: on P1, on P2
    std::optional<Vec3q> direction;               // Depth (nonzero)
    // Depth on objects made of parts: the part pair it speaks of (a contact), [P1 part, P2 part].
    std::optional<std::array<int, 2>> parts;
    // The objects at poses (Verdict, Plane, Witness, Distance, Depth): P_i moved by [R_i | t_i]
    // as the scene places it, its seed too, then scaled about the seed (none: as the scene is).
    std::array<std::optional<Pose>, 2> pose;
    bool posed() const { return pose[0] || pose[1]; }
    std::optional<std::string> contact;         // SwitchPoint
    std::shared_ptr<const ClaimedCurve> curve;  // Curve
    // A field the program wrote no answer in (CLAIMS.md, "Outputs that are no answer"): a NaN, an
    // infinity or a null where a number is due, or a zero normal or direction. The claim is
    // judged wrong; that field's value above is not used.
    std::string no_answer, no_answer_reason;
    // Witness: also the exact verdict, which the report says (a judge that needs the membership
    // alone, as scalecert mujoco's of contact points, skips that cost: the verdict stays Separated).
    bool with_verdict = true;
};

// A JSON claims file's root ({"format": "scalecert-claims-1", "claims": [...]}), checked, and one
// claim of its list on two convex objects, read as certify-fp reads it (JSON numbers by
// `numbers`, strings exact): InputError names what is wrong, after `name`.
JNode read_claims_root(const std::string& claims, const std::string& name);
TypedClaim read_claim(const JNode& claim, size_t index, const std::string& name, Numbers numbers);

// An exact switch point of the curve, with its contact label.
struct ExactSwitch {
    Q rho1, rho2;
    std::string label;
};

// A judgement: right or wrong, and by the claim's kind the parts of the claim judged and the exact
// values they rest on (one type per kind below). On objects made of parts, part1 and part2 name the
// part pair the exact answer rests on (a verdict's deciding pair, a distance's closest pair, a
// depth's pair; −1 for none).
struct VerdictJudged {
    Verdict exact = Verdict::Separated;
    Q rho2_minus_curve;  // on convex objects: ρ2 − f(ρ1)
};
// A number a + b√c: a, b rational, c a natural number with no square factor below 2^10 and not a
// perfect square; b = 0 and c = 0 when the number is rational.
struct QuadSurd {
    Q a, b;
    Z c;
};
struct GrowthJudged {
    Q exact;  // ρ*
    // On objects with a radius ρ* is a + b√c (`exact` unused).
    std::optional<QuadSurd> surd;
};
struct CurvePointJudged {
    Q exact;  // f(ρ1)
};
struct SwitchPointJudged {
    // The exact switch point matched (or the nearest in ρ1), none when the proved range has none;
    // that range (whole: the whole curve).
    std::optional<ExactSwitch> nearest;
    bool matched = false, window_whole = true;
    Q window_lo;
    std::optional<Q> window_hi;
    std::optional<bool> contact_right;
};
struct CurveJudged {
    // The errors and the switch points' and contacts' faults (CLAIMS.md, "Curve claims").
    struct Misplaced {
        Q exact_rho1, exact_rho2, claimed_rho1, claimed_rho2;
    };
    struct WrongContact {
        Q rho1;
        std::string claimed, exact;
    };
    bool exact_positive = true;
    Q max_vertical, max_vertical_at, max_horizontal;
    std::vector<std::pair<Q, Q>> missed, extra;
    std::vector<Misplaced> misplaced;
    std::vector<WrongContact> wrong_contacts;
};
struct PlaneJudged {
    Q c1, c2;  // max over P1(ρ1) of n·x, min over P2(ρ2)
};
// Claimed points in P1 and in P2; on parts, the part holding each (−1: none); near: outside, within
// the absolute tolerance.
struct Membership {
    bool in1 = false, in2 = false;
    int in_part1 = -1, in_part2 = -1;
    bool near1 = false, near2 = false;
};
struct WitnessJudged : Membership {
    Verdict exact_verdict = Verdict::Separated;
};
struct DistanceJudged : Membership {
    bool value_right = false;
    std::optional<bool> closest_right;  // when closest points are claimed
    Q exact_squared;
    Vec3q exact_p1{}, exact_p2{};  // the exact closest points
    Q closest_squared;             // |q − p|² of the claimed closest points
};
struct DepthJudged {
    // A separated pair: its verdict, and nothing else.
    std::optional<Verdict> separated;
    std::optional<bool> value_right, direction_right;
    std::optional<Q> exact_squared;  // none when separated
    Vec3z exact_direction{};
    Q along;  // the squared depth along the claimed direction
    // The depth is root_sign·√exact_squared, plus R on objects with a radius (Judged::radii):
    // there −1 when only the balls meet (R − D).
    int root_sign = 1;
};
// The exact signed distance σ·√E: the distance when apart (σ = 1), 0 touching, minus the
// penetration depth when overlapping (σ = −1).
struct SignedDistanceJudged {
    Verdict exact = Verdict::Separated;
    Q exact_squared;  // D² apart, P² overlapping, 0 touching
    int sign() const { return exact == Verdict::Separated ? 1 : exact == Verdict::Touching ? 0 : -1; }
    // On objects with a radius (Judged::radii) the value is s·√E − R, with s and E the hulls'
    // (s = root_sign; the verdict is then the objects').
    std::optional<int> root_sign;
    int root() const { return root_sign ? *root_sign : sign(); }
};
struct Judged {
    bool right = false;
    int part1 = -1, part2 = -1;
    // On objects with a radius: ρ1·r1 and ρ2·r2 at the claim (CLAIMS.md, "Objects with a radius").
    std::optional<std::array<Q, 2>> radii;
    // Nothing for a claim with no answer.
    std::variant<std::monostate, VerdictJudged, GrowthJudged, CurvePointJudged, SwitchPointJudged, CurveJudged,
                 PlaneJudged, WitnessJudged, DistanceJudged, DepthJudged, SignedDistanceJudged>
        of;
    template <class T>
    T& set() {
        return of.emplace<T>();
    }
    template <class T>
    const T* get() const {
        return std::get_if<T>(&of);
    }
    // A distance's or a depth's exact squared value (none otherwise, and for a separated depth).
    std::optional<Q> exact_squared() const {
        if (const auto* d = get<DistanceJudged>()) return d->exact_squared;
        if (const auto* d = get<DepthJudged>()) return d->exact_squared;
        if (const auto* d = get<SignedDistanceJudged>()) return d->exact_squared;
        return std::nullopt;
    }
    // A distance's, a depth's or a signed distance's exact value as s·√E + k: k = 0 on objects
    // without a radius, else from the radii (CLAIMS.md, "Objects with a radius"); none for a
    // separated pair's depth.
    struct Surd {
        int s;
        Q E, k;
    };
    std::optional<Surd> exact_value() const;
    // The exact verdict a verdict, a witness or a separated depth states.
    std::optional<Verdict> exact_verdict() const {
        if (const auto* d = get<VerdictJudged>()) return d->exact;
        if (const auto* d = get<WitnessJudged>()) return d->exact_verdict;
        if (const auto* d = get<DepthJudged>()) return d->separated;
        if (const auto* d = get<SignedDistanceJudged>()) return d->exact;
        return std::nullopt;
    }
};

// A judgement's proof for the judgements certificates (FORMAT.md): the claim with every number
// exact, and the proof of its judgement; the certificate's own JSON, written only when asked.
struct Proof {
    Json claim, proof;
};

// Tolerance rules (CLAIMS.md, "Tolerances"), exact: `rel` a relative error on values, `abs` a
// length (points, values that are lengths, planes). abs = 0: the exact rules.
struct Tolerance {
    Q rel = 0, abs = 0;
    // |c − e| ≤ rel·|e| (scalings: ρ values, growth distances, curves; abs does not apply)
    bool close(const Q& c, const Q& e) const;
    // A claimed length c against an exact square E: |c − √E| ≤ abs + rel·√E (abs = 0: c ≥ 0 and
    // (1 − rel)² E ≤ c² ≤ (1 + rel)² E).
    bool close_sq(const Q& c, const Q& E) const;
    // A squared length x of a pair `apart` points at least √E apart when in their bodies:
    // √x ≤ (1 + rel)·√E + apart·abs (abs = 0: E ≤ x ≤ (1 + rel)² E).
    bool within_above(const Q& x, const Q& E, int apart = 1) const;
    // x ≤ abs·√N (a plane's side: x the excess of a body past it along a normal of squared length N).
    bool within_abs(const Q& x, const Q& N) const;
    // A claimed signed distance c against the exact s·√E (s = 1, 0 or −1):
    // |c − s√E| ≤ abs + rel·√E.
    bool close_signed(const Q& c, int s, const Q& E) const;
    // A claimed value c against the exact x = s·√E + k: |c − x| ≤ abs + rel·|x|.
    bool close_value(const Q& c, int s, const Q& E, const Q& k) const;
};
// The sign of a − k·√E (E ≥ 0), exactly.
int sign_minus_sqrt(const Q& a, const Q& k, const Q& E);
// The sign of a + b·√A + c·√E (A, E ≥ 0), exactly.
int sign_two_sqrts(const Q& a, const Q& b, const Q& A, const Q& c, const Q& E);

// The rules of one kind of object, as every front end asks them (claims.cpp's formats, the C++
// API): a judgement with its proof, the part pair a claim names, the certificate of the proofs.
class ClaimRules {
  public:
    explicit ClaimRules(const Tolerance& tolerance) : tol_(tolerance) {}
    virtual ~ClaimRules() = default;
    virtual Judged judge(const TypedClaim& c, Proof* proof = nullptr) = 0;
    // The scene of objects made of parts whose part pairs and names the claims and reports use;
    // null on two convex objects.
    virtual const ExactScene* parts() const = 0;
    // The part pair a penetration depth names ({part of P1, part of P2}), as the typed claim holds
    // it: InputError after `where` when it names a part the objects lack, or when the objects'
    // depth is not defined without one.
    virtual std::optional<std::array<int, 2>> part_pair(const std::optional<std::array<int, 2>>& given,
                                                        const std::string& where) const = 0;
    // Why claims of kind t are not judged on these objects, in a reader's words; "" when they are.
    virtual std::string refusal(ClaimType) const { return {}; }
    // The judgements certificate of these entries (FORMAT.md: kind judgements or compound_judgements).
    virtual std::string certificate(Json entries) const = 0;
    // How often the exact fallbacks ran {distances, depths}, for JSON reports; none where they do
    // not apply.
    virtual std::optional<std::array<long, 2>> fallbacks() const { return std::nullopt; }
    const Tolerance& tolerance() const { return tol_; }

  protected:
    Tolerance tol_;
};

// The rules on two convex objects: every type.
class ConvexRules final : public ClaimRules {
  public:
    ConvexRules(const ClaimModels& models, const Tolerance& tolerance);
    ~ConvexRules() override;
    Judged judge(const TypedClaim& c, Proof* proof = nullptr) override;
    const ExactScene* parts() const override { return nullptr; }
    // Only the pair (0, 0), which says nothing on two convex objects: none.
    std::optional<std::array<int, 2>> part_pair(const std::optional<std::array<int, 2>>& given,
                                                const std::string& where) const override;
    std::string certificate(Json entries) const override;
    // How often the exact fallback ran: the distance by CGAL's QP over all vertices, when the
    // proof from the floating-point guess did not close (proved_distance); the same for depths.
    std::optional<std::array<long, 2>> fallbacks() const override;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The rules on two objects made of parts (CLAIMS.md, "Objects made of parts"): Verdict, Plane,
// Witness and Distance (the least over the part pairs), and Depth of one part pair (a contact),
// at any (ρ1, ρ2) > 0.
class CompoundJudge;
class PartsRules final : public ClaimRules {
  public:
    PartsRules(CompoundJudge& judge, const Tolerance& tolerance);
    ~PartsRules() override;
    // Whether the type is judged on parts.
    static bool takes(ClaimType t);
    Judged judge(const TypedClaim& c, Proof* proof = nullptr) override;
    std::string refusal(ClaimType t) const override;
    const ExactScene* parts() const override;
    std::optional<std::array<int, 2>> part_pair(const std::optional<std::array<int, 2>>& given,
                                                const std::string& where) const override;
    std::string certificate(Json entries) const override;

  private:
    // A claim at poses is judged on the scene moved by them: its own judge (every part's hull
    // built anew), kept for the claims at the same poses.
    CompoundJudge& posed(const std::array<std::optional<Pose>, 2>& pose);
    std::map<std::string, std::unique_ptr<CompoundJudge>> posed_;
    // The part of object i holding x scaled by ρ, or within the absolute tolerance of it (−1: none).
    int place(int i, const Q& rho, const Vec3q& x, Json* proof, bool* near) const;
    // The rules, kind by kind (kinds/), with the proof in *p when given.
    void judge_verdict(const TypedClaim& c, Judged& g, Json* p);
    void judge_plane(const TypedClaim& c, Judged& g, Json* p);
    void judge_witness(const TypedClaim& c, Judged& g, Json* p);
    void judge_distance(const TypedClaim& c, Judged& g, Json* p);
    void judge_depth(const TypedClaim& c, Judged& g, Json* p);
    CompoundJudge& judge_;
};

// A part pair {part of P1, part of P2} checked against the objects' part counts: InputError after
// `where` (".parts[k]") naming the part past them.
void check_part_pair(const std::array<int, 2>& pair, const size_t counts[2], const std::string& where);

// P1(ρ1) ⊆ {n·x ≤ c1} and P2(ρ2) ⊆ {n·x ≥ c2}: the plane n·x = offset (or, with none, some plane of
// normal n) lies strictly between them.
bool plane_separates(const Q& c1, const Q& c2, const std::optional<Q>& offset);

// One claim judged by `rules`; with `entries`, its certificate entry ({index, claim, right, proof})
// appended. A limit met while judging a claim at poses (its moved points) is refused naming the
// claim: InputError "WHERE.what" (`where`: "FILE: claims[3]").
Judged judge_claim(ClaimRules& rules, const TypedClaim& c, size_t index, const std::string& where, Json* entries);

// Every claim of a file (the JSON or the line format, claims.hpp) read into types and judged by
// `rules`: the report; the number of wrong claims in *wrong (and of claims in *count); with
// `certificate`, the rules' certificate of every judgement.
std::string certify_fp(ClaimRules& rules, const std::string& claims, const std::string& name, const ClaimOptions& opt,
                       long* wrong, long* count = nullptr, std::string* certificate = nullptr);

// A judgement's report (certify-fp's JSON object beside the claim's index and kind, and its text
// line), kind by kind, each beside its rule (kinds/); `parts`: the scene when the claim was on
// objects made of parts, else null.
void describe(const TypedClaim& c, const VerdictJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text);
void describe(const TypedClaim& c, const GrowthJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text);
void describe(const TypedClaim& c, const CurvePointJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text);
void describe(const TypedClaim& c, const SwitchPointJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text);
void describe(const TypedClaim& c, const CurveJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text);
void describe(const TypedClaim& c, const PlaneJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text);
void describe(const TypedClaim& c, const WitnessJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text);
void describe(const TypedClaim& c, const DistanceJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text);
void describe(const TypedClaim& c, const DepthJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text);
void describe(const TypedClaim& c, const SignedDistanceJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text);

// The same for the line format's claims ('RHO1 RHO2 VERDICT', 'curve RHO1 RHO2', 'growth RHO'; w:
// the line's words as written), the object beside its line number.
void describe_line(const TypedClaim& c, const VerdictJudged& d, const Judged& g, const ExactScene* parts,
                   const std::vector<std::string>& w, Json& o, std::string& text);
void describe_line(const TypedClaim& c, const CurvePointJudged& d, const Judged& g, const ExactScene* parts,
                   const std::vector<std::string>& w, Json& o, std::string& text);
void describe_line(const TypedClaim& c, const GrowthJudged& d, const Judged& g, const ExactScene* parts,
                   const std::vector<std::string>& w, Json& o, std::string& text);

// The claim as the certificates state it (FORMAT.md): every number an exact string.
Json exact_claim_json(const TypedClaim& c);

}  // namespace scalecert::internal
