// The only translation unit that includes Eigen.
#include "geometry/ellipsoid.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace scalecert::internal {

namespace {
using M3 = Eigen::Matrix3d;
using V3 = Eigen::Vector3d;

struct Halfspaces {
    std::vector<V3> a;  // unit normals
    std::vector<double> b;
};

// P_i(lo) = {x : n·x ≤ n·s + lo·n·(a_f − s)} for its faces, normals scaled to unit length.
Halfspaces halfspaces(const Polyhedron& P, const Vec3q& s, const Q& lo) {
    Halfspaces h;
    for (const Face& f : P.faces) {
        Vec3q n = to_q(f.normal);
        Q off = dot(n, s) + lo * dot(n, sub(P.points[f.verts[0]], s));
        V3 a(n[0].get_d(), n[1].get_d(), n[2].get_d());
        double len = a.norm();
        h.a.push_back(a / len);
        h.b.push_back(off.get_d() / len);
    }
    return h;
}

// Slacks b_j − a_j·c − |B a_j|; false if any is not positive or B is not positive definite.
bool slacks(const Halfspaces& h, const M3& B, const V3& c, std::vector<double>& s) {
    Eigen::LLT<M3> llt(B);
    if (llt.info() != Eigen::Success) return false;
    s.resize(h.a.size());
    for (size_t j = 0; j < h.a.size(); ++j) {
        s[j] = h.b[j] - h.a[j].dot(c) - (B * h.a[j]).norm();
        if (!(s[j] > 0)) return false;
    }
    return true;
}

double barrier(const Halfspaces& h, const M3& B, const V3& c, double mu, bool& ok) {
    std::vector<double> s;
    ok = slacks(h, B, c, s);
    if (!ok) return -INFINITY;
    double f = std::log(B.determinant());
    for (double v : s) f += mu * std::log(v);
    return f;
}

// None when floating point cannot even start (the seed not inside in doubles, or overflow).
std::optional<InnerEllipsoid> mvie(const Halfspaces& h, const V3& start) {
    V3 c = start;
    double r = INFINITY;
    for (size_t j = 0; j < h.a.size(); ++j) r = std::min(r, h.b[j] - h.a[j].dot(c));
    if (!(r > 0) || !std::isfinite(r) || !c.allFinite()) return std::nullopt;
    M3 B = 0.5 * r * M3::Identity();
    std::vector<double> s0;
    if (!slacks(h, B, c, s0)) return std::nullopt;
    for (double mu : {1.0, 0.1, 0.01, 1e-3, 1e-4}) {
        for (int it = 0; it < 400; ++it) {
            std::vector<double> s;
            if (!slacks(h, B, c, s)) break;  // the line search keeps (B, c) feasible; never expected
            M3 gB = B.inverse();
            V3 gc = V3::Zero();
            for (size_t j = 0; j < h.a.size(); ++j) {
                V3 u = B * h.a[j];
                double un = u.norm();
                M3 d = (u * h.a[j].transpose() + h.a[j] * u.transpose()) / (2 * un);
                gB -= mu / s[j] * d;
                gc -= mu / s[j] * h.a[j];
            }
            bool ok;
            double f0 = barrier(h, B, c, mu, ok), t = 1.0;
            double g2 = gB.squaredNorm() + gc.squaredNorm();
            if (g2 < 1e-20) break;
            // backtracking: stay feasible, increase enough
            for (; t > 1e-12; t *= 0.5) {
                double f1 = barrier(h, B + t * gB, c + t * gc, mu, ok);
                if (ok && f1 >= f0 + 1e-4 * t * g2) break;
            }
            if (t <= 1e-12) break;
            B += t * gB;
            c += t * gc;
            if (t * std::sqrt(g2) < 1e-12) break;
        }
    }
    InnerEllipsoid e;
    for (int i = 0; i < 3; ++i) {
        e.center[i] = c[i];
        for (int k = 0; k < 3; ++k) e.matrix[i][k] = B(i, k);
    }
    return e;
}
}  // namespace

std::optional<EllipsoidPath> ellipsoid_path(const Bodies& m) {
    EllipsoidPath p;
    M3 B[2];
    V3 c[2];
    for (int i = 0; i < 2; ++i) {
        Halfspaces h = halfspaces(m.P[i], m.s[i], m.scene.lo[i]);
        auto e = mvie(h, V3(m.s[i][0].get_d(), m.s[i][1].get_d(), m.s[i][2].get_d()));
        if (!e) return std::nullopt;
        p.E[i] = *e;
        for (int r = 0; r < 3; ++r) {
            c[i][r] = p.E[i].center[r];
            for (int k = 0; k < 3; ++k) B[i](r, k) = p.E[i].matrix[r][k];
        }
    }
    // min |B1 u + c1 − B2 v − c2| over the unit balls: projected gradient.
    V3 u = (c[1] - c[0]).normalized(), v = -u;
    if (!u.allFinite()) u = V3::UnitX(), v = -u;
    auto ball = [](V3& x) {
        double n = x.norm();
        if (n > 1) x /= n;
    };
    ball(u);
    ball(v);
    double L = 2 * (B[0].squaredNorm() + B[1].squaredNorm()) + 1e-300;
    for (int it = 0; it < 20000; ++it) {
        V3 r = B[0] * u + c[0] - B[1] * v - c[1];
        V3 u2 = u - (2 / L) * (B[0].transpose() * r), v2 = v + (2 / L) * (B[1].transpose() * r);
        ball(u2);
        ball(v2);
        double step = (u2 - u).norm() + (v2 - v).norm();
        u = u2;
        v = v2;
        if (step < 1e-15) break;
    }
    V3 x1 = B[0] * u + c[0], x2 = B[1] * v + c[1];
    p.distance = (x1 - x2).norm();
    if (p.distance < 1e-9 * (1 + c[0].norm() + c[1].norm())) {  // the ellipsoids meet
        x1 = c[0];
        x2 = c[1];
    } else {  // pull the ends into the ellipsoids, off any face they touch
        x1 = c[0] + 0.999 * (x1 - c[0]);
        x2 = c[1] + 0.999 * (x2 - c[1]);
    }
    if (!x1.allFinite() || !x2.allFinite()) return std::nullopt;
    for (int k = 0; k < 3; ++k) {
        p.v1[k] = exact_from_double(x1[k]);
        p.v2[k] = exact_from_double(x2[k]);
    }
    return p;
}

}  // namespace scalecert::internal
