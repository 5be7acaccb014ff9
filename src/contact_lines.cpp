#include "scalecert/contact_lines.hpp"

#include "scalecert/gauss_map.hpp"
#include "scalecert/timing.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <map>

namespace scalecert {

char feature_letter(size_t n) { return n == 1 ? 'V' : n == 2 ? 'E' : 'F'; }

namespace {
// In integers: with S1 = max n·x over P1's scaled points and S2 = max −n·x over P2's (x·scale_i),
//   h1 = H1 / (scale_1·sden_1),  h2 = H2 / (scale_2·sden_2),  n·d = ND / dden.
struct Numerators { Z H1, H2, ND; };
Numerators numerators(const Model& m, const Vec3z& n, const Z& S1, const Z& S2) {
    return {S1 * m.sden[0] - dotz(n, m.sz[0]), S2 * m.sden[1] + dotz(n, m.sz[1]), dotz(n, m.dz)};
}
}  // namespace

ContactLine line_for_normal(const Model& m, const Vec3z& n) {
    ContactLine L;
    L.normal = n;
    Z sup1, sup2;
    L.feat1 = m.P[0].argmax(n, nullptr, &sup1);
    L.feat2 = m.P[1].argmax(neg(n), nullptr, &sup2);
    const auto [H1, H2, ND] = numerators(m, n, sup1, sup2);
    const Z D1 = m.P[0].scale * m.sden[0], D2 = m.P[1].scale * m.sden[1];
    auto frac = [](const Z& p, const Z& q) { Q r(p, q); r.canonicalize(); return r; };
    L.h1 = frac(H1, D1);
    L.h2 = frac(H2, D2);
    L.nd = frac(ND, m.dden);
    L.slope = frac(-H1 * D2, H2 * D1);
    L.intercept = frac(ND * D2, m.dden * H2);
    L.contact = {feature_letter(L.feat1.size()), feature_letter(L.feat2.size())};
    return L;
}

namespace {

}  // namespace

std::vector<size_t> undominated(const std::vector<double>& a, const std::vector<double>& b) {
    const size_t n = a.size();
    std::vector<size_t> by_slope(n);
    std::iota(by_slope.begin(), by_slope.end(), size_t{0});
    std::sort(by_slope.begin(), by_slope.end(), [&](size_t i, size_t j) { return a[i] > a[j]; });
    constexpr double kRel = 1e-12;
    auto lower = [&](size_t i) { return a[i] - kRel * std::fabs(a[i]); };  // below the true slope
    auto upper = [&](size_t i) { return a[i] + kRel * std::fabs(a[i]); };  // above it
    std::vector<size_t> keep;
    double bmax = -INFINITY, bmax_err = 0;
    size_t j = 0;  // lines by_slope[0..j) have a slope certainly larger than the current line's
    for (size_t k = 0; k < n; ++k) {
        size_t i = by_slope[k];
        while (j < k && lower(by_slope[j]) > upper(i)) {
            size_t m = by_slope[j++];
            if (b[m] - kRel * std::fabs(b[m]) > bmax - bmax_err) bmax = b[m], bmax_err = kRel * std::fabs(b[m]);
        }
        if (bmax - bmax_err > b[i] + kRel * std::fabs(b[i])) continue;  // certainly dominated
        keep.push_back(i);
    }
    std::sort(keep.begin(), keep.end());
    return keep;
}


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
    auto integral = [](const Vec3q& v, Vec3z& z, Z& den) {  // v = z / den
        den = 1;
        for (const Q& c : v) mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), c.get_den_mpz_t());
        for (int k = 0; k < 3; ++k) z[k] = Z(v[k] * den);
    };
    for (int i = 0; i < 2; ++i) {
        Vec3q ss{m.s[i][0] * m.P[i].scale, m.s[i][1] * m.P[i].scale, m.s[i][2] * m.P[i].scale};
        integral(ss, m.sz[i], m.sden[i]);
    }
    integral(m.d, m.dz, m.dden);
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
    // Doubles of the arc data for a filter: a sign is taken from doubles only when it exceeds a
    // bound far above their rounding error; otherwise it is computed exactly.
    using D3 = std::array<double, 3>;
    auto dbl = [](const Vec3z& v) { return D3{v[0].get_d(), v[1].get_d(), v[2].get_d()}; };
    auto crossd = [](const D3& a, const D3& b) { return D3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; };
    auto norm = [](const D3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); };
    auto dotd = [](const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    std::vector<std::array<D3, 3>> da(A.edges.size()), db(B.edges.size());  // from, to, plane normal
    for (size_t i = 0; i < A.edges.size(); ++i) da[i] = {dbl(arcs_a[i].from), dbl(arcs_a[i].to), dbl(pa[i])};
    for (size_t j = 0; j < B.edges.size(); ++j) db[j] = {dbl(arcs_b[j].from), dbl(arcs_b[j].to), dbl(pb[j])};
    // Sign of (u × x)·p (or (x × u)·p): filtered, exact when unsure; x = ±(pa × pb), computed
    // exactly only when some sign or the accepted normal needs it.
    for (const auto& [i, j] : arc_candidates(arcs_a, arcs_b)) {
        ++m.stats.edge_pairs_tested;
        const auto& A3 = da[i];
        const auto& B3 = db[j];
        std::optional<Vec3z> xe;
        auto exact_x = [&]() -> const Vec3z& {
            if (!xe) xe = cross(pa[i], pb[j]);
            return *xe;
        };
        D3 xd = crossd(A3[2], B3[2]);
        double xb = 1e-10 * norm(A3[2]) * norm(B3[2]);
        if (!(std::fabs(xd[0]) > xb || std::fabs(xd[1]) > xb || std::fabs(xd[2]) > xb)) {
            if (is_zero(exact_x())) continue;  // parallel edges: no facet of the sum
            xd = dbl(exact_x());
        }
        for (int sign : {1, -1}) {
            D3 xs{sign * xd[0], sign * xd[1], sign * xd[2]};
            auto side = [&](const D3& ud, const D3& pd, bool x_first, const Vec3z& u, const Vec3z& p) {
                D3 c = x_first ? crossd(xs, ud) : crossd(ud, xs);
                double v = dotd(c, pd), bound = 1e-10 * norm(ud) * norm(xs) * norm(pd);
                if (v > bound) return ++m.stats.arc_signs_filtered, 1;
                if (v < -bound) return ++m.stats.arc_signs_filtered, -1;
                ++m.stats.arc_signs_exact;
                Vec3z x = sign > 0 ? exact_x() : neg(exact_x());
                return sgn(dotz(x_first ? cross(x, u) : cross(u, x), p));
            };
            if (side(A3[0], A3[2], false, arcs_a[i].from, pa[i]) > 0 && side(A3[1], A3[2], true, arcs_a[i].to, pa[i]) > 0 &&
                side(B3[0], B3[2], false, arcs_b[j].from, pb[j]) > 0 && side(B3[1], B3[2], true, arcs_b[j].to, pb[j]) > 0) {
                normals.emplace(primitive(sign > 0 ? exact_x() : neg(exact_x())), 2);
                ++m.stats.arc_crossings;
                break;
            }
        }
    }
    clock.lap("gauss map overlay");
    m.stats.distinct_normals = normals.size();
    // Approximate lines from the exact maximisers (the filtered climb decides exactly): slope and
    // intercept as doubles of exact integers, within 10^-15 relative. Certainly dominated lines
    // are dropped; the rest are built exactly, with their contact features.
    std::vector<const Vec3z*> ns;
    std::vector<double> sa, sb;
    const double D1 = Z(m.P[0].scale * m.sden[0]).get_d(), D2 = Z(m.P[1].scale * m.sden[1]).get_d(), DD = m.dden.get_d();
    for (const auto& [n, origin] : normals) {
        const Vec3z mn = neg(n);
        const Numerators u = numerators(m, n, dotz(n, m.P[0].ipts[m.P[0].climb(n)]), dotz(mn, m.P[1].ipts[m.P[1].climb(mn)]));
        const double H1 = u.H1.get_d(), H2 = u.H2.get_d(), ND = u.ND.get_d();
        ns.push_back(&n);
        sa.push_back(-(H1 * D2) / (H2 * D1));
        sb.push_back((ND * D2) / (DD * H2));
    }
    std::vector<size_t> keep = undominated(sa, sb);
    m.stats.dominated_lines = normals.size() - keep.size();
    m.lines.reserve(keep.size());
    for (size_t i : keep) m.lines.push_back(line_for_normal(m, *ns[i]));
    clock.lap("contact lines");
    return m;
}

}  // namespace scalecert
