// The paper's closed forms (Appendix): each contact line as ρ2 = (α·ρ1 + β)/γ computed from the
// contact features' vertices alone, and the switch points by equations (4), (5) and case (a).
// Independent of the support-function computation in contact_lines.cpp; tests hold them equal.
#pragma once
#include "curve/contact_lines.hpp"

namespace scalecert::internal {

struct ClosedLine {
    Q alpha, beta, gamma;  // ρ2 = (α·ρ1 + β)/γ
    std::string formula;   // "(i) F,V", "(i) V,F", "(ii) E,E"; an F,F, F,E or E,F line by (i) as F,V or V,F
    Q slope() const { return alpha / gamma; }
    Q intercept() const { return beta / gamma; }
};

// Appendix (i) for (F,V), (F,E), (F,F) — face of P1, any vertex of the P2 feature, as in (iv)–(v);
// (i) with P1 and P2 exchanged for (V,F), (E,F); (ii) determinants for (E,E).
ClosedLine closed_form_line(const Model& m, const ContactLine& L);

struct ClosedSwitch {
    Q rho1;
    std::string equation;  // "(4)", "(5)", "(a)", or the mirrored forms
};

// Where the left piece's contact changes to the right piece's:
//   ρ1 = (β'γ − βγ') / (αγ' − α'γ), which is (4) for (E,E)→(E,E), (5) for (F,·)→(F,·) and
//   case (a) for (F,V)↔(E,E).
ClosedSwitch closed_form_switch(const Model& m, const ContactLine& left, const ContactLine& right);

}  // namespace scalecert::internal
