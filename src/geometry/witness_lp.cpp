// The only translation unit that includes CGAL's LP solver.
#include "geometry/witness.hpp"

#include <CGAL/Gmpz.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

namespace scalecert::internal {

namespace {
using ET = CGAL::Gmpz;
using Program = CGAL::Quadratic_program<ET>;

ET to_et(const Z& z) { return ET(z.get_mpz_t()); }
Q to_q(const CGAL::Quotient<ET>& q) {
    Q r(Z(q.numerator().mpz()), Z(q.denominator().mpz()));
    r.canonicalize();
    return r;
}

// Adds the equality row Σ coeff_j x_j = rhs with rational data, scaled to integers.
void set_row(Program& lp, int row, const std::vector<std::pair<int, Q>>& coeffs, const Q& rhs,
             CGAL::Comparison_result rel = CGAL::EQUAL) {
    Z l = rhs.get_den();
    for (const auto& [j, c] : coeffs) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
    for (const auto& [j, c] : coeffs)
        if (sgn(c)) lp.set_a(j, row, to_et(Z(c * l)));
    lp.set_b(row, to_et(Z(rhs * l)));
    lp.set_r(row, rel);
}

std::vector<Q> values(const CGAL::Quadratic_program_solution<ET>& s, size_t n) {
    std::vector<Q> out;
    for (auto it = s.variable_values_begin(); it != s.variable_values_end() && out.size() < n; ++it)
        out.push_back(to_q(*it));
    return out;
}
}  // namespace

namespace {
// Σλ = 1, Σμ = 1 and Σ λ_i A_i − Σ μ_j B_j = 0 over the variables λ (0..na−1), μ (na..).
void common_point_rows(Program& lp, const std::vector<Vec3q>& A, const std::vector<Vec3q>& B) {
    const int na = static_cast<int>(A.size()), nb = static_cast<int>(B.size());
    std::vector<std::pair<int, Q>> r0, r1;
    for (int i = 0; i < na; ++i) r0.push_back({i, Q(1)});
    for (int j = 0; j < nb; ++j) r1.push_back({na + j, Q(1)});
    set_row(lp, 0, r0, Q(1));
    set_row(lp, 1, r1, Q(1));
    for (int k = 0; k < 3; ++k) {
        std::vector<std::pair<int, Q>> r;
        for (int i = 0; i < na; ++i) r.push_back({i, A[i][k]});
        for (int j = 0; j < nb; ++j) r.push_back({na + j, Q(-B[j][k])});
        set_row(lp, 2 + k, r, Q(0));
    }
}
CommonPointWeights split(const std::vector<Q>& v, size_t na) {
    CommonPointWeights cp;
    cp.lambda.assign(v.begin(), v.begin() + static_cast<long>(na));
    cp.mu.assign(v.begin() + static_cast<long>(na), v.end());
    return cp;
}
}  // namespace

std::optional<CommonPointWeights> common_point(const std::vector<Vec3q>& A, const std::vector<Vec3q>& B) {
    Program lp(CGAL::EQUAL, true, ET(0), false, ET(0));
    common_point_rows(lp, A, B);
    auto s = CGAL::solve_linear_program(lp, ET());
    if (s.is_infeasible() || !s.is_optimal()) return std::nullopt;
    return split(values(s, A.size() + B.size()), A.size());
}

std::optional<CommonPointWeights> interior_common_point(const std::vector<Vec3q>& A, const std::vector<Vec3q>& B) {
    if (A.empty() || B.empty()) return std::nullopt;
    if (A.size() + B.size() > kBoundEveryWeightUpTo) return interior_common_point_by_centroids(A, B);
    // Variables λ, μ ≥ 0 and t ≥ 0 (index n); maximise t subject to λ_i − t ≥ 0, μ_j − t ≥ 0.
    Program lp(CGAL::EQUAL, true, ET(0), false, ET(0));
    common_point_rows(lp, A, B);
    const int n = static_cast<int>(A.size() + B.size());
    for (int i = 0; i < n; ++i) set_row(lp, 5 + i, {{i, Q(1)}, {n, Q(-1)}}, Q(0), CGAL::LARGER);
    lp.set_c(n, ET(-1));
    auto s = CGAL::solve_linear_program(lp, ET());
    if (!s.is_optimal()) return std::nullopt;
    std::vector<Q> v = values(s, static_cast<size_t>(n) + 1);
    if (v.size() != static_cast<size_t>(n) + 1 || sgn(v.back()) <= 0) return std::nullopt;
    v.pop_back();
    return split(v, A.size());
}

std::optional<CommonPointWeights> interior_common_point_by_centroids(const std::vector<Vec3q>& A,
                                                                     const std::vector<Vec3q>& B) {
    if (A.empty() || B.empty()) return std::nullopt;
    // Each set's centroid joins it as its last point, and only the two centroids' weights are
    // bounded below by t (two rows, not one per point).
    auto with_centroid = [](std::vector<Vec3q> P) {
        Vec3q c{Q(0), Q(0), Q(0)};
        for (const Vec3q& p : P)
            for (int k = 0; k < 3; ++k) c[k] += p[k];
        for (int k = 0; k < 3; ++k) c[k] /= Q(static_cast<long>(P.size()));
        P.push_back(c);
        return P;
    };
    const std::vector<Vec3q> A1 = with_centroid(A), B1 = with_centroid(B);
    Program lp(CGAL::EQUAL, true, ET(0), false, ET(0));
    common_point_rows(lp, A1, B1);
    const int na = static_cast<int>(A1.size()), n = na + static_cast<int>(B1.size());
    set_row(lp, 5, {{na - 1, Q(1)}, {n, Q(-1)}}, Q(0), CGAL::LARGER);
    set_row(lp, 6, {{n - 1, Q(1)}, {n, Q(-1)}}, Q(0), CGAL::LARGER);
    lp.set_c(n, ET(-1));
    auto s = CGAL::solve_linear_program(lp, ET());
    if (!s.is_optimal()) return std::nullopt;
    std::vector<Q> v = values(s, static_cast<size_t>(n) + 1);
    if (v.size() != static_cast<size_t>(n) + 1 || sgn(v.back()) <= 0) return std::nullopt;
    // The centroid's weight spread evenly over its set: every weight > 0, the same point.
    CommonPointWeights cp;
    const Q a = v[static_cast<size_t>(na - 1)] / Q(static_cast<long>(A.size()));
    const Q b = v[static_cast<size_t>(n - 1)] / Q(static_cast<long>(B.size()));
    for (size_t i = 0; i < A.size(); ++i) cp.lambda.push_back(v[i] + a);
    for (size_t j = 0; j < B.size(); ++j) cp.mu.push_back(v[static_cast<size_t>(na) + j] + b);
    return cp;
}

std::optional<std::vector<Q>> maximise_free(const std::vector<std::vector<Q>>& A, const std::vector<Q>& b,
                                            const std::vector<Q>& c) {
    Program lp(CGAL::SMALLER, false, ET(0), false, ET(0));
    for (size_t i = 0; i < A.size(); ++i) {
        std::vector<std::pair<int, Q>> r;
        for (size_t j = 0; j < A[i].size(); ++j) r.push_back({static_cast<int>(j), A[i][j]});
        set_row(lp, static_cast<int>(i), r, b[i], CGAL::SMALLER);
    }
    Z l = 1;  // the objective in integers: minimise −c·x
    for (const Q& q : c) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), q.get_den_mpz_t());
    for (size_t j = 0; j < c.size(); ++j)
        if (sgn(c[j])) lp.set_c(static_cast<int>(j), to_et(Z(-c[j] * l)));
    auto s = CGAL::solve_linear_program(lp, ET());
    if (!s.is_optimal()) return std::nullopt;
    std::vector<Q> v = values(s, c.size());
    if (v.size() != c.size()) v.resize(c.size(), Q(0));
    return v;
}

}  // namespace scalecert::internal
