#include "campaign/families.hpp"

#include <cmath>

namespace scalecert::internal {

std::uint64_t Rng::next() {  // splitmix64
    std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

long Rng::uniform(long lo, long hi) { return lo + static_cast<long>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }

namespace {
Q qc(long p, long q) {
    Q r(p, q);
    r.canonicalize();
    return r;
}
Vec3q v3(const Q& x, const Q& y, const Q& z) { return {x, y, z}; }
std::vector<Vec3q> box(const Q& hx, const Q& hy, const Q& hz, const Vec3q& c) {
    std::vector<Vec3q> p;
    for (int x : {-1, 1})
        for (int y : {-1, 1})
            for (int z : {-1, 1}) p.push_back({c[0] + hx * x, c[1] + hy * y, c[2] + hz * z});
    return p;
}
void finish(ExactScene& s, const Q& lo, const Q& hi) {
    for (int i = 0; i < 2; ++i) {
        if (!s.P[i].seed_given) {
            Vec3q c{Q(0), Q(0), Q(0)};
            for (const auto& v : s.P[i].points)
                for (int k = 0; k < 3; ++k) c[k] += v[k];
            for (int k = 0; k < 3; ++k) c[k] /= Q(static_cast<long>(s.P[i].points.size()));
            s.P[i].seed = c;
        }
        s.lo[i] = lo;
        s.hi[i] = hi;
    }
}
// A random polytope: n integer points in [-r, r]^3 around c, made non-flat by a tetrahedron.
std::vector<Vec3q> random_poly(Rng& g, int n, long r, const Vec3q& c) {
    std::vector<Vec3q> p{
        {c[0] + r, c[1], c[2]}, {c[0], c[1] + r, c[2]}, {c[0], c[1], c[2] + r}, {c[0] - r, c[1] - r, c[2] - r}};
    while (static_cast<int>(p.size()) < n)
        p.push_back({c[0] + g.uniform(-r, r), c[1] + g.uniform(-r, r), c[2] + g.uniform(-r, r)});
    return p;
}
}  // namespace

const std::vector<std::string>& family_names() {
    static const std::vector<std::string> n{
        "random",          "parallel-faces", "nearly-equal-slopes", "nearly-parallel-edges", "vertex-vertex",
        "far-from-origin", "sliver",         "near-sphere"};
    return n;
}

std::string family_description(const std::string& name) {
    if (name == "random") return "random integer polytopes (ε unused)";
    if (name == "parallel-faces") return "a box under a box whose bottom face is tilted by ε: (F,F) contact as ε → 0";
    if (name == "nearly-equal-slopes")
        return "a vertex sliding over a roof ridge of height ε: slopes differ by O(ε) at the switch";
    if (name == "nearly-parallel-edges") return "crossed edges at angle ε: (E,E) contact with nearly parallel edges";
    if (name == "vertex-vertex")
        return "two pyramids apex to apex, the second apex offset by ε from the seed line: (V,V) as ε → 0";
    if (name == "far-from-origin") return "unit-size random polytopes at offsets of 10^6, seeds ε-perturbed";
    if (name == "sliver") return "a tetrahedron of height ε over a box";
    if (name == "near-sphere") return "many-vertex hulls of points near spheres (200 points; ε unused)";
    throw InputError("--family: unknown family " + in_quotes(name));
}

ExactScene make_family_scene(const std::string& name, const Q& eps, Rng& g) {
    ExactScene s;
    const Q lo = qc(1, 2), hi = Q(3);
    if (name == "random") {
        s.P[0].points = random_poly(g, static_cast<int>(g.uniform(6, 12)), 4, v3(Q(0), Q(0), Q(0)));
        s.P[1].points = random_poly(g, static_cast<int>(g.uniform(6, 12)), 4,
                                    v3(Q(g.uniform(5, 9)), Q(g.uniform(-3, 3)), Q(g.uniform(-3, 3))));
    } else if (name == "parallel-faces") {
        s.P[0].points = box(Q(2), Q(2), Q(1), v3(Q(0), Q(0), Q(0)));
        Q dx = qc(g.uniform(-5, 5), 10);
        auto b = box(Q(2), Q(2), Q(1), v3(dx, Q(0), Q(4)));
        for (auto& v : b)
            if (v[2] < 4) v[2] += eps * v[0];  // tilt the bottom face
        s.P[1].points = b;
    } else if (name == "nearly-equal-slopes") {
        s.P[0].points = {{Q(-3), Q(-1), Q(-1)}, {Q(3), Q(-1), Q(-1)}, {Q(-3), Q(1), Q(-1)},   {Q(3), Q(1), Q(-1)},
                         {Q(-3), Q(-1), Q(1)},  {Q(-3), Q(1), Q(1)},  {Q(0), Q(-1), 1 + eps}, {Q(0), Q(1), 1 + eps},
                         {Q(3), Q(-1), Q(1)},   {Q(3), Q(1), Q(1)}};
        s.P[0].seed = {Q(0), Q(0), Q(0)};
        s.P[0].seed_given = true;
        Q cx = -qc(g.uniform(50, 100), 100);
        s.P[1].points = {{cx, Q(0), Q(3)}, {Q(-4), Q(2), Q(6)}, {Q(-4), Q(-2), Q(6)}, {Q(-2), Q(0), Q(8)}};
        s.P[1].seed = {Q(-2), Q(0), Q(5)};
        s.P[1].seed_given = true;
    } else if (name == "nearly-parallel-edges") {
        // P1: a wedge with a top edge along x; P2: an inverted wedge with bottom edge turned by ε.
        s.P[0].points = {{Q(-3), Q(-1), Q(0)}, {Q(3), Q(-1), Q(0)}, {Q(-3), Q(1), Q(0)},
                         {Q(3), Q(1), Q(0)},   {Q(-3), Q(0), Q(1)}, {Q(3), Q(0), Q(1)}};
        Q oy = qc(g.uniform(-3, 3), 10);
        s.P[1].points = {{Q(-3), -eps * 3 + oy, Q(2)}, {Q(3), eps * 3 + oy, Q(2)}, {Q(-3), Q(-1) + oy, Q(3)},
                         {Q(3), Q(-1) + oy, Q(3)},     {Q(-3), Q(1) + oy, Q(3)},   {Q(3), Q(1) + oy, Q(3)}};
    } else if (name == "vertex-vertex") {
        s.P[0].points = {
            {Q(-1), Q(-1), Q(0)}, {Q(1), Q(-1), Q(0)}, {Q(-1), Q(1), Q(0)}, {Q(1), Q(1), Q(0)}, {Q(0), Q(0), Q(1)}};
        s.P[1].points = {{Q(-1), Q(-1), Q(4)},
                         {Q(1), Q(-1), Q(4)},
                         {Q(-1), Q(1), Q(4)},
                         {Q(1), Q(1), Q(4)},
                         {eps * g.uniform(1, 3), eps, Q(3)}};
    } else if (name == "far-from-origin") {
        Vec3q c{Q(1000000), Q(-1000000), Q(1000000)};
        s.P[0].points = random_poly(g, 8, 1, c);
        s.P[1].points = random_poly(g, 8, 1, v3(c[0] + 3, c[1] + eps, c[2] + eps));
    } else if (name == "sliver") {
        s.P[0].points = box(Q(1), Q(1), Q(1), v3(Q(0), Q(0), Q(0)));
        Q x = qc(g.uniform(-5, 5), 10);
        s.P[1].points = {{x - 2, Q(-2), Q(3)}, {x + 2, Q(-2), Q(3)}, {x, Q(2), Q(3)}, {x, Q(0), 3 - eps}};
    } else if (name == "near-sphere") {
        for (int i = 0; i < 2; ++i) {
            for (int k = 0; k < 200; ++k) {
                double u = 2.0 * (g.next() >> 11) * 0x1.0p-53 - 1, t = 6.283185307179586 * (g.next() >> 11) * 0x1.0p-53;
                double r = std::sqrt(1 - u * u);
                s.P[i].points.push_back({Q(std::lround(1000 * r * std::cos(t)) + (i ? 3000 : 0)),
                                         Q(std::lround(1000 * r * std::sin(t))), Q(std::lround(1000 * u))});
            }
        }
    } else {
        family_description(name);  // throws for unknown names
    }
    finish(s, lo, hi);
    return s;
}

}  // namespace scalecert::internal
