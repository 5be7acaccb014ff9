#include "scalecert/polyhedron.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace scalecert {

std::vector<int> Polyhedron::argmax(const Vec3z& n, Q* value) const {
    const Vec3q nq = to_q(n);
    int cur = vertices.front();
    Q best = dot(nq, points[cur]);
    for (bool moved = true; moved;) {
        moved = false;
        for (int w : adj[cur]) {
            Q val = dot(nq, points[w]);
            if (val > best) { best = val; cur = w; moved = true; break; }
        }
    }
    // The face of maximisers is connected in the vertex graph.
    std::vector<int> out{cur}, stack{cur};
    std::set<int> seen{cur};
    while (!stack.empty()) {
        int v = stack.back();
        stack.pop_back();
        for (int w : adj[v])
            if (!seen.count(w) && dot(nq, points[w]) == best) {
                seen.insert(w);
                out.push_back(w);
                stack.push_back(w);
            }
    }
    std::sort(out.begin(), out.end());
    if (value) *value = best;
    return out;
}

Q Polyhedron::support(const Vec3z& n) const {
    Q v;
    argmax(n, &v);
    return v;
}

bool Polyhedron::strictly_inside(const Vec3q& p) const {
    for (const Face& f : faces)
        if (dot(to_q(f.normal), p) >= dot(to_q(f.normal), points[f.verts[0]])) return false;
    return true;
}

namespace {

// Sorts the vertices of a convex polygon with outward normal n counter-clockwise (seen from
// outside), exactly: angular order around an interior point, in the plane projected along the
// dominant axis of n.
void order_ccw(std::vector<int>& vs, const std::vector<Vec3q>& pts, const Vec3z& n) {
    int drop = 0;
    for (int k = 1; k < 3; ++k)
        if (abs(n[k]) > abs(n[drop])) drop = k;
    int u = (drop + 1) % 3, w = (drop + 2) % 3;
    Q cu = 0, cw = 0;
    for (int v : vs) { cu += pts[v][u]; cw += pts[v][w]; }
    cu /= Q(static_cast<long>(vs.size()));
    cw /= Q(static_cast<long>(vs.size()));
    // In the (u, w) projection, counter-clockwise around +drop axis means ccw seen from outside
    // when n[drop] > 0; reverse otherwise.
    auto half = [&](int v) { Q du = pts[v][u] - cu, dw = pts[v][w] - cw; return (dw > 0 || (dw == 0 && du > 0)) ? 0 : 1; };
    std::sort(vs.begin(), vs.end(), [&](int a, int b) {
        int ha = half(a), hb = half(b);
        if (ha != hb) return ha < hb;
        Q au = pts[a][u] - cu, aw = pts[a][w] - cw, bu = pts[b][u] - cu, bw = pts[b][w] - cw;
        return au * bw - aw * bu > 0;
    });
    if (sgn(n[drop]) < 0) std::reverse(vs.begin(), vs.end());
}

bool affinely_3d(const std::vector<Vec3q>& pts) {
    size_t i1 = 0, i2 = 0;
    for (i1 = 1; i1 < pts.size() && pts[i1] == pts[0]; ++i1) {}
    if (i1 == pts.size()) return false;
    Vec3q e1 = sub(pts[i1], pts[0]);
    Vec3q c;
    for (i2 = i1 + 1; i2 < pts.size(); ++i2) {
        c = cross(e1, sub(pts[i2], pts[0]));
        if (sgn(c[0]) || sgn(c[1]) || sgn(c[2])) break;
    }
    if (i2 >= pts.size()) return false;
    for (size_t i3 = i2 + 1; i3 < pts.size(); ++i3)
        if (sgn(dot(c, sub(pts[i3], pts[0])))) return true;
    return false;
}

}  // namespace

Polyhedron build_polyhedron(const std::vector<Vec3q>& pts, const std::string& name) {
    if (!affinely_3d(pts))
        throw InputError(name + ": fewer than 4 affinely independent vertices (the points are flat)");
    Polyhedron P;
    P.points = pts;
    auto tris = hull_triangles(pts);
    // Group hull triangles by their supporting plane: on a convex polytope one plane, one face.
    std::map<Vec3z, int> plane_of;
    std::vector<std::set<int>> face_pts;
    std::map<int, std::set<int>> faces_at;  // hull point -> faces through it
    for (const auto& t : tris) {
        Vec3z n = primitive(cross(sub(pts[t[1]], pts[t[0]]), sub(pts[t[2]], pts[t[0]])));
        auto [it, fresh] = plane_of.emplace(n, static_cast<int>(face_pts.size()));
        if (fresh) face_pts.emplace_back();
        for (int v : t) {
            face_pts[it->second].insert(v);
            faces_at[v].insert(it->second);
        }
    }
    // True vertices lie on at least three faces; points inside a face or an edge are dropped.
    std::set<int> is_vertex;
    for (const auto& [v, fs] : faces_at)
        if (fs.size() >= 3) is_vertex.insert(v);
    P.vertices.assign(is_vertex.begin(), is_vertex.end());
    P.faces.resize(face_pts.size());
    for (const auto& [n, fi] : plane_of) {
        Face& f = P.faces[fi];
        f.normal = n;
        for (int v : face_pts[fi])
            if (is_vertex.count(v)) f.verts.push_back(v);
        order_ccw(f.verts, pts, n);
    }
    // Order faces deterministically by normal, so output never depends on CGAL's traversal.
    std::sort(P.faces.begin(), P.faces.end(), [](const Face& a, const Face& b) { return a.normal < b.normal; });
    std::map<std::pair<int, int>, std::vector<int>> edge_faces;
    for (size_t fi = 0; fi < P.faces.size(); ++fi) {
        const auto& vs = P.faces[fi].verts;
        for (size_t k = 0; k < vs.size(); ++k) {
            int a = vs[k], b = vs[(k + 1) % vs.size()];
            edge_faces[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(fi));
        }
    }
    P.adj.assign(pts.size(), {});
    for (const auto& [ab, fs] : edge_faces) {
        if (fs.size() != 2) throw std::logic_error("hull edge not shared by exactly two faces");
        P.edges.push_back({ab.first, ab.second, fs[0], fs[1]});
        P.adj[ab.first].push_back(ab.second);
        P.adj[ab.second].push_back(ab.first);
    }
    if (P.vertices.size() + P.faces.size() != P.edges.size() + 2)
        throw std::logic_error("hull fails Euler's formula");
    return P;
}

}  // namespace scalecert
