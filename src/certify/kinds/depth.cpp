// Penetration depths (CLAIMS.md, "Claims": `penetration_depth`): the rule on two convex objects, on one part
// pair of objects made of parts (a contact), and the report.
#include "certify/report.hpp"
#include "certify/rules_impl.hpp"

namespace scalecert::internal {

using namespace report_parts;

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

void ConvexRules::Impl::depth(const TypedClaim& c, Judged& g, Proof* proof) {
    // The exact squared depth (none when separated) and a minimising direction, with its proof.
    const MeasuredDepth md = depth_of(c.rho1, c.rho2);
    if (proof) proof->proof = depth_proof(nullptr, md, c.rho1, c.rho2);
    depth_rule(c, md, tol, g, [&](const Vec3q& n) { return directional_depth_squared(points(), n, c.rho1, c.rho2); });
}

void PartsRules::judge_depth(const TypedClaim& c, Judged& g, Json* p) {
    // One part pair's depth, by the rule for two convex objects (the parts scaled about their
    // objects' seeds); its proof that rule's, over the two parts' own points.
    if (!c.parts) throw std::logic_error("PartsRules: a depth with no part pair");
    const int a = (*c.parts)[0], b = (*c.parts)[1];
    g.part1 = a;
    g.part2 = b;
    const MeasuredDepth md = judge_.pair_depth(a, b, c.rho1, c.rho2, p);
    depth_rule(c, md, tol_, g, [&](const Vec3q& n) { return judge_.pair_directional_depth(a, b, n, c.rho1, c.rho2); });
}

void describe(const TypedClaim& c, const DepthJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text) {
    put_rhos(o, c);
    // On parts, the contact's part pair, named in the line.
    std::string of;
    if (parts && c.parts) {
        put_part_pair(o, "parts", *parts, g.part1, g.part2);
        of = " of " + parts_named(*parts, g.part1, g.part2);
    }
    if (!d.exact_squared) {
        o["exact_verdict"] = verdict_name(Verdict::Separated);
        put_exact(o, "claimed", c.value);
        text = "penetration depth" + of + " at " + at(c) + ": claimed " + num(c.value) + ", but the " +
               (of.empty() ? "pair is" : "parts are") + " separated";
        return;
    }
    if (g.radii) {
        // R + s·√E: the hulls' depth plus R (s = 1), R (0), or R less the hulls' distance (−1).
        const Q R = (*g.radii)[0] + (*g.radii)[1];
        errors_surd(o, c.value, d.root_sign, *d.exact_squared, R, R,
                    d.root_sign < 0 ? "hulls_squared_distance" : "hulls_squared_depth");
        text = "penetration depth" + of + " at " + at(c) + ": claimed " + num(c.value) + ", exact ~" +
               dbl(surd_rn(d.root_sign, *d.exact_squared, R), 17) + " (the " + radii_text(g) +
               (d.root_sign > 0   ? " plus the hulls' depth, squared " + num(*d.exact_squared)
                : d.root_sign < 0 ? " less the hulls' distance, squared " + num(*d.exact_squared)
                                  : ": the hulls touch") +
               ")";
    } else {
        errors_sq(o, c.value, *d.exact_squared);
        text = "penetration depth" + of + " at " + at(c) + ": claimed " + num(c.value) + ", exact squared " +
               num(*d.exact_squared) + " (depth ~" + dbl(sqrt_minus_rn(*d.exact_squared, Q(0))) + ")";
    }
    o["exact_direction"] =
        Json::array({d.exact_direction[0].get_str(), d.exact_direction[1].get_str(), d.exact_direction[2].get_str()});
    o["value_right"] = *d.value_right;
    if (c.direction) {
        // On objects with a radius, the hulls' (signed); the objects part after its root plus R.
        put_exact(o, g.radii ? "hulls_depth_squared_along_direction" : "depth_squared_along_direction", d.along);
        o["direction_right"] = *d.direction_right;
        if (*d.value_right && !*d.direction_right) text += ", but the direction is wrong";
        if (!*d.value_right && !*d.direction_right) text += ", and the direction is wrong too";
    }
}

}  // namespace scalecert::internal
