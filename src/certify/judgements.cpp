// Proofs of certify-fp's judgements (judgements.hpp), every one exact.
#include "certify/judgements.hpp"
#include "certify/model_points.hpp"

#include <algorithm>
#include <iterator>
#include <limits>
#include <map>
#include <stdexcept>

namespace scalecert::internal {

namespace {

Vec3q unscaled(const Vec3q& s, const Q& rho, const Vec3q& x) {  // y with x = s + ρ(y − s)
    return {s[0] + (x[0] - s[0]) / rho, s[1] + (x[1] - s[1]) / rho, s[2] + (x[2] - s[2]) / rho};
}

// y on face f (in its plane, inside the polygon): weights over a fan triangle of f holding it.
std::vector<std::pair<int, Q>> face_weights(const Polyhedron& P, const Face& f, const Vec3q& y) {
    const Vec3q N = to_q(f.normal);
    const Vec3q& a = P.points[static_cast<size_t>(f.verts[0])];
    for (size_t t = 1; t + 1 < f.verts.size(); ++t) {
        const Vec3q &b = P.points[static_cast<size_t>(f.verts[t])], &c = P.points[static_cast<size_t>(f.verts[t + 1])];
        // Barycentric coordinates in the plane: signed areas along the face normal.
        const Q A = dot(N, cross(sub(b, a), sub(c, a)));
        const Q la = dot(N, cross(sub(b, y), sub(c, y))) / A, lb = dot(N, cross(sub(c, y), sub(a, y))) / A;
        const Q lc = Q(1) - la - lb;
        if (sgn(la) < 0 || sgn(lb) < 0 || sgn(lc) < 0) continue;
        std::vector<std::pair<int, Q>> w;
        const int ids[3] = {f.verts[0], f.verts[t], f.verts[t + 1]};
        const Q ls[3] = {la, lb, lc};
        std::map<int, Q> by_index;
        for (int k = 0; k < 3; ++k)
            if (sgn(ls[k])) by_index[ids[k]] += ls[k];
        for (auto& [i, q] : by_index) w.push_back({i, q});
        return w;
    }
    throw std::logic_error("face_weights: the point is not on the face");
}

}  // namespace

Json membership_proof(const Model& m, int i, const Q& rho, const Vec3q& x, bool* inside) {
    return membership_proof(m.P[i], m.s[i], rho, x, inside);
}

Json membership_proof(const Polyhedron& P, const Vec3q& seed, const Q& rho, const Vec3q& x, bool* inside) {
    const Vec3q y = unscaled(seed, rho, x);
    const PointPlace at = P.place(y);
    *inside = at.side <= 0;
    if (at.side > 0) return Json{{"out", normal_json(at.face->normal)}};
    return Json{{"in", weights_json(at.side == 0 ? face_weights(P, *at.face, y) : P.interior_weights(y))}};
}

namespace {
// One body of a point set (set 0 here) and one point x (set 1, its own seed: no scaling moves it),
// so that the distance between them, proved from support queries, says whether x is in the body.
class BodyAndPoint final : public PointSets {
  public:
    BodyAndPoint(const PointSets& S, int body, const Vec3q& x) : S_(S), body_(body), x_(x), den_(1) {
        for (const Q& c : x) mpz_lcm(den_.get_mpz_t(), den_.get_mpz_t(), c.get_den_mpz_t());
    }
    Vec3q point(int i, int k) const override { return i == 0 ? S_.point(body_, k) : x_; }
    D3 dpoint(int i, int k) const override {
        if (i == 0) return S_.dpoint(body_, k);
        return {to_double_rn(x_[0]), to_double_rn(x_[1]), to_double_rn(x_[2])};
    }
    const Vec3q& seed(int i) const override { return i == 0 ? S_.seed(body_) : x_; }
    const Z& scale(int i) const override { return i == 0 ? S_.scale(body_) : den_; }
    int argmax(int i, const Vec3z& n) const override { return i == 0 ? S_.argmax(body_, n) : 0; }
    int dargmax(int i, const D3& d) const override { return i == 0 ? S_.dargmax(body_, d) : 0; }

  private:
    const PointSets& S_;
    int body_;
    Vec3q x_;
    Z den_;
};
}  // namespace

std::optional<bool> membership_by_points(const PointSets& S, int i, const Q& rho, const Vec3q& x, Json* proof,
                                         int max_rounds) {
    // Beyond the body's box along an axis (six exact support queries): out, with that axis. A
    // point far away, or beyond doubles (where the distance's guess in doubles is lost), ends here.
    const Vec3q& s = S.seed(i);
    for (int a = 0; a < 3; ++a)
        for (int sign : {1, -1}) {
            Vec3z e{Z(0), Z(0), Z(0)};
            e[a] = sign;
            const Vec3q v = S.point(i, S.argmax(i, e));
            const Q reach = sign * (s[a] + rho * (v[a] - s[a]));
            if (sign * x[a] > reach) {
                if (proof) *proof = Json{{"out", normal_json(e)}};
                return false;
            }
        }
    const std::optional<ProvedDistance> pd = proved_distance(BodyAndPoint(S, i, x), rho, Q(1), max_rounds);
    if (!pd) return std::nullopt;
    const bool inside = sgn(pd->d.squared) == 0;
    if (proof) {
        if (inside)
            *proof = Json{{"in", weights_json(pd->d.w1)}};
        else
            *proof = Json{{"out", normal_json(primitive(sub(pd->d.p2, pd->d.p1)))}};
    }
    return inside;
}

bool near_proof(const PointSets& S, int i, const Q& rho, const Vec3q& x, const Q& abs, Json* proof) {
    const std::optional<ProvedDistance> pd =
        proved_distance(BodyAndPoint(S, i, x), rho, Q(1), std::numeric_limits<int>::max());
    if (!pd) throw std::logic_error("near_proof: the distance did not close");
    const bool near = pd->d.squared <= abs * abs;
    if (proof) {
        if (near)
            *proof = Json{{"near", weights_json(pd->d.w1)}};
        else
            *proof = Json{{"out", normal_json(primitive(sub(pd->d.p2, pd->d.p1)))}};
    }
    return near;
}

ExactDistance point_to_body(const PointSets& S, int i, const Q& rho, const Vec3q& x) {
    const std::optional<ProvedDistance> pd =
        proved_distance(BodyAndPoint(S, i, x), rho, Q(1), std::numeric_limits<int>::max());
    if (!pd) throw std::logic_error("point_to_body: the distance did not close");
    return pd->d;
}

Json verdict_proof(const Model& m, const QueryAnswer& r) {
    return Json{{"verdict", verdict_name(r.verdict)}, {"certificate", query_certificate_json(m, r)}};
}

Json distance_proof(const Model* m, const ExactDistance& e, const Q& rho1, const Q& rho2) {
    Json j;
    j["squared"] = to_exact_string(e.squared);
    if (!e.w1.empty() && !e.w2.empty()) {
        j["P1"] = weights_json(e.w1);
        j["P2"] = weights_json(e.w2);
        return j;
    }
    if (!m) throw std::logic_error("distance_proof: closest points without weights, and no hull");
    bool in1 = false, in2 = false;
    Json p1 = membership_proof(*m, 0, rho1, e.p1, &in1), p2 = membership_proof(*m, 1, rho2, e.p2, &in2);
    if (!in1 || !in2) throw std::logic_error("distance_proof: a closest point outside its body");
    j["P1"] = p1["in"];
    j["P2"] = p2["in"];
    return j;
}

Json depth_proof(const Model* m, const MeasuredDepth& d, const Q& rho1, const Q& rho2) {
    if (d.state == Verdict::Separated) return Json{{"separated", normal_json(d.normal)}};
    if (d.state == Verdict::Touching) {
        const Json common = distance_proof(m, d.distance, rho1, rho2);
        return Json{{"squared", "0"},
                    {"direction", normal_json(d.normal)},
                    {"common", Json{{"P1", common["P1"]}, {"P2", common["P2"]}}}};
    }
    const ProvedDepth& p = *d.depth;
    // The points in order of first use.
    std::map<int, int> renumber;
    Json points = Json::array(), triangles = Json::array();
    for (const auto& t : p.triangles) {
        Json tri = Json::array();
        for (int v : t) {
            auto it = renumber.find(v);
            if (it == renumber.end()) {
                it = renumber.emplace(v, static_cast<int>(renumber.size())).first;
                points.push_back(
                    Json::array({p.points[static_cast<size_t>(v)].first, p.points[static_cast<size_t>(v)].second}));
            }
            tri.push_back(it->second);
        }
        triangles.push_back(tri);
    }
    Json j;
    j["squared"] = to_exact_string(p.squared);
    j["direction"] = normal_json(p.direction);
    j["points"] = std::move(points);
    j["triangles"] = std::move(triangles);
    return j;
}

Json growth_proof(const Model& m, const TouchingCurve& c) {
    const Q& g = c.growth.value;
    Json j;
    j["value"] = to_exact_string(g);
    if (sgn(g) == 0) return j;
    const size_t line = c.env.pieces[c.growth.env].line;
    j["normal"] = normal_json(m.lines[line].normal);
    j["witness"] = witness_object(make_witness(m, g, g, line));
    return j;
}

std::pair<Q, Q> curve_proof_window(const TouchingCurve& c, const Q& lo_need, const Q& hi_need) {
    // The envelope's breaks (every one at ρ1, ρ2 > 0: it goes on as one line from ρ2 = 0).
    std::vector<Q> breaks;
    for (const EnvPiece& p : c.env.pieces)
        if (p.to) breaks.push_back(*p.to);
    Q a = 0;
    if (sgn(lo_need) > 0) {
        auto it = std::lower_bound(breaks.begin(), breaks.end(), lo_need);  // first break >= lo_need
        a = it == breaks.begin() ? Q(lo_need / 2) : Q((*std::prev(it) + lo_need) / 2);
    }
    auto it = std::upper_bound(breaks.begin(), breaks.end(), hi_need);  // first break > hi_need
    const Q b = it == breaks.end() ? Q(hi_need + 1) : Q((*it + hi_need) / 2);
    return {a, b};
}

Json curve_proof(const Model& m, const TouchingCurve& c, const Q& lo_need, const Q& hi_need) {
    const auto [a, b] = curve_proof_window(c, lo_need, hi_need);
    TouchingCurve w;
    w.env = c.env;
    restrict_curve(m, w, a, b);
    return curve_proof_json(m, w, curve_witnesses(m, w, points_of(m).curve_seeds(m)));
}

std::string judgements_text(const Model& m, const Q& tolerance, const Q& abs_tolerance, Json judgements) {
    Json j;
    j["format"] = "scalecert-2";
    j["kind"] = "judgements";
    if (sgn(abs_tolerance) > 0) j["abs_tolerance"] = to_exact_string(abs_tolerance);
    j["tolerance"] = to_exact_string(tolerance);
    j["judgements"] = std::move(judgements);
    j["seed_interior"] = seed_interior(seed_weights(m));
    j["scene"] = document_scene(m);
    return document_text(m, j);
}

}  // namespace scalecert::internal
