// Reading a certificate: strict JSON (RFC 8259) into a tree, and the shapes every object must
// have (certificates/FORMAT.md, "What the checker rejects": exactly the documented keys, no
// duplicate key, nesting at most kMaxDepth, indices as JSON integers in range).
#pragma once
#include "context.hpp"
#include "points.hpp"

#include <initializer_list>
#include <string>
#include <vector>

namespace scalecert_check {
// s for a message: its first 40 bytes, control characters as '?', "..." when cut.
std::string printable(const std::string& s);

// The JSON value of the text: strict JSON, without duplicate keys, nested at most kMaxDepth
// levels, with no NUL byte and no byte-order mark; else Unreadable.
J parse_strict(const std::string& text);

// A certificate's text read as parse_strict reads it, except the scene's vertex lists
// (`scene.P1.vertices`, `scene.P2.vertices`, and each `scene.P1.parts[k].vertices`, and P2's):
// a list whose every vertex is a list of three strings, each an integer written as FORMAT.md's
// exact numbers must be ("p": an optional "-", then "0" or digits without a leading zero; not
// "-0"), is taken straight from the text into `points`, and the tree holds at its place a marker
// that no JSON text can make (a binary value; captured() finds the list). A list that is anything
// else (a rational coordinate, a number, a point of two coordinates, "007", ...) is built into the
// tree as parse_strict builds it, from the element where it leaves that form on, and num() judges
// it as before. With direct false every list is built into the tree.
struct Parsed {
    J root;
    std::vector<IntPoints> points;
};
Parsed parse_certificate(const std::string& text, bool direct = true);
// The vertex list that parse_certificate took at j (its marker), or nullptr.
IntPoints* captured(Context& cx, const J& j);

// o is an object with every key of `required`, and no key outside required ∪ optional.
void shape(Context& cx, const J& o, const std::string& where, std::initializer_list<const char*> required,
           std::initializer_list<const char*> optional = {});
inline const J& at(const J& o, const char* k) { return o.find(k).value(); }  // after shape(): present

// A JSON integer >= 0 written without sign, fraction or exponent (nlohmann reads "-0" as a signed
// integer: refused).
inline bool natural(const J& j) { return j.is_number_unsigned(); }

// An index: a JSON integer (no fraction, no exponent) with 0 <= i < n.
size_t index(Context& cx, const J& j, size_t n, const std::string& where);
// The same, with where() naming it only in a message (when a claim fails).
template <class Where>
size_t index_at(Context& cx, const J& j, size_t n, Where where) {
    cx.claim_lazy(natural(j), [&] { return where() + " is a non-negative JSON integer"; });
    const unsigned long long v = j.get<unsigned long long>();
    cx.claim_lazy(v < n,
                  [&] { return where() + " = " + std::to_string(v) + " is an index below " + std::to_string(n); });
    return static_cast<size_t>(v);
}
// A nonempty list of distinct indices below n.
std::vector<int> index_list(Context& cx, const J& j, size_t n, const std::string& where);
// x is in v (ascending: every vertex list the checker builds is).
bool has(const std::vector<int>& v, int x);

// An optional annotation of o, which must be a string when present.
void annotation_string(Context& cx, const J& o, const char* key, const std::string& where);
}  // namespace scalecert_check
