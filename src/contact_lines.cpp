#include "scalecert/contact_lines.hpp"

#include "scalecert/gauss_map.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace scalecert {

char feature_letter(size_t n) { return n == 1 ? 'V' : n == 2 ? 'E' : 'F'; }

ContactLine line_for_normal(const Model& m, const Vec3z& n) {
    ContactLine L;
    L.normal = n;
    const Vec3q nq = to_q(n);
    Q sup1, sup2;
    L.feat1 = m.P[0].argmax(n, &sup1);
    L.feat2 = m.P[1].argmax(neg(n), &sup2);
    L.h1 = sup1 - dot(nq, m.s[0]);
    L.h2 = sup2 + dot(nq, m.s[1]);
    L.nd = dot(nq, m.d);
    L.slope = -L.h1 / L.h2;
    L.intercept = L.nd / L.h2;
    L.contact = {feature_letter(L.feat1.size()), feature_letter(L.feat2.size())};
    return L;
}

namespace {

// x strictly inside the great-circle arc from a0 to a1 (|arc| < π), given p = a0 × a1 and x·p = 0.
bool in_open_arc(const Vec3z& x, const Vec3z& a0, const Vec3z& a1, const Vec3z& p) {
    return sgn(dotz(cross(a0, x), p)) > 0 && sgn(dotz(cross(x, a1), p)) > 0;
}

}  // namespace

namespace {
// SCALECERT_TIMING=1 prints the time of each stage on stderr (never in the output).
struct StageClock {
    bool on = std::getenv("SCALECERT_TIMING") != nullptr;
    std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
    void lap(const char* what) {
        if (!on) return;
        auto now = std::chrono::steady_clock::now();
        std::fprintf(stderr, "scalecert: timing: %-22s %9.3f ms\n", what, std::chrono::duration<double, std::milli>(now - t).count());
        t = now;
    }
};
}  // namespace

Model build_model(const Scene& scene) {
    StageClock clock;
    Model m;
    m.scene = scene;
    const char* names[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        m.P[i] = build_polyhedron(scene.P[i].points, names[i]);
        m.s[i] = scene.P[i].seed;
        if (!m.P[i].strictly_inside(m.s[i]))
            throw InputError(std::string(names[i]) + ".seed: not strictly inside the polyhedron" +
                             (scene.P[i].seed_given ? "" : " (the default seed is the mean of the vertices)"));
    }
    m.d = sub(m.s[1], m.s[0]);
    clock.lap("hulls");

    std::map<Vec3z, int> normals;  // normal -> origin (for statistics only)
    for (const Face& f : m.P[0].faces) normals.emplace(f.normal, 0), ++m.stats.face_normals;
    for (const Face& f : m.P[1].faces) normals.emplace(neg(f.normal), 1), ++m.stats.face_normals;
    // Edge pairs: e1 of P1 has the Gauss arc from n(f0) to n(f1); e2 of P2, in −Q2, the arc from
    // −n(g0) to −n(g1). A proper crossing of the two arcs is a facet normal of the Minkowski sum.
    // Arcs that only touch give a face normal already listed; parallel edges give none.
    const Polyhedron& A = m.P[0];
    const Polyhedron& B = m.P[1];
    std::vector<Vec3z> pa(A.edges.size()), pb(B.edges.size());
    std::vector<Arc> arcs_a(A.edges.size()), arcs_b(B.edges.size());
    for (size_t i = 0; i < A.edges.size(); ++i) {
        arcs_a[i] = {A.faces[A.edges[i].f0].normal, A.faces[A.edges[i].f1].normal};
        pa[i] = cross(arcs_a[i].from, arcs_a[i].to);
    }
    for (size_t j = 0; j < B.edges.size(); ++j) {
        arcs_b[j] = {neg(B.faces[B.edges[j].f0].normal), neg(B.faces[B.edges[j].f1].normal)};
        pb[j] = cross(arcs_b[j].from, arcs_b[j].to);
    }
    for (const auto& [i, j] : arc_candidates(arcs_a, arcs_b)) {
        ++m.stats.edge_pairs_tested;
        Vec3z x = cross(pa[i], pb[j]);
        if (is_zero(x)) continue;
        for (int sign = 0; sign < 2; ++sign, x = neg(x)) {
            if (in_open_arc(x, arcs_a[i].from, arcs_a[i].to, pa[i]) && in_open_arc(x, arcs_b[j].from, arcs_b[j].to, pb[j])) {
                normals.emplace(primitive(x), 2);
                ++m.stats.arc_crossings;
                break;
            }
        }
    }
    clock.lap("gauss map overlay");
    m.stats.distinct_normals = normals.size();
    m.lines.reserve(normals.size());
    for (const auto& [n, origin] : normals) m.lines.push_back(line_for_normal(m, n));
    clock.lap("contact lines");
    return m;
}

}  // namespace scalecert
