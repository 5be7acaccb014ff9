// Signed distances (CLAIMS.md, "Claims": `signed_distance`): the distance when apart, minus the
// penetration depth when overlapping; a value, or a bound on it (at least, below). The rule on two
// convex objects, and the report.
#include "certify/report.hpp"
#include "certify/rules_impl.hpp"

#include <cmath>

namespace scalecert::internal {

using namespace report_parts;

namespace {
const char* bound_key(TypedClaim::Bound b) {
    return b == TypedClaim::Bound::Value     ? "value"
           : b == TypedClaim::Bound::AtLeast ? "at_least"
           : b == TypedClaim::Bound::AtMost  ? "at_most"
                                             : "below";
}
}  // namespace

// The rule on the exact s·√E: a value within the tolerance (Tolerance::close_signed); at least m
// when s√E ≥ m − abs; below m when s√E < m + abs. Every comparison squares with signs.
bool signed_distance_right(const TypedClaim& c, int s, const Q& E, const Tolerance& tol) {
    switch (c.bound) {
    case TypedClaim::Bound::Value: return tol.close_signed(c.value, s, E);
    case TypedClaim::Bound::AtLeast: return sign_minus_sqrt(c.value - tol.abs, s, E) <= 0;
    case TypedClaim::Bound::Below: return sign_minus_sqrt(c.value + tol.abs, s, E) > 0;
    case TypedClaim::Bound::AtMost: return sign_minus_sqrt(c.value + tol.abs, s, E) >= 0;
    }
    return false;
}

void ConvexRules::Impl::signed_distance(const TypedClaim& c, Judged& g, Proof* proof) {
    // The measured depth decides the state: apart, its proved distance; meeting, its depth.
    auto& d = g.set<SignedDistanceJudged>();
    const MeasuredDepth md = depth_of(c.rho1, c.rho2);
    d.exact = md.state;
    d.exact_squared = md.state == Verdict::Separated  ? md.distance.squared
                      : md.state == Verdict::Touching ? Q(0)
                                                      : md.depth->squared;
    if (proof)
        proof->proof = md.state == Verdict::Separated
                           ? Json{{"distance", distance_proof(nullptr, md.distance, c.rho1, c.rho2)}}
                           : Json{{"depth", depth_proof(nullptr, md, c.rho1, c.rho2)}};
    g.right = signed_distance_right(c, d.sign(), d.exact_squared, tol);
}

void describe(const TypedClaim& c, const SignedDistanceJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text) {
    put_rhos(o, c);
    // On parts with radii, the contact's part pair, named in the line.
    std::string of;
    if (parts && c.parts) {
        put_part_pair(o, "parts", *parts, g.part1, g.part2);
        of = " of " + parts_named(*parts, g.part1, g.part2);
    }
    if (g.radii) {
        // s·√E − R: the hulls' signed distance less the radii.
        const Q R = (*g.radii)[0] + (*g.radii)[1];
        o["bound"] = bound_key(c.bound);
        errors_surd(o, c.value, d.root(), d.exact_squared, Q(-R), R, "hulls_signed_squared");
        o["hulls_sign"] = d.root();
        o["exact_verdict"] = verdict_name(d.exact);
        const std::string claimed = c.bound == TypedClaim::Bound::Value     ? "claimed " + num(c.value)
                                    : c.bound == TypedClaim::Bound::AtLeast ? "claimed at least " + num(c.value)
                                    : c.bound == TypedClaim::Bound::AtMost  ? "claimed at most " + num(c.value)
                                                                            : "claimed below " + num(c.value);
        text = "signed distance" + of + " at " + at(c) + ": " + claimed + ", exact ~" +
               dbl(surd_rn(d.root(), d.exact_squared, Q(-R)), 17) + " (" + verdict_name(d.exact) + "; the hulls' " +
               (d.root() > 0   ? "distance"
                : d.root() < 0 ? "depth, negated"
                               : "0 (touching)") +
               (d.root() != 0 ? ", squared " + num(d.exact_squared) : std::string()) + ", less the " + radii_text(g) +
               ")";
        return;
    }
    o["bound"] = bound_key(c.bound);
    put_exact(o, "claimed", c.value);
    o["exact_verdict"] = verdict_name(d.exact);
    put_exact(o, "exact_squared", d.exact_squared);
    // s·√E as the nearest double (display only).
    const double e = sqrt_minus_rn(d.exact_squared, Q(0));
    o["exact_double"] = d.sign() < 0 ? -e : e;
    // |claimed − s√E| (MPFR-rounded; display only).
    o["abs_error_double"] = d.sign() == 0
                                ? std::fabs(to_double_rn(c.value))
                                : std::fabs(sqrt_minus_rn(d.exact_squared, d.sign() > 0 ? c.value : Q(-c.value)));
    const std::string claimed = c.bound == TypedClaim::Bound::Value     ? "claimed " + num(c.value)
                                : c.bound == TypedClaim::Bound::AtLeast ? "claimed at least " + num(c.value)
                                : c.bound == TypedClaim::Bound::AtMost  ? "claimed at most " + num(c.value)
                                                                        : "claimed below " + num(c.value);
    text = "signed distance at " + at(c) + ": " + claimed + ", exact " +
           (d.sign() == 0 ? std::string("0 (touching)")
                          : "~" + dbl(d.sign() < 0 ? -e : e, 17) + " (" + verdict_name(d.exact) +
                                (d.sign() > 0 ? ": the distance" : ": minus the depth") + ", squared " +
                                num(d.exact_squared) + ")");
}

}  // namespace scalecert::internal
