#include "geometry/bodies.hpp"
#include "geometry/point_sets.hpp"
#include "numeric/limits.hpp"

namespace scalecert::internal {

void set_seeds_in_integers(Bodies& b) {
    b.d = sub(b.s[1], b.s[0]);
    for (int i = 0; i < 2; ++i) {
        const Vec3q ss{b.s[i][0] * b.P[i].scale, b.s[i][1] * b.P[i].scale, b.s[i][2] * b.P[i].scale};
        b.sz[i] = over_common_denominator(ss, b.sden[i]);
    }
    b.dz = over_common_denominator(b.d, b.dden);
}

}  // namespace scalecert::internal

namespace scalecert::internal {

PosedPoints::PosedPoints(const PointSets& base, const std::array<std::optional<Pose>, 2>& poses) : base_(base) {
    for (int i = 0; i < 2; ++i) {
        if (!poses[i]) continue;
        posed_[i] = true;
        const Pose& m = *poses[i];
        // D·L·(R·X/D + t) = L·R·X + D·L·t is integral for L the lcm of the pose's denominators.
        Z L = 1;
        for (const auto& row : m)
            for (const Q& x : row) lcm_into(L, x.get_den());
        // The moved points are numbers the engine and the checker read like any other: past the
        // limit of a polyhedron's common denominator the claim is refused, before any work (a
        // bound: the moved points' own common denominator divides it).
        scale_[i] = base.scale(i) * L;
        if (mpz_sizeinbase(scale_[i].get_mpz_t(), 2) > kMaxDenominatorBits)
            throw InputError(std::string("pose") + (i ? "2" : "1") + ": the moved points of P" + (i ? "2" : "1") +
                             " would have a common denominator past " + std::to_string(kMaxDenominatorBits) +
                             " bits (the limit of a polyhedron's; README \"Limits\"): the pose's denominators "
                             "times the object's");
        // The seed S/E moves to (L·R·S + L·t·E) / (L·E).
        Z E;
        const Vec3z S = over_common_denominator(base.seed(i), E);
        const Z LE = L * E;
        for (size_t r = 0; r < 3; ++r) {
            for (size_t c = 0; c < 3; ++c) LR_[i][r][c] = over(m[r][c], L);
            const Z Lt = over(m[r][3], L);
            DLt_[i][r] = Lt * base.scale(i);
            Z num = Lt * E;
            for (size_t c = 0; c < 3; ++c) mpz_addmul(num.get_mpz_t(), LR_[i][r][c].get_mpz_t(), S[c].get_mpz_t());
            seed_[i][r] = Q(num, LE);
            seed_[i][r].canonicalize();
            for (size_t c = 0; c < 4; ++c) dpose_[i][r][c] = m[r][c].get_d();
        }
    }
}

Vec3z PointSets::zpoint(int i, int k) const {
    const Vec3q x = point(i, k);
    Vec3z z;
    for (int c = 0; c < 3; ++c) {
        const Q q = x[c] * scale(i);
        if (q.get_den() != 1) throw std::logic_error("a point off its set's scale");
        z[c] = q.get_num();
    }
    return z;
}

Vec3z PosedPoints::zpoint(int i, int k) const {
    if (!posed_[i]) return base_.zpoint(i, k);
    const Vec3z X = base_.zpoint(i, k);
    Vec3z z;
    for (size_t r = 0; r < 3; ++r) {
        z[r] = DLt_[i][r];
        for (size_t c = 0; c < 3; ++c) mpz_addmul(z[r].get_mpz_t(), LR_[i][r][c].get_mpz_t(), X[c].get_mpz_t());
    }
    return z;
}

Vec3q PosedPoints::point(int i, int k) const {
    if (!posed_[i]) return base_.point(i, k);
    const Vec3z z = zpoint(i, k);
    Vec3q out;
    for (size_t r = 0; r < 3; ++r) {
        out[r] = Q(z[r], scale_[i]);
        out[r].canonicalize();
    }
    return out;
}

D3 PosedPoints::dpoint(int i, int k) const {
    const D3 p = base_.dpoint(i, k);
    if (!posed_[i]) return p;
    const double(&m)[3][4] = dpose_[i];
    D3 out;
    for (int r = 0; r < 3; ++r) out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3];
    return out;
}

int PosedPoints::argmax(int i, const Vec3z& n) const {
    if (!posed_[i]) return base_.argmax(i, n);
    // L·Rᵀn: a positive multiple of Rᵀn, the same maximisers.
    Vec3z u;
    for (size_t c = 0; c < 3; ++c) {
        u[c] = 0;
        for (size_t r = 0; r < 3; ++r) mpz_addmul(u[c].get_mpz_t(), LR_[i][r][c].get_mpz_t(), n[r].get_mpz_t());
    }
    return base_.argmax(i, u);
}

int PosedPoints::dargmax(int i, const D3& d) const {
    if (!posed_[i]) return base_.dargmax(i, d);
    const double(&m)[3][4] = dpose_[i];
    D3 u;
    for (int c = 0; c < 3; ++c) u[c] = m[0][c] * d[0] + m[1][c] * d[1] + m[2][c] * d[2];
    return base_.dargmax(i, u);
}

}  // namespace scalecert::internal
