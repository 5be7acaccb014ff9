#include "geometry/bodies.hpp"

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
