// What the two judgement formats share (certificates/FORMAT.md, "A judgements file" and "A
// compound judgements file"; CLAIMS.md's rules): the list of judgements, each entry's claim and
// proof, the tolerance rules, the extents and points of scaled bodies, and the claim kinds whose
// rules are the same for two convex polytopes and for two objects made of parts
// (separating_plane, witness_point, a distance claim's closest points).
#pragma once
#include "context.hpp"
#include "json.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace scalecert_check {
struct Scene;
class Scan;

// CLAIMS.md's closeness rules ("Tolerances") at the file's tolerances, each counted before it runs:
// tol relative, abs a length (0 when the file has no abs_tolerance: exact points and planes).
struct Rules {
    Q tol, abs;
    // |c − e| <= tol·|e| (scalings; abs does not apply)
    bool close(Context& cx, const Q& c, const Q& e) const;
    // a length c against an exact square E: |c − √E| <= abs + tol·√E (abs = 0: c >= 0, squares)
    bool close_sq(Context& cx, const Q& c, const Q& E) const;
    // a squared length x against E: √x <= (1 + tol)√E + apart·abs (abs = 0: E <= x <= (1 + tol)² E)
    bool within_above(Context& cx, const Q& x, const Q& E, int apart = 1) const;
    // x <= abs·√N
    bool within_abs(Context& cx, const Q& x, const Q& N) const;
    // a signed length c against the exact s·√E (s = 1, 0 or −1): |c − s√E| <= abs + tol·√E
    bool close_signed(Context& cx, const Q& c, int s, const Q& E) const;
    // a value c against the exact x = s·√E + k (s = 1, 0 or −1): |c − x| <= abs + tol·|x|
    bool close_value(Context& cx, const Q& c, int s, const Q& E, const Q& k) const;
};
// The sign of a − k·√E (E >= 0), exactly.
int sign_minus_sqrt(const Q& a, const Q& k, const Q& E);
// The sign of a + b·√A + c·√E (A, E >= 0), exactly: by squaring with signs.
int sign_two_roots(const Q& a, const Q& b, const Q& A, const Q& c, const Q& E);
// The file's `tolerance` (an exact number >= 0) and its optional `abs_tolerance` (> 0).
Rules read_rules(Context& cx, const J& c);
// "N right, M wrong, tolerance T" for the line printed for a valid file. A long tolerance is
// shown by its size, never by a prefix (a prefix hides a factor of 10^61): a forged tolerance
// makes wrong values right, and stays valid (it is the file's claim), so the line shows it.
// With an absolute tolerance, ", abs_tolerance A" follows, shown the same way.
std::string judged(size_t rights, size_t total, const Rules& R);

// The largest limbs of a vector's coordinates, for counting.
double vsize(const V3& v);
// n·L for the least L > 0 making every component an integer; L in *scale.
V3 integral(const V3& n, mpz_class* scale);
// o[key], an exact number > 0.
Q positive(Context& cx, const J& o, const char* key, const std::string& where);
// A point that is not the origin.
V3 nonzero_vector(Context& cx, const J& j, const std::string& where);

// max over P_i(rho) of n·x, for a nonzero rational n: n·s_i + rho max_v n·(v − s_i), the maximum a
// scan of every vertex of polyhedron i.
Q reach(Context& cx, const Scene& sc, int i, const V3& n, const Q& rho);
// min over P_i(rho) of n·x.
Q reach_min(Context& cx, const Scene& sc, int i, const V3& n, const Q& rho);
// s + rho (Σ w v − s) for weights over the vertices of a polytope P (combination()) scaled by rho
// about s: a point of polyhedron i of a scene, or of a compound's part.
V3 body_point(Context& cx, const Scan& P, const V3& s, const Q& rho, const J& w, const std::string& where,
              std::vector<int>* used = nullptr);
inline V3 body_point(Context& cx, const Scene& sc, int i, const Q& rho, const J& w, const std::string& where) {
    return body_point(cx, *sc.scan[i], sc.s[i], rho, w, where);
}

// A {"near"} membership: y (a point of the body) within abs of x; Invalid if not.
bool near_enough(Context& cx, const V3& x, const V3& y, const Q& abs, const std::string& where);
// An {"out"} normal n: x lies beyond the body's extent h = max n·v along n, strictly (abs = 0) or
// by more than abs (n·x − h > abs·|n|); Invalid if not.
void beyond(Context& cx, const V3& n, const V3& x, const Q& h, const Q& abs, const std::string& where);

// The two bodies a judgement speaks of, scaled: P1(ρ1) and P2(ρ2), two convex polytopes or two
// objects made of parts.
class Bodies {
  public:
    explicit Bodies(const Q& abs) : abs(abs) {}
    virtual ~Bodies() = default;
    // The absolute tolerance: a point within it of a body counts as in it ({"near": weights}), and
    // an {"out"} normal must show it farther than that.
    const Q abs;
    // max over body i scaled by rho of n·x (n a nonzero rational vector).
    virtual Q reach(Context& cx, int i, const V3& n, const Q& rho) const = 0;
    // min over body i scaled by rho of n·x.
    Q reach_min(Context& cx, int i, const V3& n, const Q& rho) const {
        return -reach(cx, i, {-n[0], -n[1], -n[2]}, rho);
    }
    // Whether x lies in body i scaled by rho, by the membership proof p (Invalid if p proves
    // neither).
    virtual bool member(Context& cx, int i, const Q& rho, const V3& x, const J& p, const std::string& where) const = 0;
};

// One entry of `judgements`: its claim and proof, the claim's kind, and their names in messages.
struct Judgement {
    const J& claim;
    const J& proof;
    std::string kind;
    std::string where, wc, wp;  // "judgements[k]", and its ".claim" and ".proof"
};

// A claim the program gave no answer in (FORMAT.md, "A judgements file"), whose proof is
// {"no_answer": FIELD}: FIELD is a field where the claim's kind answers, and the claim has it null
// or, for a normal or a direction, three exact zeros. Such a claim is wrong.
void check_no_answer(Context& cx, const Judgement& j);

// Every entry {"index", "claim", "right", "proof"} of a judgements list (which may be empty):
// distinct indices, a claim with a kind of `kinds` and a proof object, and "right" the judgement that
// judge(entry) gives, or wrong for a claim with no answer. Returns how many are right.
template <class Judge>
size_t judge_all(Context& cx, const J& js, const std::set<std::string>& kinds, Judge judge) {
    cx.claim(js.is_array(), "judgements is a list");
    std::set<size_t> indices;
    size_t rights = 0;
    for (size_t k = 0; k < js.size(); ++k) {
        const std::string w = "judgements[" + std::to_string(k) + "]";
        shape(cx, js[k], w, {"index", "claim", "right", "proof"});
        cx.claim(natural(at(js[k], "index")) && indices.insert(at(js[k], "index").get<size_t>()).second,
                 w + ".index is a distinct natural number");
        cx.claim(at(js[k], "right").is_boolean(), w + ".right is true or false");
        const J &cl = at(js[k], "claim"), &pr = at(js[k], "proof");
        cx.claim(cl.is_object() && cl.contains("kind") && cl["kind"].is_string(), w + ".claim has a kind");
        cx.claim(pr.is_object(), w + ".proof is an object");
        const Judgement j{cl, pr, cl["kind"].get<std::string>(), w, w + ".claim", w + ".proof"};
        cx.claim(kinds.count(j.kind) == 1, j.wc + ".kind is a kind of this file's claims");
        const bool no_answer = pr.contains("no_answer");
        if (no_answer) check_no_answer(cx, j);
        const bool right = !no_answer && judge(j);
        cx.claim(right == at(js[k], "right").get<bool>(),
                 w + ".right must be the judgement the rules give, which is " + (right ? "right" : "wrong"));
        rights += right;
    }
    return rights;
}

// A claimed verdict: separated, touching, overlapping or intersecting (not separated).
void check_claimed_verdict(Context& cx, const std::string& c, const std::string& wc);
// Whether the claimed verdict c is right when the exact one is v.
inline bool verdict_right(const std::string& c, const std::string& v) {
    return c == "intersecting" ? v != "separated" : c == "not_overlapping" ? v != "overlapping" : c == v;
}

// The claim kinds judged alike for both formats. separating_plane: the claim's plane separates
// the bodies strictly (and its offset lies strictly between), computed from every vertex; at an
// absolute tolerance, each body lies within it of its side.
bool judge_separating_plane(Context& cx, const Bodies& B, const Rules& R, const Judgement& j);
// witness_point: the claim's point lies in both bodies, by the proof's two memberships.
bool judge_witness_point(Context& cx, const Bodies& B, const Judgement& j);
// A distance claim's closest points ("closest": [a, b]) and whether both lie in their bodies (the
// proof's "closest": P1, P2).
struct Closest {
    V3 a, b;
    bool in;
};
Closest closest_points(Context& cx, const Bodies& B, const Judgement& j, const Q& r1, const Q& r2);

// A distance proof {"squared", "P1", "P2"} (its shape checked by the caller) on the two polytopes
// of the scene at (r1, r2): p in P1(r1), q in P2(r2), E = |q − p|², and when E > 0 no point of P1
// beyond p along q − p nor of P2 before q. Returns E, the exact squared distance.
Q proved_distance_sq(Context& cx, const Scene& sc, const J& pr, const std::string& wp, const Q& r1, const Q& r2);
// The depth a depth proof shows on the two polytopes of the scene at (r1, r2): none for a
// separated pair (its proof a separating normal), 0 for a touching pair, else the squared depth
// (FORMAT.md).
std::optional<Q> proved_depth(Context& cx, const Scene& sc, const J& pr, const std::string& wp, const Q& r1,
                              const Q& r2);
// A penetration_depth claim judged by its proof on the two polytopes of the scene (the claim's
// shape checked by the caller): the claimed value c within the tolerances of the exact depth the
// proof shows, and the claimed direction dir, if any, one along which moving P2 that far
// separates them.
bool judge_depth(Context& cx, const Scene& sc, const Rules& R, const J& pr, const std::string& wp, const Q& r1,
                 const Q& r2, const Q& c, const std::optional<V3>& dir);
}  // namespace scalecert_check
