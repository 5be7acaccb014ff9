// The pieces every claim kind's report is written with (report.hpp).
#include "certify/report.hpp"

#include "certify/region_certificate.hpp"
#include "geometry/measures.hpp"

#include <cmath>
#include <cstdio>

namespace scalecert::internal::report_parts {

void put_point(Json& o, const std::string& key, const Vec3q& v) {
    o[key] = Json::array({to_exact_string(v[0]), to_exact_string(v[1]), to_exact_string(v[2])});
}

std::string dbl(double d, int digits) {
    char b[40];
    std::snprintf(b, sizeof b, "%.*g", digits, d);
    return b;
}
std::string num(const Q& q, int digits) { return to_exact_string(q) + " (~" + dbl(to_double_rn(q), digits) + ")"; }

void errors(Json& o, const Q& claimed, const Q& exact) {
    put_exact(o, "claimed", claimed);
    put_exact(o, "exact", exact);
    const Q err = abs(Q(claimed - exact));
    put_exact(o, "abs_error", err);
    if (sgn(exact) != 0)
        put_exact(o, "rel_error", err / abs(exact));
    else
        o["rel_error"] = nullptr;
}
void errors_sq(Json& o, const Q& claimed, const Q& E) {
    put_exact(o, "claimed", claimed);
    put_exact(o, "exact_squared", E);
    put_exact(o, "squared_error", Q(claimed * claimed - E));
    const double d = -sqrt_minus_rn(E, claimed);  // c − √E
    o["abs_error_double"] = std::fabs(d);
    o["rel_error_double"] = sgn(E) ? Json(relative_sqrt_error_rn(E, claimed)) : Json(nullptr);
}
double surd_rn(int s, const Q& E, const Q& k) {
    if (s == 0 || sgn(E) == 0) return to_double_rn(k);
    return s > 0 ? sqrt_minus_rn(E, Q(-k)) : -sqrt_minus_rn(E, k);
}
void errors_surd(Json& o, const Q& claimed, int s, const Q& E, const Q& k, const Q& R, const std::string& hulls_key) {
    put_exact(o, "claimed", claimed);
    put_exact(o, hulls_key, E);
    put_exact(o, "radius_sum", R);
    const double x = surd_rn(s, E, k);
    o["exact_double"] = x;
    o["abs_error_double"] = std::fabs(surd_rn(s, E, Q(k - claimed)));
    o["rel_error_double"] = x != 0 ? Json(std::fabs(surd_rn(s, E, Q(k - claimed))) / std::fabs(x)) : Json(nullptr);
}
std::string radii_text(const Judged& g) {
    const auto& m = *g.radii;
    return "radii " + num(m[0]) + " + " + num(m[1]);
}
std::string at(const TypedClaim& c) {
    const char* posed = c.pose[0] && c.pose[1] ? " with P1 and P2 at poses"
                        : c.pose[0]            ? " with P1 at a pose"
                        : c.pose[1]            ? " with P2 at a pose"
                                               : "";
    return "(" + num(c.rho1) + ", " + num(c.rho2) + ")" + posed;
}
Json part_or_false(int k) { return k >= 0 ? Json(k) : Json(false); }
std::string name_of(const ExactScene& sc, int i, int k) { return part_name_suffix(sc.P[i], static_cast<size_t>(k)); }
std::string parts_named(const ExactScene& sc, int a, int b) {
    return "parts " + std::to_string(a) + name_of(sc, 0, a) + " and " + std::to_string(b) + name_of(sc, 1, b);
}
std::string part_or_no(const ExactScene& sc, int i, int k, bool near) {
    return k < 0 ? "NO" : (near ? "within LEN of part " : "part ") + std::to_string(k) + name_of(sc, i, k);
}
const char* yes_near_no(bool in, bool near) { return !in ? "NO" : near ? "within LEN" : "yes"; }
void put_near(Json& o, const char* key, bool near) {
    if (near) o[key] = true;
}
void put_part_pair(Json& o, const std::string& key, const ExactScene& sc, int a, int b) {
    if (a < 0) {
        o[key] = nullptr;
        return;
    }
    o[key] = Json::array({a, b});
    const std::string &n1 = part_name(sc.P[0], static_cast<size_t>(a)),
                      &n2 = part_name(sc.P[1], static_cast<size_t>(b));
    if (!n1.empty() || !n2.empty())
        o[key + "_names"] = Json::array({n1.empty() ? Json(nullptr) : Json(n1), n2.empty() ? Json(nullptr) : Json(n2)});
}

void put_rhos(Json& o, const TypedClaim& c) {
    put_exact(o, "rho1", c.rho1);
    put_exact(o, "rho2", c.rho2);
    for (size_t i = 0; i < 2; ++i)
        if (c.pose[i]) o[i ? "pose2" : "pose1"] = exact_claim_json(c)[i ? "pose2" : "pose1"];
}

}  // namespace scalecert::internal::report_parts
