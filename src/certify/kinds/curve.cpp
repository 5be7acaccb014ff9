// Claims of the curve (CLAIMS.md, "Claims" and "Curve claims"), on two convex objects:
// growth distances, curve points, switch points and whole curves; each rule and its report.
#include "certify/report.hpp"
#include "certify/rounded.hpp"
#include "certify/rules_impl.hpp"

namespace scalecert::internal {

using namespace report_parts;

void ConvexRules::Impl::growth(const TypedClaim& c, Judged& g, Proof* proof) {
    auto& d = g.set<GrowthJudged>();
    d.exact = models.growth();
    g.right = tol.close(c.value, d.exact);
    if (proof) {
        proof->proof = models.growth_proof();
        if (proof->proof["value"] != to_exact_string(d.exact))
            throw std::logic_error("certify-fp: the proved growth distance and the exact one differ");
    }
}

namespace {
// On objects with a radius: the exact ρ* = a + b√c beside the claim, the errors as doubles.
void surd_errors(Json& o, const Q& claimed, const QuadSurd& x) {
    put_exact(o, "claimed", claimed);
    o["exact"] = surd_text(x);
    o["exact_surd"] = surd_json(x);
    const double e = surd_double(x), err = std::fabs(surd_double({Q(x.a - claimed), x.b, x.c}));
    o["exact_double"] = e;
    o["abs_error_double"] = err;
    o["rel_error_double"] = e != 0 ? Json(err / std::fabs(e)) : Json(nullptr);
}
}  // namespace

void describe(const TypedClaim& c, const GrowthJudged& d, const Judged&, const ExactScene*, Json& o,
              std::string& text) {
    if (d.surd) {
        surd_errors(o, c.value, *d.surd);
        text = "growth distance " + num(c.value) + ": exact " + surd_text(*d.surd) + " (~" +
               dbl(surd_double(*d.surd), 17) + ")";
        return;
    }
    errors(o, c.value, d.exact);
    text = "growth distance " + num(c.value) + ": exact " + num(d.exact);
}

void ConvexRules::Impl::curve_point(const TypedClaim& c, Judged& g, Proof* proof) {
    auto& d = g.set<CurvePointJudged>();
    d.exact = models.curve_value(c.rho1);
    g.right = sgn(d.exact) > 0 && tol.close(c.rho2, d.exact);
    if (proof) {
        const Curve V = models.curve_around(c.rho1, c.rho1);
        proof->proof = curve_proof(*V.model, *V.curve, c.rho1, c.rho1);
    }
}

void describe(const TypedClaim& c, const CurvePointJudged& d, const Judged&, const ExactScene*, Json& o,
              std::string& text) {
    put_rhos(o, c);
    put_exact(o, "curve_rho2", d.exact);
    errors(o, c.rho2, d.exact);
    text = "curve point " + at(c) + ": exact curve at rho1 is " + num(d.exact);
}

void ConvexRules::Impl::switch_point(const TypedClaim& c, Judged& g, Proof* proof) {
    auto& d = g.set<SwitchPointJudged>();
    const Q &r1 = c.rho1, &r2 = c.rho2, &t = tol.rel;
    // Every ρ1 within the tolerance of the claim's (|x − ρ1| <= tol·x) lies in [lo, hi]: the
    // walk proves the curve over a window holding it; a tolerance of 1 or more needs the whole
    // curve (on to where it reaches ρ2 = 0, past every switch point).
    const Q lo = r1 / (1 + t);
    const Curve V = t < 1 ? models.curve_around(lo, Q(r1 / (1 - t))) : whole();
    const auto& exs = exact_switches(V);
    d.window_whole = V.whole();
    d.window_lo = V.lo_proved;
    d.window_hi = V.hi_proved;
    if (exs.empty()) {
        // The proof: the whole curve from ρ1 = 0 to past where it reaches ρ2 = 0, or the window.
        if (proof) {
            proof->proof = V.whole() ? curve_proof(*V.model, *V.curve, Q(0), zero_crossing(V))
                                     : curve_proof(*V.model, *V.curve, lo, Q(r1 / (1 - t)));
        }
        g.right = false;
        return;
    }
    // Right when some exact switch point matches (both coordinates within the tolerance, and
    // the contact when claimed): the judgement names the first that does, else the nearest in ρ1.
    const ExactSwitch* best = nullptr;
    for (const ExactSwitch& s : exs)
        if (tol.close(r1, s.rho1) && tol.close(r2, s.rho2) && (!c.contact || *c.contact == s.label)) {
            best = &s;
            break;
        }
    d.matched = best != nullptr;
    if (!best) {
        best = &exs.front();
        for (const ExactSwitch& s : exs)
            if (abs(Q(s.rho1 - r1)) < abs(Q(best->rho1 - r1))) best = &s;
    }
    d.nearest = *best;
    // The proof: the curve over a window holding every ρ1 within the tolerance of the claim's
    // (from ρ1/(1 + tol) to ρ1/(1 − tol), or on to where the curve reaches ρ2 = 0 when tol >= 1).
    if (proof) {
        const Q hi = t < 1 ? Q(r1 / (1 - t)) : std::max(r1, zero_crossing(V));
        proof->proof = curve_proof(*V.model, *V.curve, lo, hi);
    }
    if (c.contact) d.contact_right = *c.contact == best->label;
    g.right = d.matched;
}

void describe(const TypedClaim& c, const SwitchPointJudged& d, const Judged&, const ExactScene*, Json& o,
              std::string& text) {
    put_rhos(o, c);
    const std::string head = "switch point " + at(c);
    if (!d.nearest) {
        o["nearest"] = nullptr;
        if (d.window_whole)
            text = head + ": the exact curve has no switch point at rho1, rho2 > 0";
        else
            text = head + ": the exact curve has no switch point from rho1 = " + num(d.window_lo) +
                   (d.window_hi ? " to " + num(*d.window_hi) : std::string(" on")) + " (the range the walk proved)";
        return;
    }
    const ExactSwitch& b = *d.nearest;
    Json n;
    put_exact(n, "rho1", b.rho1);
    put_exact(n, "rho2", b.rho2);
    n["contact"] = b.label;
    o["nearest"] = n;
    Json e1, e2;
    errors(e1, c.rho1, b.rho1);
    errors(e2, c.rho2, b.rho2);
    o["rho1_error"] = e1;
    o["rho2_error"] = e2;
    o["contact_right"] = d.contact_right ? Json(*d.contact_right) : Json(nullptr);
    text = "switch point (" + num(c.rho1) + ", " + num(c.rho2) + (c.contact ? ", " + *c.contact : "") +
           (d.matched ? "): matches exact (" : "): nearest exact (") + num(b.rho1) + ", " + num(b.rho2) + ", " +
           b.label + ")";
}

// A curve claim: the rules of CLAIMS.md ("Curve claims").
void ConvexRules::Impl::curve(const TypedClaim& c, Judged& g, Proof* proof) {
    auto& d = g.set<CurveJudged>();
    const ClaimedCurve& k = *c.curve;
    const auto& segs = k.segments;
    const Q lo = segs.front().x0, hi = segs.back().x1;
    // The curve proved over a window around [lo, hi], and around every ρ1 where f takes a
    // claimed end's ρ2 (the horizontal error): walked wider until it is, a few rounds, else
    // the whole curve.
    Curve V = models.curve_around(lo, hi);
    for (int round = 0; !V.whole(); ++round) {
        Q need_lo = lo, need_hi = hi;
        bool fits = true, whole_needed = false;
        for (const CurveSegment& s : segs)
            for (const Q& y : {s.y0, s.y1}) {
                const std::optional<Q> x = inverse(V, y);
                if (x && V.proves(*x)) continue;
                fits = false;
                if (!x || sgn(*x) <= 0)
                    whole_needed = true;  // at or before ρ1 = 0 on the walked lines
                else
                    need_lo = std::min(need_lo, *x), need_hi = std::max(need_hi, *x);
            }
        if (fits) break;
        V = whole_needed || round == 8 ? whole() : models.curve_around(need_lo, need_hi);
    }
    const TouchingCurve& cv = *V.curve;
    const Model& mv = *V.model;
    if (proof) proof->proof = curve_proof(mv, cv, lo, hi);
    // Vertical error: on a stretch where the claim and f are both linear, so is their
    // difference (and so are the tolerance's bounds), so the claimed ends and the exact
    // breaks inside each segment suffice.
    const auto& exs = exact_switches(V);
    Q max_v = 0, max_h = 0, worst_v_at = lo;
    bool within = true;
    auto check_v = [&](const Q& x, const Q& y) {
        const Q f = cv.env.value(mv.lines, x);
        const Q e = abs(Q(y - f));
        if (e > max_v) max_v = e, worst_v_at = x;
        within = within && tol.close(y, f);
    };
    for (const CurveSegment& s : segs) {
        check_v(s.x0, s.y0);
        check_v(s.x1, s.y1);
        for (const EnvPiece& p : cv.env.pieces)
            if (p.to && *p.to > s.x0 && *p.to < s.x1)
                check_v(*p.to, s.y0 + (s.y1 - s.y0) * (*p.to - s.x0) / (s.x1 - s.x0));
        for (const auto& [x, y] : {std::pair{s.x0, s.y0}, std::pair{s.x1, s.y1}})
            if (auto xi = inverse(V, y)) max_h = std::max(max_h, Q(abs(Q(*xi - x))));
    }
    // Nothing touches where f ≤ 0; f descends, so it is > 0 on the whole range iff at hi.
    d.exact_positive = sgn(cv.env.value(mv.lines, hi)) > 0;
    d.max_vertical = max_v;
    d.max_vertical_at = worst_v_at;
    d.max_horizontal = max_h;
    // Switch points: the exact ones in the closed range [lo, hi], each matched with the claimed
    // one nearest to it in ρ1 when that one's nearest exact switch is it. An exact switch
    // strictly inside the range that is not matched is missed; one at an end of the range
    // may go unclaimed. A claimed one not matched is extra; a matched pair must agree in ρ1
    // and ρ2 within the tolerance, or it is misplaced.
    const auto& claimed = k.switches;
    std::vector<const ExactSwitch*> exact;
    for (const ExactSwitch& s : exs)
        if (s.rho1 >= lo && s.rho1 <= hi) exact.push_back(&s);
    auto nearest_claimed = [&](const Q& x) {
        size_t b = 0;
        for (size_t i = 1; i < claimed.size(); ++i)
            if (abs(Q(claimed[i].first - x)) < abs(Q(claimed[b].first - x))) b = i;
        return b;
    };
    auto nearest_exact = [&](const Q& x) {
        size_t b = 0;
        for (size_t i = 1; i < exact.size(); ++i)
            if (abs(Q(exact[i]->rho1 - x)) < abs(Q(exact[b]->rho1 - x))) b = i;
        return b;
    };
    std::vector<bool> used(claimed.size(), false);
    for (size_t i = 0; i < exact.size(); ++i) {
        const bool at_end = exact[i]->rho1 == lo || exact[i]->rho1 == hi;
        size_t n = 0;
        if (claimed.empty() || nearest_exact(claimed[n = nearest_claimed(exact[i]->rho1)].first) != i) {
            if (!at_end) d.missed.push_back({exact[i]->rho1, exact[i]->rho2});
            continue;
        }
        used[n] = true;
        if (!tol.close(claimed[n].first, exact[i]->rho1) || !tol.close(claimed[n].second, exact[i]->rho2))
            d.misplaced.push_back({exact[i]->rho1, exact[i]->rho2, claimed[n].first, claimed[n].second});
    }
    for (size_t n = 0; n < claimed.size(); ++n)
        if (!used[n]) d.extra.push_back(claimed[n]);
    // Contacts: the exact contact at each claimed piece's midpoint.
    for (const CurveSegment& s : segs) {
        if (!s.contact) continue;
        const Q mid = (s.x0 + s.x1) / 2;
        // At an exact switch point the contact is the switch point's.
        std::string e =
            d.exact_positive ? piece_contact(mv, cv.env.pieces[cv.env.locate(mid)]).label : std::string("none");
        for (const ExactSwitch& sw : exs)
            if (sw.rho1 == mid) e = sw.label;
        if (*s.contact != e) d.wrong_contacts.push_back({mid, *s.contact, e});
    }
    g.right = d.exact_positive && within && d.missed.empty() && d.extra.empty() && d.misplaced.empty() &&
              d.wrong_contacts.empty();
}

void describe(const TypedClaim& c, const CurveJudged& d, const Judged&, const ExactScene*, Json& o, std::string& text) {
    o["exact_rho2_positive_over_range"] = d.exact_positive;
    put_exact(o, "max_vertical_error", d.max_vertical);
    put_exact(o, "max_vertical_error_at_rho1", d.max_vertical_at);
    put_exact(o, "max_horizontal_error", d.max_horizontal);
    auto pairs = [](const std::vector<std::pair<Q, Q>>& v) {
        Json a = Json::array();
        for (const auto& [x, y] : v) a.push_back(Json::array({to_exact_string(x), to_exact_string(y)}));
        return a;
    };
    o["switch_points_missed"] = pairs(d.missed);
    o["switch_points_extra"] = pairs(d.extra);
    Json mp = Json::array();
    for (const CurveJudged::Misplaced& m : d.misplaced) {
        Json j;
        put_exact(j, "exact_rho1", m.exact_rho1);
        put_exact(j, "exact_rho2", m.exact_rho2);
        put_exact(j, "claimed_rho1", m.claimed_rho1);
        put_exact(j, "claimed_rho2", m.claimed_rho2);
        mp.push_back(j);
    }
    o["switch_points_misplaced"] = mp;
    Json wl = Json::array();
    for (const CurveJudged::WrongContact& w : d.wrong_contacts) {
        Json j;
        put_exact(j, "rho1", w.rho1);
        j["claimed"] = w.claimed;
        j["exact"] = w.exact;
        wl.push_back(j);
    }
    o["wrong_contacts"] = wl;
    const size_t n = c.curve->segments.size();
    text = "curve of " + std::to_string(n) + (n == 1 ? " segment" : " segments") + ": max vertical error " +
           num(d.max_vertical) + ", max horizontal error " + num(d.max_horizontal) + ", switch points missed " +
           std::to_string(d.missed.size()) + ", extra " + std::to_string(d.extra.size()) + ", misplaced " +
           std::to_string(d.misplaced.size()) + ", wrong contacts " + std::to_string(d.wrong_contacts.size()) +
           (d.exact_positive ? "" : ", and the exact curve reaches rho2 <= 0 in the claimed range");
}

void describe_line(const TypedClaim& c, const GrowthJudged& d, const Judged&, const ExactScene*,
                   const std::vector<std::string>& w, Json& o, std::string& text) {
    o["claim"] = "growth";
    if (d.surd) {
        surd_errors(o, c.value, *d.surd);
        text =
            "growth distance " + w[1] + ": exact " + surd_text(*d.surd) + " (~" + dbl(surd_double(*d.surd), 17) + ")";
        return;
    }
    put_exact(o, "claimed", c.value);
    put_exact(o, "exact", d.exact);
    text = "growth distance " + w[1] + ": exact " + num(d.exact, 17) + ", off by " + num(c.value - d.exact, 17);
}

void describe_line(const TypedClaim& c, const CurvePointJudged& d, const Judged&, const ExactScene*,
                   const std::vector<std::string>& w, Json& o, std::string& text) {
    o["claim"] = "curve";
    put_exact(o, "rho1", c.rho1);
    put_exact(o, "rho2", c.rho2);
    put_exact(o, "curve_rho2", d.exact);
    put_exact(o, "rho2_minus_curve", c.rho2 - d.exact);
    text = "curve point (" + w[1] + ", " + w[2] + "): exact curve at rho1 is " + num(d.exact, 17) + ", off by " +
           num(c.rho2 - d.exact, 17);
}

}  // namespace scalecert::internal
