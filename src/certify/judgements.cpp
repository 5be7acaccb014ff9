// Proofs of certify-fp's judgements (judgements.hpp), every one exact.
#include "certify/judgements.hpp"

#include <map>
#include <stdexcept>

namespace scalecert::internal {

namespace {

Vec3q unscaled(const Model& m, int i, const Q& rho, const Vec3q& x) {  // y with x = s + ρ(y − s)
    const Vec3q& s = m.s[i];
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

// A support point of M = P1(ρ1) − P2(ρ2) in the integer direction n: vertex i of P1 maximising
// n·v, vertex j of P2 minimising n·w (the smallest index of each), and i(ρ1) − j(ρ2).
struct MPoint {
    int i, j;
    Vec3q z;
};
MPoint support_M(const HullModel& m, const Q& rho1, const Q& rho2, const Vec3z& n) {
    const int i = m.P[0].argmax(n).front();
    const int j = m.P[1].argmax(Vec3z{-n[0], -n[1], -n[2]}).front();
    const Vec3q a = scaled_point(m, 0, rho1, m.P[0].points[static_cast<size_t>(i)]);
    const Vec3q b = scaled_point(m, 1, rho2, m.P[1].points[static_cast<size_t>(j)]);
    return {i, j, sub(a, b)};
}

// The exact EPA: a convex polytope K ⊆ M, grown from a tetrahedron by support points, until its
// face nearest the origin lies on a face of M. Then every face of K is at least that far from
// the origin, and that distance is M's: the depth.
struct Epa {
    const HullModel& m;
    Q r1, r2;
    std::vector<MPoint> pts;
    struct Tri {
        std::array<int, 3> v;
        Vec3q N;  // (b − a) × (c − a), outward
        Q off;    // N·a
        Q key;    // signed squared distance of the plane from the origin: sgn(off)·off²/|N|²
        bool alive = true;
    };
    std::vector<Tri> tris;
    std::map<std::pair<int, int>, size_t> edge;  // directed edge -> its live triangle

    int add_point(const MPoint& p) {
        pts.push_back(p);
        return static_cast<int>(pts.size()) - 1;
    }
    void add_tri(int a, int b, int c) {
        Tri t;
        t.v = {a, b, c};
        t.N = cross(sub(pts[static_cast<size_t>(b)].z, pts[static_cast<size_t>(a)].z),
                    sub(pts[static_cast<size_t>(c)].z, pts[static_cast<size_t>(a)].z));
        t.off = dot(t.N, pts[static_cast<size_t>(a)].z);
        t.key = Q(t.off * t.off) / dot(t.N, t.N);
        if (sgn(t.off) < 0) t.key = -t.key;
        const size_t k = tris.size();
        tris.push_back(std::move(t));
        edge[{a, b}] = k;
        edge[{b, c}] = k;
        edge[{c, a}] = k;
    }
    bool visible(const Tri& t, const Vec3q& z) const { return dot(t.N, z) > t.off; }

    // Four affinely independent support points, from fixed directions and then from directions
    // off the span found so far (M has an interior when the pair overlaps).
    void start() {
        std::vector<Vec3z> dirs;
        for (int a = 0; a < 3; ++a)
            for (int s : {1, -1}) {
                Vec3z d{Z(0), Z(0), Z(0)};
                d[static_cast<size_t>(a)] = s;
                dirs.push_back(d);
            }
        for (int x : {1, -1})
            for (int y : {1, -1})
                for (int z : {1, -1}) dirs.push_back({Z(x), Z(y), Z(z)});
        std::vector<MPoint> base;
        auto independent = [&](const Vec3q& z) {
            if (base.empty()) return true;
            const Vec3q e1 = sub(z, base[0].z);
            if (base.size() == 1) return sgn(e1[0]) || sgn(e1[1]) || sgn(e1[2]);
            const Vec3q c = cross(sub(base[1].z, base[0].z), e1);
            if (base.size() == 2) return sgn(c[0]) || sgn(c[1]) || sgn(c[2]);
            return sgn(dot(cross(sub(base[1].z, base[0].z), sub(base[2].z, base[0].z)), e1)) != 0;
        };
        for (size_t k = 0; base.size() < 4; ++k) {
            if (k >= dirs.size()) {
                // A direction off the span: the plane's normal, or one across the line (both
                // signs, so that a support point leaves the span).
                if (k > dirs.size() + 12) throw std::logic_error("EPA: the Minkowski difference is flat");
                Vec3q d;
                if (base.size() == 3) d = cross(sub(base[1].z, base[0].z), sub(base[2].z, base[0].z));
                else if (base.size() == 2) {
                    const Vec3q e = sub(base[1].z, base[0].z);
                    d = cross(e, Vec3q{Q(1), Q(0), Q(0)});
                    if (!sgn(d[0]) && !sgn(d[1]) && !sgn(d[2])) d = cross(e, Vec3q{Q(0), Q(1), Q(0)});
                } else throw std::logic_error("EPA: no support points");
                const Vec3z p = primitive(d);
                dirs.push_back(p);
                dirs.push_back({-p[0], -p[1], -p[2]});
            }
            const MPoint p = support_M(m, r1, r2, dirs[k]);
            if (independent(p.z)) base.push_back(p);
        }
        for (const MPoint& p : base) add_point(p);
        // Faces of the tetrahedron, each turned to face away from the fourth point.
        const int f[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
        for (const auto& q : f) {
            const Vec3q N = cross(sub(pts[static_cast<size_t>(q[1])].z, pts[static_cast<size_t>(q[0])].z),
                                  sub(pts[static_cast<size_t>(q[2])].z, pts[static_cast<size_t>(q[0])].z));
            if (sgn(dot(N, sub(pts[static_cast<size_t>(q[3])].z, pts[static_cast<size_t>(q[0])].z))) > 0) add_tri(q[0], q[2], q[1]);
            else add_tri(q[0], q[1], q[2]);
        }
    }

    // Runs to the end; the index of the nearest triangle.
    size_t run() {
        start();
        for (;;) {
            size_t best = tris.size();
            for (size_t k = 0; k < tris.size(); ++k)
                if (tris[k].alive && (best == tris.size() || tris[k].key < tris[best].key)) best = k;
            const Vec3z n = primitive(tris[best].N);
            const MPoint p = support_M(m, r1, r2, n);
            if (!visible(tris[best], p.z)) return best;  // the plane supports M: a face of M
            const int k = add_point(p);
            // Remove every face the point sees, and close the hole with a fan from the horizon.
            std::vector<std::pair<int, int>> horizon;
            std::vector<size_t> seen;
            for (size_t t = 0; t < tris.size(); ++t)
                if (tris[t].alive && visible(tris[t], p.z)) seen.push_back(t);
            for (size_t t : seen) tris[t].alive = false;
            for (size_t t : seen)
                for (int e = 0; e < 3; ++e) {
                    const int a = tris[t].v[static_cast<size_t>(e)], b = tris[t].v[static_cast<size_t>((e + 1) % 3)];
                    const auto other = edge.find({b, a});
                    if (other != edge.end() && tris[other->second].alive) horizon.push_back({a, b});
                }
            for (size_t t : seen)
                for (int e = 0; e < 3; ++e) {
                    const auto it = edge.find({tris[t].v[static_cast<size_t>(e)], tris[t].v[static_cast<size_t>((e + 1) % 3)]});
                    if (it != edge.end() && it->second == t) edge.erase(it);
                }
            for (const auto& [a, b] : horizon) add_tri(a, b, k);
        }
    }
};

}  // namespace

Json membership_proof(const HullModel& m, int i, const Q& rho, const Vec3q& x, bool* inside) {
    const Polyhedron& P = m.P[i];
    const Vec3q y = unscaled(m, i, rho, x);
    const Face* on = nullptr;
    for (const Face& f : P.faces) {
        const Q v = dot(f.normal, y) - dot(f.normal, P.points[static_cast<size_t>(f.verts.front())]);
        if (sgn(v) > 0) {
            *inside = false;
            return Json{{"out", normal_json(f.normal)}};
        }
        if (sgn(v) == 0 && !on) on = &f;
    }
    *inside = true;
    return Json{{"in", weights_json(on ? face_weights(P, *on, y) : P.interior_weights(y))}};
}

Json verdict_proof(const HullModel& m, const TouchingCurve& c, const Q& rho1, const Q& rho2, Verdict* verdict) {
    const QueryAnswer r = query(m, c, rho1, rho2, true);
    *verdict = r.verdict;
    return Json{{"verdict", verdict_name(r.verdict)}, {"certificate", query_certificate_json(m, r)}};
}

Json distance_proof(const HullModel& m, const ExactDistance& e, const Q& rho1, const Q& rho2) {
    bool in1 = false, in2 = false;
    Json p1 = membership_proof(m, 0, rho1, e.p1, &in1), p2 = membership_proof(m, 1, rho2, e.p2, &in2);
    if (!in1 || !in2) throw std::logic_error("distance_proof: a closest point outside its body");
    Json j;
    j["squared"] = to_exact_string(e.squared);
    j["P1"] = p1["in"];
    j["P2"] = p2["in"];
    return j;
}

Json depth_proof(const HullModel& m, const TouchingCurve& c, const Q& rho1, const Q& rho2, Q* squared) {
    const QueryAnswer r = query(m, c, rho1, rho2, true);
    if (r.verdict == Verdict::Separated) {
        *squared = -1;
        return Json{{"separated", normal_json(m.lines[r.plane->line].normal)}};
    }
    if (r.verdict == Verdict::Touching) {
        *squared = 0;
        return Json{{"squared", "0"},
                    {"direction", normal_json(m.lines[r.plane->line].normal)},
                    {"common", Json{{"P1", weights_json(r.witness->w1)}, {"P2", weights_json(r.witness->w2)}}}};
    }
    Epa epa{m, rho1, rho2, {}, {}, {}};
    const size_t best = epa.run();
    *squared = epa.tris[best].key;
    if (sgn(*squared) <= 0) throw std::logic_error("depth_proof: the origin is not inside the Minkowski difference");
    // Only the live triangles and their points, renumbered in order of first use.
    std::map<int, int> renumber;
    Json points = Json::array(), triangles = Json::array();
    for (const auto& t : epa.tris) {
        if (!t.alive) continue;
        Json tri = Json::array();
        for (int v : t.v) {
            auto it = renumber.find(v);
            if (it == renumber.end()) {
                it = renumber.emplace(v, static_cast<int>(renumber.size())).first;
                points.push_back(Json::array({epa.pts[static_cast<size_t>(v)].i, epa.pts[static_cast<size_t>(v)].j}));
            }
            tri.push_back(it->second);
        }
        triangles.push_back(tri);
    }
    Json j;
    j["squared"] = to_exact_string(*squared);
    j["direction"] = normal_json(primitive(epa.tris[best].N));
    j["points"] = std::move(points);
    j["triangles"] = std::move(triangles);
    return j;
}

Json growth_proof(const HullModel& m, const TouchingCurve& c) {
    const Q& g = c.growth.value;
    Json j;
    j["value"] = to_exact_string(g);
    if (sgn(g) == 0) return j;
    const size_t line = c.env.pieces[c.growth.env].line;
    j["normal"] = normal_json(m.lines[line].normal);
    j["witness"] = witness_object(make_witness(m, g, g, line));
    return j;
}

std::string judgements_text(const HullModel& m, const Q& tolerance, Json judgements, Json not_certified) {
    Json j;
    j["format"] = "scalecert-2";
    j["kind"] = "judgements";
    j["tolerance"] = to_exact_string(tolerance);
    j["judgements"] = std::move(judgements);
    j["not_certified"] = std::move(not_certified);
    j["seed_interior"] = seed_interior(seed_weights(m));
    j["scene"] = scene_json(m.scene);
    return dump(j);
}

}  // namespace scalecert::internal
