#include "certify/golden.hpp"

#include "certify/claim.hpp"
#include "geometry/measures.hpp"
#include "numeric/limits.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>

namespace scalecert::internal {

void validate(const GoldenPoints& p) {
    if (p.verticals < 0 || p.verticals > kMaxGoldenVerticals)
        throw InputError("golden: the verticals (--verticals) must be from 0 to " +
                         std::to_string(kMaxGoldenVerticals) + " (got " + std::to_string(p.verticals) + ")");
    if (p.offsets.size() > kMaxGoldenOffsets)
        throw InputError("golden: at most " + std::to_string(kMaxGoldenOffsets) + " offsets (--offsets; got " +
                         std::to_string(p.offsets.size()) + ")");
    for (size_t i = 0; i < p.offsets.size(); ++i) {
        if (p.offsets[i] < 1 || p.offsets[i] > kMaxGoldenOffset)
            throw InputError("golden: each offset (--offsets) is a K from 1 to " + std::to_string(kMaxGoldenOffset) +
                             " (the pairs 2^-K away; got " + std::to_string(p.offsets[i]) + ")");
        for (size_t j = 0; j < i; ++j)
            if (p.offsets[j] == p.offsets[i])
                throw InputError("golden: the offsets (--offsets) name " + std::to_string(p.offsets[i]) + " twice");
    }
}

std::vector<int> parse_offsets(const std::string& text) {
    std::vector<int> ks;
    size_t at = 0;
    while (at <= text.size()) {
        const size_t comma = std::min(text.find(',', at), text.size());
        const std::string item = text.substr(at, comma - at);
        if (item.empty() || item.size() > 4 || item.find_first_not_of("0123456789") != std::string::npos)
            throw InputError("--offsets takes exponents K as K,K,... (e.g. 4,12,52), not " + in_quotes(text));
        ks.push_back(std::stoi(item));
        at = comma + 1;
    }
    return ks;
}

double double_in(const Q& v, const Q& lo, const Q& hi) {
    double d = to_double_rn(v);
    const Q e = exact_from_double(d);
    if (e > hi || e < lo) {
        const double n = std::nextafter(d, e > hi ? -HUGE_VAL : HUGE_VAL);
        const Q m = exact_from_double(n);
        if (lo <= m && m <= hi) d = n;
    }
    return d;
}

namespace {

struct Rect {
    Q lo[2], hi[2];
    bool holds(const Q& x, const Q& y) const { return lo[0] <= x && x <= hi[0] && lo[1] <= y && y <= hi[1]; }
};

// The pairs near a sampled point (x, y) of the boundary, in the rectangle: on it, then for each k
// above, below, right and left of it by 2^-k of its own coordinate.
std::vector<std::tuple<std::string, Q, Q>> around(const Q& x, const Q& y, const std::vector<int>& offsets,
                                                  const Rect& r) {
    std::vector<std::tuple<std::string, Q, Q>> pts;
    if (r.holds(x, y)) pts.emplace_back("on", x, y);
    for (int k : offsets) {
        const std::string e = " 2^-" + std::to_string(k);
        const Q dy = y / Q(Z(1) << k), dx = x / Q(Z(1) << k);
        if (sgn(dy) != 0) {
            if (r.holds(x, y + dy)) pts.emplace_back("above" + e, x, y + dy);
            if (r.holds(x, y - dy)) pts.emplace_back("below" + e, x, y - dy);
        }
        if (sgn(dx) != 0) {
            if (r.holds(x + dx, y)) pts.emplace_back("right" + e, x + dx, y);
            if (r.holds(x - dx, y)) pts.emplace_back("left" + e, x - dx, y);
        }
    }
    return pts;
}

// The exact answers at a pair of doubles.
struct Measure {
    Verdict verdict = Verdict::Separated;
    const char* kind = "touching";  // distance, depth, touching, overlapping
    std::optional<Q> squared;       // none: overlapping parts
    std::optional<Vec3q> p1, p2;    // distance: the closest points; touching: the common point, twice
    std::optional<Vec3z> normal;    // distance (convex): the separating plane's; depth: the direction
    std::optional<Q> offset;        // that plane's: n·x = offset
    int part1 = -1, part2 = -1;     // parts: the closest points' parts
};

// The rows, written to the JSON queries and both CSV texts at once.
class Rows {
  public:
    // With objects whose parts have names (`names`, a list per object, "" for a part without one),
    // the measures name their parts (P1_part_name, P2_part_name) and the CSVs end in the columns
    // part1_name and part2_name; without, the bytes are those of a scene without names.
    explicit Rows(std::array<std::vector<std::string>, 2> names = {}) : names_(std::move(names)) {
        named_ = !names_[0].empty() || !names_[1].empty();
        const std::string tail = named_ ? ",part1_name,part2_name\n" : "\n";
        csv_ =
            "rho1,rho2,where,verdict_at_doubles,measure,value,near,p1x,p1y,p1z,p2x,p2y,p2z,nx,ny,nz,offset,part1,"
            "part2" +
            tail;
        rcsv_ = "rho1_num,rho1_den,rho2_num,rho2_den,near,where,verdict,measure,squared_num,squared_den";
        for (const char* p : {"p1", "p2"})
            for (const char* c : {"x", "y", "z"}) rcsv_ += std::string(",") + p + c + "_num," + p + c + "_den";
        rcsv_ += ",nx,ny,nz,offset_num,offset_den,part1,part2" + tail;
    }
    void add(const Q& x, const Q& y, const std::string& where, const std::string& near, Verdict exact, double xd,
             double yd, const Measure& m) {
        Json o;
        put_exact(o, "rho1", x);
        put_exact(o, "rho2", y);
        o["rho1_double"] = xd;  // the doubles asked: the nearest, kept in the rectangle
        o["rho2_double"] = yd;
        o["where"] = where;
        o["near"] = near;
        o["verdict"] = verdict_name(exact);
        o["verdict_at_doubles"] = verdict_name(m.verdict);
        Json ms{{"kind", m.kind}};
        std::string value, unit[4];
        if (m.squared) {
            const double root = sqrt_minus_rn(*m.squared, Q(0));
            ms["squared"] = to_exact_string(*m.squared);
            ms["value_double"] = root;
            value = num(root);
        }
        auto point = [](const Vec3q& p) {
            return Json::array({to_exact_string(p[0]), to_exact_string(p[1]), to_exact_string(p[2])});
        };
        if (m.p1 && std::string(m.kind) == "touching") ms["point"] = point(*m.p1);
        if (m.p1 && std::string(m.kind) == "distance") {
            ms["closest_P1"] = point(*m.p1);
            ms["closest_P2"] = point(*m.p2);
        }
        if (m.part1 >= 0) ms["parts"] = Json::array({m.part1, m.part2});
        if (const std::string n = name(0, m.part1); !n.empty()) ms["P1_part_name"] = n;
        if (const std::string n = name(1, m.part2); !n.empty()) ms["P2_part_name"] = n;
        if (m.normal) {
            const Vec3z& n = *m.normal;
            const Q nn = Q(dotz(n, n));
            for (int i = 0; i < 3; ++i) unit[i] = num(signed_root(Q(n[i] * n[i]) / nn, sgn(n[i])));
            if (m.offset) {
                ms["plane"] = Json{{"normal", normal_json(n)}, {"offset", to_exact_string(*m.offset)}};
                unit[3] = num(signed_root(*m.offset * *m.offset / nn, sgn(*m.offset)));
            } else {
                ms["direction"] = normal_json(n);
            }
        }
        o["measure_at_doubles"] = std::move(ms);
        qs_.push_back(std::move(o));

        const Vec3q none{};
        const Vec3q& p1 = m.p1 ? *m.p1 : none;
        const Vec3q& p2 = m.p2 ? *m.p2 : none;
        csv_ += num(xd) + "," + num(yd) + "," + where + "," + verdict_name(m.verdict) + "," + m.kind + "," + value +
                "," + near;
        for (const Vec3q* p : {&p1, &p2})
            for (int i = 0; i < 3; ++i) csv_ += "," + (m.p1 ? num(to_double_rn((*p)[i])) : std::string());
        for (const std::string& u : unit) csv_ += "," + u;
        const std::string names = named_ ? "," + csv_field(name(0, m.part1)) + "," + csv_field(name(1, m.part2)) : "";
        csv_ += "," + part(m.part1) + "," + part(m.part2) + names + "\n";

        rcsv_ += frac(exact_from_double(xd)) + "," + frac(exact_from_double(yd)) + "," + near + "," + where + "," +
                 verdict_name(m.verdict) + "," + m.kind + "," + (m.squared ? frac(*m.squared) : ",");
        for (const Vec3q* p : {&p1, &p2})
            for (int i = 0; i < 3; ++i) rcsv_ += "," + (m.p1 ? frac((*p)[i]) : ",");
        for (int i = 0; i < 3; ++i) rcsv_ += "," + (m.normal ? (*m.normal)[i].get_str() : std::string());
        rcsv_ += "," + (m.offset ? frac(*m.offset) : ",");
        rcsv_ += "," + part(m.part1) + "," + part(m.part2) + names + "\n";
    }
    Json queries() { return std::move(qs_); }
    std::string csv() { return std::move(csv_); }
    std::string rational_csv() { return std::move(rcsv_); }

  private:
    // Object i's part k's name ("" for none, and for k < 0: no part).
    std::string name(int i, int k) const {
        const std::vector<std::string>& n = names_[static_cast<size_t>(i)];
        return k >= 0 && static_cast<size_t>(k) < n.size() ? n[static_cast<size_t>(k)] : std::string();
    }
    // A CSV field (RFC 4180): quoted, its quotes doubled, when it holds a comma, a quote or a line end.
    static std::string csv_field(const std::string& t) {
        if (t.find_first_of(",\"\r\n") == std::string::npos) return t;
        std::string q = "\"";
        for (char c : t) q += c == '"' ? std::string("\"\"") : std::string(1, c);
        return q + "\"";
    }
    std::array<std::vector<std::string>, 2> names_;
    bool named_ = false;
    static std::string num(double d) {
        char b[40];
        std::snprintf(b, sizeof b, "%.17g", d);
        return b;
    }
    static std::string frac(const Q& q) { return q.get_num().get_str() + "," + q.get_den().get_str(); }
    static std::string part(int k) { return k >= 0 ? std::to_string(k) : std::string(); }
    static double signed_root(const Q& square, int sign) {
        const double r = sqrt_minus_rn(square, Q(0));
        return sign < 0 ? -r : r;
    }
    Json qs_ = Json::array();
    std::string csv_, rcsv_;
};

// Every pair near each sampled point, then the rectangle's corners (and its centre when asked),
// each asked at its doubles: `exact` gives the verdict at a pair, `measure` the answers at doubles.
void emit(Rows& rows, const Rect& r, const std::vector<std::pair<Q, std::pair<Q, std::string>>>& samples, bool centre,
          const GoldenPoints& points, const std::function<Verdict(const Q&, const Q&)>& exact,
          const std::function<Measure(const Q&, const Q&)>& measure) {
    auto one = [&](const Q& x, const Q& y, const std::string& where, const std::string& near) {
        const double xd = double_in(x, r.lo[0], r.hi[0]), yd = double_in(y, r.lo[1], r.hi[1]);
        rows.add(x, y, where, near, exact(x, y), xd, yd, measure(exact_from_double(xd), exact_from_double(yd)));
    };
    for (const auto& [x, s] : samples)
        for (const auto& [where, a, b] : around(x, s.first, points.offsets, r)) one(a, b, where, s.second);
    for (int c = 0; c < 4; ++c)  // (each once: a side of the rectangle may have no length)
        if (!((c & 1) && r.hi[0] == r.lo[0]) && !((c & 2) && r.hi[1] == r.lo[1]))
            one(c & 1 ? r.hi[0] : r.lo[0], c & 2 ? r.hi[1] : r.lo[1], "corner", "corner");
    if (centre) one((r.lo[0] + r.hi[0]) / 2, (r.lo[1] + r.hi[1]) / 2, "centre", "centre");
}

Json points_json(const GoldenPoints& p) { return Json{{"verticals", p.verticals}, {"offsets", p.offsets}}; }

Q fraction(int p, int q) {
    Q f(p, q);
    f.canonicalize();
    return f;
}

Rect rect_of(const ExactScene& s) {
    Rect r;
    for (int i = 0; i < 2; ++i) r.lo[i] = s.lo[i], r.hi[i] = s.hi[i];
    return r;
}

}  // namespace

GoldenAnswers golden_answers(const ExactScene& s, const Model& m, const TouchingCurve& c, const ClaimModels& models,
                             const GoldenPoints& points) {
    validate(points);
    // The exact answers come from the typed claim rules at tolerance 0: a distance claim's exact
    // square and closest points where the doubles are apart or touch, a depth claim's where they
    // overlap.
    ConvexRules rules(models, Tolerance{});
    auto judged = [&](ClaimType type, const Q& a, const Q& b) {
        TypedClaim t;
        t.type = type;
        t.rho1 = a;
        t.rho2 = b;
        Judged g = rules.judge(t);
        if (!g.exact_squared()) throw std::logic_error("golden: no exact measure at a pair of doubles");
        return g;
    };
    const Rect r = rect_of(s);
    // The curve in the rectangle: on each piece (ρ2 linear in ρ1 over [from, to]) the ρ1 where
    // ρ2 lies in I2, [xa, xb] over all of them (one interval: the curve is continuous).
    std::optional<Q> xa, xb;
    for (const CurvePiece& p : c.pieces) {
        const Q y0 = models.curve_value(p.from), y1 = models.curve_value(p.to);
        Q a = p.from, b = p.to;
        if (y0 == y1) {
            if (y0 < r.lo[1] || y0 > r.hi[1]) continue;
        } else {
            auto at = [&](const Q& y) -> Q { return p.from + (p.to - p.from) * (y - y0) / (y1 - y0); };
            const Q t0 = at(r.lo[1]), t1 = at(r.hi[1]);
            a = std::max(a, std::min(t0, t1));
            b = std::min(b, std::max(t0, t1));
            if (a > b) continue;
        }
        if (!xa || a < *xa) xa = a;
        if (!xb || b > *xb) xb = b;
    }
    // Sampled points of the curve by ρ1 (one name each: a switch point, else an end, else a vertical).
    std::map<Q, std::string> at;
    if (xa) {
        for (int k = 1; k <= points.verticals; ++k)
            at[*xa + (*xb - *xa) * fraction(k, points.verticals + 1)] = "vertical";
        at[*xa] = "enters";
        at[*xb] = "leaves";
        for (const CurveSwitch& sp : c.switches)
            if (r.holds(sp.rho1, sp.rho2)) at[sp.rho1] = "switch";
    }
    std::vector<std::pair<Q, std::pair<Q, std::string>>> samples;
    for (const auto& [x, near] : at) {
        Q y = models.curve_value(x);
        y.canonicalize();
        samples.push_back({x, {y, near}});
    }
    Rows rows;
    emit(
        rows, r, samples, !xa, points, [&models](const Q& a, const Q& b) { return models.verdict(a, b); },
        [&](const Q& a, const Q& b) {
            Measure ms;
            ms.verdict = models.verdict(a, b);
            if (ms.verdict == Verdict::Overlapping) {
                const Judged g = judged(ClaimType::Depth, a, b);
                ms.kind = "depth";
                ms.squared = *g.exact_squared();
                ms.normal = primitive(std::get<DepthJudged>(g.of).exact_direction);
            } else {
                const Judged g = judged(ClaimType::Distance, a, b);
                const DistanceJudged& e = std::get<DistanceJudged>(g.of);
                ms.squared = e.exact_squared;
                ms.p1 = e.exact_p1;
                ms.p2 = e.exact_p2;
                if (ms.verdict == Verdict::Separated) {
                    // The plane through the closest points' midpoint, normal to their difference,
                    // separates the two convex bodies (each lies on its side of its supporting plane).
                    ms.kind = "distance";
                    const Vec3q d = sub(e.exact_p2, e.exact_p1);
                    ms.normal = primitive(d);
                    const Vec3q n = to_q(*ms.normal);
                    ms.offset = (dot(n, e.exact_p1) + dot(n, e.exact_p2)) / 2;
                }
            }
            return ms;
        });
    Json doc = curve_json(m, c);
    doc["query_points"] = points_json(points);
    return {std::move(doc), rows.queries(), rows.csv(), rows.rational_csv()};
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

GoldenAnswers golden_answers_parts(const CompoundRegion& r, CompoundJudge& judge, Json region,
                                   const GoldenPoints& points) {
    validate(points);
    const ExactScene& s = judge.scene();
    const Rect rect = rect_of(s);
    std::map<Q, std::string> xs;
    for (int k = 1; k <= points.verticals; ++k)
        xs[s.lo[0] + (s.hi[0] - s.lo[0]) * fraction(k, points.verticals + 1)] = "vertical";
    if (region.contains("switch_points") && region["switch_points"].is_array())
        for (const Json& sp : region["switch_points"]) xs[parse_exact(sp["rho1"].get<std::string>())] = "switch";
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
    std::vector<std::pair<Q, std::pair<Q, std::string>>> samples;
    for (const auto& [x, near] : xs) {
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
        for (const Q& y : ends) samples.push_back({x, {y, near}});
    }
    Rows rows({s.P[0].part_names, s.P[1].part_names});
    emit(
        rows, rect, samples, false, points, [&](const Q& a, const Q& b) { return judge.verdict(a, b).verdict; },
        [&](const Q& a, const Q& b) {
            Measure ms;
            ms.verdict = judge.verdict(a, b).verdict;
            if (ms.verdict == Verdict::Overlapping) {
                ms.kind = "overlapping";
                return ms;
            }
            const CompoundJudge::Distance d = judge.distance(a, b);
            ms.kind = ms.verdict == Verdict::Separated ? "distance" : "touching";
            ms.squared = d.squared;
            ms.p1 = d.p1;
            ms.p2 = d.p2;
            ms.part1 = d.part1;
            ms.part2 = d.part2;
            return ms;
        });
    region["query_points"] = points_json(points);
    return {std::move(region), rows.queries(), rows.csv(), rows.rational_csv()};
}

}  // namespace scalecert::internal
