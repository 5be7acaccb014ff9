#include "curve/closed_forms.hpp"

namespace scalecert::internal {

namespace {
Q det3(const Vec3q& a, const Vec3q& b, const Vec3q& c) { return dot(a, cross(b, c)); }

// Outward normal of face f of polyhedron i through three of its vertices, from the vertices alone.
Vec3q face_normal(const Model& m, int i, const std::vector<int>& f) {
    const Vec3q a = m.pt(i, f[0]), b = m.pt(i, f[1]), c = m.pt(i, f[2]);
    Vec3q n = cross(sub(b, a), sub(c, a));
    if (sgn(dot(n, sub(a, m.s[i]))) < 0) n = {Q(-n[0]), Q(-n[1]), Q(-n[2])};
    return n;
}

int kind(const std::string& c) {  // 1: face of P1, 2: face of P2, 3: edge-edge
    if (c[0] == 'F') return 1;
    if (c[1] == 'F') return 2;
    return 3;
}
}  // namespace

ClosedLine closed_form_line(const Model& m, const ContactLine& L) {
    const Vec3q &s1 = m.s[0], &s2 = m.s[1];
    ClosedLine c;
    switch (kind(L.contact)) {
    case 1: {  // (F,V): ρ2 = (ρ1 n1·(a1−s1) + n1·(s1−s2)) / n1·(c2−s2)
        Vec3q n1 = face_normal(m, 0, L.feat1);
        const Vec3q a1 = m.pt(0, L.feat1[0]);
        const Vec3q c2 = m.pt(1, L.feat2[0]);
        c.alpha = dot(n1, sub(a1, s1));
        c.beta = dot(n1, sub(s1, s2));
        c.gamma = dot(n1, sub(c2, s2));
        // (F,F) and (F,E): P1's face meets P2's face or edge in its plane, which (i) gives with any
        // vertex of P2's feature.
        c.formula = L.contact == "FV"
                        ? std::string("(i) F,V")
                        : std::string("(i) F,") + L.contact[1] + " (as F,V: P1's face, a vertex of P2's " +
                              (L.contact[1] == 'F' ? "face)" : "edge)");
        break;
    }
    case 2: {  // (V,F): (i) with the roles exchanged, solved for ρ2
        Vec3q n2 = face_normal(m, 1, L.feat2);
        const Vec3q a2 = m.pt(1, L.feat2[0]);
        const Vec3q c1 = m.pt(0, L.feat1[0]);
        c.alpha = dot(n2, sub(c1, s1));
        c.beta = dot(n2, sub(s1, s2));
        c.gamma = dot(n2, sub(a2, s2));
        c.formula = L.contact == "VF" ? std::string("(i) V,F")
                                      : std::string("(i) E,F (as V,F: a vertex of P1's edge, P2's face)");
        break;
    }
    default: {  // (E,E): ρ2 = (det[VS] + ρ1 det[VV]) / det[A]
        const Vec3q v11 = m.pt(0, L.feat1[0]), v12 = m.pt(0, L.feat1[1]);
        const Vec3q v21 = m.pt(1, L.feat2[0]), v22 = m.pt(1, L.feat2[1]);
        Vec3q e1 = sub(v11, v12);  // −(v12 − v11)
        Vec3q e2 = sub(v22, v21);
        c.alpha = det3(e1, sub(v11, s1), e2);
        c.beta = det3(e1, sub(s1, s2), e2);
        c.gamma = det3(e1, sub(v21, s2), e2);
        c.formula = "(ii) E,E";
    }
    }
    return c;
}

ClosedSwitch closed_form_switch(const Model& m, const ContactLine& left, const ContactLine& right) {
    ClosedLine A = closed_form_line(m, left), B = closed_form_line(m, right);
    ClosedSwitch s;
    s.rho1 = (B.beta * A.gamma - A.beta * B.gamma) / (A.alpha * B.gamma - B.alpha * A.gamma);
    int ka = kind(left.contact), kb = kind(right.contact);
    if (ka == 3 && kb == 3)
        s.equation = "(4)";
    else if (ka == 1 && kb == 1)
        s.equation = "(5)";
    else if (ka == 2 && kb == 2)
        s.equation = "(5) P1,P2 exchanged";
    else if ((ka == 1 && kb == 3) || (ka == 3 && kb == 1))
        s.equation = "(a)";
    else if ((ka == 2 && kb == 3) || (ka == 3 && kb == 2))
        s.equation = "(a) P1,P2 exchanged";
    else
        s.equation = "(i) F,V = (i) V,F";
    return s;
}

}  // namespace scalecert::internal
