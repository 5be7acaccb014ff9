// Objects with a radius (CLAIMS.md, "Objects with a radius"): CLAIMS.md's hand-derived cases, then
// a brute force in rationals that shares nothing with the engine (closed forms for a point, a
// segment and a box: no hull, no GJK, no EPA) over random spheres, capsules and rounded boxes at
// poses, every claim kind judged right and wrong.
#include <boost/test/unit_test.hpp>

#include "certify/rounded.hpp"
#include "session/engine.hpp"
#include "support.hpp"

#include <cmath>
#include <random>

using namespace scalecert::internal;

namespace {

struct Case {
    std::shared_ptr<const ExactScene> scene;
    std::unique_ptr<SceneEngine> engine;
    std::unique_ptr<ClaimRules> rules;
};
Case open_text(const std::string& json, const Tolerance& tol = {}) {
    Case c;
    c.scene = std::make_shared<const ExactScene>(parse_scene_text(json, "scene", "."));
    c.engine = open_engine(c.scene, "scene");
    c.engine->check();
    c.rules = c.engine->rules(tol);
    return c;
}
TypedClaim claim(ClaimType t, const Q& r1, const Q& r2) {
    TypedClaim c;
    c.type = t;
    c.rho1 = r1;
    c.rho2 = r2;
    return c;
}
TypedClaim value_claim(ClaimType t, const Q& r1, const Q& r2, const Q& v) {
    TypedClaim c = claim(t, r1, r2);
    c.value = v;
    return c;
}
Verdict verdict_of(Case& k, const Q& r1, const Q& r2) { return k.engine->verdict(r1, r2); }
bool right(Case& k, const TypedClaim& c) { return k.rules->judge(c).right; }
Q q(long p, long d = 1) { return test::qc(p, d); }

// The double nearest x = s·√E + k, by long double (a display of the brute force, not a decision).
long double approx(int s, const Q& E, const Q& k) {
    return static_cast<long double>(s) * std::sqrt(static_cast<long double>(E.get_d())) + k.get_d();
}

}  // namespace

// Two spheres: P1 radius 1 at 0, P2 radius 2 at (5, 0, 0). At (ρ1, ρ2) the centres stay 5 apart
// and R = ρ1 + 2ρ2: the signed distance is 5 − ρ1 − 2ρ2 (CLAIMS.md's first case).
BOOST_AUTO_TEST_CASE(two_spheres_by_hand) {
    Case k = open_text(R"({"P1": {"sphere": 1}, "P2": {"sphere": 2, "pose": [[1,0,0,5],[0,1,0,0],[0,0,1,0]]}})");
    BOOST_TEST(verdict_of(k, q(1), q(1)) == scalecert::Verdict::Separated);  // 5 − 3 = 2
    BOOST_TEST(verdict_of(k, q(1), q(2)) == scalecert::Verdict::Touching);   // 5 − 5 = 0
    BOOST_TEST(verdict_of(k, q(2), q(2)) == scalecert::Verdict::Overlapping);
    BOOST_TEST(right(k, value_claim(ClaimType::Distance, q(1), q(1), q(2))));
    BOOST_TEST(!right(k, value_claim(ClaimType::Distance, q(1), q(1), q(5))));  // the centres' distance
    BOOST_TEST(right(k, value_claim(ClaimType::Distance, q(2), q(2), q(0))));   // overlapping: 0
    BOOST_TEST(right(k, value_claim(ClaimType::SignedDistance, q(2), q(2), q(-1))));
    BOOST_TEST(!right(k, value_claim(ClaimType::SignedDistance, q(2), q(2), q(1))));
    TypedClaim d = value_claim(ClaimType::Depth, q(2), q(2), q(1));
    BOOST_TEST(right(k, d));
    d.direction = Vec3q{q(3), q(0), q(0)};  // along the centres: right
    BOOST_TEST(right(k, d));
    d.direction = Vec3q{q(1), q(1), q(0)};  // 45° off: the balls part after 6 − 5/√2 > 1
    BOOST_TEST(!right(k, d));
    BOOST_TEST(!right(k, value_claim(ClaimType::Depth, q(1), q(1), q(0))));  // separated
    // Closest points (1, 0, 0) and (3, 0, 0); a point of P1's hull is not on the ball's surface.
    TypedClaim c = value_claim(ClaimType::Distance, q(1), q(1), q(2));
    c.closest = std::array<Vec3q, 2>{Vec3q{q(1), q(0), q(0)}, Vec3q{q(3), q(0), q(0)}};
    BOOST_TEST(right(k, c));
    c.closest = std::array<Vec3q, 2>{Vec3q{q(0), q(0), q(0)}, Vec3q{q(3), q(0), q(0)}};
    BOOST_TEST(!right(k, c));  // in P1, but 3 apart where the distance is 2
    c.closest = std::array<Vec3q, 2>{Vec3q{q(1), q(1, 100), q(0)}, Vec3q{q(3), q(0), q(0)}};
    BOOST_TEST(!right(k, c));  // |(1, 1/100, 0)| > 1: not in P1
    // Witness (5/2... ) at touching (1, 2): (1, 0, 0) is on both.
    TypedClaim w = claim(ClaimType::Witness, q(1), q(2));
    w.point = Vec3q{q(1), q(0), q(0)};
    BOOST_TEST(right(k, w));
    w.point = Vec3q{q(1), q(1, 1000), q(0)};
    BOOST_TEST(!right(k, w));
    // Planes x = 2 (between 1 and 3) and, normal (1, 1, 0), offset 2: P1 reaches √2 < 2, P2
    // starts at 5 − 2√2 ≈ 2.17 > 2: both separate. Offset 2.2 is past P2's start.
    TypedClaim p = claim(ClaimType::Plane, q(1), q(1));
    p.normal = Vec3q{q(1), q(1), q(0)};
    p.offset = q(2);
    BOOST_TEST(right(k, p));
    p.offset = q(11, 5);
    BOOST_TEST(!right(k, p));
    // Coincident centres (both at the origin): the hulls touch (a flat difference), depth R.
    Case same = open_text(R"({"P1": {"sphere": 1}, "P2": {"sphere": "1/2"}})");
    BOOST_TEST(right(same, value_claim(ClaimType::Depth, q(1), q(1), q(3, 2))));
    BOOST_TEST(right(same, value_claim(ClaimType::SignedDistance, q(1), q(1), q(-3, 2))));
}

// A sphere of radius 1/2 against the box [−1, 1]³ (no radius): the face region at (3, 0, 0) is
// 2 − 1/2 = 3/2 away; the edge region at (2, 2, 0) is √2 − 1/2; the vertex region at (2, 2, 2) is
// √3 − 1/2. Irrational values are right within a relative 2^-50 and wrong 10^-9 off.
BOOST_AUTO_TEST_CASE(sphere_against_box_regions) {
    const std::string box = R"("P1": {"box": [1, 1, 1]})";
    auto at = [&](int x, int y, int z) {
        return "{" + box + R"(, "P2": {"sphere": "1/2", "pose": [[1,0,0,)" + std::to_string(x) + "],[0,1,0," +
               std::to_string(y) + "],[0,0,1," + std::to_string(z) + "]]}}";
    };
    Case face = open_text(at(3, 0, 0));
    BOOST_TEST(right(face, value_claim(ClaimType::Distance, q(1), q(1), q(3, 2))));
    Tolerance rel;
    rel.rel = Q(1) / (Q(1) << 50);
    const double root2 = std::sqrt(2.0) - 0.5, root3 = std::sqrt(3.0) - 0.5;
    Case edge = open_text(at(2, 2, 0), rel);
    BOOST_TEST(right(edge, value_claim(ClaimType::Distance, q(1), q(1), exact_from_double(root2))));
    BOOST_TEST(!right(edge, value_claim(ClaimType::Distance, q(1), q(1), exact_from_double(root2 + 1e-9))));
    Case exact_edge = open_text(at(2, 2, 0));  // no tolerance: no rational is √2 − 1/2
    BOOST_TEST(!right(exact_edge, value_claim(ClaimType::Distance, q(1), q(1), exact_from_double(root2))));
    Case vertex = open_text(at(2, 2, 2), rel);
    BOOST_TEST(right(vertex, value_claim(ClaimType::SignedDistance, q(1), q(1), exact_from_double(root3))));
    BOOST_TEST(!right(vertex, value_claim(ClaimType::SignedDistance, q(1), q(1), exact_from_double(root3 - 1e-9))));
    // Grown about its centre (the seed): at (1, 3) the radius is 3/2 < √3, still apart; at (1, 4)
    // it is 2 > √3.
    BOOST_TEST(verdict_of(vertex, q(1), q(3)) == scalecert::Verdict::Separated);
    BOOST_TEST(verdict_of(vertex, q(1), q(4)) == scalecert::Verdict::Overlapping);  // √3 < 2
    // The face region at ρ2 = 3: 2 − 3/2 = 1/2; at ρ2 = 4 touching (2 − 2), at 6 a depth 1 along x.
    BOOST_TEST(verdict_of(face, q(1), q(4)) == scalecert::Verdict::Touching);
    TypedClaim d = value_claim(ClaimType::Depth, q(1), q(6), q(1));
    d.direction = Vec3q{q(1), q(0), q(0)};
    BOOST_TEST(right(face, d));
}

// Capsules along z, half-length 1, radius 1/4. Parallel, 1 apart in x: the segments are 1 apart,
// the capsules 1/2. Skew: the second turned onto x and moved to y = 2: the segments cross at
// distance 2 (the points (0, 0, 0) and (0, 2, 0)), the capsules 3/2 apart. Crossing segments
// (the hulls' difference flat): depth R = 1/2.
BOOST_AUTO_TEST_CASE(capsules_by_hand) {
    const std::string cap = R"({"capsule": {"radius": "1/4", "half_length": 1}})";
    Case parallel = open_text(R"({"P1": )" + cap + R"(, "P2": {"capsule": {"radius": "1/4", "half_length": 1},
        "pose": [[1,0,0,1],[0,1,0,0],[0,0,1,0]]}})");
    BOOST_TEST(right(parallel, value_claim(ClaimType::Distance, q(1), q(1), q(1, 2))));
    BOOST_TEST(verdict_of(parallel, q(2), q(2)) == scalecert::Verdict::Touching);  // 1 − 2·(1/4)·2 = 0
    Case skew = open_text(R"({"P1": )" + cap + R"(, "P2": {"capsule": {"radius": "1/4", "half_length": 1},
        "pose": [[0,0,1,0],[0,1,0,2],[-1,0,0,0]]}})");
    BOOST_TEST(right(skew, value_claim(ClaimType::SignedDistance, q(1), q(1), q(3, 2))));
    BOOST_TEST(!right(skew, value_claim(ClaimType::SignedDistance, q(1), q(1), q(7, 4))));
    Case cross = open_text(R"({"P1": )" + cap + R"(, "P2": {"capsule": {"radius": "1/4", "half_length": 1},
        "pose": [[0,0,1,0],[0,1,0,0],[-1,0,0,0]]}})");
    BOOST_TEST(right(cross, value_claim(ClaimType::Depth, q(1), q(1), q(1, 2))));
    TypedClaim d = value_claim(ClaimType::Depth, q(1), q(1), q(1, 2));
    d.direction = Vec3q{q(0), q(1), q(0)};  // normal to both axes: the balls part after R
    BOOST_TEST(right(cross, d));
    d.direction = Vec3q{q(1), q(0), q(0)};  // along P2's axis: they part only after 1 + 1/2
    BOOST_TEST(!right(cross, d));
}

// A box [−1, 1]³ rounded by 1/2 under the box [−1, 1]² × [3/2, 7/2] (seed (0, 0, 5/2)): P1(ρ1)
// reaches z = 3ρ1/2, P2(ρ2) starts at 5/2 − ρ2: touching on 3ρ1/2 + ρ2 = 5/2, so at (1, 1), and
// at (2, 1) a depth 3 − 3/2 = 3/2 along z. The same at poses: both turned by one orthogonal matrix
// and moved, every value unchanged.
BOOST_AUTO_TEST_CASE(rounded_box_resting_on_a_box) {
    const std::string scene = R"({"P1": {"box": [1, 1, 1], "radius": "1/2"},
        "P2": {"box": [1, 1, 1], "pose": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, "5/2"]]}})";
    Case k = open_text(scene);
    BOOST_TEST(verdict_of(k, q(1), q(1)) == scalecert::Verdict::Touching);
    BOOST_TEST(verdict_of(k, q(1), q(1, 2)) == scalecert::Verdict::Separated);
    TypedClaim d = value_claim(ClaimType::Depth, q(2), q(1), q(3, 2));
    d.direction = Vec3q{q(0), q(0), q(1)};
    BOOST_TEST(right(k, d));
    BOOST_TEST(right(k, value_claim(ClaimType::SignedDistance, q(1), q(1, 2), q(1, 2))));
    // R = [[-1, 8, 4], [8, -1, 4], [-4, -4, 7]] / 9: rows of length 9, pairwise orthogonal.
    Pose turn;
    const long R[3][3] = {{-1, 8, 4}, {8, -1, 4}, {-4, -4, 7}};
    const long t[3] = {3, -2, 5};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) turn[i][j] = q(R[i][j], 9);
        turn[i][3] = q(t[i]);
    }
    for (const auto& [c, want] : std::vector<std::pair<TypedClaim, bool>>{
             {d, true},
             {value_claim(ClaimType::SignedDistance, q(1), q(1, 2), q(1, 2)), true},
             {value_claim(ClaimType::SignedDistance, q(1), q(1, 2), q(1, 3)), false},
             {value_claim(ClaimType::SignedDistance, q(1), q(1), q(0)), true}}) {
        TypedClaim posed = c;
        posed.pose = {turn, turn};
        if (posed.direction) {  // the direction turns with them
            const Vec3q u = *posed.direction;
            posed.direction = Vec3q{turn[0][0] * u[0] + turn[0][1] * u[1] + turn[0][2] * u[2],
                                    turn[1][0] * u[0] + turn[1][1] * u[1] + turn[1][2] * u[2],
                                    turn[2][0] * u[0] + turn[2][1] * u[1] + turn[2][2] * u[2]};
        }
        BOOST_TEST(right(k, posed) == want);
    }
}

BOOST_AUTO_TEST_CASE(scenes_refused_in_one_line) {
    auto err = [](const std::string& json) {
        return test::input_error([&] {
            auto sc = std::make_shared<const ExactScene>(parse_scene_text(json, "s.json", "."));
            open_engine(sc, "s.json")->check();
        });
    };
    BOOST_TEST(err(R"({"P1": {"sphere": -1}, "P2": {"sphere": 1}})").find("P1.sphere: a sphere's radius is > 0") !=
               std::string::npos);
    BOOST_TEST(err(R"({"P1": {"sphere": 0}, "P2": {"sphere": 1}})").find("P1.sphere") != std::string::npos);
    BOOST_TEST(
        err(R"({"P1": {"box": [1,1,1], "radius": -2}, "P2": {"sphere": 1}})").find("P1.radius: a radius is >= 0") !=
        std::string::npos);
    BOOST_TEST(err(R"({"P1": {"sphere": "nan"}, "P2": {"sphere": 1}})").find("P1.sphere") != std::string::npos);
    BOOST_TEST(err(R"({"P1": {"sphere": 1, "radius": 1}, "P2": {"sphere": 1}})").find("P1.radius") !=
               std::string::npos);
    BOOST_TEST(err(R"({"P1": {"capsule": {"radius": 1}}, "P2": {"sphere": 1}})").find("half_length") !=
               std::string::npos);
    BOOST_TEST(err(R"({"P1": {"capsule": {"radius": 1, "half_length": -1}}, "P2": {"sphere": 1}})")
                   .find("a half-length is >= 0") != std::string::npos);
    BOOST_TEST(err(R"({"P1": {"sphere": 1, "vertices": [[0,0,0]]}, "P2": {"sphere": 1}})").find("give one of") !=
               std::string::npos);
    // A seed on the ball's surface is not interior; inside it is.
    BOOST_TEST(err(R"({"P1": {"sphere": 1, "seed": [1, 0, 0]}, "P2": {"sphere": 1}})").find("P1: the seed") !=
               std::string::npos);
    BOOST_TEST(err(R"({"P1": {"sphere": 1, "seed": ["99/100", 0, 0]}, "P2": {"sphere": 1}})").empty());
    // A flat object needs a radius; one of three points with radius 0 has fewer than 4.
    BOOST_TEST(err(R"({"P1": {"vertices": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]]}, "P2": {"sphere": 1}})")
                   .find("P1: its points span no volume (they lie in a plane)") != std::string::npos);
    BOOST_TEST(err(R"({"P1": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "radius": 0}, "P2": {"sphere": 1}})")
                   .find("fewer than 4 vertices (3) and no radius > 0") != std::string::npos);
    // What is not built for them says so.
    auto sc = std::make_shared<const ExactScene>(
        parse_scene_text(R"({"P1": {"sphere": 1}, "P2": {"sphere": 1}})", "s.json", "."));
    const auto e = open_engine(sc, "s.json");
    BOOST_TEST(test::input_error([&] { e->partition_document(); })
                   .find("s.json: the partition is not built for objects "
                         "with a radius") != std::string::npos);
    BOOST_TEST(test::input_error([&] { e->curve("x"); }).find("curved") != std::string::npos);
    // A query's certificate: a judgements file of its one verdict, the exact one (centres 0 apart:
    // the spheres overlap).
    const std::string doc = e->verdict_document(Q(1), Q(1));
    BOOST_TEST(doc.find("\"verdict\": \"overlapping\"") != std::string::npos);
    BOOST_TEST(doc.find("\"right\": true") != std::string::npos);
}

// ---- the brute force ---------------------------------------------------------------------------

namespace {

// An object at (ρ, pose) in closed form: a point (sphere), a segment (capsule) or an axis box in
// its own frame (rounded box), moved by an orthogonal rational R and t; radius m = ρr.
struct Shape {
    int kind = 0;  // 0 sphere, 1 capsule, 2 box
    Q r, h;        // radius; capsule half-length
    Q e[3];        // box half-extents
    Q R[3][3], t[3];
    // Scaled about its seed (its centre t) by ρ.
    Vec3q local_to_world(const Vec3q& v, const Q& rho) const {
        Vec3q w;
        for (int i = 0; i < 3; ++i) w[i] = t[i] + rho * (R[i][0] * v[0] + R[i][1] * v[1] + R[i][2] * v[2]);
        return w;
    }
    Vec3q world_to_local(const Vec3q& w) const {  // Rᵀ(w − t), unscaled
        Vec3q v;
        for (int j = 0; j < 3; ++j) v[j] = R[0][j] * (w[0] - t[0]) + R[1][j] * (w[1] - t[1]) + R[2][j] * (w[2] - t[2]);
        return v;
    }
    std::string json() const {
        auto s = [](const Q& x) { return "\"" + to_exact_string(x) + "\""; };
        std::string o = kind == 0 ? "{\"sphere\": " + s(r)
                        : kind == 1
                            ? "{\"capsule\": {\"radius\": " + s(r) + ", \"half_length\": " + s(h) + "}"
                            : "{\"box\": [" + s(e[0]) + ", " + s(e[1]) + ", " + s(e[2]) + "], \"radius\": " + s(r);
        o += ", \"pose\": [";
        for (int i = 0; i < 3; ++i)
            o += std::string(i ? ", " : "") + "[" + s(R[i][0]) + ", " + s(R[i][1]) + ", " + s(R[i][2]) + ", " +
                 s(t[i]) + "]";
        return o + "]}";
    }
};

Q dot(const Vec3q& a, const Vec3q& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3q minus(const Vec3q& a, const Vec3q& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Q clamp01(const Q& x) { return x < 0 ? Q(0) : x > 1 ? Q(1) : x; }

// Squared distance from p to the segment [a, b].
Q point_segment(const Vec3q& p, const Vec3q& a, const Vec3q& b) {
    const Vec3q u = minus(b, a), w = minus(p, a);
    const Q uu = dot(u, u);
    const Q s = sgn(uu) == 0 ? Q(0) : clamp01(dot(w, u) / uu);
    const Vec3q d{w[0] - s * u[0], w[1] - s * u[1], w[2] - s * u[2]};
    return dot(d, d);
}
// Squared distance between segments [a, b] and [c, d]: the least of the convex quadratic over the
// square, at its interior critical point or on an edge (each edge a point-segment distance).
Q segment_segment(const Vec3q& a, const Vec3q& b, const Vec3q& c, const Vec3q& d) {
    Q best = std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b), point_segment(d, a, b)});
    const Vec3q u = minus(b, a), v = minus(d, c), w = minus(a, c);
    const Q uu = dot(u, u), vv = dot(v, v), uv = dot(u, v), wu = dot(w, u), wv = dot(w, v);
    const Q det = uu * vv - uv * uv;
    if (sgn(det) != 0) {  // ∂/∂s = uu s − uv t + wu = 0, ∂/∂t = −uv s + vv t − wv = 0
        const Q s = (uv * wv - vv * wu) / det, t = (uu * wv - uv * wu) / det;
        if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {
            const Vec3q x{w[0] + s * u[0] - t * v[0], w[1] + s * u[1] - t * v[1], w[2] + s * u[2] - t * v[2]};
            best = std::min(best, dot(x, x));
        }
    }
    return best;
}

// The hulls' signed distance s·√E of a pair at (ρ1, ρ2), in closed form: the hulls are a point
// and a point, segment or box, or two segments.
std::pair<int, Q> brute_hulls(const Shape& A, const Q& r1, const Shape& B, const Q& r2) {
    auto ends = [](const Shape& S, const Q& rho) {
        return std::pair{S.local_to_world({Q(0), Q(0), Q(-S.h)}, rho), S.local_to_world({Q(0), Q(0), S.h}, rho)};
    };
    if (A.kind == 2 || B.kind == 2) {
        const bool box_first = A.kind == 2;
        const Shape &X = box_first ? A : B, &P = box_first ? B : A;
        const Q& rx = box_first ? r1 : r2;
        const Vec3q c = X.world_to_local(P.local_to_world({Q(0), Q(0), Q(0)}, Q(1)));  // a sphere's centre
        Q out = 0, depth;
        bool inside = true;
        for (int k = 0; k < 3; ++k) {
            const Q half = rx * X.e[k], a = abs(c[k]);
            if (a > half) out += (a - half) * (a - half), inside = false;
            const Q gap = half - a;
            if (k == 0 || gap < depth) depth = gap;
        }
        if (!inside) return {1, out};
        return sgn(depth) == 0 ? std::pair{0, Q(0)} : std::pair{-1, depth * depth};
    }
    Q E;
    if (A.kind == 0 && B.kind == 0) {
        const Vec3q d = minus(A.local_to_world({0, 0, 0}, r1), B.local_to_world({0, 0, 0}, r2));
        E = dot(d, d);
    } else if (A.kind == 0 || B.kind == 0) {
        const bool sphere_first = A.kind == 0;
        const auto [a, b] = sphere_first ? ends(B, r2) : ends(A, r1);
        E = point_segment((sphere_first ? A : B).local_to_world({0, 0, 0}, Q(1)), a, b);
    } else {
        const auto [a, b] = ends(A, r1);
        const auto [c, d] = ends(B, r2);
        E = segment_segment(a, b, c, d);
    }
    // Meeting hulls of points and segments have a flat difference: they touch.
    return sgn(E) > 0 ? std::pair{1, E} : std::pair{0, Q(0)};
}

// A random rational rotation: the quaternion (a, b, c, d) of small integers over a²+b²+c²+d².
void random_pose(std::mt19937_64& g, Shape& S) {
    std::uniform_int_distribution<int> small(-3, 3), far(-12, 12);
    long a, b, c, d;
    do a = small(g), b = small(g), c = small(g), d = small(g);
    while (a * a + b * b + c * c + d * d == 0);
    const Q n(a * a + b * b + c * c + d * d);
    const long M[3][3] = {{a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)},
                          {2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)},
                          {2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d}};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) S.R[i][j] = Q(M[i][j]) / n;
        S.t[i] = test::qc(far(g), 4);
    }
}

}  // namespace

BOOST_AUTO_TEST_CASE(brute_force_in_rationals) {
    std::mt19937_64 g(57);
    std::uniform_int_distribution<int> kinds(0, 2), num(1, 8), rho(2, 8);
    long judged = 0, right_count = 0, by_kind[3][3] = {};
    Tolerance tol;
    tol.rel = Q(1, 1000000000);  // 1e-9: a claim 1e-6 off is wrong, the nearest double right
    for (int trial = 0; trial < 240; ++trial) {
        Shape A, B;
        A.kind = kinds(g);
        B.kind = kinds(g);
        if (A.kind == 2 && B.kind == 2) B.kind = 0;  // box against box has no closed form here
        if (A.kind != 0 && B.kind != 0 && (A.kind == 2 || B.kind == 2)) (A.kind == 2 ? B : A).kind = 0;
        for (Shape* S : {&A, &B}) {
            S->r = test::qc(num(g), 4);
            S->h = test::qc(num(g) - 1, 2);
            for (Q& e : S->e) e = test::qc(num(g), 2);
            if (S->kind == 2 && trial % 3 == 0) S->r = 0;  // a plain box beside a ball
            random_pose(g, *S);
        }
        ++by_kind[A.kind][B.kind];
        Case k = open_text("{\"P1\": " + A.json() + ", \"P2\": " + B.json() + "}", tol);
        for (int pair = 0; pair < 3; ++pair) {
            const Q r1 = test::qc(rho(g), 4), r2 = test::qc(rho(g), 4);
            const auto [s, E] = brute_hulls(A, r1, B, r2);
            const Q R = r1 * A.r + r2 * B.r;
            // The verdict: s√E against R, exactly (E vs R² apart; meeting hulls with R > 0 overlap).
            const scalecert::Verdict v = s > 0 ? (E > R * R    ? scalecert::Verdict::Separated
                                                  : E == R * R ? scalecert::Verdict::Touching
                                                               : scalecert::Verdict::Overlapping)
                                               : (sgn(R) > 0 ? scalecert::Verdict::Overlapping
                                                  : s == 0   ? scalecert::Verdict::Touching
                                                             : scalecert::Verdict::Overlapping);
            BOOST_TEST(verdict_of(k, r1, r2) == v, "trial " << trial);
            // Signed distance and (when not separated) depth: the nearest double right, 1e-6
            // (relative) off wrong, each also as at_least / below bounds.
            const long double x = approx(s, E, Q(-R));
            if (std::fabs(static_cast<double>(x)) < 1e-3) continue;  // too near 0 for a relative test
            const Q near = exact_from_double(static_cast<double>(x)),
                    off = exact_from_double(static_cast<double>(x * (1 + 1e-6L)));
            const Q below = exact_from_double(static_cast<double>(x - std::fabs(x) * 1e-6L));
            for (const auto& [c, want] : std::vector<std::pair<TypedClaim, bool>>{
                     {value_claim(ClaimType::SignedDistance, r1, r2, near), true},
                     {value_claim(ClaimType::SignedDistance, r1, r2, off), false},
                     {value_claim(ClaimType::Distance, r1, r2, x > 0 ? near : Q(0)), true},
                     {value_claim(ClaimType::Distance, r1, r2,
                                  x > 0 ? off : exact_from_double(-static_cast<double>(x))),
                      false},
                     {value_claim(ClaimType::Depth, r1, r2, x < 0 ? Q(-near) : Q(0)), x < 0},
                     {value_claim(ClaimType::Depth, r1, r2, x < 0 ? Q(-off) : Q(1)), false}}) {
                BOOST_TEST(right(k, c) == want, "trial " << trial << " kind " << type_name(c.type));
                ++judged;
                right_count += want;
            }
            TypedClaim at_least = value_claim(ClaimType::SignedDistance, r1, r2, below);
            at_least.bound = TypedClaim::Bound::AtLeast;
            BOOST_TEST(right(k, at_least));
            at_least.value = off > near ? off : Q(near + (near - below));  // above the value
            BOOST_TEST(!right(k, at_least));
            // Witness: a point of the segment between the two centres (each object's seed) at the
            // brute force's membership, its squared distance to each hull against (ρr)².
            const Vec3q c1 = A.local_to_world({0, 0, 0}, Q(1)), c2 = B.local_to_world({0, 0, 0}, Q(1));
            for (const Q& f : {Q(1, 4), Q(1, 2), Q(3, 4)}) {
                const Vec3q p{c1[0] + f * (c2[0] - c1[0]), c1[1] + f * (c2[1] - c1[1]), c1[2] + f * (c2[2] - c1[2])};
                auto in = [&](const Shape& S, const Q& r) {
                    Q d2;
                    if (S.kind == 0) {
                        const Vec3q d = minus(p, S.local_to_world({0, 0, 0}, r));
                        d2 = dot(d, d);
                    } else if (S.kind == 1) {
                        d2 = point_segment(p, S.local_to_world({0, 0, -S.h}, r), S.local_to_world({0, 0, S.h}, r));
                    } else {
                        const Vec3q l = S.world_to_local(p);
                        d2 = 0;
                        for (int j = 0; j < 3; ++j) {
                            const Q a = abs(l[j]) - r * S.e[j];
                            if (sgn(a) > 0) d2 += a * a;
                        }
                    }
                    return d2 <= r * r * S.r * S.r;
                };
                TypedClaim w = claim(ClaimType::Witness, r1, r2);
                w.point = p;
                w.with_verdict = false;
                BOOST_TEST(right(k, w) == (in(A, r1) && in(B, r2)), "trial " << trial << " witness " << f);
            }
        }
    }
    BOOST_TEST_MESSAGE("rounded brute force: " << judged << " value claims, " << right_count << " right");
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) BOOST_TEST_MESSAGE("pairs " << a << "-" << b << ": " << by_kind[a][b]);
    BOOST_TEST(judged > 500);
    BOOST_TEST(right_count > 150);
    BOOST_TEST(judged - right_count > 150);
}

// ---- growth distances ------------------------------------------------------------------------

namespace {
// The engine's ρ* = a + b√c, from a growth_distance claim's judgement.
QuadSurd growth_of(Case& k) {
    TypedClaim c;
    c.type = ClaimType::Growth;
    const Judged g = k.rules->judge(c);
    BOOST_TEST_REQUIRE(g.get<GrowthJudged>());
    BOOST_TEST_REQUIRE(g.get<GrowthJudged>()->surd.has_value());
    return *g.get<GrowthJudged>()->surd;
}
bool growth_right(Case& k, const Q& v) {
    TypedClaim c;
    c.type = ClaimType::Growth;
    c.value = v;
    return k.rules->judge(c).right;
}
// The sign of a + b√c − x.
int surd_minus(const QuadSurd& r, const Q& x) { return sign_minus_sqrt(Q(r.a - x), Q(-r.b), Q(r.c)); }
}  // namespace

// CLAIMS.md's growth distances by hand. Two unit spheres with centres (their seeds) 4 apart touch
// when ρ + ρ = 4: ρ* = 2. The capsules along z 1 apart in x (radius 1/4) touch when ρ/2 = 1:
// ρ* = 2. A sphere of radius 1/2 centred at (3, 0, 0) against the box [−1, 1]³ (seed 0): the face
// region, 3 − ρ = ρ/2, ρ* = 2. At (2, 2, 0), the edge region: √2·(2 − ρ) = ρ/2, so
// ρ* = 4√2/(1 + 2√2) = (16 − 4√2)/7. At (2, 2, 2), the vertex region: √3·(2 − ρ) = ρ/2, so
// ρ* = 4√3/(1 + 2√3) = (24 − 4√3)/11. Spheres about one centre: ρ* = 0.
BOOST_AUTO_TEST_CASE(growth_distances_by_hand) {
    Case spheres = open_text(R"({"P1": {"sphere": 1}, "P2": {"sphere": 1, "pose": [[1,0,0,4],[0,1,0,0],[0,0,1,0]]}})");
    QuadSurd r = growth_of(spheres);
    BOOST_TEST(r.a == q(2));
    BOOST_TEST(sgn(r.b) == 0);
    BOOST_TEST(growth_right(spheres, q(2)));
    BOOST_TEST(!growth_right(spheres, Q(2) + Q(1) / (Q(1) << 60)));

    Case capsules = open_text(R"({"P1": {"capsule": {"radius": "1/4", "half_length": 1}},
        "P2": {"capsule": {"radius": "1/4", "half_length": 1}, "pose": [[1,0,0,1],[0,1,0,0],[0,0,1,0]]}})");
    r = growth_of(capsules);
    BOOST_TEST((r.a == q(2) && sgn(r.b) == 0));

    const std::string box = R"("P1": {"box": [1, 1, 1]})";
    auto at = [&](int x, int y, int z) {
        return "{" + box + R"(, "P2": {"sphere": "1/2", "pose": [[1,0,0,)" + std::to_string(x) + "],[0,1,0," +
               std::to_string(y) + "],[0,0,1," + std::to_string(z) + "]]}}";
    };
    Case face = open_text(at(3, 0, 0));
    r = growth_of(face);
    BOOST_TEST((r.a == q(2) && sgn(r.b) == 0));
    BOOST_TEST(verdict_of(face, q(2), q(2)) == scalecert::Verdict::Touching);

    Tolerance rel;
    rel.rel = Q(1) / (Q(1) << 50);
    Case edge = open_text(at(2, 2, 0), rel);
    r = growth_of(edge);
    BOOST_TEST(r.a == q(16, 7));
    BOOST_TEST(r.b == q(-4, 7));
    BOOST_TEST(r.c == 2);
    BOOST_TEST(surd_text(r) == "16/7 - 4/7*sqrt(2)");
    const double e = (16 - 4 * std::sqrt(2.0)) / 7;
    BOOST_TEST(growth_right(edge, exact_from_double(e)));
    BOOST_TEST(!growth_right(edge, exact_from_double(e + 1e-9)));
    Case exact_edge = open_text(at(2, 2, 0));  // no rational is it
    BOOST_TEST(!growth_right(exact_edge, exact_from_double(e)));
    // The report: the exact value as text and as {a, b, c}, its double, the claim's error.
    long wrong = 0;
    const Json rep = Json::parse(certify_fp(*exact_edge.rules,
                                            R"({"format": "scalecert-claims-1", "claims": [{"kind": "growth_distance",
                   "value": "3/2"}]})",
                                            "claims", scalecert::ClaimOptions{}, &wrong));
    BOOST_TEST(wrong == 1);
    const auto& o = rep["claims"][0];
    BOOST_TEST(o["exact"] == "16/7 - 4/7*sqrt(2)");
    BOOST_TEST(o["exact_surd"] == Json::parse(R"({"a": "16/7", "b": "-4/7", "c": "2"})"));
    BOOST_TEST(std::fabs(o["exact_double"].get<double>() - e) < 1e-15);
    BOOST_TEST(std::fabs(o["abs_error_double"].get<double>() - (1.5 - e)) < 1e-15);
    // Separated just below, overlapping just above, by the engine's own verdict.
    const Q below = exact_from_double(e * (1 - 1e-12)), above = exact_from_double(e * (1 + 1e-12));
    BOOST_TEST(verdict_of(edge, below, below) == scalecert::Verdict::Separated);
    BOOST_TEST(verdict_of(edge, above, above) == scalecert::Verdict::Overlapping);

    Case vertex = open_text(at(2, 2, 2), rel);
    r = growth_of(vertex);
    BOOST_TEST(r.a == q(24, 11));
    BOOST_TEST(r.b == q(-4, 11));
    BOOST_TEST(r.c == 3);
    BOOST_TEST(growth_right(vertex, exact_from_double((24 - 4 * std::sqrt(3.0)) / 11)));

    Case one_centre = open_text(R"({"P1": {"sphere": 1}, "P2": {"sphere": 2}})");
    r = growth_of(one_centre);
    BOOST_TEST((sgn(r.a) == 0 && sgn(r.b) == 0));
    BOOST_TEST(growth_right(one_centre, q(0)));
}

// A brute force of growth distances that shares nothing with the engine. Random spheres (each
// one point with a radius and a seed within it), capsules and rounded boxes at rational poses: by
// exact bisection on the closed-form verdict at (ρ, ρ) (brute_hulls), ρ* lies in (lo, hi], a
// separated pair and one that is not, hi − lo < 2^-40·hi. Two spheres with seeds off their centres
// c_i: the centres at ρ are d + ρe apart (d = s2 − s1, e = (c2 − s2) − (c1 − s1)), so ρ* is the
// one positive root of (|e|² − R0²)ρ² + 2(d·e)ρ + |d|² = 0 (|e| < R0), checked exactly in Q(√c).
BOOST_AUTO_TEST_CASE(growth_distances_brute_force) {
    std::mt19937_64 g(91);
    std::uniform_int_distribution<int> kinds(0, 2), num(1, 8);
    int irrational = 0;
    for (int trial = 0; trial < 60; ++trial) {
        Shape A, B;
        A.kind = kinds(g);
        B.kind = kinds(g);
        if (A.kind == 2 && B.kind == 2) B.kind = 0;
        if (A.kind != 0 && B.kind != 0 && (A.kind == 2 || B.kind == 2)) (A.kind == 2 ? B : A).kind = 0;
        for (Shape* S : {&A, &B}) {
            S->r = test::qc(num(g), 4);
            S->h = test::qc(num(g) - 1, 2);
            for (Q& e : S->e) e = test::qc(num(g), 2);
            if (S->kind == 2 && trial % 3 == 0) S->r = 0;
            random_pose(g, *S);
        }
        Case k = open_text("{\"P1\": " + A.json() + ", \"P2\": " + B.json() + "}");
        const QuadSurd r = growth_of(k);
        irrational += sgn(r.b) != 0;
        auto separated = [&](const Q& rho) {
            const auto [s, E] = brute_hulls(A, rho, B, rho);
            const Q R = rho * (A.r + B.r);
            return s > 0 && E > R * R;
        };
        Q lo = Q(1) / (Q(1) << 20), hi = 1;
        BOOST_TEST_REQUIRE(separated(lo));
        while (separated(hi)) hi *= 2;
        while (hi - lo >= hi / (Q(1) << 40)) {
            const Q m = (lo + hi) / 2;
            (separated(m) ? lo : hi) = m;
        }
        BOOST_TEST(surd_minus(r, lo) > 0, "trial " << trial << ": " << surd_text(r));
        BOOST_TEST(surd_minus(r, hi) <= 0, "trial " << trial << ": " << surd_text(r));
    }
    BOOST_TEST_MESSAGE("growth brute force: " << irrational << " of 60 irrational");
    BOOST_TEST(irrational > 10);

    std::uniform_int_distribution<int> coord(-8, 8);
    for (int trial = 0; trial < 40; ++trial) {
        Vec3q c[2], s[2];
        Q rad[2];
        for (int i = 0; i < 2; ++i) {
            rad[i] = test::qc(num(g) + 4, 4);  // at least 5/4
            for (int a = 0; a < 3; ++a) {
                c[i][a] = test::qc(coord(g), 2) + (i ? 6 : 0);
                s[i][a] = c[i][a] + test::qc(coord(g), 16);  // within √3/2 < 5/4 of the centre
            }
        }
        auto v = [](const Vec3q& x) {
            return "[\"" + to_exact_string(x[0]) + "\", \"" + to_exact_string(x[1]) + "\", \"" + to_exact_string(x[2]) +
                   "\"]";
        };
        auto obj = [&](int i) {
            return "{\"vertices\": [" + v(c[i]) + "], \"radius\": \"" + to_exact_string(rad[i]) +
                   "\", \"seed\": " + v(s[i]) + "}";
        };
        Case k = open_text("{\"P1\": " + obj(0) + ", \"P2\": " + obj(1) + "}");
        const QuadSurd r = growth_of(k);
        const Vec3q d = minus(s[1], s[0]), e = minus(minus(c[1], s[1]), minus(c[0], s[0]));
        const Q R0 = rad[0] + rad[1], A2 = dot(e, e) - R0 * R0, A1 = 2 * dot(d, e), A0 = dot(d, d);
        // A2·ρ² + A1·ρ + A0 at ρ = a + b√c: (A2(a² + b²c) + A1 a + A0) + (2A2ab + A1 b)√c.
        const Q cc(r.c);
        const Q p0 = A2 * (r.a * r.a + r.b * r.b * cc) + A1 * r.a + A0, p1 = 2 * A2 * r.a * r.b + A1 * r.b;
        BOOST_TEST((sgn(p0) == 0 && sgn(p1) == 0), "sphere trial " << trial << ": " << surd_text(r));
        BOOST_TEST(surd_minus(r, Q(0)) > 0);
    }
}

// Golden data on a curved touching set: the box [−1, 1]³ and a sphere of radius 1/2 centred at
// (2, 2, 0), I1 = [1, 3/2], I2 = [1, 8]. The centre lies in an edge region of the box scaled by
// ρ1 < 2, so the pair touches where ρ2/2 = √2·(2 − ρ1): a conic, not a line. Every sample's
// `below` is separated and `above` is not, by that closed form in rationals ((ρ2/2)² against
// 2(2 − ρ1)²), 2^-60 of I2 apart at most; every query's verdict agrees with it too.
BOOST_AUTO_TEST_CASE(golden_samples_a_curved_touching_set) {
    auto sc = std::make_shared<const ExactScene>(parse_scene_text(
        R"({"P1": {"box": [1, 1, 1]}, "P2": {"sphere": "1/2", "pose": [[1,0,0,2],[0,1,0,2],[0,0,1,0]]},
            "I1": [1, "3/2"], "I2": [1, 8]})",
        "edge.json", "."));
    const auto e = open_engine(sc, "edge.json");
    GoldenPoints pts;
    pts.verticals = 5;
    pts.offsets = {4, 30, 52};
    const GoldenAnswers g = e->golden(pts);
    auto closed_form = [](const Q& r1, const Q& r2) {  // the brute verdict: (ρ2/2)² vs 2(2 − ρ1)²
        const int c = cmp(r2 * r2 / 4, 2 * (2 - r1) * (2 - r1));
        return c < 0    ? scalecert::Verdict::Separated
               : c == 0 ? scalecert::Verdict::Touching
                        : scalecert::Verdict::Overlapping;
    };
    BOOST_TEST_REQUIRE(g.curve["samples"].size() == 5u);
    for (const auto& s : g.curve["samples"]) {
        BOOST_TEST_REQUIRE(s["crosses"] == true);
        const Q x = parse_exact(s["rho1"].get<std::string>()), a = parse_exact(s["below"].get<std::string>()),
                b = parse_exact(s["above"].get<std::string>());
        BOOST_TEST(closed_form(x, a) == scalecert::Verdict::Separated);
        BOOST_TEST(closed_form(x, b) != scalecert::Verdict::Separated);
        BOOST_TEST(b - a <= Q(7) / (Q(1) << 60));
    }
    BOOST_TEST(g.queries.size() > 20u);
    for (const auto& q : g.queries)
        BOOST_TEST(verdict_name(closed_form(parse_exact(q["rho1"].get<std::string>()),
                                            parse_exact(q["rho2"].get<std::string>()))) ==
                   q["verdict_at_doubles"].get<std::string>());
    BOOST_TEST(g.csv.find("rho1,rho2,where,verdict_at_doubles,signed_distance\n") == 0);
}
