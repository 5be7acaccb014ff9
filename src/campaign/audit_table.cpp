#include "campaign/audit_table.hpp"

#include "certify/claim.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace scalecert::internal {

const char* AuditRow::said_word(int said) {
    switch (said) {
    case kSaidSeparated: return claimed_name(Claimed::Separated);
    case kSaidTouching: return claimed_name(Claimed::Touching);
    case kSaidIntersecting: return claimed_name(Claimed::Intersecting);
    case kSaidNoAnswer: return "no answer";
    default: return claimed_name(Claimed::Overlapping);
    }
}

bool AuditRow::wrong(int said, Verdict exact) {
    switch (said) {
    case kSaidSeparated: return exact != Verdict::Separated;
    case kSaidTouching: return exact != Verdict::Touching;
    case kSaidIntersecting: return exact == Verdict::Separated;
    case kSaidNoAnswer: return true;
    default: return exact != Verdict::Overlapping;
    }
}

void AuditRow::count(double r1, double r2, int said, Verdict exact) {
    if (said == kSaidNoAnswer) return count_no_answer(r1, r2, exact, "no answer", "");
    ++queries;
    if (!wrong(said, exact)) return;
    ++(said == kSaidSeparated ? false_separated : said == kSaidTouching ? false_touching : false_overlapping);
    if (failures.size() < kMaxFailures) failures.push_back({r1, r2, said, exact});
}

void AuditRow::count_no_answer(double r1, double r2, Verdict exact, std::string reason, std::string claim) {
    ++queries;
    ++not_answered;
    if (failures.size() < kMaxFailures)
        failures.push_back({r1, r2, kSaidNoAnswer, exact, std::move(reason), std::move(claim)});
}

void AuditRow::note_measures(std::vector<MeasureFailure> all, double tolerance) {
    const double past = tolerance + std::ldexp(tolerance, -40);
    all.erase(std::remove_if(all.begin(), all.end(), [past](const MeasureFailure& f) { return !(f.error > past); }),
              all.end());
    measures_wrong = static_cast<long>(all.size());
    std::stable_sort(all.begin(), all.end(),
                     [](const MeasureFailure& a, const MeasureFailure& b) { return a.error > b.error; });
    if (all.size() > kMaxFailures) all.resize(kMaxFailures);
    measure_failures = std::move(all);
}

std::string audit_csv(const std::vector<AuditRow>& rows, bool timing) {
    std::string s =
        "scene,eps,method,queries,false_separated,false_overlapping,false_touching,seconds_per_query,grid_n,seconds_"
        "per_curve,growth_"
        "error,exact_junctions,junctions_found,junctions_missed,junctions_merged,max_junction_error,"
        "distances,distance_err_median,distance_err_max,depths,depth_err_median,depth_err_max,direction_err_max\n";
    bool with_bd = false, with_on = false, with_answers = false, with_not_run = false;
    for (const AuditRow& r : rows) {
        with_bd |= !r.by_distance.empty(), with_on |= r.on_boundary.has_value();
        with_answers |= r.not_answered > 0, with_not_run |= !r.not_run.empty();
    }
    if (with_bd || with_on || with_answers || with_not_run) {
        s.pop_back();
        if (with_bd)
            for (int k = 4; k <= 52; k += 4) {
                const std::string K = "bd" + std::to_string(k);
                s += "," + K + "_pairs," + K + "_wrong," + K + "_touching";
            }
        if (with_on)
            s +=
                ",on_points,on_touching,on_said_separated,on_said_touching,on_said_overlapping,on_moved,on_moved_wrong";
        if (with_answers) s += ",not_answered";
        if (with_not_run) s += ",not_run";
        s += "\n";
    }
    // A CSV field in quotes, its quotes doubled (RFC 4180).
    auto quoted = [](const std::string& t) {
        std::string q = "\"";
        for (char ch : t) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        return q + "\"";
    };
    // The by-distance and on-boundary columns of a row (empty where it has none).
    auto extra = [&](const AuditRow& r) {
        std::string e;
        if (with_bd)
            for (int k = 4; k <= 52; k += 4) {
                const AuditRow::ByDistance* b = nullptr;
                for (const AuditRow::ByDistance& x : r.by_distance)
                    if (x.k == k) b = &x;
                e += b ? "," + std::to_string(b->pairs) + "," + std::to_string(b->wrong) + "," +
                             std::to_string(b->touching)
                       : std::string(",,,");
            }
        if (with_on) {
            if (const auto& o = r.on_boundary) {
                for (long v : {o->points, o->touching, o->said_separated, o->said_touching, o->said_overlapping,
                               o->moved, o->moved_wrong})
                    e += "," + std::to_string(v);
            } else {
                e += ",,,,,,,";
            }
        }
        if (with_answers) e += "," + std::to_string(r.not_answered);
        if (with_not_run) e += "," + (r.not_run.empty() ? std::string() : quoted(r.not_run));
        return e;
    };
    // A text field as it is, or quoted when it holds a comma, a quote or a line end (a scene's path
    // or a command may); the not_run reason always quoted.
    auto text = [&quoted](const std::string& t) {
        return t.find_first_of(",\"\r\n") == std::string::npos ? t : quoted(t);
    };
    auto num = [](const char* format, auto v) {
        char b[64];
        std::snprintf(b, sizeof b, format, v);
        return std::string(b);
    };
    for (const AuditRow& r : rows) {
        // Without timing the columns seconds_per_query (8th) and seconds_per_curve (10th) are empty.
        const std::vector<std::string> cols = {text(r.scene),
                                               num("%.17g", to_double_rn(r.eps)),
                                               text(r.method),
                                               num("%ld", r.queries),
                                               num("%ld", r.false_separated),
                                               num("%ld", r.false_overlapping),
                                               num("%ld", r.false_touching),
                                               timing ? num("%.6g", r.seconds_per_query) : "",
                                               num("%d", r.grid_n),
                                               timing ? num("%.6g", r.seconds_per_curve) : "",
                                               num("%.6g", r.growth_error),
                                               num("%d", r.exact_junctions),
                                               num("%d", r.junctions_found),
                                               num("%d", r.junctions_missed),
                                               num("%d", r.junctions_merged),
                                               num("%.6g", r.max_junction_error),
                                               num("%ld", r.distances),
                                               num("%.6g", r.distance_err_median),
                                               num("%.6g", r.distance_err_max),
                                               num("%ld", r.depths),
                                               num("%.6g", r.depth_err_median),
                                               num("%.6g", r.depth_err_max),
                                               num("%.6g", r.direction_err_max)};
        for (size_t k = 0; k < cols.size(); ++k) s += (k ? "," : "") + cols[k];
        s += extra(r) + "\n";
    }
    return s;
}

Json audit_json(const std::vector<AuditRow>& rows, bool timing) {
    Json a = Json::array();
    for (const AuditRow& r : rows) {
        Json o{{"scene", r.scene}, {"eps", to_exact_string(r.eps)}, {"method", r.method}};
        for (const auto& [key, value] : r.settings)  // an iteration limit as the integer it is
            if (value == std::floor(value) && std::fabs(value) < 0x1p53)
                o["settings"][key] = static_cast<long long>(value);
            else
                o["settings"][key] = value;
        if (r.has_curve) {
            o["grid_n"] = r.grid_n;
            if (timing) o["seconds_per_curve"] = r.seconds_per_curve;
            o["growth_error"] = r.growth_error;
            o["exact_junctions"] = r.exact_junctions;
            o["junctions_found"] = r.junctions_found;
            o["junctions_missed"] = r.junctions_missed;
            o["junctions_merged"] = r.junctions_merged;
            o["max_junction_error"] = r.max_junction_error;
        } else {
            o["queries"] = r.queries;
            o["false_separated"] = r.false_separated;
            o["false_overlapping"] = r.false_overlapping;
            o["false_touching"] = r.false_touching;
            if (r.not_answered) o["not_answered"] = r.not_answered;
            if (r.extra_claims) o["extra_claims"] = r.extra_claims;
            if (timing) o["seconds_per_query"] = r.seconds_per_query;
            if (r.distances) {
                o["distances"] = r.distances;
                o["closest_outside"] = r.closest_outside;
                o["distance_err_median"] = r.distance_err_median;
                o["distance_err_max"] = r.distance_err_max;
            }
            if (!r.by_distance.empty()) {
                Json bd = Json::array();
                for (const AuditRow::ByDistance& b : r.by_distance)
                    bd.push_back(Json{{"k", b.k}, {"pairs", b.pairs}, {"wrong", b.wrong}, {"touching", b.touching}});
                o["by_distance"] = bd;
            }
            if (const auto& ob = r.on_boundary)
                o["on_boundary"] = Json{{"points", ob->points},
                                        {"touching", ob->touching},
                                        {"said_separated", ob->said_separated},
                                        {"said_touching", ob->said_touching},
                                        {"said_overlapping", ob->said_overlapping},
                                        {"moved", ob->moved},
                                        {"moved_wrong", ob->moved_wrong}};
            if (!r.failures.empty()) {
                Json fs = Json::array();
                for (const AuditRow::Failure& f : r.failures) {
                    Json fj{{"rho1", f.rho1},
                            {"rho2", f.rho2},
                            {"said", AuditRow::said_word(f.said)},
                            {"exact", verdict_name(f.exact)}};
                    if (f.said == AuditRow::kSaidNoAnswer) {
                        fj["reason"] = f.reason;
                        fj["claim"] = f.claim.empty() ? Json() : Json::parse(f.claim);
                    }
                    fs.push_back(std::move(fj));
                }
                o["failures"] = fs;  // the first AuditRow::kMaxFailures wrong verdicts
            }
            if (r.measures_wrong) {
                o["measures_wrong"] = r.measures_wrong;
                Json ms = Json::array();
                for (const AuditRow::MeasureFailure& f : r.measure_failures) {
                    Json m{{"rho1", f.rho1},
                           {"rho2", f.rho2},
                           {"kind", f.depth ? "penetration_depth" : "distance"},
                           {"value", f.value},
                           {"rel_error", f.error}};
                    if (f.part1 >= 0) m["parts"] = Json::array({f.part1, f.part2});
                    ms.push_back(std::move(m));
                }
                o["measure_failures"] = ms;  // the worst AuditRow::kMaxFailures past --measure-tolerance
            }
            if (r.depths) {
                o["depths"] = r.depths;
                o["depth_err_median"] = r.depth_err_median;
                o["depth_err_max"] = r.depth_err_max;
                o["direction_err_max"] = r.direction_err_max;
            }
            if (r.contacts_apart) o["contacts_apart"] = r.contacts_apart;
        }
        if (!r.not_run.empty()) o["not_run"] = r.not_run;
        a.push_back(o);
    }
    return a;
}

}  // namespace scalecert::internal
