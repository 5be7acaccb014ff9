// Verdicts (CLAIMS.md, "Claims": `verdict`): the rule on two convex objects, on objects made of
// parts, and the report.
#include "certify/report.hpp"
#include "certify/rules_impl.hpp"

namespace scalecert::internal {

using namespace report_parts;

void ConvexRules::Impl::verdict(const TypedClaim& c, Judged& g, Proof* proof) {
    auto& d = g.set<VerdictJudged>();
    if (posed && !proof) {
        // Without a certificate, the verdict alone where a few support queries prove it.
        if (const std::optional<Verdict> v = proved_verdict(*posed, c.rho1, c.rho2)) {
            d.exact = *v;
            g.right = verdict_matches(c.verdict, d.exact);
            return;
        }
    }
    if (posed) {
        const MeasuredDepth md = depth_of(c.rho1, c.rho2);
        d.exact = md.state;
        g.right = verdict_matches(c.verdict, d.exact);
        if (proof) proof->proof = Json{{"depth", depth_proof(nullptr, md, c.rho1, c.rho2)}};
        return;
    }
    const Verdict e = models.verdict(c.rho1, c.rho2);
    g.right = verdict_matches(c.verdict, e);
    d.exact = e;
    d.rho2_minus_curve = c.rho2 - models.curve_value(c.rho1);
    if (proof) {
        const auto [pm, r] = models.certified_query(c.rho1, c.rho2);
        if (r.verdict != e) throw std::logic_error("certify-fp: the certified verdict and the exact one differ");
        proof->proof = verdict_proof(*pm, r);
    }
}

void PartsRules::judge_verdict(const TypedClaim& c, Judged& g, Json* p) {
    auto& d = g.set<VerdictJudged>();
    const CompoundVerdict e = judge_.verdict(c.rho1, c.rho2, p);
    d.exact = e.verdict;
    g.part1 = e.part1;
    g.part2 = e.part2;
    g.right = verdict_matches(c.verdict, d.exact);
}

void describe(const TypedClaim& c, const VerdictJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text) {
    put_rhos(o, c);
    if (parts) {
        o["exact"] = verdict_name(d.exact);
        put_part_pair(o, "pair", *parts, g.part1, g.part2);
        o["claimed"] = claimed_name(c.verdict);
    } else {
        o["claimed"] = claimed_name(c.verdict);
        o["exact"] = verdict_name(d.exact);
        // No curve at a pose, nor on objects with a radius.
        if (!c.posed() && !g.radii) put_exact(o, "rho2_minus_curve", d.rho2_minus_curve);
    }
    text = "verdict at " + at(c) + ": claimed " + claimed_name(c.verdict) + ", exact " + verdict_name(d.exact);
}

void describe_line(const TypedClaim& c, const VerdictJudged& d, const Judged& g, const ExactScene* parts,
                   const std::vector<std::string>& w, Json& o, std::string& text) {
    const std::string v = claimed_name(c.verdict), e = verdict_name(d.exact);
    o["claim"] = v;
    put_exact(o, "rho1", c.rho1);
    put_exact(o, "rho2", c.rho2);
    o["exact"] = e;
    if (parts || g.radii) {
        if (parts) put_part_pair(o, "pair", *parts, g.part1, g.part2);
        text = "(" + num(c.rho1, 17) + ", " + num(c.rho2, 17) + ") claimed " + v + ": exact " + e;
    } else {
        put_exact(o, "rho2_minus_curve", d.rho2_minus_curve);
        text = "(" + w[0] + ", " + w[1] + ") claimed " + v + ": exact " + e +
               ", rho2 - curve = " + num(d.rho2_minus_curve, 17);
    }
}

}  // namespace scalecert::internal
