#include "segment/segment.hpp"

#include <algorithm>

namespace scalecert::internal {

namespace {
// Lower envelope of y = a·x + b over [lo, hi] (brute force: fine for the face counts of scenes
// one plots; each step finds the next line to take over).
std::vector<LinearPiece> lower_envelope(const std::vector<std::pair<Q, Q>>& lines, const Q& lo, const Q& hi) {
    std::vector<LinearPiece> out;
    Q x = lo;
    // active line at x: the smallest value, then the smallest slope (lowest just right of x)
    auto active = [&](const Q& at) {
        size_t best = 0;
        for (size_t k = 1; k < lines.size(); ++k) {
            Q vk = lines[k].first * at + lines[k].second, vb = lines[best].first * at + lines[best].second;
            if (vk < vb || (vk == vb && lines[k].first < lines[best].first)) best = k;
        }
        return best;
    };
    size_t cur = active(x);
    for (;;) {
        Q next = hi;
        size_t nxt = cur;
        for (size_t k = 0; k < lines.size(); ++k) {
            if (lines[k].first >= lines[cur].first) continue;  // only a steeper-down line overtakes
            Q xk = (lines[cur].second - lines[k].second) / (lines[k].first - lines[cur].first);
            if (xk > x && xk < next) {
                next = xk;
                nxt = k;
            }
        }
        out.push_back({x, next, lines[cur].first, lines[cur].second});
        if (next >= hi) break;
        x = next;
        cur = active(x);
        (void)nxt;
    }
    return out;
}

// Exit parameter of the ray v + t·e from P(ρ) = s + ρ(P − s): min over faces with n·e > 0 of
// (n·s + ρ·h_f − n·v) / (n·e), h_f = n·(a_f − s).
std::vector<LinearPiece> exit_parameter(const Polyhedron& P, const Vec3q& s, const Vec3q& v, const Vec3q& e,
                                        const Q& lo, const Q& hi) {
    std::vector<std::pair<Q, Q>> lines;
    for (const Face& f : P.faces) {
        Vec3q n = to_q(f.normal);
        Q ne = dot(n, e);
        if (sgn(ne) <= 0) continue;
        Q h = dot(n, sub(P.points[f.verts[0]], s));
        lines.push_back({h / ne, (dot(n, s) - dot(n, v)) / ne});
    }
    return lower_envelope(lines, lo, hi);
}
}  // namespace

Q eval(const std::vector<LinearPiece>& f, const Q& x) {
    for (const LinearPiece& p : f)
        if (x <= p.to) return p.slope * x + p.intercept;
    return f.back().slope * x + f.back().intercept;
}

Segment make_segment(const HullModel& m, const Vec3q& v1, const Vec3q& v2) {
    Segment s;
    s.v1 = v1;
    s.v2 = v2;
    const Vec3q* v[2] = {&v1, &v2};
    for (int i = 0; i < 2; ++i) {
        const Q& lo = m.scene.lo[i];
        Vec3q inner;  // v_i inside P_i(lo) iff s + (v_i − s)/lo inside P_i
        for (int k = 0; k < 3; ++k) inner[k] = m.s[i][k] + ((*v[i])[k] - m.s[i][k]) / lo;
        if (!m.P[i].strictly_inside(inner))
            throw InputError(std::string("segment: endpoint ") + (i ? "v2" : "v1") + " is not strictly inside P" +
                             std::to_string(i + 1) + "(lo" + std::to_string(i + 1) + ")");
    }
    if (v1 == v2) throw InputError("segment: the endpoints coincide");
    s.t[0] = exit_parameter(m.P[0], m.s[0], v1, sub(v2, v1), m.scene.lo[0], m.scene.hi[0]);
    s.t[1] = exit_parameter(m.P[1], m.s[1], v2, sub(v1, v2), m.scene.lo[1], m.scene.hi[1]);
    return s;
}

std::optional<Q> rho_from_t(const Segment& s, int i, const Q& t) {
    for (const LinearPiece& p : s.t[i]) {
        Q a = p.slope * p.from + p.intercept, b = p.slope * p.to + p.intercept;
        if (t >= a && t <= b) return (t - p.intercept) / p.slope;
    }
    return std::nullopt;
}

Segment segment_by_kind(const HullModel& m, const std::string& kind) {
    if (kind == "seeds") {
        Segment s = make_segment(m, m.s[0], m.s[1]);
        s.kind = "seeds";
        return s;
    }
    if (kind != "ellipsoids") throw InputError("--segment: unknown kind " + in_quotes(kind));
    std::optional<EllipsoidPath> p = ellipsoid_path(m);
    Segment s;
    if (!p) {
        s = make_segment(m, m.s[0], m.s[1]);
        s.kind = "seeds";
        s.note = "the inner ellipsoids could not be computed in floating point; using the seeds";
        return s;
    }
    try {
        s = make_segment(m, p->v1, p->v2);
        s.kind = "ellipsoids";
    } catch (const InputError& e) {
        s = make_segment(m, m.s[0], m.s[1]);
        s.kind = "seeds";
        s.note = std::string("the inner-ellipsoid path failed the exact check (") + e.what() + "); using the seeds";
    }
    s.path = p;
    return s;
}

Q directional_gap(const Segment& s, const Q& rho1, const Q& rho2) {
    return Q(1) - eval(s.t[0], rho1) - eval(s.t[1], rho2);
}

std::vector<std::array<Q, 2>> t_curve(const Model& m, const TouchingCurve& c, const Segment& s) {
    const ExactScene& sc = m.scene;
    auto f = [&](const Q& x) { return c.env.value(m.lines, x); };
    // ρ1 range where the curve is inside I2 (f decreases strictly): [x_top, x_bottom] ∩ I1.
    auto inverse = [&](const Q& y) -> Q {  // the x in I1 with f(x) = y, clamped to I1
        if (f(sc.lo[0]) <= y) return sc.lo[0];
        if (f(sc.hi[0]) >= y) return sc.hi[0];
        for (const CurvePiece& p : c.pieces) {
            const ContactLine& L = m.lines[c.env.pieces[p.env].line];
            if (L.at(p.from) >= y && L.at(p.to) <= y) return (y - L.intercept) / L.slope;
        }
        return sc.hi[0];
    };
    Q a = inverse(sc.hi[1]), b = inverse(sc.lo[1]);
    if (a > b || f(a) > sc.hi[1] || f(b) < sc.lo[1]) return {};  // the curve misses the rectangle
    std::vector<Q> xs{a, b};
    for (const CurveSwitch& sp : c.switches) xs.push_back(sp.rho1);
    for (const LinearPiece& p : s.t[0]) xs.push_back(p.from);
    for (const LinearPiece& p : s.t[1]) xs.push_back(inverse(p.from));
    std::vector<std::array<Q, 2>> out;
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    for (const Q& x : xs)
        if (x >= a && x <= b) out.push_back({eval(s.t[0], x), eval(s.t[1], f(x))});
    return out;
}

std::vector<std::array<Q, 2>> curve_vertices(const Model& m, const TouchingCurve& c) {
    std::vector<std::array<Q, 2>> v;
    auto add = [&](const Q& x) {
        Q y = c.env.value(m.lines, x);
        if (sgn(y) > 0) v.push_back({x, y});
    };
    add(c.pieces.front().from);
    for (const CurveSwitch& sp : c.switches) add(sp.rho1);
    add(c.pieces.back().to);
    return v;
}

}  // namespace scalecert::internal
