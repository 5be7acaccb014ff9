#include "certify/golden.hpp"

#include "certify/claim.hpp"
#include "geometry/measures.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <stdexcept>

namespace scalecert::internal {

namespace {
// The pair on the boundary at ρ2 = f, and the ρ2 above and below it at relative distances 2^-k.
std::vector<std::pair<std::string, Q>> around(const Q& f) {
    std::vector<std::pair<std::string, Q>> pts{{"on", f}};
    for (int k : {4, 12, 20, 30, 40, 52}) {
        const Q d = f / Q(Z(1) << k);
        pts.push_back({"above 2^-" + std::to_string(k), f + d});
        pts.push_back({"below 2^-" + std::to_string(k), f - d});
    }
    return pts;
}
}  // namespace

GoldenAnswers golden_answers(const ExactScene& s, const Model& m, const TouchingCurve& c, const ClaimModels& models) {
    // The exact values come from the typed claim rules at tolerance 0: a distance claim's exact
    // square where the doubles are apart, a depth claim's where they overlap.
    ConvexRules rules(models, Tolerance{});
    auto exact_square = [&](ClaimType type, const Q& a, const Q& b) {
        TypedClaim t;
        t.type = type;
        t.rho1 = a;
        t.rho2 = b;
        const Judged g = rules.judge(t);
        if (!g.exact_squared) throw std::logic_error("golden: no exact measure at a pair of doubles");
        return *g.exact_squared;
    };
    Json qs = Json::array();
    std::string csv = "rho1,rho2,where,verdict_at_doubles,measure,value\n";
    std::vector<Q> xs;
    for (int k = 1; k < 8; ++k) xs.push_back(s.lo[0] + (s.hi[0] - s.lo[0]) * Q(k, 8));
    for (const CurveSwitch& sp : c.switches) xs.push_back(sp.rho1);
    for (Q x : xs) {
        x.canonicalize();
        Q f = models.curve_value(x);
        if (sgn(f) <= 0) continue;
        for (const auto& [where, y] : around(f)) {
            Verdict v = models.verdict(x, y);
            Json o;
            put_exact(o, "rho1", x);
            put_exact(o, "rho2", y);
            o["where"] = where;
            o["verdict"] = verdict_name(v);
            // what a floating-point suite will feed: the nearest doubles, and their exact verdict
            double xd = to_double_rn(x), yd = to_double_rn(y);
            const Q a = exact_from_double(xd), b = exact_from_double(yd);
            Verdict vd = models.verdict(a, b);
            o["verdict_at_doubles"] = verdict_name(vd);
            // and there the exact distance (separated) or penetration depth (overlapping): the
            // exact square and its root, correctly rounded
            Q sq(0);
            const char* kind = "touching";
            if (vd == Verdict::Separated) {
                kind = "distance";
                sq = exact_square(ClaimType::Distance, a, b);
            } else if (vd == Verdict::Overlapping) {
                kind = "depth";
                sq = exact_square(ClaimType::Depth, a, b);
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

namespace {
// The range of y over a convex polygon's points on the vertical ρ1 = x (none when it misses it).
std::optional<std::pair<Q, Q>> vertical_range(const std::vector<Point2q>& poly, const Q& x) {
    std::optional<std::pair<Q, Q>> r;
    auto add = [&](const Q& y) {
        if (!r)
            r = std::pair{y, y};
        else
            r->first = std::min(r->first, y), r->second = std::max(r->second, y);
    };
    for (size_t i = 0; i < poly.size(); ++i) {
        const Point2q &a = poly[i], &b = poly[(i + 1) % poly.size()];
        if (a[0] == x) add(a[1]);
        if ((a[0] < x && x < b[0]) || (b[0] < x && x < a[0])) add(a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]));
    }
    return r;
}
}  // namespace

GoldenAnswers golden_answers_parts(const CompoundRegion& r, CompoundJudge& judge, Json region) {
    const ExactScene& s = judge.scene();
    Json qs = Json::array();
    std::string csv = "rho1,rho2,where,verdict_at_doubles,measure,value\n";
    std::vector<Q> xs;
    for (int k = 1; k < 8; ++k) xs.push_back(s.lo[0] + (s.hi[0] - s.lo[0]) * Q(k, 8));
    if (region.contains("switch_points") && region["switch_points"].is_array())
        for (const Json& sp : region["switch_points"]) xs.push_back(parse_exact(sp["rho1"].get<std::string>()));
    for (Q& x : xs) x.canonicalize();
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    struct Budget {  // on the judge while the answers are found (it may judge claims after)
        CompoundJudge& j;
        ~Budget() { j.clear_budget(); }
    } budget{judge};
    judge.set_budget(kMaxGoldenJudgements, kMaxGoldenDistances, kMaxGoldenBoxComparisons,
                     "golden: " + std::to_string(xs.size()) + " verticals on " + std::to_string(judge.parts(0)) +
                         " x " + std::to_string(judge.parts(1)) +
                         " parts pass the limit of golden data on objects made of parts (the judgements' work: " +
                         std::to_string(kMaxGoldenJudgements) + " part pairs judged exactly, " +
                         std::to_string(kMaxGoldenDistances) + " exact distances, " +
                         std::to_string(kMaxGoldenBoxComparisons) + " box comparisons: docs/manual.md, \"Limits\")");
    for (const Q& x : xs) {
        // The meeting set on this vertical: the pairs' intervals, merged; its ends inside I2.
        std::vector<std::pair<Q, Q>> spans;
        for (const CompoundRegion::Pair& p : r.pairs)
            if (auto v = vertical_range(p.polygon, x)) spans.push_back(*v);
        std::sort(spans.begin(), spans.end());
        std::vector<Q> ends;
        for (size_t i = 0; i < spans.size();) {
            Q lo = spans[i].first, hi = spans[i].second;
            for (++i; i < spans.size() && spans[i].first <= hi; ++i) hi = std::max(hi, spans[i].second);
            for (const Q& y : {lo, hi})
                if (s.lo[1] < y && y < s.hi[1] && (ends.empty() || ends.back() != y)) ends.push_back(y);
        }
        for (const Q& f : ends) {
            for (const auto& [where, y] : around(f)) {
                Json o;
                put_exact(o, "rho1", x);
                put_exact(o, "rho2", y);
                o["where"] = where;
                o["verdict"] = verdict_name(judge.verdict(x, y).verdict);
                const double xd = to_double_rn(x), yd = to_double_rn(y);
                const Q a = exact_from_double(xd), b = exact_from_double(yd);
                const Verdict vd = judge.verdict(a, b).verdict;
                o["verdict_at_doubles"] = verdict_name(vd);
                char buf[128];
                std::snprintf(buf, sizeof buf, "%.17g,%.17g,", xd, yd);
                std::string line = buf + where + "," + verdict_name(vd) + ",";
                if (vd == Verdict::Overlapping) {
                    o["measure_at_doubles"] = Json{{"kind", "overlapping"}};
                    line += "overlapping,\n";
                } else {
                    const Q sq = vd == Verdict::Separated ? judge.distance(a, b).squared : Q(0);
                    const char* kind = vd == Verdict::Separated ? "distance" : "touching";
                    const double root = sqrt_minus_rn(sq, Q(0));
                    o["measure_at_doubles"] =
                        Json{{"kind", kind}, {"squared", to_exact_string(sq)}, {"value_double", root}};
                    char val[40];
                    std::snprintf(val, sizeof val, "%.17g", root);
                    line += std::string(kind) + "," + val + "\n";
                }
                qs.push_back(o);
                csv += line;
            }
        }
    }
    return {std::move(region), std::move(qs), std::move(csv)};
}

}  // namespace scalecert::internal
