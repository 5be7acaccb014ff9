// How a judgement is reported (certify-fp's JSON report object and text line): the pieces every
// claim kind's description (kinds/) is written with. Display doubles are correctly rounded (MPFR).
#pragma once
#include "certify/claim.hpp"
#include "certify/region_certificate.hpp"

#include <string>

namespace scalecert::internal::report_parts {

void put_point(Json& o, const std::string& key, const Vec3q& v);  // three exact strings
std::string dbl(double d, int digits = 6);                        // "%.*g"
// "p/q (~d)": the exact value and its nearest double, to `digits` significant digits (the JSON
// claims' report uses 6, the line format's 17).
std::string num(const Q& q, int digits = 6);
// claimed, exact, and the absolute and relative errors (exact, with nearest doubles).
void errors(Json& o, const Q& claimed, const Q& exact);
// For a value whose exact square E is known: the error of the squares exactly, and |c − √E|
// and its relative size as MPFR-rounded doubles.
void errors_sq(Json& o, const Q& claimed, const Q& E);
// s·√E + k as the nearest double (MPFR; display only).
double surd_rn(int s, const Q& E, const Q& k);
// On objects with a radius: a claimed value against the exact s·√E + k, with the hulls' E under
// `hulls_key` and R = ρ1r1 + ρ2r2 (the errors as MPFR-rounded doubles).
void errors_surd(Json& o, const Q& claimed, int s, const Q& E, const Q& k, const Q& R, const std::string& hulls_key);
// "radii ρ1r1 + ρ2r2" for a text line (Judged::radii).
std::string radii_text(const Judged& g);
// (ρ1, ρ2), and which objects are at poses.
std::string at(const TypedClaim& c);
// The claim's rho1, rho2 (exact, with doubles) and its poses.
void put_rhos(Json& o, const TypedClaim& c);
// A point's part on an object made of parts: its number, or false when no part holds it.
Json part_or_false(int k);
// After part k of object i in a text line: " ('foot')", its name, or "" when it has none.
std::string name_of(const ExactScene& sc, int i, int k);
// A part pair in a text line: "parts 2 ('foot') and 0", each with its name when it has one.
std::string parts_named(const ExactScene& sc, int a, int b);
// Part k of object i in a text line: "part 3", "part 3 ('foot')" when it has a name, "NO" for none.
std::string part_or_no(const ExactScene& sc, int i, int k, bool near = false);
// A membership for the text line: "yes", "within LEN" (outside, within the absolute tolerance), "NO".
const char* yes_near_no(bool in, bool near);
// o[key] = true beside o[in_key] for a point outside its body but within the absolute tolerance.
void put_near(Json& o, const char* key, bool near);
// A part pair [a, b] as o[key], and beside it o[key + "_names"], [name or null, name or null], when
// either part has a name (null for the pair itself: no pair).
void put_part_pair(Json& o, const std::string& key, const ExactScene& sc, int a, int b);

}  // namespace scalecert::internal::report_parts
