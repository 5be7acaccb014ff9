// The segments' JSON (segment_json.hpp).
#include "segment/segment_json.hpp"

#include "certify/query.hpp"

#include <mpfr.h>

namespace scalecert::internal {

namespace {
Json pieces_json(const std::vector<LinearPiece>& f) {
    Json a = Json::array();
    for (const LinearPiece& p : f) {
        Json o;
        put_exact(o, "rho", std::vector<Q>{p.from, p.to});
        put_exact(o, "slope", p.slope);
        put_exact(o, "intercept", p.intercept);
        a.push_back(o);
    }
    return a;
}
}  // namespace

namespace {
Json segment_head(const Segment& s) {
    Json seg;
    seg["kind"] = s.kind;
    if (!s.note.empty()) seg["note"] = s.note;
    put_exact(seg, "from", s.v1);
    put_exact(seg, "to", s.v2);
    if (s.path) {  // floating point: the ellipsoids themselves are not certified, the ends are checked
        Json es;
        const char* names[2] = {"P1", "P2"};
        for (int i = 0; i < 2; ++i)
            es[names[i]] = Json{{"center", s.path->E[i].center}, {"matrix", s.path->E[i].matrix}};
        es["distance_double"] = s.path->distance;
        seg["inner_ellipsoids"] = es;
    }
    return seg;
}
}  // namespace

double scaled_length(const Vec3q& v1, const Vec3q& v2, const Q& g) {
    Vec3q e = sub(v2, v1);
    Q len2 = dot(e, e);
    mpfr_t x, y;
    mpfr_inits2(256, x, y, static_cast<mpfr_ptr>(nullptr));
    mpfr_set_q(x, len2.get_mpq_t(), MPFR_RNDN);
    mpfr_sqrt(x, x, MPFR_RNDN);
    mpfr_set_q(y, g.get_mpq_t(), MPFR_RNDN);
    mpfr_mul(x, x, y, MPFR_RNDN);
    double d = mpfr_get_d(x, MPFR_RNDN);
    mpfr_clears(x, y, static_cast<mpfr_ptr>(nullptr));
    return d;
}

void add_segment_json(Json& j, const HullModel& m, const TouchingCurve& c, const Segment& s) {
    Json seg = segment_head(s);
    seg["t1"] = pieces_json(s.t[0]);
    seg["t2"] = pieces_json(s.t[1]);
    j["segment"] = seg;
    Json tc = Json::array(), tcd = Json::array();
    for (const auto& p : t_curve(m, c, s)) {
        tc.push_back(Json::array({to_exact_string(p[0]), to_exact_string(p[1])}));
        tcd.push_back(Json::array({to_double_rn(p[0]), to_double_rn(p[1])}));
    }
    j["t_curve"] = tc;
    j["t_curve_double"] = tcd;
    // Contact loci: the common point at each curve vertex (the contact point moves linearly
    // between them on (V,F), (F,V) and (E,E) pieces).
    Json loci = Json::array();
    for (const auto& v : curve_vertices(m, c)) {
        size_t line = c.env.pieces[c.env.locate(v[0])].line;
        loci.push_back(witness_object(make_witness(m, v[0], v[1], line)));
    }
    j["contact_loci"] = loci;
    Json faces;
    const char* names[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        Json fs = Json::array();
        for (const Face& f : m.P[i].faces) fs.push_back(f.verts);
        faces[names[i]] = fs;
    }
    j["faces"] = faces;
    j["scene"] = scene_json(m.scene);
}

void add_query_segment_json(Json& j, const Segment& s, const Q& rho1, const Q& rho2) {
    Json seg = segment_head(s);
    put_exact(seg, "t1", eval(s.t[0], rho1));
    put_exact(seg, "t2", eval(s.t[1], rho2));
    Q g = directional_gap(s, rho1, rho2);
    put_exact(seg, "gap_fraction", g);
    seg["gap_distance_double"] = scaled_length(s.v1, s.v2, g);
    seg["gap_meaning"] = g > 0   ? "gap along the segment"
                         : g < 0 ? "penetration along the segment"
                                 : "contact on the segment";
    j["segment"] = seg;
}

}  // namespace scalecert::internal
