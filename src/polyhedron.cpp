#include "scalecert/polyhedron.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace scalecert {

namespace {
constexpr int kG = 16;  // start table resolution per cube face
using D3 = std::array<double, 3>;
// The cube-map cell of a direction.
int cube_cell(const D3& v) {
    int ax = 0;
    for (int k = 1; k < 3; ++k)
        if (std::fabs(v[k]) > std::fabs(v[ax])) ax = k;
    double m = std::fabs(v[ax]);
    if (!(m > 0)) return 0;
    int face = 2 * ax + (v[ax] < 0 ? 1 : 0);
    double a = v[(ax + 1) % 3] / m, b = v[(ax + 2) % 3] / m;  // in [-1, 1]
    int i = std::clamp(static_cast<int>((a + 1) * 0.5 * kG), 0, kG - 1);
    int j = std::clamp(static_cast<int>((b + 1) * 0.5 * kG), 0, kG - 1);
    return (face * kG + i) * kG + j;
}
}  // namespace

int Polyhedron::start_vertex(const Vec3z& n) const {
    if (start_table.empty()) return vertices.front();
    return start_table[cube_cell({n[0].get_d(), n[1].get_d(), n[2].get_d()})];
}

namespace {
// n·x compared through a double filter: the products and sums of doubles of the integer data err
// by at most a few ulps of Σ|n_k x_k|; 1e-14 of it bounds that with room. Only comparisons the
// filter cannot decide (or non-finite ones) use exact integers.
struct FilteredDot {
    const Polyhedron& P;
    const Vec3z& n;
    D3 nd{n[0].get_d(), n[1].get_d(), n[2].get_d()};
    double approx(int v, double& err) const {
        const D3& x = P.dpts[v];
        double a = nd[0] * x[0], b = nd[1] * x[1], c = nd[2] * x[2];
        err = 1e-14 * (std::fabs(a) + std::fabs(b) + std::fabs(c));
        return a + b + c;
    }
    // sign of n·x_w − n·x_v, exactly
    int compare(int w, double wd, double we, int v, double vd, double ve) const {
        double diff = wd - vd, tol = we + ve;
        if (diff > tol) return ++P.cmp_filtered, 1;
        if (diff < -tol) return ++P.cmp_filtered, -1;
        ++P.cmp_exact;
        return cmp(dotz(n, P.ipts[w]), dotz(n, P.ipts[v]));
    }
};
}  // namespace

int Polyhedron::climb(const Vec3z& n) const {
    FilteredDot f{*this, n};
    int cur = start_vertex(n);
    double ce, cd = f.approx(cur, ce);
    for (bool moved = true; moved;) {
        moved = false;
        for (int w : adj[cur]) {
            double we, wd = f.approx(w, we);
            if (f.compare(w, wd, we, cur, cd, ce) > 0) { cur = w; cd = wd; ce = we; moved = true; break; }
        }
    }
    return cur;
}

std::vector<int> Polyhedron::argmax(const Vec3z& n, Q* value, Z* scaled_value) const {
    FilteredDot f{*this, n};
    const int top = climb(n);
    double ce, cd = f.approx(top, ce);
    // The face of maximisers is connected in the vertex graph.
    std::vector<int> out{top}, stack{top};
    while (!stack.empty()) {
        int v = stack.back();
        stack.pop_back();
        for (int w : adj[v]) {
            if (std::find(out.begin(), out.end(), w) != out.end()) continue;
            double we, wd = f.approx(w, we);
            if (f.compare(w, wd, we, top, cd, ce) == 0) {
                out.push_back(w);
                stack.push_back(w);
            }
        }
    }
    std::sort(out.begin(), out.end());
    if (value || scaled_value) {
        Z best = dotz(n, ipts[top]);  // = max n·x times scale
        if (value) *value = Q(best, scale), value->canonicalize();
        if (scaled_value) *scaled_value = std::move(best);
    }
    return out;
}

Q Polyhedron::support(const Vec3z& n) const {
    Q v;
    argmax(n, &v);
    return v;
}

bool Polyhedron::strictly_inside(const Vec3q& p) const {
    // In the integer frame: p·scale = z/den, so n·p < n·v  iff  n·z < den·(n·ipts[v]).
    Z den = 1;
    for (const Q& c : p) mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), c.get_den_mpz_t());
    Vec3z z;
    for (int k = 0; k < 3; ++k) z[k] = Z(p[k] * scale * den);
    for (const Face& f : faces)
        if (dotz(f.normal, z) >= den * dotz(f.normal, ipts[f.verts[0]])) return false;
    return true;
}

namespace {

// Sorts the vertices of a convex polygon with outward normal n counter-clockwise (seen from
// outside), exactly: angular order around an interior point, in the plane projected along the
// dominant axis of n.
void order_ccw(std::vector<int>& vs, const std::vector<Vec3z>& pts, const Vec3z& n) {
    int drop = 0;
    for (int k = 1; k < 3; ++k)
        if (abs(n[k]) > abs(n[drop])) drop = k;
    int u = (drop + 1) % 3, w = (drop + 2) % 3;
    // Centre (times the vertex count, to stay in integers).
    const Z cnt = static_cast<long>(vs.size());
    Z cu = 0, cw = 0;
    for (int v : vs) { cu += pts[v][u]; cw += pts[v][w]; }
    auto du = [&](int v) { return Z(pts[v][u] * cnt - cu); };
    auto dw = [&](int v) { return Z(pts[v][w] * cnt - cw); };
    // In the (u, w) projection, counter-clockwise around +drop axis means ccw seen from outside
    // when n[drop] > 0; reverse otherwise.
    auto half = [&](int v) { Z a = du(v), b = dw(v); return (sgn(b) > 0 || (sgn(b) == 0 && sgn(a) > 0)) ? 0 : 1; };
    std::sort(vs.begin(), vs.end(), [&](int a, int b) {
        int ha = half(a), hb = half(b);
        if (ha != hb) return ha < hb;
        return sgn(Z(du(a) * dw(b) - dw(a) * du(b))) > 0;
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
    // Integer coordinates: every point times the lcm of all denominators (same planes, same order).
    P.scale = 1;
    for (const Vec3q& v : pts)
        for (const Q& c : v) mpz_lcm(P.scale.get_mpz_t(), P.scale.get_mpz_t(), c.get_den_mpz_t());
    P.ipts.resize(pts.size());
    for (size_t i = 0; i < pts.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            mpz_divexact(P.ipts[i][k].get_mpz_t(), P.scale.get_mpz_t(), pts[i][k].get_den_mpz_t());
            P.ipts[i][k] *= pts[i][k].get_num();
        }
    const std::vector<Vec3z>& ip = P.ipts;
    P.dpts.resize(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) P.dpts[i] = {ip[i][0].get_d(), ip[i][1].get_d(), ip[i][2].get_d()};
    // The hull of the integer-scaled points (a uniform scaling: same faces), which lets CGAL use
    // Epick's exact filtered predicates whenever these integers are exact doubles.
    auto tris = hull_triangles(ip);
    // Group hull triangles by their supporting plane: on a convex polytope one plane, one face.
    std::map<Vec3z, int> plane_of;
    std::vector<std::vector<int>> face_pts;       // hull points of each face (with repeats)
    std::vector<int> face_tris;                   // triangles per face
    std::vector<std::array<int, 3>> first_tri;    // a triangle of each face, outward
    std::vector<std::vector<int>> faces_at(pts.size());  // hull point -> faces through it
    for (const auto& t : tris) {
        Vec3z n = primitive(cross(sub(ip[t[1]], ip[t[0]]), sub(ip[t[2]], ip[t[0]])));
        auto [it, fresh] = plane_of.emplace(n, static_cast<int>(face_pts.size()));
        if (fresh) face_pts.emplace_back(), face_tris.push_back(0), first_tri.push_back(t);
        ++face_tris[it->second];
        for (int v : t) {
            face_pts[it->second].push_back(v);
            auto& fa = faces_at[v];
            if (std::find(fa.begin(), fa.end(), it->second) == fa.end()) fa.push_back(it->second);
        }
    }
    // True vertices lie on at least three faces; points inside a face or an edge are dropped.
    std::vector<char> is_vertex(pts.size(), 0);
    for (size_t v = 0; v < pts.size(); ++v)
        if (faces_at[v].size() >= 3) is_vertex[v] = 1, P.vertices.push_back(static_cast<int>(v));
    P.faces.resize(face_pts.size());
    for (const auto& [n, fi] : plane_of) {
        Face& f = P.faces[fi];
        f.normal = n;
        const auto& t = first_tri[fi];
        if (face_tris[fi] == 1 && is_vertex[t[0]] && is_vertex[t[1]] && is_vertex[t[2]]) {
            // a triangular face: CGAL's triangle is already counter-clockwise from outside
            int r = static_cast<int>(std::min_element(t.begin(), t.end()) - t.begin());
            f.verts = {t[r], t[(r + 1) % 3], t[(r + 2) % 3]};
            continue;
        }
        std::vector<int> vs = face_pts[fi];
        std::sort(vs.begin(), vs.end());
        vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
        for (int v : vs)
            if (is_vertex[v]) f.verts.push_back(v);
        order_ccw(f.verts, ip, n);
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
    // Start table: for each cube-map cell centre, the argmax found by climbing in doubles from the
    // previous cell's answer. Only a hint: argmax always finishes the climb exactly.
    const std::vector<D3>& dp = P.dpts;  // scaled coordinates: the same maximisers
    if (P.vertices.size() <= 64) return P;  // small: climbing from any vertex is already short
    P.start_table.assign(6 * kG * kG, P.vertices.front());
    int cur = P.vertices.front();
    for (int face = 0; face < 6; ++face)
        for (int i = 0; i < kG; ++i)
            for (int j = 0; j < kG; ++j) {
                int ax = face / 2;
                D3 dir{};
                dir[ax] = face % 2 ? -1.0 : 1.0;
                dir[(ax + 1) % 3] = (i + 0.5) / kG * 2 - 1;
                dir[(ax + 2) % 3] = (j + 0.5) / kG * 2 - 1;
                auto f = [&](int v) { return dir[0] * dp[v][0] + dir[1] * dp[v][1] + dir[2] * dp[v][2]; };
                for (int steps = 0, moved = 1; moved && steps < 100000; ++steps) {
                    moved = 0;
                    for (int w : P.adj[cur])
                        if (f(w) > f(cur)) { cur = w; moved = 1; break; }
                }
                P.start_table[(face * kG + i) * kG + j] = cur;
            }
    return P;
}

}  // namespace scalecert
