// Witness points (CLAIMS.md, "Claims": `witness_point`): the rule on two convex objects, on objects made of
// parts, and the report.
#include "certify/report.hpp"
#include "certify/rules_impl.hpp"

namespace scalecert::internal {

using namespace report_parts;

void ConvexRules::Impl::witness(const TypedClaim& c, Judged& g, Proof* proof) {
    auto& d = g.set<WitnessJudged>();
    Json mp;
    members(c.rho1, c.rho2, c.point, c.point, d, proof ? &mp : nullptr);
    if (c.with_verdict) d.exact_verdict = exact_verdict(c.rho1, c.rho2);
    g.right = d.in1 && d.in2;
    if (proof) proof->proof = std::move(mp);
}

void PartsRules::judge_witness(const TypedClaim& c, Judged& g, Json* p) {
    auto& d = g.set<WitnessJudged>();
    Json p1, p2;
    d.in_part1 = place(0, c.rho1, c.point, p ? &p1 : nullptr, &d.near1);
    d.in_part2 = place(1, c.rho2, c.point, p ? &p2 : nullptr, &d.near2);
    d.in1 = d.in_part1 >= 0;
    d.in2 = d.in_part2 >= 0;
    d.exact_verdict = judge_.verdict(c.rho1, c.rho2).verdict;
    g.right = d.in1 && d.in2;
    if (p) *p = Json{{"P1", std::move(p1)}, {"P2", std::move(p2)}};
}

void describe(const TypedClaim& c, const WitnessJudged& d, const Judged&, const ExactScene* parts, Json& o,
              std::string& text) {
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
}

}  // namespace scalecert::internal
