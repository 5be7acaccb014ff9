#include "curve/envelope.hpp"

#include "curve/closed_forms.hpp"

#include <algorithm>
#include <functional>
#include <iterator>
#include <numeric>

namespace scalecert::internal {

namespace {
// ρ1 where lines i and j (different slopes) meet.
Q meet(const ContactLine& a, const ContactLine& b) { return (b.intercept - a.intercept) / (a.slope - b.slope); }
}  // namespace

Envelope upper_envelope(const std::vector<ContactLine>& lines) {
    // build_model already dropped the certainly dominated lines; the hull sweep below handles any
    // that remain.
    std::vector<size_t> order(lines.size());
    std::iota(order.begin(), order.end(), size_t{0});
    // Increasing slope; for one slope the highest line first; ties by normal (lines are sorted).
    std::stable_sort(order.begin(), order.end(), [&](size_t i, size_t j) {
        if (lines[i].slope != lines[j].slope) return lines[i].slope < lines[j].slope;
        return lines[i].intercept > lines[j].intercept;
    });
    std::vector<EnvPiece> st;
    for (size_t k = 0; k < order.size(); ++k) {
        const ContactLine& L = lines[order[k]];
        if (!st.empty()) {
            const ContactLine& top = lines[st.back().line];
            if (top.slope == L.slope) {
                if (top.intercept == L.intercept) st.back().same.push_back(order[k]);
                continue;  // lower parallel line: never on the envelope
            }
        }
        // Max-envelope with increasing slopes: drop the top while it is nowhere strictly highest.
        while (st.size() >= 2 &&
               meet(lines[st[st.size() - 2].line], lines[st.back().line]) >= meet(lines[st.back().line], L))
            st.pop_back();
        st.push_back({order[k], {order[k]}, Q(0), std::nullopt});
    }
    for (size_t k = 0; k + 1 < st.size(); ++k) st[k].to = meet(lines[st[k].line], lines[st[k + 1].line]);
    for (size_t k = 1; k < st.size(); ++k) st[k].from = *st[k - 1].to;
    // Keep ρ1 ≥ 0 only.
    size_t first = 0;
    while (first + 1 < st.size() && sgn(*st[first].to) <= 0) ++first;
    st.erase(st.begin(), st.begin() + static_cast<long>(first));
    st.front().from = 0;
    // Below ρ2 = 0 nothing touches, and the lines' envelope there describes no contact: from the
    // first x0 >= 0 with ρ2 <= 0, the curve is the line of the piece that reaches 0 there (the
    // left one where the envelope turns exactly at (x0, 0)), carried on to +∞. So every switch
    // point has ρ2 > 0, and that line is a touching piece's, pinned by its witnesses.
    for (size_t k = 0; k + 1 < st.size(); ++k) {
        if (sgn(lines[st[k].line].at(*st[k].to)) > 0) continue;
        st.resize(k + 1);
        st.back().to.reset();
        break;
    }
    for (auto& p : st) std::sort(p.same.begin(), p.same.end());
    return Envelope{st};
}

size_t Envelope::locate(const Q& x) const {
    // First piece whose right end is > x (or the last piece).
    size_t lo = 0, hi = pieces.size() - 1;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (*pieces[mid].to > x)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

Q Envelope::value(const std::vector<ContactLine>& lines, const Q& x) const {
    return lines[pieces[locate(x)].line].at(x);
}

ContactFeatures contact_on_line(const Vec3z& u, const std::vector<int> A[2],
                                const std::function<Vec3q(int, int)>& scaled) {
    // The vertices A_i of P_i maximising both normals scale onto the common line, direction u,
    // and span a segment S_i; the touching set is S_1 ∩ S_2, and the contact feature of P_i is the
    // smallest face holding it: S_i (an edge) when the touching set reaches into S_i's interior,
    // else the end it meets.
    std::vector<Q> t[2];
    Q lo[2], hi[2];
    for (int i = 0; i < 2; ++i) {
        if (A[i].empty() || is_zero(u)) throw std::logic_error("contact_at: point not on a consistent contact");
        for (int k : A[i]) {
            const Vec3q v = scaled(i, k);
            Q x = 0;
            for (int c = 0; c < 3; ++c) x += Q(u[c]) * v[c];
            t[i].push_back(x);
        }
        lo[i] = *std::min_element(t[i].begin(), t[i].end());
        hi[i] = *std::max_element(t[i].begin(), t[i].end());
    }
    const Q tlo = std::max(lo[0], lo[1]), thi = std::min(hi[0], hi[1]);
    if (tlo > thi) throw std::logic_error("contact_at: the contact features do not meet");
    ContactFeatures c;
    std::vector<int>* out[2] = {&c.feat1, &c.feat2};
    for (int i = 0; i < 2; ++i) {
        const bool edge = lo[i] < hi[i] && thi > lo[i] && tlo < hi[i];
        const Q& end = thi == lo[i] ? lo[i] : hi[i];
        for (size_t k = 0; k < A[i].size(); ++k)
            if (edge || t[i][k] == end) out[i]->push_back(A[i][k]);
        c.label += edge ? 'E' : 'V';
    }
    return c;
}

ContactFeatures contact_at(const Model& m, const ContactLine& L, const ContactLine& R, const Q& rho1, const Q& rho2) {
    // Both planes touch, so P1(ρ1) ∩ P2(ρ2) lies on their common line, direction nL × nR.
    const std::vector<int>* fl[2] = {&L.feat1, &L.feat2};
    const std::vector<int>* fr[2] = {&R.feat1, &R.feat2};
    const Q rho[2] = {rho1, rho2};
    std::vector<int> A[2];
    for (int i = 0; i < 2; ++i)
        std::set_intersection(fl[i]->begin(), fl[i]->end(), fr[i]->begin(), fr[i]->end(), std::back_inserter(A[i]));
    return contact_on_line(cross(L.normal, R.normal), A, [&](int i, int k) {
        const Vec3q v = m.pt(i, static_cast<size_t>(k));
        Vec3q x;
        for (int c = 0; c < 3; ++c) x[c] = m.s[i][c] + rho[i] * (v[c] - m.s[i][c]);
        return x;
    });
}

ContactFeatures piece_contact(const Model& m, const EnvPiece& e) {
    ContactFeatures c;
    c.feat1 = m.lines[e.same.front()].feat1;
    c.feat2 = m.lines[e.same.front()].feat2;
    for (size_t k : e.same) {
        std::vector<int> a, b;
        std::set_intersection(c.feat1.begin(), c.feat1.end(), m.lines[k].feat1.begin(), m.lines[k].feat1.end(),
                              std::back_inserter(a));
        std::set_intersection(c.feat2.begin(), c.feat2.end(), m.lines[k].feat2.begin(), m.lines[k].feat2.end(),
                              std::back_inserter(b));
        c.feat1 = std::move(a);
        c.feat2 = std::move(b);
    }
    if (c.feat1.empty() || c.feat2.empty())
        throw std::logic_error("piece_contact: identical lines with no common maximiser");
    c.label = {feature_letter(c.feat1.size()), feature_letter(c.feat2.size())};
    return c;
}

std::optional<Q> contact_rho1(const Model& m, const TouchingCurve& c, const CurvePiece& p) {
    const ContactLine& L = m.lines[c.env.pieces[p.env].line];
    if (sgn(L.at(p.from)) <= 0) return std::nullopt;
    Q to = p.to;
    if (sgn(L.at(to)) <= 0) to = -L.intercept / L.slope;  // where ρ2 reaches 0
    return (p.from + to) / 2;
}

void restrict_curve(const Model& m, TouchingCurve& c, const Q& lo, const Q& hi) {
    c.pieces.clear();
    c.switches.clear();
    for (size_t k = c.env.locate(lo); k < c.env.pieces.size(); ++k) {
        const EnvPiece& p = c.env.pieces[k];
        Q from = std::max(p.from, lo);
        Q to = p.to ? std::min(*p.to, hi) : hi;
        if (!c.pieces.empty() && from >= hi) break;
        c.pieces.push_back({from, to, k, {}});
        if (to >= hi) break;
    }
    for (CurvePiece& p : c.pieces)
        if (contact_rho1(m, c, p)) p.contact = piece_contact(m, c.env.pieces[p.env]);
    for (size_t k = 0; k + 1 < c.pieces.size(); ++k) {
        const ContactLine& L = m.lines[c.env.pieces[c.pieces[k].env].line];
        const ContactLine& R = m.lines[c.env.pieces[c.pieces[k + 1].env].line];
        ClosedSwitch cs = closed_form_switch(m, L, R);
        CurveSwitch sp;
        sp.rho1 = cs.rho1;
        sp.rho2 = L.at(sp.rho1);
        sp.left = k;
        sp.right = k + 1;
        sp.equation = cs.equation;
        if (sp.rho1 != c.pieces[k].to) throw std::logic_error("closed-form switch point disagrees with the envelope");
        // For ρ2 ≤ 0 nothing touches (P2 would be a point or reflected): no contact there.
        if (sgn(sp.rho2) > 0) sp.contact = contact_at(m, L, R, sp.rho1, sp.rho2);
        c.switches.push_back(std::move(sp));
    }
}

TouchingCurve build_curve(const Model& m) {
    TouchingCurve c;
    c.env = upper_envelope(m.lines);
    restrict_curve(m, c, m.scene.lo[0], m.scene.hi[0]);
    // Growth distance: f(ρ) = ρ. g(ρ) = f(ρ) − ρ decreases strictly, g(0) = max intercept ≥ 0.
    size_t lo_k = 0, hi_k = c.env.pieces.size() - 1;
    while (lo_k < hi_k) {
        size_t mid = (lo_k + hi_k) / 2;
        const Q& x = *c.env.pieces[mid].to;
        if (m.lines[c.env.pieces[mid].line].at(x) <= x)
            hi_k = mid;
        else
            lo_k = mid + 1;
    }
    const ContactLine& G = m.lines[c.env.pieces[lo_k].line];
    c.growth.value = G.intercept / (Q(1) - G.slope);
    c.growth.env = lo_k;
    const ExactScene& s = m.scene;
    c.growth.in_rectangle = c.growth.value >= s.lo[0] && c.growth.value <= s.hi[0] && c.growth.value >= s.lo[1] &&
                            c.growth.value <= s.hi[1];
    return c;
}

}  // namespace scalecert::internal
