#include "certify/golden.hpp"

#include "geometry/measures.hpp"

#include <cstdio>
#include <stdexcept>

namespace scalecert::internal {

GoldenAnswers golden_answers(const ExactScene& s, const HullModel& m, const TouchingCurve& c) {
    Json qs = Json::array();
    std::string csv = "rho1,rho2,where,verdict_at_doubles,measure,value\n";
    std::vector<Q> xs;
    for (int k = 1; k < 8; ++k) xs.push_back(s.lo[0] + (s.hi[0] - s.lo[0]) * Q(k, 8));
    for (const CurveSwitch& sp : c.switches) xs.push_back(sp.rho1);
    for (Q x : xs) {
        x.canonicalize();
        Q f = c.env.value(m.lines, x);
        if (sgn(f) <= 0) continue;
        std::vector<std::pair<std::string, Q>> pts{{"on", f}};
        for (int k : {4, 12, 20, 30, 40, 52}) {
            Q d = f / Q(Z(1) << k);
            pts.push_back({"above 2^-" + std::to_string(k), f + d});
            pts.push_back({"below 2^-" + std::to_string(k), f - d});
        }
        for (const auto& [where, y] : pts) {
            Verdict v = query(m, c, x, y, false).verdict;
            Json o;
            put_exact(o, "rho1", x);
            put_exact(o, "rho2", y);
            o["where"] = where;
            o["verdict"] = verdict_name(v);
            // what a floating-point suite will feed: the nearest doubles, and their exact verdict
            double xd = to_double_rn(x), yd = to_double_rn(y);
            Verdict vd = query(m, c, exact_from_double(xd), exact_from_double(yd), false).verdict;
            o["verdict_at_doubles"] = verdict_name(vd);
            // and there the exact distance (separated) or penetration depth (overlapping), proved
            // at floating-point speed (measures.hpp): the exact square and its root, correctly rounded
            const Q a = exact_from_double(xd), b = exact_from_double(yd);
            Q sq(0);
            const char* kind = "touching";
            if (vd == Verdict::Separated) {
                kind = "distance";
                sq = proved_distance(m, a, b).d.squared;
            } else if (vd == Verdict::Overlapping) {
                kind = "depth";
                const std::optional<ProvedDepth> d = proved_depth(m, a, b);
                if (!d) throw std::logic_error("golden: an overlapping pair whose difference does not hold the origin");
                sq = d->squared;
            }
            const double root = sqrt_minus_rn(sq, Q(0));
            o["measure_at_doubles"] = Json{{"kind", kind}, {"squared", to_exact_string(sq)}, {"value_double", root}};
            qs.push_back(o);
            char buf[128];
            std::snprintf(buf, sizeof buf, "%.17g,%.17g,", xd, yd);
            char val[40];
            std::snprintf(val, sizeof val, "%.17g", root);
            csv += buf + where + "," + verdict_name(vd) + "," + kind + "," + val + "\n";
        }
    }
    return {curve_json(m, c), std::move(qs), std::move(csv)};
}

}  // namespace scalecert::internal
