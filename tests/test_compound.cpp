// Compounds: each part pair's overlap polygon in I1 × I2 and their union, against
// regions derived by hand and against a brute force that shares nothing with the Gauss-map
// overlay: the separating-axis test over every face normal of both parts and the cross product
// of every pair of their edges (a superset of the facet normals of A ⊕ (−B)).
#include <boost/test/unit_test.hpp>

#include "certify/claims.hpp"
#include "certify/compound_judge.hpp"
#include "certify/region_certificate.hpp"
#include "geometry/measures.hpp"
#include "compound/boundary.hpp"
#include "compound/locate.hpp"
#include "compound/region.hpp"
#include "support.hpp"

#include <optional>
#include <random>

using namespace scalecert::internal;

namespace {
Polyhedron box(int x0, int y0, int z0, int x1, int y1, int z1) {
    std::vector<Vec3q> v;
    for (int x : {x0, x1})
        for (int y : {y0, y1})
            for (int z : {z0, z1}) v.push_back({Q(x), Q(y), Q(z)});
    return build_polyhedron(v, "part");
}
const Q kLo[2] = {Q(1), Q(1)}, kHi[2] = {Q(4), Q(3)};

// Do A(ρ1) and B(ρ2) meet? No axis among the faces and edge pairs separates them.
// The separating-axis brute force for two convex parts scaled about their seeds: they meet iff no
// face normal of either and no cross product of an edge of each separates them. For r > 0 the
// projection of A(r) on n is n·s + r(n·p − n·s) over A's vertices p, so the extremes of n·p over the
// vertices are taken once per axis and each pair (r1, r2) costs a few products an axis.
struct SatPair {
    struct Axis {
        Q ns1, a_lo, a_hi, ns2, b_lo, b_hi;
    };
    std::vector<Axis> axes;
    SatPair(const Polyhedron& A, const Polyhedron& B, const Vec3q& s1, const Vec3q& s2) {
        std::vector<Vec3q> normals;
        for (const Face& f : A.faces) normals.push_back(to_q(f.normal));
        for (const Face& f : B.faces) normals.push_back(to_q(f.normal));
        for (const Edge& e : A.edges)
            for (const Edge& g : B.edges) {
                const Vec3q c = cross(sub(A.points[static_cast<size_t>(e.b)], A.points[static_cast<size_t>(e.a)]),
                                      sub(B.points[static_cast<size_t>(g.b)], B.points[static_cast<size_t>(g.a)]));
                if (sgn(c[0]) || sgn(c[1]) || sgn(c[2])) normals.push_back(c);
            }
        auto extremes = [](const Polyhedron& P, const Vec3q& n, Q& lo, Q& hi) {
            bool first = true;
            for (int v : P.vertices) {
                const Q t = dot(n, P.points[static_cast<size_t>(v)]);
                if (first || t < lo) lo = t;
                if (first || t > hi) hi = t;
                first = false;
            }
        };
        for (const Vec3q& n : normals) {
            Axis x{dot(n, s1), 0, 0, dot(n, s2), 0, 0};
            extremes(A, n, x.a_lo, x.a_hi);
            extremes(B, n, x.b_lo, x.b_hi);
            axes.push_back(std::move(x));
        }
    }
    bool meets(const Q& r1, const Q& r2) const {
        for (const Axis& x : axes) {
            const Q a0 = x.ns1 + r1 * (x.a_lo - x.ns1), a1 = x.ns1 + r1 * (x.a_hi - x.ns1);
            const Q b0 = x.ns2 + r2 * (x.b_lo - x.ns2), b1 = x.ns2 + r2 * (x.b_hi - x.ns2);
            if (a1 < b0 || b1 < a0) return false;
        }
        return true;
    }
};
bool meet_brute(const Polyhedron& A, const Polyhedron& B, const Vec3q& s1, const Vec3q& s2, const Q& r1, const Q& r2) {
    return SatPair(A, B, s1, s2).meets(r1, r2);
}
// Whether some part of P1(r1) meets some part of P2(r2), by SatPair on every part pair.
struct SatAll {
    std::vector<SatPair> pairs;
    SatAll(const std::vector<Polyhedron> (&parts)[2], const ExactScene& sc) {
        for (const Polyhedron& A : parts[0])
            for (const Polyhedron& B : parts[1]) pairs.emplace_back(A, B, sc.P[0].seed, sc.P[1].seed);
    }
    bool meets(const Q& r1, const Q& r2) const {
        for (const SatPair& p : pairs)
            if (p.meets(r1, r2)) return true;
        return false;
    }
};
bool inside_convex(const std::vector<Point2q>& p, const Point2q& x) {
    if (p.empty()) return false;
    if (p.size() == 1) return p[0] == x;
    if (p.size() == 2) {
        const Q c = (p[1][0] - p[0][0]) * (x[1] - p[0][1]) - (p[1][1] - p[0][1]) * (x[0] - p[0][0]);
        return sgn(c) == 0 && std::min(p[0][0], p[1][0]) <= x[0] && x[0] <= std::max(p[0][0], p[1][0]) &&
               std::min(p[0][1], p[1][1]) <= x[1] && x[1] <= std::max(p[0][1], p[1][1]);
    }
    for (size_t i = 0; i < p.size(); ++i) {
        const Point2q &a = p[i], &b = p[(i + 1) % p.size()];
        if (sgn((b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0])) < 0) return false;
    }
    return true;
}
// A random part of 4 to 8 points in a cube of side 6 at (ox, oy, 0), added to `in` and `parts`;
// false (and nothing added) when the points are flat.
bool add_random_part(std::mt19937& g, int ox, int oy, PolyInput& in, std::vector<Polyhedron>& parts) {
    std::uniform_int_distribution<int> c(-3, 3), np(4, 8);
    std::vector<Vec3q> v;
    for (int k = np(g); k > 0; --k) v.push_back({Q(c(g) + ox), Q(c(g) + oy), Q(c(g))});
    try {
        parts.push_back(build_polyhedron(v, "part"));
    } catch (const InputError&) {
        return false;
    }
    in.parts.push_back(v);
    in.points.insert(in.points.end(), v.begin(), v.end());
    return true;
}
// Two random compounds of three parts each (4 to 8 points in a cube of side 6 at random offsets,
// object 2 shifted by 7 along x), seeds anywhere in the plane z = 0, I1 = I2 = [1/4, 3]; the parts'
// polyhedra in `parts`.
ExactScene three_part_compounds(std::mt19937& g, std::vector<Polyhedron> parts[2]) {
    std::uniform_int_distribution<int> off(-5, 5);
    ExactScene sc;
    for (int i = 0; i < 2; ++i) {
        while (sc.P[i].parts.size() < 3) {
            const int ox = off(g) + (i ? 7 : 0), oy = off(g);
            add_random_part(g, ox, oy, sc.P[i], parts[i]);
        }
        sc.P[i].seed = {Q(off(g) + (i ? 7 : 0)), Q(off(g)), Q(0)};
        sc.P[i].seed_given = true;
        sc.lo[i] = Q(1, 4);
        sc.hi[i] = Q(3);
    }
    return sc;
}
}  // namespace

BOOST_AUTO_TEST_CASE(a_band_two_parts_either_side_of_the_seed) {
    // Object 1: the parts [2,3] x [-1,1]^2 and [-3,-2] x [-1,1]^2 about the seed 0, in neither.
    // Object 2: the box [4,5] x [-1,1]^2, seed (9/2, 0, 0). The right part spans
    // [2ρ1, 3ρ1] in x and [-ρ1, ρ1] in y and z; the box [9/2 − ρ2/2, 9/2 + ρ2/2] and [-ρ2, ρ2]. They
    // meet iff 3ρ1 >= 9/2 − ρ2/2 and 2ρ1 <= 9/2 + ρ2/2: a band, by hand. In I1 × I2 = [1,4] x [1,3]
    // its corners are (4/3, 1), (5/2, 1), (3, 3), (1, 3). The left part never meets the box.
    const Polyhedron right = box(2, -1, -1, 3, 1, 1), left = box(-3, -1, -1, -2, 1, 1), B = box(4, -1, -1, 5, 1, 1);
    const Vec3q s1{Q(0), Q(0), Q(0)}, s2{Q(9, 2), Q(0), Q(0)};
    const PairRegion r = pair_region(right, B, s1, s2, kLo, kHi);
    const std::vector<Point2q> band = {{Q(4, 3), Q(1)}, {Q(5, 2), Q(1)}, {Q(3), Q(3)}, {Q(1), Q(3)}};
    BOOST_TEST((r.polygon == band));
    // hA(+x) = 3, hB(+x) = 1/2, n·d = 9/2; hA(−x) = −2 (the seed outside the part).
    bool saw_plus = false, saw_minus = false;
    for (const HalfPlane& h : r.constraints) {
        if (h.normal == Vec3z{Z(1), Z(0), Z(0)}) saw_plus = h.a == 3 && h.b == Q(1, 2) && h.c == Q(9, 2);
        if (h.normal == Vec3z{Z(-1), Z(0), Z(0)}) saw_minus = h.a == -2 && h.b == Q(1, 2) && h.c == Q(-9, 2);
    }
    BOOST_TEST(saw_plus);
    BOOST_TEST(saw_minus);
    BOOST_TEST(pair_region(left, B, s1, s2, kLo, kHi).polygon.empty());
    // The union is the band: overlap, then apart again as ρ1 grows (at ρ2 = 2: from 7/6 to 11/4).
    const std::vector<RegionPiece> u = union_of({r.polygon, pair_region(left, B, s1, s2, kLo, kHi).polygon});
    BOOST_TEST_REQUIRE(u.size() == 1u);
    BOOST_TEST((u[0].outer == band));
    BOOST_TEST(u[0].holes.empty());
    BOOST_TEST(!inside_convex(band, {Q(1), Q(2)}));
    BOOST_TEST(inside_convex(band, {Q(7, 6), Q(2)}));
    BOOST_TEST(!inside_convex(band, {Q(7, 6) - Q(1, 1000), Q(2)}));
    BOOST_TEST(inside_convex(band, {Q(11, 4), Q(2)}));
    BOOST_TEST(!inside_convex(band, {Q(3), Q(2)}));
}

BOOST_AUTO_TEST_CASE(an_l_shape_against_a_box) {
    // Object 1, an L: [0,2] x [0,1] x [0,1] and [0,1] x [1,2] x [0,1], seed (1/2, 1/2, 1/2).
    // Object 2: the box [3,4] x [0,1] x [0,1], seed (7/2, 1/2, 1/2). Along x the L's first part
    // reaches 1/2 + 3ρ1/2 and the box starts at 7/2 − ρ2/2; in y and z both hold the seed's line,
    // so the pair meets iff 3ρ1 + ρ2 >= 6. The second part reaches x = 1/2 + ρ1/2: it meets iff
    // ρ1 + ρ2 >= 6 and its y-range [1/2 + ρ1/2, 1/2 + 3ρ1/2] meets the box's [1/2 − ρ2/2,
    // 1/2 + ρ2/2], i.e. ρ1 <= ρ2: in [1,4] x [1,3] only at (3, 3). The union is the first pair's.
    const Polyhedron a = box(0, 0, 0, 2, 1, 1), b = box(0, 1, 0, 1, 2, 1), B = box(3, 0, 0, 4, 1, 1);
    const Vec3q s1{Q(1, 2), Q(1, 2), Q(1, 2)}, s2{Q(7, 2), Q(1, 2), Q(1, 2)};
    const PairRegion ra = pair_region(a, B, s1, s2, kLo, kHi), rb = pair_region(b, B, s1, s2, kLo, kHi);
    const std::vector<Point2q> first = {{Q(5, 3), Q(1)}, {Q(4), Q(1)}, {Q(4), Q(3)}, {Q(1), Q(3)}};
    BOOST_TEST((ra.polygon == first));
    BOOST_TEST((rb.polygon == std::vector<Point2q>{{Q(3), Q(3)}}));
    const std::vector<RegionPiece> u = union_of({ra.polygon, rb.polygon});
    BOOST_TEST_REQUIRE(u.size() == 1u);
    BOOST_TEST((u[0].outer == first));
}

BOOST_AUTO_TEST_CASE(pair_regions_equal_the_separating_axis_brute_force) {
    // Random parts (4 to 9 points in a cube of side 8 at random offsets) about seeds anywhere,
    // at random exact pairs and at every corner of the region (on its boundary) and 2^-20 off it.
    std::mt19937 g(22);
    std::uniform_int_distribution<int> c(-4, 4), off(-6, 6), np(4, 9);
    long checked = 0, inside = 0;
    for (int t = 0; t < 40; ++t) {
        Polyhedron P[2];
        for (int i = 0; i < 2; ++i) {
            for (;;) {
                std::vector<Vec3q> v;
                const int o = off(g) + (i ? 6 : 0);
                for (int k = np(g); k > 0; --k) v.push_back({Q(c(g) + o), Q(c(g)), Q(c(g))});
                try {
                    P[i] = build_polyhedron(v, "part");
                    break;
                } catch (const InputError&) {  // flat: draw again
                }
            }
        }
        const Vec3q s1{Q(off(g)), Q(c(g)), Q(c(g))}, s2{Q(off(g) + 6), Q(c(g)), Q(c(g))};
        const Q lo[2] = {Q(1, 4), Q(1, 4)}, hi[2] = {Q(3), Q(3)};
        const PairRegion r = pair_region(P[0], P[1], s1, s2, lo, hi);
        std::vector<Point2q> probes;
        std::uniform_int_distribution<int> q(1, 120);
        for (int k = 0; k < 40; ++k) probes.push_back({test::qc(q(g), 40), test::qc(q(g), 40)});
        for (const Point2q& x : r.polygon)
            for (const Q& e : {Q(0), Q(1, 1 << 20), Q(-1, 1 << 20)}) probes.push_back({x[0] + e, x[1] - e});
        for (const Point2q& x : probes) {
            if (x[0] < lo[0] || x[0] > hi[0] || x[1] < lo[1] || x[1] > hi[1]) continue;
            const bool want = meet_brute(P[0], P[1], s1, s2, x[0], x[1]);
            BOOST_TEST(inside_convex(r.polygon, x) == want, "scene " << t << " at (" << x[0] << ", " << x[1] << ")");
            ++checked;
            inside += want;
        }
    }
    BOOST_TEST(inside > 50);
    std::cout << "compound pairs: " << checked << " pairs against the separating-axis brute force, " << inside
              << " meeting\n";
}

BOOST_AUTO_TEST_CASE(compound_verdicts_equal_the_brute_force_over_all_pairs) {
    // Random compounds of three parts each (seeds anywhere): the objects meet at a pair iff some
    // part pair does (separating-axis brute force), pruned pairs included; at random pairs and at
    // the corners of every pair polygon.
    std::mt19937 g(2022);
    long checked = 0, meeting = 0, pruned = 0;
    for (int t = 0; t < 12; ++t) {
        std::vector<Polyhedron> parts[2];
        const ExactScene sc = three_part_compounds(g, parts);
        const CompoundRegion r = compound_region(sc, "scene");
        pruned += r.pruned;
        std::vector<Point2q> probes;
        std::uniform_int_distribution<int> q(10, 120);
        for (int k = 0; k < 60; ++k) probes.push_back({test::qc(q(g), 40), test::qc(q(g), 40)});
        for (const auto& p : r.pairs)
            for (const Point2q& x : p.polygon) probes.push_back(x);
        const SatAll sat(parts, sc);
        for (const Point2q& x : probes) {
            const bool want = sat.meets(x[0], x[1]);
            const std::string v = verdict_name(compound_verdict(r, x[0], x[1]).verdict);
            BOOST_TEST((v != "separated") == want, "scene " << t << " at (" << x[0] << ", " << x[1] << "): " << v);
            ++checked;
            meeting += want;
        }
    }
    BOOST_TEST(meeting > 20);
    std::cout << "compound verdicts: " << checked << " pairs (" << meeting << " meeting), " << pruned
              << " part pairs pruned\n";
}

namespace {
// A compound scene from parts given as boxes [x0,x1] x [y0,y1] x [z0,z1] (in halves: x2 = 2x).
std::vector<Vec3q> box_points(const std::array<int, 6>& h) {
    std::vector<Vec3q> v;
    for (int x : {h[0], h[3]})
        for (int y : {h[1], h[4]})
            for (int z : {h[2], h[5]}) v.push_back({test::qc(x, 2), test::qc(y, 2), test::qc(z, 2)});
    return v;
}
ExactScene compound_scene(const std::vector<std::array<int, 6>> parts[2], const Vec3q seeds[2], const Q lo[2],
                          const Q hi[2]) {
    ExactScene sc;
    for (int i = 0; i < 2; ++i) {
        for (const auto& h : parts[i]) {
            sc.P[i].parts.push_back(box_points(h));
            sc.P[i].points.insert(sc.P[i].points.end(), sc.P[i].parts.back().begin(), sc.P[i].parts.back().end());
        }
        sc.P[i].seed = seeds[i];
        sc.P[i].seed_given = true;
        sc.lo[i] = lo[i];
        sc.hi[i] = hi[i];
    }
    return sc;
}
Q qs(const nlohmann::ordered_json& j) { return Q(j.get<std::string>()); }
}  // namespace

// The U and the peg (tests/data/compound_u_peg.json, coordinates doubled): a_u_shape_and_a_peg.
ExactScene u_peg_scene() {
    const std::vector<std::array<int, 6>> parts[2] = {
        {{-6, -2, 0, 6, 2, 2}, {-6, -2, 2, -4, 2, 8}, {4, -2, 2, 6, 2, 8}}, {{-2, -1, 4, 2, 1, 10}}};
    const Vec3q seeds[2] = {{Q(0), Q(0), Q(1, 2)}, {Q(0), Q(0), Q(7, 2)}};
    const Q lo[2] = {Q(1, 2), Q(1, 2)}, hi[2] = {Q(2), Q(3)};
    return compound_scene(parts, seeds, lo, hi);
}

BOOST_AUTO_TEST_CASE(a_u_shape_and_a_peg) {
    // Object 1, a U about the seed (0, 0, 1/2): the bottom [-3,3] x [-1,1] x [0,1] and the walls
    // [-3,-2] and [2,3] x [-1,1] x [1,4]. Object 2, the peg [-1,1] x [-1/2,1/2] x [2,5] about its
    // centre (0, 0, 7/2), in the slot. By hand, every part and the peg an axis box (so the axes are
    // the only facet normals), each interval about its seed's coordinate scaled by ρ:
    //   bottom: z up to 1/2 + ρ1/2, peg z from 7/2 − 3ρ2/2: they meet iff ρ1 + 3ρ2 >= 6 (x and y
    //     always overlap, both holding 0);
    //   left wall: x in [−3ρ1, −2ρ1], peg x from −ρ2: meet iff ρ2 >= 2ρ1 (its z-range
    //     [1/2 + ρ1/2, 1/2 + 7ρ1/2] reaches the peg's from 7ρ1 + 3ρ2 >= 6, which ρ2 >= 2ρ1 implies
    //     for ρ1 >= 6/13); the right wall the same by symmetry.
    // In [1/2, 2] x [1/2, 3]: the bottom's polygon (2, 4/3), (2, 3), (1/2, 3), (1/2, 11/6); each
    // wall's (1/2, 1), (3/2, 3), (1/2, 3). Their union is not convex: from (1/2, 1) up the wall's
    // line to where it crosses the bottom's (ρ1 + 6ρ1 = 6: (6/7, 12/7)), then the bottom's line.
    // On ρ1 = ρ2 only the bottom meets, from 4ρ = 6: the growth set is [3/2, 2].
    const ExactScene sc = u_peg_scene();
    const CompoundRegion r = compound_region(sc, "u_peg");
    BOOST_TEST_REQUIRE(r.pairs.size() == 3u);
    BOOST_TEST(r.pruned == 0);
    const std::vector<Point2q> bottom = {{Q(2), Q(4, 3)}, {Q(2), Q(3)}, {Q(1, 2), Q(3)}, {Q(1, 2), Q(11, 6)}};
    const std::vector<Point2q> wall = {{Q(1, 2), Q(1)}, {Q(3, 2), Q(3)}, {Q(1, 2), Q(3)}};
    BOOST_TEST((r.pairs[0].polygon == bottom));
    BOOST_TEST((r.pairs[1].polygon == wall));
    BOOST_TEST((r.pairs[2].polygon == wall));
    BOOST_TEST_REQUIRE(r.region.size() == 1u);
    BOOST_TEST(
        (r.region[0].outer ==
         std::vector<Point2q>{{Q(1, 2), Q(1)}, {Q(6, 7), Q(12, 7)}, {Q(2), Q(4, 3)}, {Q(2), Q(3)}, {Q(1, 2), Q(3)}}));
    BOOST_TEST_REQUIRE(r.growth.size() == 1u);
    BOOST_TEST(r.growth[0].from == Q(3, 2));
    BOOST_TEST(r.growth[0].to == Q(2));
    BOOST_TEST(r.growth[0].part1 == 0);
    // The certificate's fences, by hand: the bottom is cut by +z alone, the walls by +x and −x.
    const nlohmann::ordered_json cert = compound_partition_json(sc, r);
    BOOST_TEST_REQUIRE(cert["pairs"].size() == 3u);
    BOOST_TEST(cert["pairs"][0]["normals"] == nlohmann::ordered_json::parse(R"([["0", "0", "1"]])"));
    BOOST_TEST(cert["pairs"][1]["normals"] == nlohmann::ordered_json::parse(R"([["1", "0", "0"]])"));
    BOOST_TEST(cert["pairs"][2]["normals"] == nlohmann::ordered_json::parse(R"([["-1", "0", "0"]])"));
    BOOST_TEST(cert["pairs"][0]["witnesses"].size() == 4u);
    BOOST_TEST(verdict_name(compound_verdict(r, Q(1, 2), Q(1)).verdict) ==
               std::string("touching"));  // on the wall's line
    BOOST_TEST(verdict_name(compound_verdict(r, Q(6, 7), Q(12, 7) - Q(1, 100)).verdict) ==
               std::string("separated"));  // below the reflex corner
    BOOST_TEST(verdict_name(compound_verdict(r, Q(1), Q(3)).verdict) == std::string("overlapping"));
}

BOOST_AUTO_TEST_CASE(far_apart_parts_are_pruned_in_blocks) {
    // Object 1: a row of 6 unit cubes [3k, 3k + 1] x [0,1] x [0,1] (seed (8, 1/2, 1/2)); object 2:
    // 5 slabs [0,16] x [20 + 3k, 21 + 3k] x [0,1] (seed (8, 26, 1/2)). With I1 = I2 = [1/2, 1] the
    // swept boxes overlap along x (all within [0, 16]) and z (both hold [1/4, 3/4]), but object 1
    // stays in y <= 1 and object 2 in y >= 26 + (20 − 26) = 20: every pair is apart along y, part 1
    // below, so all 30 pairs are pruned and one block, normal +y, covers them.
    std::vector<std::array<int, 6>> parts[2];
    for (int k = 0; k < 6; ++k) parts[0].push_back({6 * k, 0, 0, 6 * k + 2, 2, 2});
    for (int k = 0; k < 5; ++k) parts[1].push_back({0, 40 + 6 * k, 0, 32, 42 + 6 * k, 2});
    const Vec3q seeds[2] = {{Q(8), Q(1, 2), Q(1, 2)}, {Q(8), Q(26), Q(1, 2)}};
    const Q lo[2] = {Q(1, 2), Q(1, 2)}, hi[2] = {Q(1), Q(1)};
    const CompoundRegion r = compound_region(compound_scene(parts, seeds, lo, hi), "rows");
    BOOST_TEST(r.pruned == 30);
    BOOST_TEST(r.built == 0);
    const nlohmann::ordered_json cert = compound_partition_json(compound_scene(parts, seeds, lo, hi), r);
    BOOST_TEST_REQUIRE(cert["pairs"].size() == 1u);
    BOOST_TEST(cert["pairs"][0]["P1_parts"] == nlohmann::ordered_json::parse("[0, 5]"));
    BOOST_TEST(cert["pairs"][0]["P2_parts"] == nlohmann::ordered_json::parse("[0, 4]"));
    BOOST_TEST(cert["pairs"][0]["normals"] == nlohmann::ordered_json::parse(R"([["0", "1", "0"]])"));
    BOOST_TEST(cert["growth_set"].empty());
}

BOOST_AUTO_TEST_CASE(certificate_polygons_equal_the_brute_force) {
    // Random compounds (three or four parts each, seeds anywhere): a point of I1 x I2 lies in some
    // pair polygon of the certificate iff some part pair meets there (separating-axis brute
    // force), at random points, at every polygon corner and 2^-16 off it; each polygon's witness
    // is at its corner; entries cover every pair once; a block of several pairs lists no polygon.
    std::mt19937 g(4242);
    std::uniform_int_distribution<int> c(-3, 3), off(-6, 6), np(4, 8), nparts(3, 4);
    long checked = 0, meeting = 0, blocks = 0;
    for (int t = 0; t < 10; ++t) {
        ExactScene sc;
        std::vector<Polyhedron> parts[2];
        for (int i = 0; i < 2; ++i) {
            const int want = nparts(g);
            while (static_cast<int>(sc.P[i].parts.size()) < want) {
                const int ox = off(g) * 2 + (i ? 9 : 0), oy = off(g);
                add_random_part(g, ox, oy, sc.P[i], parts[i]);
            }
            sc.P[i].seed = {Q(off(g) + (i ? 9 : 0)), Q(off(g)), Q(c(g))};
            sc.P[i].seed_given = true;
            sc.lo[i] = Q(1, 4);
            sc.hi[i] = Q(5, 2);
        }
        const CompoundRegion r = compound_region(sc, "scene");
        const nlohmann::ordered_json cert = compound_partition_json(sc, r);
        std::vector<std::vector<Point2q>> polys;
        std::set<std::pair<size_t, size_t>> covered;
        for (const auto& e : cert["pairs"]) {
            const size_t a0 = e["P1_parts"][0], a1 = e["P1_parts"][1], b0 = e["P2_parts"][0], b1 = e["P2_parts"][1];
            for (size_t a = a0; a <= a1; ++a)
                for (size_t b = b0; b <= b1; ++b) BOOST_TEST(covered.insert({a, b}).second);
            if (a0 != a1 || b0 != b1) {
                ++blocks;
                BOOST_TEST(e["vertices"].empty());
            }
            std::vector<Point2q> p;
            for (size_t k = 0; k < e["vertices"].size(); ++k) {
                p.push_back({qs(e["vertices"][k][0]), qs(e["vertices"][k][1])});
                BOOST_TEST(qs(e["witnesses"][k]["rho1"]) == p.back()[0]);
                BOOST_TEST(qs(e["witnesses"][k]["rho2"]) == p.back()[1]);
            }
            polys.push_back(p);
        }
        BOOST_TEST(covered.size() == parts[0].size() * parts[1].size());
        std::vector<Point2q> probes;
        std::uniform_int_distribution<int> q(10, 100);
        for (int k = 0; k < 50; ++k) probes.push_back({test::qc(q(g), 40), test::qc(q(g), 40)});
        for (const auto& p : polys)
            for (const Point2q& x : p)
                for (const Q& e : {Q(0), Q(1, 1 << 16), Q(-1, 1 << 16)}) probes.push_back({x[0] + e, x[1] - e});
        const SatAll sat(parts, sc);
        for (const Point2q& x : probes) {
            if (x[0] < sc.lo[0] || x[0] > sc.hi[0] || x[1] < sc.lo[1] || x[1] > sc.hi[1]) continue;
            const bool want = sat.meets(x[0], x[1]);
            bool got = false;
            for (const auto& p : polys) got = got || inside_convex(p, x);
            BOOST_TEST(got == want, "scene " << t << " at (" << x[0] << ", " << x[1] << ")");
            ++checked;
            meeting += want;
        }
    }
    BOOST_TEST(meeting > 20);
    std::cout << "compound certificates: " << checked << " points against the brute force (" << meeting << " meeting), "
              << blocks << " blocks of pruned pairs\n";
}

BOOST_AUTO_TEST_CASE(located_verdicts_equal_the_exact_ones) {
    // The grid's verdicts (locate.hpp) against compound_verdict, which tests every pair's every
    // constraint exactly, and against the separating-axis brute force for meeting: on the U and
    // peg (by hand: (1/2, 1) touches on the wall's line, (1, 3) overlaps, (2, 1) is apart) and on
    // random compounds, at random doubles, at the doubles nearest every polygon corner and its
    // neighbours, on every grid line and on the rectangle's edges; grids of 1 to 64 cells a side.
    const ExactScene usc = u_peg_scene();
    const Q *ulo = usc.lo, *uhi = usc.hi;
    const CompoundRegion ur = compound_region(usc, "u_peg");
    filter::PredicateStats st;
    for (int G : {1, 3, 16, 64}) {
        const CompoundLocator L(ur, ulo, uhi, G);
        BOOST_TEST(static_cast<int>(L.verdict(0.5, 1.0, st)) == 1);
        BOOST_TEST(static_cast<int>(L.verdict(1.0, 3.0, st)) == 2);
        BOOST_TEST(static_cast<int>(L.verdict(2.0, 1.0, st)) == 0);
        BOOST_TEST(static_cast<int>(L.verdict(0.5, std::nextafter(1.0, 0.0), st)) == 0);
    }
    std::mt19937 g(99);
    std::uniform_real_distribution<double> ur01(0, 1);
    long checked = 0, counts[3] = {0, 0, 0};
    for (int t = 0; t < 8; ++t) {
        std::vector<Polyhedron> parts[2];
        const ExactScene sc = three_part_compounds(g, parts);
        const CompoundRegion r = compound_region(sc, "scene");
        const SatAll sat(parts, sc);
        std::vector<std::pair<double, double>> probes;
        for (int k = 0; k < 300; ++k) probes.push_back({0.25 + 2.75 * ur01(g), 0.25 + 2.75 * ur01(g)});
        for (const auto& p : r.pairs)
            for (const Point2q& x : p.polygon)
                for (double e1 : {-1.0, 0.0, 1.0})
                    for (double e2 : {-1.0, 0.0, 1.0}) {
                        double a = x[0].get_d(), b = x[1].get_d();
                        if (e1) a = std::nextafter(a, e1 * INFINITY);
                        if (e2) b = std::nextafter(b, e2 * INFINITY);
                        probes.push_back({a, b});
                    }
        for (int G : {1, 5, 32}) {
            const CompoundLocator L(r, sc.lo, sc.hi, G);
            std::vector<std::pair<double, double>> all = probes;
            for (int k = 0; k <= G; ++k) {  // on the grid lines (as the locator draws them) and the rectangle's edges
                const double x = 0.25 + 2.75 * k / G;
                all.push_back({x, 0.25}), all.push_back({x, 3.0}), all.push_back({0.25, x}), all.push_back({3.0, x}),
                    all.push_back({x, x});
            }
            for (const auto& [a, b] : all) {
                const Q qa(a), qb(b);
                if (qa < sc.lo[0] || qa > sc.hi[0] || qb < sc.lo[1] || qb > sc.hi[1]) continue;
                const std::string want = verdict_name(compound_verdict(r, qa, qb).verdict);
                const int got = static_cast<int>(L.verdict(a, b, st));
                BOOST_TEST(std::string(got == 0   ? "separated"
                                       : got == 1 ? "touching"
                                                  : "overlapping") == want,
                           "scene " << t << " G " << G << " at (" << a << ", " << b << ")");
                if (G == 5) BOOST_TEST((got > 0) == sat.meets(qa, qb));
                ++checked;
                ++counts[got];
            }
        }
        const std::vector<Verdict> batch =
            CompoundLocator(r, sc.lo, sc.hi, 16).classify({1.0, 2.0, 0.25}, {1.0, 2.0, 3.0}, 2);
        for (int k = 0; k < 3; ++k) {
            const double a[3] = {1.0, 2.0, 0.25}, b[3] = {1.0, 2.0, 3.0};
            const std::string want = verdict_name(compound_verdict(r, Q(a[k]), Q(b[k])).verdict);
            BOOST_TEST(static_cast<int>(batch[static_cast<size_t>(k)]) == (want == "separated"  ? 0
                                                                           : want == "touching" ? 1
                                                                                                : 2));
        }
    }
    BOOST_TEST(counts[1] > 20);  // touching points (on polygon edges) were reached
    BOOST_TEST(counts[2] > 100);
    std::cout << "located verdicts: " << checked << " points (" << counts[0] << " separated, " << counts[1]
              << " touching, " << counts[2] << " overlapping), filter " << st[filter::Predicate::HalfPlaneSide].filtered
              << ", exact " << st[filter::Predicate::HalfPlaneSide].exact << "\n";
    BOOST_CHECK_THROW(CompoundLocator(ur, ulo, uhi, 4).verdict(0.4, 1.0, st), InputError);
}

namespace {
// A labelled contact edge as the test states it: its pair, label and the one tight normal.
void expect_contact(const BoundaryEdge& e, int p1, int p2, const CompoundRegion& r, const char* label, const Vec3z& n) {
    BOOST_TEST_REQUIRE(e.contact.has_value());
    const CompoundRegion::Pair& p = r.pairs[e.contact->pair];
    BOOST_TEST(p.part1 == p1);
    BOOST_TEST(p.part2 == p2);
    BOOST_TEST(e.contact->contact.label == label);
    BOOST_TEST_REQUIRE(e.contact->tight.size() == 1u);
    BOOST_TEST((p.constraints[e.contact->tight[0]].normal == n));
}
}  // namespace

BOOST_AUTO_TEST_CASE(the_u_and_peg_boundary_labelled_by_hand) {
    // The U and the peg of a_u_shape_and_a_peg. By hand: up the left wall's line ρ2 = 2ρ1 from
    // (1/2, 1) to (6/7, 12/7), the wall's inner face x = −2 against the peg's face x = −1, normal
    // +x (the left wall is the first of the two walls, whose polygons are equal); then the
    // bottom's line ρ1 + 3ρ2 = 6 to (2, 4/3), the bottom's top z = 1 against the peg's bottom
    // z = 2, normal +z (box_points lists a box's corners x-major, z fastest: the upper x face is
    // points 4..7, the lower 0..3, the upper z face 1, 3, 5, 7, the lower 0, 2, 4, 6);
    // then the rectangle's sides ρ1 = 2, ρ2 = 3, ρ1 = 1/2. One switch point, (6/7, 12/7), where the
    // pair changes and the peg touches the bottom and both walls, each face to face.
    const ExactScene sc = u_peg_scene();
    const CompoundRegion r = compound_region(sc, "u_peg");
    const CompoundBoundary b = label_boundary(r, sc);
    BOOST_TEST_REQUIRE(b.rings.size() == 1u);
    const std::vector<BoundaryEdge>& e = b.rings[0].edges;
    BOOST_TEST_REQUIRE(e.size() == 5u);
    BOOST_TEST((e[0].from == Point2q{Q(1, 2), Q(1)}));
    BOOST_TEST((e[0].to == Point2q{Q(6, 7), Q(12, 7)}));
    expect_contact(e[0], 1, 0, r, "FF", {Z(1), Z(0), Z(0)});
    BOOST_TEST((e[0].contact->contact.feat1 == std::vector<int>{4, 5, 6, 7}));
    BOOST_TEST((e[0].contact->contact.feat2 == std::vector<int>{0, 1, 2, 3}));
    BOOST_TEST((e[1].to == Point2q{Q(2), Q(4, 3)}));
    expect_contact(e[1], 0, 0, r, "FF", {Z(0), Z(0), Z(1)});
    BOOST_TEST((e[1].contact->contact.feat1 == std::vector<int>{1, 3, 5, 7}));
    BOOST_TEST((e[1].contact->contact.feat2 == std::vector<int>{0, 2, 4, 6}));
    BOOST_TEST(e[2].bound == 1);  // ρ1 = 2
    BOOST_TEST(e[3].bound == 3);  // ρ2 = 3
    BOOST_TEST(e[4].bound == 0);  // ρ1 = 1/2
    BOOST_TEST_REQUIRE(b.switches.size() == 1u);
    BOOST_TEST((b.switches[0].at == Point2q{Q(6, 7), Q(12, 7)}));
    BOOST_TEST(b.switches[0].pair_change);
    BOOST_TEST_REQUIRE(b.switches[0].contacts.size() == 3u);
    for (size_t k = 0; k < 3; ++k) {
        BOOST_TEST(r.pairs[b.switches[0].contacts[k].pair].part1 == static_cast<int>(k));
        BOOST_TEST(b.switches[0].contacts[k].contact.label == "FF");
    }
}

BOOST_AUTO_TEST_CASE(the_band_boundary_labelled_by_hand) {
    // The band of a_band_two_parts_either_side_of_the_seed: from (4/3, 1) along ρ2 = 1 to (5/2, 1);
    // up 2ρ1 = 9/2 + ρ2/2 to (3, 3), where the right part's face x = 2 (scaled to 2ρ1) has passed
    // the box's far face x = 5 (9/2 + ρ2/2): normal −x, a = hA(−x) = −2, b = 1/2, c = −9/2; back
    // along ρ2 = 3 to (1, 3); down 3ρ1 = 9/2 − ρ2/2, the part's face x = 3 reaching the box's near
    // face x = 4: normal +x. Face to face, and no switch point (each line runs side to side).
    const ExactScene sc = load_scene(std::string(SCALECERT_SOURCE_DIR) + "/tests/data/compound_band.json",
                                     ReadOptions{scalecert::Numbers::Exact, true, true});
    const CompoundRegion r = compound_region(sc, "band");
    const CompoundBoundary b = label_boundary(r, sc);
    BOOST_TEST_REQUIRE(b.rings.size() == 1u);
    const std::vector<BoundaryEdge>& e = b.rings[0].edges;
    BOOST_TEST_REQUIRE(e.size() == 4u);
    BOOST_TEST(e[0].bound == 2);
    expect_contact(e[1], 0, 0, r, "FF", {Z(-1), Z(0), Z(0)});
    const HalfPlane& h = r.pairs[e[1].contact->pair].constraints[e[1].contact->tight[0]];
    BOOST_TEST((h.a == -2 && h.b == Q(1, 2) && h.c == Q(-9, 2)));
    BOOST_TEST((e[1].from == Point2q{Q(5, 2), Q(1)} && e[1].to == Point2q{Q(3), Q(3)}));
    BOOST_TEST(e[2].bound == 3);
    expect_contact(e[3], 0, 0, r, "FF", {Z(1), Z(0), Z(0)});
    BOOST_TEST(b.switches.empty());
}

BOOST_AUTO_TEST_CASE(the_paper_fig5_sequence_on_the_region_boundary) {
    // The paper's Fig. 5 scene as a region of one part each: its boundary inside [4/5, 3]^2 runs
    // from (1, 3) (the curve ρ2 = 6 − 3ρ1 leaving ρ2 = 3) through the paper's sequence
    // (V1,F2) -> (V1,E2) -> (E1,E2) -> (E1,V2) -> (F1,V2): switch points (23/19, 45/19), a vertex of
    // P1 on an edge of P2, and (29/13, 18/13), an edge of P1 on a vertex of P2 (README, paper).
    const ExactScene sc = load_scene(std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/fig5_vf_ve_ee.json",
                                     ReadOptions{scalecert::Numbers::Exact, true, true});
    const CompoundRegion r = compound_region(sc, "fig5");
    const CompoundBoundary b = label_boundary(r, sc);
    BOOST_TEST_REQUIRE(b.rings.size() == 1u);
    std::string seq;
    for (const BoundaryEdge& e : b.rings[0].edges)
        if (e.contact) seq += e.contact->contact.label + " ";
    BOOST_TEST(seq == "VF EE FV ");
    BOOST_TEST_REQUIRE(b.switches.size() == 2u);
    BOOST_TEST((b.switches[0].at == Point2q{Q(23, 19), Q(45, 19)}));
    BOOST_TEST((b.switches[1].at == Point2q{Q(29, 13), Q(18, 13)}));
    BOOST_TEST_REQUIRE(b.switches[0].contacts.size() == 1u);
    BOOST_TEST_REQUIRE(b.switches[1].contacts.size() == 1u);
    BOOST_TEST(b.switches[0].contacts[0].contact.label == "VE");
    BOOST_TEST(b.switches[1].contacts[0].contact.label == "EV");
    BOOST_TEST(!b.switches[0].pair_change);
}

BOOST_AUTO_TEST_CASE(boundary_labels_equal_the_brute_force_contacts) {
    // Random compounds (three parts each, seeds anywhere): at the middle of every contact edge of
    // the region's boundary the labelled pair meets and no pair overlaps (separating-axis brute
    // force), and its features are the brute force's smallest faces holding the touching set (over
    // every cross product of point-to-point directions, support/brute_contact: no Gauss map). At
    // every switch point the listed pairs are exactly those that meet there, each with the brute
    // force's features.
    std::mt19937 g(2211);
    long edges = 0, switches = 0, contacts = 0, contact_changes = 0;
    for (int t = 0; t < 12; ++t) {
        std::vector<Polyhedron> parts[2];
        const ExactScene sc = three_part_compounds(g, parts);
        const CompoundRegion r = compound_region(sc, "scene");
        const CompoundBoundary b = label_boundary(r, sc);
        // The brute force's features of pair (a, b) at x, restricted to the parts' vertices.
        auto brute = [&](int a, int bb, const Point2q& x) {
            ExactScene one;
            one.P[0].points = sc.P[0].parts[static_cast<size_t>(a)];
            one.P[1].points = sc.P[1].parts[static_cast<size_t>(bb)];
            for (int i = 0; i < 2; ++i) one.P[i].seed = sc.P[i].seed;
            auto [f1, f2] = test::brute_contact(one, x[0], x[1]);
            const Polyhedron* P[2] = {&parts[0][static_cast<size_t>(a)], &parts[1][static_cast<size_t>(bb)]};
            std::vector<int>* f[2] = {&f1, &f2};
            for (int i = 0; i < 2; ++i)
                f[i]->erase(std::remove_if(f[i]->begin(), f[i]->end(),
                                           [&](int v) {
                                               return std::find(P[i]->vertices.begin(), P[i]->vertices.end(), v) ==
                                                      P[i]->vertices.end();
                                           }),
                            f[i]->end());
            return std::pair{f1, f2};
        };
        auto meets = [&](size_t a, size_t bb, const Point2q& x) {
            return meet_brute(parts[0][a], parts[1][bb], sc.P[0].seed, sc.P[1].seed, x[0], x[1]);
        };
        for (const BoundaryRing& ring : b.rings)
            for (const BoundaryEdge& e : ring.edges) {
                if (!e.contact) continue;
                const Point2q mid{(e.from[0] + e.to[0]) / 2, (e.from[1] + e.to[1]) / 2};
                const CompoundRegion::Pair& p = r.pairs[e.contact->pair];
                BOOST_TEST(meets(static_cast<size_t>(p.part1), static_cast<size_t>(p.part2), mid));
                const auto [f1, f2] = brute(p.part1, p.part2, mid);
                BOOST_TEST((f1 == e.contact->contact.feat1), "scene " << t);
                BOOST_TEST((f2 == e.contact->contact.feat2), "scene " << t);
                BOOST_TEST(verdict_name(compound_verdict(r, mid[0], mid[1]).verdict) == std::string("touching"));
                ++edges;
            }
        for (const CompoundSwitch& s : b.switches) {
            std::vector<std::pair<int, int>> want, got;
            for (size_t a = 0; a < parts[0].size(); ++a)
                for (size_t bb = 0; bb < parts[1].size(); ++bb)
                    if (meets(a, bb, s.at)) want.push_back({static_cast<int>(a), static_cast<int>(bb)});
            for (const PairContact& c : s.contacts) {
                const CompoundRegion::Pair& p = r.pairs[c.pair];
                got.push_back({p.part1, p.part2});
                const auto [f1, f2] = brute(p.part1, p.part2, s.at);
                BOOST_TEST((f1 == c.contact.feat1), "scene " << t << " switch");
                BOOST_TEST((f2 == c.contact.feat2), "scene " << t << " switch");
                ++contacts;
            }
            BOOST_TEST((got == want), "scene " << t << " switch pairs");
            ++switches;
            contact_changes += !s.pair_change;
        }
    }
    BOOST_TEST(edges > 20);
    BOOST_TEST(switches > 5);
    BOOST_TEST(contact_changes > 5);  // a pair's own contact changing: two tight normals (contact_on_line)
    std::cout << "compound boundaries: " << edges << " contact edges and " << switches << " switch points ("
              << contact_changes << " within one pair; " << contacts << " pair contacts) against the brute force\n";
}

BOOST_AUTO_TEST_CASE(wedges_sharing_two_lines_each_labelled_by_its_own_pair) {
    // Object 1: six slabs x in [101 c, 100 c + 25/4] (c = 1/2 + k/4), y in [1, 100], z in [-100, 1],
    // seed 0; object 2: the box [100, 101] x [3/2, 5/2]^2, seed (0, 7/2, 5/2). By hand, slab k meets
    // the box iff ρ1 + ρ2 >= 5/2 (z: the slab's top ρ1 against the box's bottom 5/2 − ρ2),
    // ρ1 + ρ2 <= 7/2 (y: the slab's ρ1 against the box's 7/2 − ρ2) and c <= ρ2/ρ1 <= c + 1/16
    // (x). So six disjoint quadrilaterals, all on the same two lines: each ring is its own pair's,
    // four face-to-face edges, four corners where two faces' edges cross (EE). (Slivers: pair edges
    // on shared lines must not be scanned in full for each ring edge.)
    std::vector<std::array<int, 6>> parts[2];
    ExactScene sc;
    for (int k = 0; k < 6; ++k) {
        const Q c = Q(1, 2) + Q(k, 4), x0 = 101 * c, x1 = 100 * c + Q(25, 4);
        std::vector<Vec3q> v;
        for (const Q& x : {x0, x1})
            for (int y : {1, 100})
                for (int z : {-100, 1}) v.push_back({x, Q(y), Q(z)});
        sc.P[0].parts.push_back(v);
        sc.P[0].points.insert(sc.P[0].points.end(), v.begin(), v.end());
    }
    for (int x : {100, 101})
        for (const Q& y : {Q(3, 2), Q(5, 2)})
            for (const Q& z : {Q(3, 2), Q(5, 2)}) sc.P[1].points.push_back({Q(x), y, z});
    sc.P[1].parts.push_back(sc.P[1].points);
    sc.P[0].seed = {Q(0), Q(0), Q(0)};
    sc.P[1].seed = {Q(0), Q(7, 2), Q(5, 2)};
    for (int i = 0; i < 2; ++i) sc.P[i].seed_given = true, sc.lo[i] = Q(1, 2), sc.hi[i] = Q(3);
    const CompoundRegion r = compound_region(sc, "wedges");
    const CompoundBoundary b = label_boundary(r, sc);
    BOOST_TEST_REQUIRE(b.rings.size() == 6u);
    std::set<int> seen;
    for (const BoundaryRing& ring : b.rings) {
        BOOST_TEST_REQUIRE(ring.edges.size() == 4u);
        const int part = r.pairs[ring.edges[0].contact->pair].part1;
        seen.insert(part);
        int on_sum_lines = 0;
        for (const BoundaryEdge& e : ring.edges) {
            BOOST_TEST_REQUIRE(e.contact.has_value());
            BOOST_TEST(r.pairs[e.contact->pair].part1 == part);  // its own pair, not the first on the line
            BOOST_TEST(e.contact->contact.label == "FF");
            const HalfPlane& h = r.pairs[e.contact->pair].constraints[e.contact->line];
            on_sum_lines += h.a == h.b && (h.c / h.a == Q(5, 2) || h.c / h.a == Q(7, 2));
        }
        BOOST_TEST(on_sum_lines == 2);
    }
    BOOST_TEST(seen.size() == 6u);
    BOOST_TEST_REQUIRE(b.switches.size() == 24u);
    for (const CompoundSwitch& s : b.switches) {
        BOOST_TEST(!s.pair_change);
        BOOST_TEST_REQUIRE(s.contacts.size() == 1u);
        BOOST_TEST(s.contacts[0].contact.label == "EE");
    }
}

BOOST_AUTO_TEST_CASE(a_normal_tight_everywhere_holds_no_edge) {
    // Both seeds at the origin, on the plane x = 0 that holds a face of each part: P1's part
    // [0,2] x [-1,1]^2 spans x in [0, 2ρ1], P2's [-2,0] x [3,5] x [-1,1] spans x in [-2ρ2, 0], so the
    // normal −x (hA = hB = 0, n·d = 0) touches at every (ρ1, ρ2) and the parts never overlap; in y,
    // [-ρ1, ρ1] reaches [3ρ2, 5ρ2] iff ρ1 >= 3ρ2. The one contact edge, from (4, 4/3) to
    // (3/2, 1/2), lies on ρ1 − 3ρ2 = 0 (normal +y: hA = 1, hB = −3), not on −x's 0 = 0; the parts
    // touch along edges: x = 0, y = 1 of P1's part and x = 0, y = 3 of P2's.
    const std::vector<std::array<int, 6>> parts[2] = {{{0, -2, -2, 4, 2, 2}}, {{-4, 6, -2, 0, 10, 2}}};
    const Vec3q seeds[2] = {{Q(0), Q(0), Q(0)}, {Q(0), Q(0), Q(0)}};
    const Q lo[2] = {Q(1), Q(1, 2)}, hi[2] = {Q(4), Q(2)};
    const ExactScene sc = compound_scene(parts, seeds, lo, hi);
    const CompoundRegion r = compound_region(sc, "flat");
    const CompoundBoundary b = label_boundary(r, sc);
    BOOST_TEST_REQUIRE(b.rings.size() == 1u);
    int contacts = 0;
    for (const BoundaryEdge& e : b.rings[0].edges) {
        if (!e.contact) continue;
        ++contacts;
        BOOST_TEST((e.from == Point2q{Q(4), Q(4, 3)} && e.to == Point2q{Q(3, 2), Q(1, 2)}));
        const HalfPlane& h = r.pairs[e.contact->pair].constraints[e.contact->line];
        BOOST_TEST((h.normal == Vec3z{Z(0), Z(1), Z(0)} && h.a == 1 && h.b == -3 && h.c == 0));
        BOOST_TEST(e.contact->contact.label == "EE");
        BOOST_TEST(e.contact->tight.size() == 2u);  // −x and +y
    }
    BOOST_TEST(contacts == 1);
    BOOST_TEST(verdict_name(compound_verdict(r, Q(3), Q(1, 2)).verdict) ==
               std::string("touching"));  // inside the polygon, yet touching
}

// ---- certify-fp on compounds ------------------------------------------------------------------
namespace {
// certify-fp's JSON claims on a scene of parts: each judgement, and the certificate text.
std::vector<bool> judge_claims(const ExactScene& sc, const std::string& claims, std::string* certificate = nullptr,
                               const Q& tol = Q(0)) {
    CompoundJudge judge(sc, "scene");
    long wrong = 0;
    const std::string rep = certify_fp(judge, claims, "claims", ClaimOptions{scalecert::Numbers::Double, tol, true},
                                       &wrong, nullptr, certificate);
    std::vector<bool> right;
    const auto report = nlohmann::ordered_json::parse(rep);
    for (const auto& c : report["claims"]) right.push_back(c["right"].get<bool>());
    return right;
}
ExactScene band_scene() {
    const std::vector<std::array<int, 6>> parts[2] = {{{4, -2, -2, 6, 2, 2}, {-6, -2, -2, -4, 2, 2}},
                                                      {{8, -2, -2, 10, 2, 2}}};
    const Vec3q seeds[2] = {{Q(0), Q(0), Q(0)}, {Q(9, 2), Q(0), Q(0)}};
    return compound_scene(parts, seeds, kLo, kHi);
}
}  // namespace

BOOST_AUTO_TEST_CASE(band_claims_judged_by_hand) {
    // The band (a_band_two_parts_either_side_of_the_seed): the right part spans [2ρ1, 3ρ1] in x,
    // the left [−3ρ1, −2ρ1], the box [9/2 − ρ2/2, 9/2 + ρ2/2]; y and z always overlap.
    //  (1, 2): right part [2, 3], box [7/2, 11/2]: apart by 1/2 along x (the left by 11/2).
    //  (1, 3): box [3, 6]: touches the right part at x = 3. (7/6, 2): [7/3, 7/2] touches at 7/2.
    //  (3/2, 2): [3, 9/2] and [7/2, 11/2] overlap. (3, 2): [6, 9] is past the box, [−9, −6] before
    //  it: separated, 1/2 apart (from x = 11/2 to 6), and no plane separates the two objects (the
    //  box lies between the parts). (4, 3/2, 3/2) at (3/2, 2) is on an edge of the right part, inside the box.
    const std::string claims = R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "separated"},
     {"kind": "verdict", "rho1": 1, "rho2": 3, "verdict": "touching"},
     {"kind": "verdict", "rho1": "7/6", "rho2": 2, "verdict": "touching"},
     {"kind": "verdict", "rho1": 1.5, "rho2": 2, "verdict": "overlapping"},
     {"kind": "verdict", "rho1": 3, "rho2": 2, "verdict": "intersecting"},
     {"kind": "verdict", "rho1": 3, "rho2": 2, "verdict": "separated"},
     {"kind": "distance", "rho1": 1, "rho2": 2, "value": 0.5, "closest": [[3, 0, 0], [3.5, 0, 0]]},
     {"kind": "distance", "rho1": 1, "rho2": 2, "value": 0.5, "closest": [[3, 0, 0], [3.5, 2.5, 0]]},
     {"kind": "distance", "rho1": 3, "rho2": 2, "value": 0.5, "closest": [[6, 1, 1], [5.5, 1, 1]]},
     {"kind": "distance", "rho1": 3, "rho2": 2, "value": 5.5},
     {"kind": "distance", "rho1": 1.5, "rho2": 2, "value": 0},
     {"kind": "separating_plane", "rho1": 1, "rho2": 2, "normal": [1, 0, 0], "offset": 3.25},
     {"kind": "separating_plane", "rho1": 3, "rho2": 2, "normal": [1, 0, 0]},
     {"kind": "separating_plane", "rho1": 3, "rho2": 2, "normal": [-1, 0, 0]},
     {"kind": "witness_point", "rho1": 1.5, "rho2": 2, "point": [4, 0, 0]},
     {"kind": "witness_point", "rho1": 1.5, "rho2": 2, "point": [-4, 0, 0]},
     {"kind": "witness_point", "rho1": 1.5, "rho2": 2, "point": [4, 1.5, 1.5]}
    ]})";
    const std::vector<bool> want = {true,  true, true, true,  false, true, true,  false, true,
                                    false, true, true, false, false, true, false, true};
    const std::vector<bool> got = judge_claims(band_scene(), claims);
    BOOST_TEST_REQUIRE(got.size() == want.size());
    for (size_t k = 0; k < want.size(); ++k) BOOST_TEST(got[k] == want[k], "claim " << k);
    // The exact values: at (3, 2) the least distance is the right part's (squared 1/4), not the left's.
    CompoundJudge judge(band_scene(), "band");
    const CompoundJudge::Distance d = judge.distance(Q(3), Q(2));
    BOOST_TEST(d.squared == Q(1, 4));
    BOOST_TEST(d.part1 == 0);
    BOOST_TEST(static_cast<int>(judge.verdict(Q(3, 2), Q(2)).verdict) == 2);
    BOOST_TEST(static_cast<int>(judge.verdict(Q(7, 6), Q(2)).verdict) == 1);
    BOOST_TEST(static_cast<int>(judge.verdict(Q(7, 6) - Q(1, 1000), Q(2)).verdict) == 0);
    BOOST_TEST(judge.locate(0, Q(3, 2), {Q(-4), Q(0), Q(0)}) == 1);  // in the left part
}

BOOST_AUTO_TEST_CASE(u_and_peg_claims_judged_by_hand) {
    // The U and peg (a_u_shape_and_a_peg): the bottom's top at z = (1 + ρ1)/2, the peg's bottom at
    // 7/2 − 3ρ2/2 (they meet on ρ1 + 3ρ2 >= 6); the right wall from x = 2ρ1, the peg to x = ρ2
    // (they meet on ρ2 >= 2ρ1). (1, 1): 1 apart in z from the bottom and 1 in x from each wall:
    // separated, distance 1, and no plane: the walls rise past the peg's bottom. (1, 3/2): 1/4 from
    // the bottom (z 1 to 5/4), 1/2 from the walls. (1, 2): the peg's bottom at 1/2 sinks into the
    // bottom (z up to 1) with x in [−2, 2] and y in [−1, 1]: overlapping. (6/7, 12/7): all three touch.
    const std::string claims = R"({"format": "scalecert-claims-1", "claims": [
     {"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated"},
     {"kind": "distance", "rho1": 1, "rho2": 1, "value": 1},
     {"kind": "separating_plane", "rho1": 1, "rho2": 1, "normal": [0, 0, 1]},
     {"kind": "distance", "rho1": 1, "rho2": 1.5, "value": 0.25, "closest": [[0, 0, 1], [0, 0, 1.25]]},
     {"kind": "distance", "rho1": 1, "rho2": 1.5, "value": 0.5},
     {"kind": "verdict", "rho1": 1, "rho2": 2, "verdict": "overlapping"},
     {"kind": "verdict", "rho1": "6/7", "rho2": "12/7", "verdict": "touching"},
     {"kind": "witness_point", "rho1": "6/7", "rho2": "12/7", "point": ["12/7", 0, 1]}
    ]})";
    const std::vector<bool> want = {true, true, false, true, false, true, true, true};
    std::string cert;
    const std::vector<bool> got = judge_claims(u_peg_scene(), claims, &cert);
    BOOST_TEST_REQUIRE(got.size() == want.size());
    for (size_t k = 0; k < want.size(); ++k) BOOST_TEST(got[k] == want[k], "claim " << k);
    const auto j = nlohmann::ordered_json::parse(cert);
    BOOST_TEST(j["kind"] == "compound_judgements");
    BOOST_TEST(j["judgements"][6]["proof"]["verdict"] == "touching");
    BOOST_TEST(j["judgements"][1]["proof"]["squared"] == "1");
}

BOOST_AUTO_TEST_CASE(compound_judgements_equal_the_brute_force) {
    // Random compounds (three_part_compounds), at random pairs and at the corners of the pair
    // polygons (compound_region): the verdict against the brute force over every part pair
    // (test::Brute: every cross product of point differences, no hull), and the distance against
    // the least of CGAL's exact polytope distance over every pair (all vertices).
    std::mt19937 g(7077);
    long checked = 0, kinds[3] = {0, 0, 0};
    for (int t = 0; t < 12; ++t) {
        std::vector<Polyhedron> parts[2];
        const ExactScene sc = three_part_compounds(g, parts);
        CompoundJudge judge(sc, "scene");
        std::uniform_int_distribution<int> q(10, 120);
        // Random pairs, and the corners of every pair's polygon in I1 × I2 (touching or more).
        std::vector<Point2q> probes;
        for (int k = 0; k < 12; ++k) probes.push_back({test::qc(q(g), 40), test::qc(q(g), 40)});
        for (const auto& p : compound_region(sc, "scene", false).pairs)
            for (const Point2q& x : p.polygon) probes.push_back(x);
        // Each pair's brute force and exact model, built once.
        std::vector<ExactScene> pairs;
        std::vector<test::Brute> brutes;
        std::vector<HullModel> models;
        for (size_t a = 0; a < 3; ++a)
            for (size_t b = 0; b < 3; ++b) {
                ExactScene pair;
                pair.P[0].points = sc.P[0].parts[a];
                pair.P[1].points = sc.P[1].parts[b];
                pair.P[0].seed = sc.P[0].seed;
                pair.P[1].seed = sc.P[1].seed;
                brutes.emplace_back(pair);
                pairs.push_back(std::move(pair));
                HullModel hm;
                hm.P[0] = parts[0][a];
                hm.P[1] = parts[1][b];
                hm.s[0] = sc.P[0].seed;
                hm.s[1] = sc.P[1].seed;
                models.push_back(std::move(hm));
            }
        for (const Point2q& x : probes) {
            const Q &r1 = x[0], &r2 = x[1];
            int want = 0;  // 0 separated, 1 touching, 2 overlapping
            Q least = -1;
            for (size_t k = 0; k < pairs.size(); ++k) {
                want = std::max(want, 1 - brutes[k].classify(pairs[k], r1, r2));
                const Q e = exact_distance(models[k], r1, r2).squared;
                if (least < 0 || e < least) least = e;
            }
            Json proof;
            BOOST_TEST(static_cast<int>(judge.verdict(r1, r2, &proof).verdict) == want,
                       "scene " << t << " at (" << r1 << ", " << r2 << ")");
            BOOST_TEST(judge.distance(r1, r2, &proof).squared == least,
                       "scene " << t << " at (" << r1 << ", " << r2 << ")");
            ++kinds[want];
            ++checked;
        }
    }
    BOOST_TEST(kinds[0] > 10);
    BOOST_TEST(kinds[1] > 10);
    BOOST_TEST(kinds[2] > 10);
    std::cout << "compound judgements: " << checked << " pairs (" << kinds[0] << " separated, " << kinds[1]
              << " touching, " << kinds[2] << " overlapping)\n";
}

BOOST_AUTO_TEST_CASE(compound_distances_over_grids_equal_the_brute_force) {
    // Two grids of 4 x 4 random parts, 4 apart, side by side: at each separated pair of scalings
    // many part pairs lie about as far apart as the nearest, so the distance proves most of them by
    // their boxes or by the slab along their double GJK direction, measures the nearest exactly,
    // and must still equal the least of CGAL's exact polytope distance over every pair. The
    // verdicts and the plane extents against every vertex, likewise.
    std::mt19937 g(4242);
    ExactScene sc;
    std::vector<Polyhedron> parts[2];
    for (int i = 0; i < 2; ++i) {
        for (int k = 0; k < 16; ++k)
            while (!add_random_part(g, (i ? 22 : 0) + (k % 4) * 4, (k / 4) * 4, sc.P[i], parts[i])) {}
        sc.P[i].seed = {Q(i ? 28 : 6), Q(6), Q(0)};
        sc.P[i].seed_given = true;
        sc.lo[i] = Q(1, 4);
        sc.hi[i] = Q(3);
    }
    CompoundJudge judge(sc, "grids");
    std::uniform_int_distribution<int> q(10, 60);
    long separated = 0;
    for (int t = 0; t < 12; ++t) {
        const Q r1 = test::qc(q(g), 40), r2 = test::qc(q(g), 40);
        Q least = -1;
        for (size_t a = 0; a < parts[0].size(); ++a)
            for (size_t b = 0; b < parts[1].size(); ++b) {
                HullModel hm;
                hm.P[0] = parts[0][a];
                hm.P[1] = parts[1][b];
                hm.s[0] = sc.P[0].seed;
                hm.s[1] = sc.P[1].seed;
                const Q e = exact_distance(hm, r1, r2).squared;
                if (least < 0 || e < least) least = e;
            }
        Json proof;
        const CompoundJudge::Distance d = judge.distance(r1, r2, t % 2 ? &proof : nullptr);
        BOOST_TEST(d.squared == least, "at (" << r1 << ", " << r2 << ")");
        BOOST_TEST((judge.verdict(r1, r2).verdict == Verdict::Separated) == (sgn(least) > 0));
        separated += sgn(least) > 0;
        // A plane's extents: every vertex of every part, scaled.
        const Vec3q n{Q(1), Q(t - 6, 7), Q(1, 3)};
        std::optional<Q> ext[2];  // max over P1(ρ1), min over P2(ρ2)
        for (int i = 0; i < 2; ++i)
            for (const Polyhedron& P : parts[i])
                for (int v : P.vertices) {
                    const Vec3q& x = P.points[static_cast<size_t>(v)];
                    const Vec3q& s = sc.P[i].seed;
                    const Q& rho = i ? r2 : r1;
                    const Q e = n[0] * (s[0] + rho * (x[0] - s[0])) + n[1] * (s[1] + rho * (x[1] - s[1])) +
                                n[2] * (s[2] + rho * (x[2] - s[2]));
                    if (!ext[i] || (i == 0 ? e > *ext[i] : e < *ext[i])) ext[i] = e;
                }
        const std::pair<Q, Q> got = judge.plane_extents(n, r1, r2);
        BOOST_TEST((got.first == *ext[0] && got.second == *ext[1]));
    }
    BOOST_TEST(separated > 6);
    BOOST_TEST(judge.counts().slabs > 0);
    std::cout << "compound grids: " << separated << " separated pairs of scalings, " << judge.counts().distances
              << " exact distances, " << judge.counts().slabs << " slabs\n";
}
