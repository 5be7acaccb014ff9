// What the two judgement formats share (certificates/FORMAT.md, "A judgements file" and "A
// compound judgements file"; CLAIMS.md's rules): the list of judgements, the tolerance rules, and
// the reading of vectors and scalings.
#pragma once
#include "context.hpp"
#include "json.hpp"

#include <set>
#include <string>

namespace scalecert_check {
// CLAIMS.md's closeness rules at the file's tolerance, each counted before it runs.
struct Rules {
    Q tol;
    bool close(Context& cx, const Q& c, const Q& e) const;
    bool close_sq(Context& cx, const Q& c, const Q& E) const;
    bool within_above(Context& cx, const Q& x, const Q& E) const;
};
// A tolerance as the checker prints it: a long one by its size, never by a prefix (a prefix hides
// a factor of 10^61).
std::string tolerance_shown(const Q& tol);

// The largest limbs of a vector's coordinates, for counting.
double vsize(const V3& v);
// n·L for the least L > 0 making every component an integer; L in *scale.
V3 integral(const V3& n, mpz_class* scale);
// o[key], an exact number > 0.
Q positive(Context& cx, const J& o, const char* key, const std::string& where);
// A point that is not the origin.
V3 nonzero_vector(Context& cx, const J& j, const std::string& where);

// Every entry {"index", "claim", "right", "proof"} of a judgements list: distinct indices, and
// "right" the judgement that judge(claim, proof, where) gives. Returns how many are right.
template <class Judge>
size_t judge_all(Context& cx, const J& js, Judge judge) {
    cx.claim(js.is_array() && !js.empty(), "judgements is a nonempty list");
    std::set<size_t> indices;
    size_t rights = 0;
    for (size_t k = 0; k < js.size(); ++k) {
        const std::string w = "judgements[" + std::to_string(k) + "]";
        shape(cx, js[k], w, {"index", "claim", "right", "proof"});
        cx.claim(natural(at(js[k], "index")) && indices.insert(at(js[k], "index").get<size_t>()).second,
                 w + ".index is a distinct natural number");
        cx.claim(at(js[k], "right").is_boolean(), w + ".right is true or false");
        const bool right = judge(at(js[k], "claim"), at(js[k], "proof"), w);
        cx.claim(right == at(js[k], "right").get<bool>(),
                 w + ".right must be the judgement the rules give, which is " + (right ? "right" : "wrong"));
        rights += right;
    }
    return rights;
}
}  // namespace scalecert_check
