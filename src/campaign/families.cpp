#include "campaign/families.hpp"

#include "numeric/exact.hpp"

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
        "far-from-origin", "sliver",         "near-sphere",         "face-to-face",          "long-edge",
        "scaled",          "touching",       "decomposition-gap",   "capsule-hull",          "far-spheres",
        "margin-hulls",    "sphere-box-edge"};
    return n;
}

const std::vector<AtlasClass>& atlas_classes() {
    static const std::vector<AtlasClass> a{
        {"face-to-face", {4, 16, 28, 40}, "face-to-face boxes near zero penetration: mujoco #3476, fcl #402, fcl #495"},
        {"long-edge",
         {3, 7, 10, 14},
         "long edges against small depths (ratios 10^1 to 10^4): Jolt PR #2065, newton #3773"},
        {"scaled", {0, 5, 10, 15, 20}, "one scene at scales 2^10 to 2^-10 (about 10^3 to 10^-3): mujoco_warp #1430"},
        {"touching", {4, 16, 28, 40}, "bodies touching at (1, 1), tilted by an angle eps: drake #21234, drake #21673"},
        {"decomposition-gap", {4, 16, 28, 40}, "two hulls of a cut cube, a gap eps apart along the cut: mujoco #3383"},
        {"capsule-hull",
         {4, 16, 28, 40},
         "a capsule eps above a cylinder's polygon hull (a depth of 7.24732 m for a barely touching cylinder and "
         "capsule): Jolt PR #2108"},
        {"far-spheres",
         {4, 16, 28, 40},
         "two spheres eps deep in each other at coordinates near 10^6 (32-bit GJK missed spheres 0.063 m deep): "
         "Genesis PR #2525"},
        {"margin-hulls",
         {4, 16, 28, 40},
         "two boxes with margins (radii), eps apart once inflated (CCD distance biased by a margin/2 support): "
         "mujoco_warp PR #1188"},
        {"sphere-box-edge",
         {4, 16, 28, 40},
         "a sphere eps from a box's edge (margin plus gap culled a sphere 0.03 away): newton PR #2916"}};
    return a;
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
    if (name == "face-to-face")
        return "a box on a box, turned about z by a random angle in doubles, a gap of ε times its height between faces";
    if (name == "long-edge")
        return "a small cube on the long edge of a bar 1/ε times longer than thick, turned in doubles";
    if (name == "scaled") return "a tetrahedron beside a box, every coordinate times 1024ε";
    if (name == "touching") return "a box tilted by ε radians (in doubles) resting on a box: they touch at (1, 1)";
    if (name == "decomposition-gap")
        return "the two hulls of a cube cut by a random plane through its centre, moved ε apart along its normal";
    if (name == "capsule-hull")
        return "a capsule of radius 1/2 lying across the top of a cylinder's 12-sided polygon hull, eps above it";
    if (name == "far-spheres")
        return "two spheres of radius 1/2 near (10^6, -10^6, 10^6), their centres 1 - eps apart: eps deep";
    if (name == "margin-hulls") return "a cube on a cube, each with a radius (a margin), eps apart once inflated";
    if (name == "sphere-box-edge") return "a sphere beside a box's top edge, eps from it";
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
    } else if (name == "face-to-face" || name == "long-edge" || name == "touching") {
        // Vertices as a program computes them: R·v + t in doubles (R about z by a random angle,
        // and for "touching" also about x by ε), then taken exactly.
        const double turn = 6.283185307179586 * static_cast<double>(g.next() >> 11) * 0x1.0p-53;
        const double tilt = name == "touching" ? eps.get_d() : 0.0;
        auto posed = [&](const std::vector<Vec3q>& pts, const Vec3q& t) {
            const double cz = std::cos(turn), sz = std::sin(turn), cx = std::cos(tilt), sx = std::sin(tilt);
            std::vector<Vec3q> out;
            for (const Vec3q& v : pts) {
                const double x = v[0].get_d(), y = v[1].get_d(), z = v[2].get_d();
                const double y1 = cx * y - sx * z, z1 = sx * y + cx * z;  // about x by the tilt
                out.push_back({exact_from_double(cz * x - sz * y1 + t[0].get_d()),
                               exact_from_double(sz * x + cz * y1 + t[1].get_d()),
                               exact_from_double(z1 + t[2].get_d())});
            }
            return out;
        };
        if (name == "long-edge") {
            const Q len = 1 / eps;  // a bar of length 2/ε and thickness 2, on it a unit cube by one end
            s.P[0].points = box(len, Q(1), Q(1), v3(Q(0), Q(0), Q(0)));
            s.P[1].points = posed(box(qc(1, 2), qc(1, 2), qc(1, 2), v3(Q(0), Q(0), Q(0))),
                                  v3(len * qc(g.uniform(1, 9), 10), Q(0), qc(3, 2)));
        } else {
            const Q hx = qc(g.uniform(2, 10), 10), hy = qc(g.uniform(2, 10), 10), hz = qc(g.uniform(1, 5), 10);
            // Face to face: boxes of one size; touching: a table (half sides 2) under the tilted box,
            // so that its lowest edge lies on the table's top.
            s.P[0].points =
                name == "touching" ? box(Q(2), Q(2), hz, v3(Q(0), Q(0), Q(0))) : box(hx, hy, hz, v3(Q(0), Q(0), Q(0)));
            const Q gap = name == "face-to-face" ? eps * 2 * hz : Q(0);
            std::vector<Vec3q> b =
                posed(box(hx, hy, hz, v3(Q(0), Q(0), Q(0))), v3(qc(g.uniform(-5, 5), 20), Q(0), Q(0)));
            // Raised so that its lowest vertex lies exactly on P1's top, plus the gap.
            Q low = b[0][2];
            for (const Vec3q& v : b) low = std::min(low, v[2]);
            for (Vec3q& v : b) v[2] += hz - low + gap;
            s.P[1].points = b;
        }
    } else if (name == "scaled") {
        const Q k = 1024 * eps;
        s.P[0].points = {{Q(0), Q(0), Q(0)}, {2 * k, Q(0), Q(0)}, {Q(0), 2 * k, Q(0)}, {Q(0), Q(0), 2 * k}};
        s.P[1].points = box(k, k, k, v3(4 * k + k * qc(g.uniform(-5, 5), 10), k * qc(g.uniform(-5, 5), 10), k));
    } else if (name == "decomposition-gap") {
        // The cube [-1, 1]^3 cut by the plane n·x = 0 (n a random integer direction): each side's
        // vertices and the cut points on its edges; the upper hull moved by ε·n.
        const Vec3q n{Q(g.uniform(-3, 3)), Q(g.uniform(-3, 3)), Q(g.uniform(1, 3))};
        const std::vector<Vec3q> c = box(Q(1), Q(1), Q(1), v3(Q(0), Q(0), Q(0)));
        for (size_t a = 0; a < c.size(); ++a) {
            const Q da = dot(n, c[a]);
            (sgn(da) <= 0 ? s.P[0].points : s.P[1].points).push_back(c[a]);
            if (sgn(da) == 0) s.P[1].points.push_back(c[a]);
            for (size_t b = a + 1; b < c.size(); ++b) {
                int diff = 0;
                for (int k = 0; k < 3; ++k) diff += c[a][k] != c[b][k];
                const Q db = dot(n, c[b]);
                if (diff != 1 || sgn(da) * sgn(db) >= 0) continue;  // an edge the plane crosses inside
                const Q t = da / (da - db);
                Vec3q p;
                for (int k = 0; k < 3; ++k) p[k] = c[a][k] + t * (c[b][k] - c[a][k]);
                s.P[0].points.push_back(p);
                s.P[1].points.push_back(p);
            }
        }
        for (Vec3q& v : s.P[1].points)
            for (int k = 0; k < 3; ++k) v[k] += eps * n[k];
    } else if (name == "capsule-hull") {
        // A prism over 12 rational points of the unit circle (its inradius cos(atan(3/4)/2) > 0.94),
        // z in [-1, 1]; a capsule of radius 1/2 along x, its axis 1/2 + ε above the top face and
        // within the face's inscribed circle: ε apart at (1, 1).
        const Q a = qc(3, 5), b = qc(4, 5);
        for (const auto& [x, y] : std::vector<std::pair<Q, Q>>{{Q(1), Q(0)},
                                                               {b, a},
                                                               {a, b},
                                                               {Q(0), Q(1)},
                                                               {-a, b},
                                                               {-b, a},
                                                               {Q(-1), Q(0)},
                                                               {-b, -a},
                                                               {-a, -b},
                                                               {Q(0), Q(-1)},
                                                               {a, -b},
                                                               {b, -a}})
            for (int z : {-1, 1}) s.P[0].points.push_back({x, y, Q(z)});
        const Q x0 = qc(g.uniform(-2, 2), 10), y0 = qc(g.uniform(-2, 2), 10), z0 = Q(1) + qc(1, 2) + eps;
        s.P[1].points = {{x0 - qc(1, 2), y0, z0}, {x0 + qc(1, 2), y0, z0}};
        s.P[1].radius = qc(1, 2);
        s.P[1].radius_given = true;
    } else if (name == "far-spheres") {
        // Centres 1 − ε apart along a rational unit vector, radii 1/2: ε deep at (1, 1).
        const Vec3q o{Q(g.uniform(1, 9) * 1000000), Q(-g.uniform(1, 9) * 1000000), Q(g.uniform(1, 9) * 1000000)};
        const std::vector<Vec3q> units{
            {qc(2, 3), qc(1, 3), qc(2, 3)}, {qc(3, 5), qc(4, 5), Q(0)}, {qc(1, 3), qc(-2, 3), qc(2, 3)}};
        const Vec3q& u = units[static_cast<size_t>(g.uniform(0, 2))];
        s.P[0].points = {o};
        s.P[1].points = {{o[0] + (1 - eps) * u[0], o[1] + (1 - eps) * u[1], o[2] + (1 - eps) * u[2]}};
        s.P[0].radius = s.P[1].radius = qc(1, 2);
        s.P[0].radius_given = s.P[1].radius_given = true;
    } else if (name == "margin-hulls") {
        // Cubes of half side 1 with radii m1, m2; the upper one's bottom face m1 + m2 + ε above the
        // lower one's top, shifted by at most 1/2 sideways: ε apart at (1, 1).
        const Q m1 = qc(g.uniform(1, 4), 16), m2 = qc(g.uniform(1, 4), 16);
        s.P[0].points = box(Q(1), Q(1), Q(1), v3(Q(0), Q(0), Q(0)));
        s.P[1].points =
            box(Q(1), Q(1), Q(1), v3(qc(g.uniform(-5, 5), 10), qc(g.uniform(-5, 5), 10), 2 + m1 + m2 + eps));
        s.P[0].radius = m1;
        s.P[1].radius = m2;
        s.P[0].radius_given = s.P[1].radius_given = true;
    } else if (name == "sphere-box-edge") {
        // A box of half sides h; a sphere of radius r whose centre is (r + ε)(3/5, 0, 4/5) past the
        // edge x = hx, z = hz, beside it (|y| < hy): its nearest point of the box is on that edge.
        const Q hx = qc(g.uniform(5, 10), 10), hy = qc(g.uniform(5, 10), 10), hz = qc(g.uniform(5, 10), 10);
        const Q r = qc(g.uniform(1, 4), 8), y = hy * qc(g.uniform(-9, 9), 10);
        s.P[0].points = box(hx, hy, hz, v3(Q(0), Q(0), Q(0)));
        s.P[1].points = {{hx + (r + eps) * qc(3, 5), y, hz + (r + eps) * qc(4, 5)}};
        s.P[1].radius = r;
        s.P[1].radius_given = true;
    } else {
        family_description(name);  // throws for unknown names
    }
    finish(s, lo, hi);
    return s;
}

}  // namespace scalecert::internal
