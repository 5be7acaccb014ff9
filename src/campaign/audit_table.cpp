#include "campaign/audit_table.hpp"

#include <cstdio>

namespace scalecert::internal {

std::string audit_csv(const std::vector<AuditRow>& rows, bool timing) {
    std::string s = "scene,eps,method,queries,false_separated,false_overlapping,seconds_per_query,grid_n,seconds_per_curve,growth_error,exact_junctions,junctions_found,junctions_missed,junctions_merged,max_junction_error,"
                    "distances,distance_err_median,distance_err_max,depths,depth_err_median,depth_err_max,direction_err_max\n";
    char b[1024];
    for (const AuditRow& r : rows) {
        std::snprintf(b, sizeof b, "%s,%.17g,%s,%ld,%ld,%ld,%.6g,%d,%.6g,%.6g,%d,%d,%d,%d,%.6g,%ld,%.6g,%.6g,%ld,%.6g,%.6g,%.6g\n", r.scene.c_str(), to_double_rn(r.eps),
                      r.method.c_str(), r.queries, r.false_separated, r.false_overlapping, r.seconds_per_query, r.grid_n,
                      r.seconds_per_curve, r.growth_error, r.exact_junctions, r.junctions_found, r.junctions_missed,
                      r.junctions_merged, r.max_junction_error, r.distances, r.distance_err_median, r.distance_err_max, r.depths,
                      r.depth_err_median, r.depth_err_max, r.direction_err_max);
        if (!timing) {  // the columns seconds_per_query (7th) and seconds_per_curve (9th) left empty
            std::string line = b;
            std::vector<std::string> cols;
            for (size_t p = 0;;) {
                const size_t q = line.find_first_of(",\n", p);
                cols.push_back(line.substr(p, q - p));
                if (line[q] == '\n') break;
                p = q + 1;
            }
            cols[6].clear();
            cols[8].clear();
            line.clear();
            for (size_t k = 0; k < cols.size(); ++k) line += cols[k] + (k + 1 < cols.size() ? "," : "\n");
            s += line;
        } else {
            s += b;
        }
    }
    return s;
}

Json audit_json(const std::vector<AuditRow>& rows, bool timing) {
    Json a = Json::array();
    for (const AuditRow& r : rows) {
        Json o{{"scene", r.scene}, {"eps", to_exact_string(r.eps)}, {"method", r.method}};
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
            if (r.depths) {
                o["depths"] = r.depths;
                o["depth_err_median"] = r.depth_err_median;
                o["depth_err_max"] = r.depth_err_max;
                o["direction_err_max"] = r.direction_err_max;
            }
        }
        a.push_back(o);
    }
    return a;
}

}  // namespace scalecert::internal
