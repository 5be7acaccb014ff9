#include "certify/model_points.hpp"

#include "curve/scan.hpp"

#include <stdexcept>

namespace scalecert::internal {

namespace {

const char* const kNames[2] = {"P1", "P2"};

// The hull model: its polyhedra, their faces and every contact line.
class HullModelPoints final : public ModelPoints {
  public:
    Json engine_json(const Model& m) const override {
        Json j;
        for (int i = 0; i < 2; ++i)
            j[kNames[i]] = Json{
                {"vertices", m.P[i].vertices.size()}, {"edges", m.P[i].edges.size()}, {"faces", m.P[i].faces.size()}};
        j["facet_normals"] = m.stats.distinct_normals;
        j["contact_lines"] = m.lines.size();  // after dropping the certainly dominated ones
        j["edge_pairs_tested"] = m.stats.edge_pairs_tested;
        j["gauss_arc_crossings"] = m.stats.arc_crossings;
        // From the predicates' statistics (predicates.hpp): the arc sides of the overlay, the
        // support comparisons of both polyhedra.
        using filter::Predicate;
        const filter::PredicateCounts arc = m.stats.predicates[Predicate::ArcSide];
        filter::PredicateCounts cmp = m.P[0].predicates[Predicate::SupportCmp];
        cmp += m.P[1].predicates[Predicate::SupportCmp];
        j["decided_by_filter"] = Json{{"arc_signs", arc.filtered}, {"support_comparisons", cmp.filtered}};
        j["decided_exactly"] = Json{{"arc_signs", arc.exact}, {"support_comparisons", cmp.exact}};
        return j;
    }
    Json scene_json(const Model& m) const override { return internal::scene_json(m.scene); }
    std::string document_text(const Model&, std::string text) const override { return text; }
    std::vector<std::pair<int, Q>> seed_weights(const Model& m, int i) const override {
        return m.P[i].interior_weights(m.s[i]);
    }
    SeedWeights curve_seeds(const Model&) const override { return {}; }
    Witness witness_off_the_curve(const Model& m, const TouchingCurve&, const Q& rho1, const Q& rho2,
                                  const std::vector<std::pair<int, Q>>[2]) const override {
        return make_witness(m, rho1, rho2, size_t(-1));
    }
};

// On the walk the points stay in machine integers (up to 10^6 per polyhedron): the scene's vertex
// lists enter the document as placeholders, and document_text writes them straight into the
// text, as dump() would have written them.
const char* const kVerticesPlaceholder[2] = {"@scalecert-vertices-P1@", "@scalecert-vertices-P2@"};

// An exact coordinate x / scale in lowest terms, as to_exact_string writes it.
void append_coordinate(std::string& t, std::int64_t x, const Z& scale) {
    if (scale == 1) {
        t += std::to_string(x);
        return;
    }
    Q q(Z(static_cast<long>(x)), scale);
    q.canonicalize();
    t += to_exact_string(q);
}

// nlohmann's dump(1) of an array of [x, y, z] arrays of strings, the array at `indent`.
std::string vertices_text(const IntPoints& P, size_t indent) {
    std::string t;
    const size_t n = P.size();
    if (n == 0) return "[]";
    t.reserve(n * (3 * (indent + 16) + 2 * indent + 8));
    t += "[\n";
    const std::string i1(indent + 1, ' '), i2(indent + 2, ' ');
    for (size_t k = 0; k < n; ++k) {
        t += i1;
        t += "[\n";
        for (int c = 0; c < 3; ++c) {
            t += i2;
            t += '"';
            append_coordinate(t, P.at(k)[c], P.scale);
            t += c < 2 ? "\",\n" : "\"\n";
        }
        t += i1;
        t += k + 1 < n ? "],\n" : "]\n";
    }
    t += std::string(indent, ' ');
    t += "]";
    return t;
}

// The walk's model: the points in machine integers (scan.hpp), no hull.
class WalkModelPoints final : public ModelPoints {
  public:
    Json engine_json(const Model& m) const override {
        Json j;
        const ScanStats& s = m.scan_stats;
        j["engine"] = "scan";
        for (int i = 0; i < 2; ++i) j[kNames[i]] = Json{{"points", m.scan->P[i].size()}};
        j["contact_lines"] = m.lines.size();
        j["support_queries"] = s.support_queries;
        j["gift_wrap_steps"] = s.gift_wrap_steps;
        j["start_lp"] = Json{{"solves", s.lp_solves}, {"rows", s.lp_rows}};
        const filter::PredicateCounts& sc = s.predicates[filter::Predicate::ScanSupport];
        j["decided_by_filter"] = Json{{"support_comparisons", sc.filtered}};
        j["decided_exactly"] = Json{{"support_comparisons", sc.exact}};
        return j;
    }
    Json scene_json(const Model& m) const override {
        ExactScene sc = m.scene;  // seeds and ranges; no points
        Json j = internal::scene_json(sc);
        for (int i = 0; i < 2; ++i) j[kNames[i]]["vertices"] = kVerticesPlaceholder[i];
        return j;
    }
    std::string document_text(const Model& m, std::string text) const override {
        // "scene" is a member of the document (indent 1), "P1" of the scene (2), "vertices" of P1 (3).
        for (int i = 0; i < 2; ++i) {
            const std::string key = std::string("\"") + kVerticesPlaceholder[i] + "\"";
            const size_t at = text.find(key);
            if (at == std::string::npos || text.find(key, at + 1) != std::string::npos)
                throw std::logic_error("document_text: the vertex placeholder is not there once");
            text.replace(at, key.size(), vertices_text(m.scan->P[i], 3));
        }
        return text;
    }
    std::vector<std::pair<int, Q>> seed_weights(const Model& m, int i) const override {
        return scan_seed_weights(*m.scan, i);
    }
    SeedWeights curve_seeds(const Model& m) const override { return internal::seed_weights(m); }
    Witness witness_off_the_curve(const Model& m, const TouchingCurve& c, const Q& rho1, const Q& rho2,
                                  const std::vector<std::pair<int, Q>> seed[2]) const override {
        return lift_witness(witness_below(m, c, rho1), rho1, rho2, seed);
    }
};

}  // namespace

const ModelPoints& points_of(const Model& m) {
    static const HullModelPoints hull;
    static const WalkModelPoints walk;
    if (m.scan) return walk;
    return hull;
}

}  // namespace scalecert::internal
