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

PosedPoints::PosedPoints(const PointSets& base, const std::array<std::optional<Pose>, 2>& poses)
    : base_(base), pose_(poses) {
    for (int i = 0; i < 2; ++i) {
        scale_[i] = base.scale(i);
        seed_[i] = base.seed(i);
        if (!pose_[i]) continue;
        const Pose& m = *pose_[i];
        // D·L·(R·X/D + t) = L·R·X + D·L·t is integral for L the lcm of the pose's denominators.
        Z L = 1;
        for (const auto& row : m)
            for (const Q& x : row) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), x.get_den_mpz_t());
        scale_[i] *= L;
        // The moved points are numbers the engine and the checker read like any other: past the
        // limit of a polyhedron's common denominator the claim is refused, before any work (a
        // bound: the moved points' own common denominator divides it).
        if (mpz_sizeinbase(scale_[i].get_mpz_t(), 2) > kMaxDenominatorBits)
            throw InputError(std::string("pose") + (i ? "2" : "1") + ": the moved points of P" + (i ? "2" : "1") +
                             " would have a common denominator past " + std::to_string(kMaxDenominatorBits) +
                             " bits (the limit of a polyhedron's; README \"Limits\"): the pose's denominators "
                             "times the object's");
        Vec3q s;
        for (size_t r = 0; r < 3; ++r) {
            s[r] = m[r][0] * seed_[i][0] + m[r][1] * seed_[i][1] + m[r][2] * seed_[i][2] + m[r][3];
            for (size_t c = 0; c < 4; ++c) dpose_[i][r][c] = m[r][c].get_d();
        }
        seed_[i] = s;
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

Vec3q PosedPoints::point(int i, int k) const {
    Vec3q p = base_.point(i, k);
    if (!pose_[i]) return p;
    const Pose& m = *pose_[i];
    Vec3q out;
    for (size_t r = 0; r < 3; ++r) out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3];
    return out;
}

D3 PosedPoints::dpoint(int i, int k) const {
    const D3 p = base_.dpoint(i, k);
    if (!pose_[i]) return p;
    const double(&m)[3][4] = dpose_[i];
    D3 out;
    for (int r = 0; r < 3; ++r) out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3];
    return out;
}

int PosedPoints::argmax(int i, const Vec3z& n) const {
    if (!pose_[i]) return base_.argmax(i, n);
    const Pose& m = *pose_[i];
    // Rᵀn over the lcm of its denominators: a positive multiple, the same maximisers.
    Vec3q u;
    Z L = 1;
    for (size_t c = 0; c < 3; ++c) {
        u[c] = m[0][c] * n[0] + m[1][c] * n[1] + m[2][c] * n[2];
        mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), u[c].get_den_mpz_t());
    }
    Vec3z z;
    for (size_t c = 0; c < 3; ++c) z[c] = u[c].get_num() * (L / u[c].get_den());
    return base_.argmax(i, z);
}

int PosedPoints::dargmax(int i, const D3& d) const {
    if (!pose_[i]) return base_.dargmax(i, d);
    const double(&m)[3][4] = dpose_[i];
    D3 u;
    for (int c = 0; c < 3; ++c) u[c] = m[0][c] * d[0] + m[1][c] * d[1] + m[2][c] * d[2];
    return base_.dargmax(i, u);
}

}  // namespace scalecert::internal
