#include "curve/contact_lines.hpp"

#include "numeric/predicates.hpp"

#include "numeric/double3.hpp"
#include "geometry/gauss_map.hpp"
#include "numeric/small_int.hpp"
#include "numeric/timing.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <type_traits>

namespace scalecert::internal {

char feature_letter(size_t n) { return n == 1 ? 'V' : n == 2 ? 'E' : 'F'; }

namespace {
// In integers: with S1 = max n·x over P1's scaled points and S2 = max −n·x over P2's (x·scale_i),
//   h1 = H1 / (scale_1·sden_1),  h2 = H2 / (scale_2·sden_2),  n·d = ND / dden.
struct Numerators {
    Z H1, H2, ND;
};
Numerators numerators(const Model& m, const Vec3z& n, const Z& S1, const Z& S2) {
    return {S1 * m.sden[0] - dotz(n, m.sz[0]), S2 * m.sden[1] + dotz(n, m.sz[1]), dotz(n, m.dz)};
}
}  // namespace

ContactLine make_line(const Model& m, const Vec3z& n, std::vector<int> feat1, std::vector<int> feat2, const Z& sup1,
                      const Z& sup2) {
    ContactLine L;
    L.normal = n;
    L.feat1 = std::move(feat1);
    L.feat2 = std::move(feat2);
    const auto [H1, H2, ND] = numerators(m, n, sup1, sup2);
    const Z D1 = m.P[0].scale * m.sden[0], D2 = m.P[1].scale * m.sden[1];
    auto frac = [](const Z& p, const Z& q) {
        Q r(p, q);
        r.canonicalize();
        return r;
    };
    L.h1 = frac(H1, D1);
    L.h2 = frac(H2, D2);
    L.nd = frac(ND, m.dden);
    L.slope = frac(-H1 * D2, H2 * D1);
    L.intercept = frac(ND * D2, m.dden * H2);
    L.contact = {feature_letter(L.feat1.size()), feature_letter(L.feat2.size())};
    return L;
}

ContactLine line_for_normal(const HullModel& m, const Vec3z& n) {
    Z sup1, sup2;
    std::vector<int> f1 = m.P[0].argmax(n, nullptr, &sup1);
    std::vector<int> f2 = m.P[1].argmax(neg(n), nullptr, &sup2);
    return make_line(m, n, std::move(f1), std::move(f2), sup1, sup2);
}

std::vector<size_t> undominated(const std::vector<double>& a, const std::vector<double>& b) {
    // A line whose approximations are not finite is kept, and takes no part in the sweep: it is
    // neither dropped nor used to drop another.
    std::vector<size_t> keep, by_slope;
    for (size_t i = 0; i < a.size(); ++i) (std::isfinite(a[i]) && std::isfinite(b[i]) ? by_slope : keep).push_back(i);
    std::sort(by_slope.begin(), by_slope.end(), [&](size_t i, size_t j) { return a[i] > a[j]; });
    // Predicate 3 (predicates.hpp): margins of kDominatedRel below and above each value.
    using filter::dominated_lower, filter::dominated_upper;
    double bmax_lower = -INFINITY;  // the largest certain lower bound of those lines' intercepts
    size_t j = 0;                   // lines by_slope[0..j) have a slope certainly larger than the current line's
    for (size_t k = 0; k < by_slope.size(); ++k) {
        size_t i = by_slope[k];
        while (j < k && dominated_lower(a[by_slope[j]]) > dominated_upper(a[i])) {
            size_t m = by_slope[j++];
            bmax_lower = std::max(bmax_lower, dominated_lower(b[m]));
        }
        if (bmax_lower > dominated_upper(b[i])) continue;  // certainly dominated
        keep.push_back(i);
    }
    std::sort(keep.begin(), keep.end());
    return keep;
}

namespace {

// x·y / (z·w) for integers, within a few ulps: each factor as mantissa · 2^exponent, so nothing
// overflows on the way. NaN when z·w = 0 or the result is outside [2^-1000, 2^1000].
double ratio(const Z& x, const Z& y, const Z& z, const Z& w) {
    long ex, ey, ez, ew;
    const double mx = mpz_get_d_2exp(&ex, x.get_mpz_t()), my = mpz_get_d_2exp(&ey, y.get_mpz_t());
    const double mz = mpz_get_d_2exp(&ez, z.get_mpz_t()), mw = mpz_get_d_2exp(&ew, w.get_mpz_t());
    if (mz == 0 || mw == 0) return NAN;
    const double mant = mx * my / (mz * mw);
    if (mant == 0) return 0.0;  // x or y is 0: exactly 0
    const long e = ex + ey - ez - ew;
    if (e > 1000 || e < -1000) return NAN;
    return std::ldexp(mant, static_cast<int>(e));
}

D3 dir_d(const Vec3z& v) { return direction_d(v); }
D3 dir_d(const Vec3s& v) { return {static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])}; }
const Vec3z& face_normal(const Polyhedron& P, int f, const Vec3z*) { return P.faces[f].normal; }
const Vec3s& face_normal(const Polyhedron& P, int f, const Vec3s*) { return P.faces[f].normal_s; }
const std::vector<Vec3z>& points(const Polyhedron& P, const Vec3z*) { return P.ipts; }
const std::vector<Vec3s>& points(const Polyhedron& P, const Vec3s*) { return P.ipts_s; }
// Sign of component k of a × b.
int cross_sign(const Vec3s& a, const Vec3s& b, int k) { return sgn128(cross_k(a, b, k)); }
int cross_sign(const Vec3z& a, const Vec3z& b, int k) {
    int i = (k + 1) % 3, j = (k + 2) % 3;
    return sgn(Z(a[i] * b[j] - a[j] * b[i]));
}

// The Gauss arc of an edge: from the normal of one face to the other's, and the edge direction
// oriented so that from × to is a positive multiple of it (the normal of the arc's plane; the
// edge is perpendicular to both faces' normals, and far smaller than their cross product).
template <class V>
struct EdgeArc {
    V from, to, p;
    D3 fd, td, pd;
};

template <class V>
std::vector<EdgeArc<V>> edge_arcs(const Polyhedron& P, bool negate) {
    const V* tag = nullptr;
    const auto& ip = points(P, tag);
    std::vector<EdgeArc<V>> out(P.edges.size());
    for (size_t i = 0; i < P.edges.size(); ++i) {
        const Edge& e = P.edges[i];
        EdgeArc<V>& a = out[i];
        a.from = face_normal(P, e.f0, tag);
        a.to = face_normal(P, e.f1, tag);
        if (negate) a.from = vneg(a.from), a.to = vneg(a.to);
        a.p = vsub(ip[e.b], ip[e.a]);
        a.pd = dir_d(a.p);
        int k = 0;  // the largest component of the edge: nonzero, and so is from × to's
        for (int c = 1; c < 3; ++c)
            if (std::fabs(a.pd[c]) > std::fabs(a.pd[k])) k = c;
        if (cross_sign(a.from, a.to, k) * sign_of(a.p[k]) < 0) a.p = vneg(a.p), a.pd = negd(a.pd);
        a.fd = dir_d(a.from), a.td = dir_d(a.to);
    }
    return out;
}

// Every facet normal of Q1 ⊕ (−Q2), primitive and sorted: faces of P1, negated faces of P2, and
// the proper crossings of an edge's Gauss arc of P1 with one of −P2 (arcs that only touch give a
// face normal already listed; parallel edges give none).
template <class V>
std::vector<V> facet_normals(const Polyhedron& P1, const Polyhedron& P2, LineStats& st) {
    const V* tag = nullptr;
    std::vector<V> normals;
    for (size_t f = 0; f < P1.faces.size(); ++f) normals.push_back(face_normal(P1, static_cast<int>(f), tag));
    for (size_t f = 0; f < P2.faces.size(); ++f) normals.push_back(vneg(face_normal(P2, static_cast<int>(f), tag)));
    st.face_normals = normals.size();
    const auto A = edge_arcs<V>(P1, false), B = edge_arcs<V>(P2, true);
    std::vector<Arc> arcs_a(A.size()), arcs_b(B.size());
    for (size_t i = 0; i < A.size(); ++i) arcs_a[i] = {A[i].fd, A[i].td};
    for (size_t j = 0; j < B.size(); ++j) arcs_b[j] = {B[j].fd, B[j].td};
    for (const auto& [i, j] : arc_candidates(arcs_a, arcs_b)) {
        ++st.edge_pairs_tested;
        const EdgeArc<V>& a = A[i];
        const EdgeArc<V>& b = B[j];
        // x = ±(p_a × p_b), the direction where the two great circles meet. Exactly for machine
        // integers (cheap); for GMP only when a filter cannot decide.
        std::optional<V> xe;
        auto exact_x = [&]() -> const V& {
            if (!xe) xe = vcross(a.p, b.p);
            return *xe;
        };
        D3 xd;
        if constexpr (std::is_same_v<V, Vec3s>) {
            if (is_zero(exact_x())) continue;  // parallel edges: no facet of the sum
            xd = dir_d(exact_x());
        } else {
            xd = crossd(a.pd, b.pd);
            if (!(normd(xd) > filter::kArcDirectionMin * normd(a.pd) * normd(b.pd))) {  // predicates.hpp, bound 2
                if (is_zero(exact_x())) continue;
                xd = dir_d(exact_x());
            }
        }
        // Sign of (u × x)·p (or (x × u)·p): predicate 2, filtered, exact when unsure.
        for (int sign : {1, -1}) {
            const D3 xs{sign * xd[0], sign * xd[1], sign * xd[2]};
            auto signed_x = [&] { return sign > 0 ? exact_x() : vneg(exact_x()); };
            auto side = [&](const D3& ud, const D3& pd, bool x_first, const V& u, const V& p) {
                return filter::arc_side(ud, xs, pd, x_first, u, signed_x, p, st.predicates);
            };
            if (side(a.fd, a.pd, false, a.from, a.p) > 0 && side(a.td, a.pd, true, a.to, a.p) > 0 &&
                side(b.fd, b.pd, false, b.from, b.p) > 0 && side(b.td, b.pd, true, b.to, b.p) > 0) {
                normals.push_back(primitive(sign > 0 ? exact_x() : vneg(exact_x())));
                ++st.arc_crossings;
                break;
            }
        }
    }
    std::sort(normals.begin(), normals.end());
    normals.erase(std::unique(normals.begin(), normals.end()), normals.end());
    st.distinct_normals = normals.size();
    return normals;
}

// The approximate line of each normal from its exact maximisers (the filtered climb decides
// exactly): slope and intercept as doubles of exact integers, within 10^-15 relative. Lines
// certainly dominated are dropped; the rest are built exactly, with their contact features.
template <class V>
void add_lines(HullModel& m, const std::vector<V>& normals) {
    const Z Dz1 = m.P[0].scale * m.sden[0], Dz2 = m.P[1].scale * m.sden[1];
    const double D1 = Dz1.get_d(), D2 = Dz2.get_d(), DD = m.dden.get_d();
    // The seeds' integers in 128 bits, when they fit: numerators then need no GMP unless a
    // product overflows (checked).
    I128 sden0 = 0, sden1 = 0, sz0[3], sz1[3], dz[3];
    bool seeds128 = to_i128(m.sden[0], sden0) && to_i128(m.sden[1], sden1);
    for (int k = 0; k < 3 && seeds128; ++k)
        seeds128 = to_i128(m.sz[0][k], sz0[k]) && to_i128(m.sz[1][k], sz1[k]) && to_i128(m.dz[k], dz[k]);
    // Normals visited in the order of a space-filling curve over the cube map of directions, so
    // consecutive support climbs touch the same vertices (the results do not depend on it).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> order(normals.size());
    for (size_t i = 0; i < normals.size(); ++i) {
        const D3 d = dir_d(normals[i]);
        int ax = 0;
        for (int k = 1; k < 3; ++k)
            if (std::fabs(d[k]) > std::fabs(d[ax])) ax = k;
        const double mx = std::fabs(d[ax]);
        auto q = [&](double x) { return static_cast<std::uint32_t>(std::clamp((x / mx + 1) * 128.0, 0.0, 255.0)); };
        std::uint32_t u = q(d[(ax + 1) % 3]), v = q(d[(ax + 2) % 3]), key = 0;
        for (int b = 0; b < 8; ++b) key |= ((u >> b) & 1u) << (2 * b) | ((v >> b) & 1u) << (2 * b + 1);
        order[i] = {static_cast<std::uint32_t>(2 * ax + (d[ax] < 0)) << 16 | key, static_cast<std::uint32_t>(i)};
    }
    std::sort(order.begin(), order.end());
    std::vector<double> sa(normals.size()), sb(normals.size());
    for (const auto& [key, idx] : order) {
        const V& n = normals[idx];
        const V mn = vneg(n);
        double H1 = 0, H2 = 0, ND = 0;
        bool done = false;
        if constexpr (std::is_same_v<V, Vec3s>) {
            if (seeds128) {
                // H1 = S1·sden1 − n·sz1, H2 = S2·sden2 + n·sz2, ND = n·dz, overflow-checked.
                const I128 S1 = dot_s(n, m.P[0].ipts_s[m.P[0].climb(n)]),
                           S2 = dot_s(mn, m.P[1].ipts_s[m.P[1].climb(mn)]);
                filter::Acc128 h1, h2, nd;
                h1.add(S1, sden0);
                h2.add(S2, sden1);
                for (int k = 0; k < 3; ++k) h1.sub(n[k], sz0[k]), h2.add(n[k], sz1[k]), nd.add(n[k], dz[k]);
                if (h1.ok() && h2.ok() && nd.ok())
                    H1 = static_cast<double>(h1.value()), H2 = static_cast<double>(h2.value()),
                    ND = static_cast<double>(nd.value()), done = true;
            }
        }
        if (done) {
            sa[idx] = -(H1 * D2) / (H2 * D1);
            sb[idx] = (ND * D2) / (DD * H2);
        } else {
            // Integers of any size: the products would overflow doubles (and an intercept of 0
            // from inf in a denominator once dropped a line of the curve), so the ratios are
            // formed from mantissas and exponents, NaN outside the double range.
            const Vec3z nz = as_z(n), mz = neg(nz);
            const Numerators u =
                numerators(m, nz, dotz(nz, m.P[0].ipts[m.P[0].climb(nz)]), dotz(mz, m.P[1].ipts[m.P[1].climb(mz)]));
            sa[idx] = -ratio(u.H1, Dz2, u.H2, Dz1);
            sb[idx] = ratio(u.ND, Dz2, m.dden, u.H2);
        }
    }
    std::vector<size_t> keep = undominated(sa, sb);
    m.stats.dominated_lines = normals.size() - keep.size();
    m.stats.predicates.filtered(filter::Predicate::DominatedLine, m.stats.dominated_lines);
    m.stats.predicates.exact(filter::Predicate::DominatedLine, keep.size());
    m.lines.reserve(keep.size());
    for (size_t i : keep) m.lines.push_back(line_for_normal(m, as_z(normals[i])));
}

}  // namespace

std::vector<Vec3z> all_facet_normals(const Polyhedron& P1, const Polyhedron& P2) {
    LineStats scratch;
    if (P1.small() && P2.small()) {
        std::vector<Vec3z> out;
        for (const Vec3s& n : facet_normals<Vec3s>(P1, P2, scratch)) out.push_back(to_z(n));
        return out;
    }
    return facet_normals<Vec3z>(P1, P2, scratch);
}

std::vector<Vec3z> all_facet_normals(const HullModel& m) { return all_facet_normals(m.P[0], m.P[1]); }

Model build_hulls(const ExactScene& scene) {
    check_scene(scene, "scene");  // a scene built in code gets the reader's checks too
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
    set_seeds_in_integers(m);
    return m;
}

HullModel build_model(Model&& hulls) {
    StageClock clock;
    HullModel m;
    static_cast<Model&>(m) = std::move(hulls);
    m.lines.clear();
    // Machine integers when both polyhedra are small (exact within small_int.hpp's bounds), GMP
    // otherwise: the same normals, lines and statistics either way.
    if (m.P[0].small() && m.P[1].small()) {
        auto ns = facet_normals<Vec3s>(m.P[0], m.P[1], m.stats);
        clock.lap("gauss map overlay");
        add_lines(m, ns);
    } else {
        auto ns = facet_normals<Vec3z>(m.P[0], m.P[1], m.stats);
        clock.lap("gauss map overlay");
        add_lines(m, ns);
    }
    clock.lap("contact lines");
    return m;
}

HullModel build_model(const ExactScene& scene) {
    StageClock clock;
    Model h = build_hulls(scene);
    clock.lap("hulls");
    return build_model(std::move(h));
}

Model build_hulls(const ExactScene& scene, const std::string& name) {
    try {
        return build_hulls(scene);
    } catch (const InputError& e) {
        throw InputError(name + ": " + e.what());
    }
}

HullModel build_model(const ExactScene& scene, const std::string& name) {
    try {
        return build_model(scene);
    } catch (const InputError& e) {
        throw InputError(name + ": " + e.what());
    }
}

}  // namespace scalecert::internal
