// The paper's node test (Section 3.2): two scaled polyhedra overlap iff some pair of their
// triangulated faces intersects. A triangle–triangle test in double precision: each triangle
// against the other's plane, then the overlap of the two intervals where the triangles cross
// the line common to both planes; coplanar pairs are tested in 2-D. (Like the paper's method it
// does not see one polyhedron wholly inside the other.)
#include "baselines/baselines.hpp"

#include <algorithm>
#include <cmath>

namespace scalecert::internal::fp {

namespace {
using T3 = std::array<D3, 3>;
D3 sub3(const D3& a, const D3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
D3 cross3(const D3& a, const D3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot3(const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// 2-D: do segments ab and cd meet (touching counts)?
bool segments_meet(const double* a, const double* b, const double* c, const double* d) {
    auto orient = [](const double* p, const double* q, const double* r) {
        double v = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
        return (v > 0) - (v < 0);
    };
    int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    auto on = [](const double* p, const double* q, const double* r) {
        return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= r[1] &&
               r[1] <= std::max(p[1], q[1]);
    };
    if (o1 != o2 && o3 != o4) return true;
    return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) || (o4 == 0 && on(c, d, b));
}

bool inside2(const double t[3][2], const double* p) {
    int s = 0;
    for (int i = 0; i < 3; ++i) {
        const double* a = t[i];
        const double* b = t[(i + 1) % 3];
        double v = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        int sv = (v > 0) - (v < 0);
        if (sv == 0) continue;
        if (s == 0)
            s = sv;
        else if (sv != s)
            return false;
    }
    return true;
}

bool coplanar_overlap(const T3& A, const T3& B, const D3& n) {
    int drop = 0;
    for (int k = 1; k < 3; ++k)
        if (std::fabs(n[k]) > std::fabs(n[drop])) drop = k;
    int u = (drop + 1) % 3, w = (drop + 2) % 3;
    double a[3][2], b[3][2];
    for (int i = 0; i < 3; ++i) a[i][0] = A[i][u], a[i][1] = A[i][w], b[i][0] = B[i][u], b[i][1] = B[i][w];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (segments_meet(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3])) return true;
    return inside2(a, b[0]) || inside2(b, a[0]);
}

// The interval of the line (parametrised by the coordinate `axis`) where triangle T, whose
// vertices have signed distances d to the other plane (not all of one sign), crosses it.
void interval(const T3& T, const double d[3], int axis, double& lo, double& hi) {
    double ts[3];
    int n = 0;
    for (int i = 0; i < 3 && n < 3; ++i) {
        int j = (i + 1) % 3;
        if (d[i] == 0) ts[n++] = T[i][axis];
        if ((d[i] > 0 && d[j] < 0) || (d[i] < 0 && d[j] > 0))
            ts[n++] = T[i][axis] + (T[j][axis] - T[i][axis]) * d[i] / (d[i] - d[j]);
    }
    lo = hi = ts[0];
    for (int k = 1; k < n; ++k) lo = std::min(lo, ts[k]), hi = std::max(hi, ts[k]);
}
}  // namespace

bool triangles_intersect(const T3& A, const T3& B) {
    D3 nB = cross3(sub3(B[1], B[0]), sub3(B[2], B[0]));
    double dA[3];
    for (int i = 0; i < 3; ++i) dA[i] = dot3(nB, sub3(A[i], B[0]));
    if ((dA[0] > 0 && dA[1] > 0 && dA[2] > 0) || (dA[0] < 0 && dA[1] < 0 && dA[2] < 0)) return false;
    D3 nA = cross3(sub3(A[1], A[0]), sub3(A[2], A[0]));
    double dB[3];
    for (int i = 0; i < 3; ++i) dB[i] = dot3(nA, sub3(B[i], A[0]));
    if ((dB[0] > 0 && dB[1] > 0 && dB[2] > 0) || (dB[0] < 0 && dB[1] < 0 && dB[2] < 0)) return false;
    if (dA[0] == 0 && dA[1] == 0 && dA[2] == 0) return coplanar_overlap(A, B, nA);
    D3 L = cross3(nA, nB);
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (std::fabs(L[k]) > std::fabs(L[axis])) axis = k;
    double a0, a1, b0, b1;
    interval(A, dA, axis, a0, a1);
    interval(B, dB, axis, b0, b1);
    return a0 <= b1 && b0 <= a1;
}

namespace {
class PaperTriTri : public Method {
  public:
    PaperTriTri(const Model& m, const FpScene& s) : s_(s) {
        for (int i = 0; i < 2; ++i)
            for (const Face& f : m.P[i].faces)
                for (size_t k = 1; k + 1 < f.verts.size(); ++k)
                    tris_[i].push_back({f.verts[0], f.verts[k], f.verts[k + 1]});
    }
    std::string name() const override { return "paper-tritri"; }
    int classify(double r1, double r2) const override {
        std::vector<T3> A, B;
        auto scaled = [&](int i, int v, double r) {
            const D3& p = s_.P[i].pts[v];
            const D3& c = s_.P[i].seed;
            return D3{c[0] + r * (p[0] - c[0]), c[1] + r * (p[1] - c[1]), c[2] + r * (p[2] - c[2])};
        };
        for (const auto& t : tris_[0]) A.push_back({scaled(0, t[0], r1), scaled(0, t[1], r1), scaled(0, t[2], r1)});
        for (const auto& t : tris_[1]) B.push_back({scaled(1, t[0], r2), scaled(1, t[1], r2), scaled(1, t[2], r2)});
        for (const T3& a : A)
            for (const T3& b : B)
                if (triangles_intersect(a, b)) return -1;
        return 1;
    }

  private:
    FpScene s_;
    std::vector<std::array<int, 3>> tris_[2];
};
}  // namespace

std::unique_ptr<Method> make_paper_tritri(const Model& m, const FpScene& s) {
    return std::make_unique<PaperTriTri>(m, s);
}

}  // namespace scalecert::internal::fp
