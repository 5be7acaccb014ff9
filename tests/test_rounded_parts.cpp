// Objects made of parts with radii (CLAIMS.md, "Objects with a radius", "Parts with radii"): the
// hand-derived case, then a brute force in rationals over random sphere sets against sphere sets
// and rounded boxes (closed forms: a point's distance to a point and to an axis box; no hull, no
// GJK), and the refusals.
#include <boost/test/unit_test.hpp>

#include "certify/rounded_parts.hpp"
#include "session/engine.hpp"
#include "support.hpp"

#include <cmath>
#include <random>

using namespace scalecert::internal;

namespace {

ReadOptions with_parts() {
    ReadOptions o;
    o.allow_parts = true;
    return o;
}
struct Opened {
    std::shared_ptr<const ExactScene> scene;
    std::unique_ptr<SceneEngine> engine;
    std::unique_ptr<ClaimRules> rules;
};
Opened open(const std::string& json, const Tolerance& tol = {}) {
    Opened o;
    o.scene = std::make_shared<const ExactScene>(parse_scene_text(json, "scene", ".", with_parts()));
    o.engine = open_engine(o.scene, "scene");
    o.engine->check();
    o.rules = o.engine->rules(tol);
    return o;
}
TypedClaim at(ClaimType t, const Q& r1, const Q& r2, const Q& value = Q(0)) {
    TypedClaim c;
    c.type = t;
    c.rho1 = r1;
    c.rho2 = r2;
    c.value = value;
    return c;
}
Q q(long p, long d = 1) { return test::qc(p, d); }
long rho_of(int p) { return 2 + p % 4; }

}  // namespace

// Two spheres about the seed 0 (radius 1 at 0, radius 1/2 at (3, 0, 0)) against the box
// [5, 7] × [−1, 1]² about its centre (6, 0, 0). Along x the second sphere reaches 3ρ1 + ρ1/2 and
// the box starts at 6 − ρ2: they touch where 7ρ1/2 = 6 − ρ2 (at ρ2 = 1, ρ1 = 10/7), and at (1, 1)
// they are 3/2 apart (the first sphere 4). At (2, 1) the second sphere's centre (6, 0, 0) lies 1
// deep in the box: that pair's depth is 1 + R = 2.
BOOST_AUTO_TEST_CASE(a_sphere_set_against_a_box_by_hand) {
    Opened k = open(R"({"P1": {"spheres": {"centres": [[0,0,0],[3,0,0]], "radii": [1, "1/2"]}, "seed": [0,0,0]},
                        "P2": {"box": [1,1,1], "pose": [[1,0,0,6],[0,1,0,0],[0,0,1,0]]}})");
    BOOST_TEST(k.engine->verdict(q(1), q(1)) == scalecert::Verdict::Separated);
    BOOST_TEST(k.engine->verdict(q(10, 7), q(1)) == scalecert::Verdict::Touching);
    BOOST_TEST(k.engine->verdict(q(10, 7), q(11, 10)) == scalecert::Verdict::Overlapping);
    BOOST_TEST(k.engine->verdict(q(1), q(5, 2)) == scalecert::Verdict::Touching);  // 7/2 = 6 − 5/2
    auto judge = [&](const TypedClaim& c) { return k.rules->judge(c); };
    // The distance is the second sphere's, 3/2: pair (1, 0).
    const Judged d = judge(at(ClaimType::Distance, q(1), q(1), q(3, 2)));
    BOOST_TEST(d.right);
    BOOST_TEST(d.part1 == 1);
    BOOST_TEST(d.part2 == 0);
    BOOST_TEST(!judge(at(ClaimType::Distance, q(1), q(1), q(4))).right);
    TypedClaim closest = at(ClaimType::Distance, q(1), q(1), q(3, 2));
    closest.closest = std::array<Vec3q, 2>{Vec3q{q(7, 2), q(0), q(0)}, Vec3q{q(5), q(0), q(0)}};
    BOOST_TEST(judge(closest).right);
    closest.closest = std::array<Vec3q, 2>{Vec3q{q(7, 2), q(1, 10), q(0)}, Vec3q{q(5), q(0), q(0)}};  // outside
    BOOST_TEST(!judge(closest).right);
    // Signed distances of part pairs: the first sphere is 5 − 1 = 4 from the box.
    TypedClaim s = at(ClaimType::SignedDistance, q(1), q(1), q(4));
    s.parts = std::array<int, 2>{0, 0};
    BOOST_TEST(judge(s).right);
    s.parts = std::array<int, 2>{1, 0};
    BOOST_TEST(!judge(s).right);
    s.value = q(3, 2);
    BOOST_TEST(judge(s).right);
    TypedClaim depth = at(ClaimType::Depth, q(2), q(1), q(2));
    depth.parts = std::array<int, 2>{1, 0};
    BOOST_TEST(judge(depth).right);
    depth.value = q(1);
    BOOST_TEST(!judge(depth).right);
    // A witness in the second sphere at ρ1 = 2 (centre 6, radius 1) and on the box's face.
    TypedClaim w = at(ClaimType::Witness, q(2), q(1));
    w.point = Vec3q{q(5), q(0), q(0)};
    const Judged wj = judge(w);
    BOOST_TEST(wj.right);
    BOOST_TEST(wj.get<WitnessJudged>()->in_part1 == 1);
    w.point = Vec3q{q(5), q(1, 2), q(1, 2)};  // √(1/2) from the centre... 1/4 + 1/4 + 1 > 1: out
    BOOST_TEST(!judge(w).right);
    // Planes x = offset at (1, 1): P1 reaches 7/2, the box starts at 5.
    TypedClaim p = at(ClaimType::Plane, q(1), q(1));
    p.normal = Vec3q{q(1), q(0), q(0)};
    p.offset = q(4);
    BOOST_TEST(judge(p).right);
    p.offset = q(7, 2);  // touches the second sphere: not strictly between
    BOOST_TEST(!judge(p).right);
    p.offset.reset();
    // Along (1, 1, 0) P1 reaches 3 + √2/2 < 4, where the box starts; along (1, 2, 0) 3 + √5/2 > 3.
    p.normal = Vec3q{q(1), q(1), q(0)};
    BOOST_TEST(judge(p).right);
    p.normal = Vec3q{q(1), q(2), q(0)};
    BOOST_TEST(!judge(p).right);
}

BOOST_AUTO_TEST_CASE(radii_on_parts_are_read) {
    // The object's radius is each part's without its own; a part's shorthand carries its own.
    const ExactScene sc = parse_scene_text(
        R"({"P1": {"parts": [{"vertices": [[0,0,0],[1,0,0]]}, {"sphere": 2}, {"box": [1,1,1], "radius": 0}],
                   "radius": "1/4", "seed": [0,0,0]},
            "P2": {"sphere": 1, "pose": [[1,0,0,9],[0,1,0,0],[0,0,1,0]]}})",
        "s.json", ".", with_parts());
    BOOST_TEST(sc.P[0].part_radius(0) == Q(1, 4));
    BOOST_TEST(sc.P[0].part_radius(1) == Q(2));
    BOOST_TEST(sc.P[0].part_radius(2) == Q(0));
    BOOST_TEST(sc.P[1].part_radius(0) == Q(1));
    BOOST_TEST(sc.rounded());
    // Along x the capsule reaches 5ρ1/4, the ball 2ρ1 and the box ρ1; P2's ball starts at 9 − ρ2.
    auto e = open_engine(std::make_shared<const ExactScene>(sc), "s.json");
    BOOST_TEST(e->verdict(q(1), q(1)) == scalecert::Verdict::Separated);
    BOOST_TEST(e->verdict(q(4), q(1)) == scalecert::Verdict::Touching);
    BOOST_TEST(e->verdict(q(4), q(2)) == scalecert::Verdict::Overlapping);
}

BOOST_AUTO_TEST_CASE(refusals_in_one_line) {
    auto err = [](const std::string& json) {
        return test::input_error([&] {
            auto sc = std::make_shared<const ExactScene>(parse_scene_text(json, "s.json", ".", with_parts()));
            open_engine(sc, "s.json")->check();
        });
    };
    const std::string two = R"("P2": {"sphere": 1, "pose": [[1,0,0,9],[0,1,0,0],[0,0,1,0]]})";
    BOOST_TEST(err(R"({"P1": {"spheres": {"centres": [[0,0,0]], "radii": [1, 2]}}, )" + two + "}")
                   .find("P1.spheres.radii: expected a list of 1 radii") != std::string::npos);
    BOOST_TEST(err(R"({"P1": {"spheres": {"centres": [[0,0,0]], "radii": [0]}}, )" + two + "}")
                   .find("P1.spheres.radii[0]: a sphere's radius is > 0") != std::string::npos);
    BOOST_TEST(err(R"({"P1": {"parts": [{"vertices": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]]}], "radius": 0}, )" + two + "}")
                   .find("P1.parts[0]: its points span no volume (they lie in a plane)") != std::string::npos);
    BOOST_TEST(err(R"({"P1": {"parts": [{"vertices": [[0,0,0]]}]}, )" + two + "}")
                   .find("P1.parts[0]: fewer than 4 vertices (1) and no radius > 0") != std::string::npos);
    // What is not built for them says so, in one line.
    auto sc = std::make_shared<const ExactScene>(parse_scene_text(
        R"({"P1": {"spheres": {"centres": [[0,0,0]], "radii": [1]}}, )" + two + "}", "s.json", ".", with_parts()));
    auto e = open_engine(sc, "s.json");
    BOOST_TEST(test::input_error([&] { e->partition_document(); })
                   .find("not built for objects made of parts with "
                         "radii") != std::string::npos);
    auto rules = e->rules({});
    BOOST_TEST(test::input_error([&] {
                   rules->part_pair(std::nullopt, "c.json: claims[0]");
               }).find("c.json: claims[0].parts: missing") != std::string::npos);
}

// ---- the brute force ---------------------------------------------------------------------------

namespace {

Q dot3q(const Vec3q& a, const Vec3q& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// An object of the brute force: spheres (centres and radii) or one axis box of half-extents e
// and radius r centred at its seed; every part scaled about the seed.
struct Thing {
    bool box = false;
    std::vector<Vec3q> centres;
    std::vector<Q> radii;
    Q e[3], r;
    Vec3q seed;
    size_t parts() const { return box ? 1 : centres.size(); }
    Vec3q centre_at(size_t k, const Q& rho) const {
        Vec3q c;
        for (int a = 0; a < 3; ++a) c[a] = seed[a] + rho * (centres[k][a] - seed[a]);
        return c;
    }
    std::string json() const {
        auto s = [](const Q& x) { return "\"" + to_exact_string(x) + "\""; };
        auto pt = [&](const Vec3q& v) { return "[" + s(v[0]) + ", " + s(v[1]) + ", " + s(v[2]) + "]"; };
        if (box)
            return "{\"box\": [" + s(e[0]) + ", " + s(e[1]) + ", " + s(e[2]) + "], \"radius\": " + s(r) +
                   ", \"pose\": [[1,0,0," + s(seed[0]) + "],[0,1,0," + s(seed[1]) + "],[0,0,1," + s(seed[2]) + "]]}";
        std::string c, rr;
        for (size_t k = 0; k < centres.size(); ++k)
            c += (k ? ", " : "") + pt(centres[k]), rr += (k ? ", " : "") + s(radii[k]);
        return "{\"spheres\": {\"centres\": [" + c + "], \"radii\": [" + rr + "]}, \"seed\": " + pt(seed) + "}";
    }
};

// T moved by [M | t] (M orthogonal; for a box, a signed permutation): its centres and seed, and
// a box's centre and half-extents.
Thing moved(const Thing& T, const Q M[3][3], const Q t[3]) {
    Thing out = T;
    auto move = [&](const Vec3q& v) {
        Vec3q w;
        for (int r = 0; r < 3; ++r) w[r] = M[r][0] * v[0] + M[r][1] * v[1] + M[r][2] * v[2] + t[r];
        return w;
    };
    for (Vec3q& c : out.centres) c = move(c);
    out.seed = move(T.seed);
    if (T.box)
        for (int r = 0; r < 3; ++r)
            for (int a = 0; a < 3; ++a)
                if (sgn(M[r][a]) != 0) out.e[r] = T.e[a];
    return out;
}

// The squared distance from x to part k of T at ρ (its hull: a point, or the box), and its radius.
std::pair<Q, Q> hull_to(const Thing& T, size_t k, const Q& rho, const Vec3q& x) {
    if (!T.box) {
        Vec3q d = T.centre_at(k, rho);
        for (int a = 0; a < 3; ++a) d[a] -= x[a];
        return {dot3q(d, d), rho * T.radii[k]};
    }
    Q s = 0;
    for (int a = 0; a < 3; ++a) {
        const Q out = abs(x[a] - T.seed[a]) - rho * T.e[a];
        if (sgn(out) > 0) s += out * out;
    }
    return {s, rho * T.r};
}

}  // namespace

BOOST_AUTO_TEST_CASE(brute_force_over_sphere_sets) {
    std::mt19937_64 g(58);
    std::uniform_int_distribution<int> coord(-16, 16), rad(1, 8), count(1, 5), rho(2, 8), coin(0, 1);
    Tolerance tol;
    tol.rel = Q(1, 1000000000);
    long verdicts[3] = {}, values = 0, right_values = 0;
    for (int trial = 0; trial < 150; ++trial) {
        Thing A, B;
        auto spheres = [&](Thing& T, long shift) {
            const int n = count(g);
            for (int k = 0; k < n; ++k) {
                T.centres.push_back({q(coord(g) + shift, 4), q(coord(g), 4), q(coord(g), 4)});
                T.radii.push_back(q(rad(g), 4));
            }
            T.seed = {q(coord(g) + shift, 8), q(coord(g), 8), q(coord(g), 8)};
        };
        spheres(A, 0);
        if (coin(g)) {
            B.box = true;
            for (Q& x : B.e) x = q(rad(g), 4);
            B.r = trial % 3 == 0 ? Q(0) : q(rad(g), 8);
            B.seed = {q(coord(g) + 24, 4), q(coord(g), 4), q(coord(g), 4)};
        } else {
            spheres(B, 24);
        }
        Opened k = open("{\"P1\": " + A.json() + ", \"P2\": " + B.json() + "}", tol);
        // Every other trial judges claims with P2 at a pose (a box: a signed permutation; spheres:
        // a rational rotation), against the brute force on P2 moved.
        Pose pose;
        Q M[3][3], t[3];
        const bool posed = trial % 2 == 1;
        if (posed) {
            std::uniform_int_distribution<int> small(-2, 2), perm(0, 5);
            if (B.box) {
                static const int P[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
                const int* p = P[perm(g)];
                for (int r = 0; r < 3; ++r)
                    for (int a = 0; a < 3; ++a) M[r][a] = a == p[r] ? Q(small(g) < 0 ? -1 : 1) : Q(0);
            } else {
                long w, x, y, z;
                do w = small(g), x = small(g), y = small(g), z = small(g);
                while (w * w + x * x + y * y + z * z == 0);
                const Q n(w * w + x * x + y * y + z * z);
                const long R[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                                      {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                                      {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
                for (int r = 0; r < 3; ++r)
                    for (int a = 0; a < 3; ++a) M[r][a] = Q(R[r][a]) / n;
            }
            for (int r = 0; r < 3; ++r) t[r] = q(coord(g), 8);
            for (size_t r = 0; r < 3; ++r) {
                for (size_t a = 0; a < 3; ++a) pose[r][a] = M[r][a];
                pose[r][3] = t[r];
            }
            B = moved(B, M, t);
        }
        for (int pr = 0; pr < 3; ++pr) {
            const Q r1 = q(rho(g), 4), r2 = q(rho(g), 4);
            auto at = [&](ClaimType type, const Q& x1, const Q& x2, const Q& value = Q(0)) {
                TypedClaim c = ::at(type, x1, x2, value);
                if (posed) c.pose[1] = pose;
                return c;
            };
            // Each pair's hulls' squared distance E and R; the union's verdict and least √E − R.
            int state = -1;  // −1 separated, 0 touching, 1 overlapping
            long double least = INFINITY;
            for (size_t a = 0; a < A.parts(); ++a)
                for (size_t b = 0; b < B.parts(); ++b) {
                    const Vec3q ca = A.centre_at(a, r1);
                    const auto [E, Rb] = hull_to(B, b, r2, ca);
                    const Q R = r1 * A.radii[a] + Rb;
                    const int c = cmp(E, R * R);
                    state = std::max(state, c > 0 ? -1 : c == 0 ? 0 : 1);
                    least = std::min(least, std::sqrt(static_cast<long double>(E.get_d())) - R.get_d());
                    // The pair's signed distance: a sphere's centre in the box is E = 0 (then the
                    // signed distance is the centre's depth below the box less R: not computed here).
                    if (sgn(E) == 0) continue;
                    const long double x = std::sqrt(static_cast<long double>(E.get_d())) - R.get_d();
                    if (std::fabs(static_cast<double>(x)) < 1e-3) continue;
                    TypedClaim s = at(ClaimType::SignedDistance, r1, r2, exact_from_double(static_cast<double>(x)));
                    s.parts = std::array<int, 2>{static_cast<int>(a), static_cast<int>(b)};
                    BOOST_TEST(k.rules->judge(s).right, "trial " << trial << " pair " << a << "," << b);
                    s.value = exact_from_double(static_cast<double>(x * (1 + 1e-6L)));
                    BOOST_TEST(!k.rules->judge(s).right, "trial " << trial << " pair " << a << "," << b);
                    values += 2;
                    ++right_values;
                }
            const scalecert::Verdict v = state < 0    ? scalecert::Verdict::Separated
                                         : state == 0 ? scalecert::Verdict::Touching
                                                      : scalecert::Verdict::Overlapping;
            ++verdicts[state + 1];
            TypedClaim vc = at(ClaimType::Verdict, r1, r2);
            vc.verdict = Claimed::Separated;
            BOOST_TEST(k.rules->judge(vc).right == (v == scalecert::Verdict::Separated), "trial " << trial);
            vc.verdict = Claimed::Overlapping;
            BOOST_TEST(k.rules->judge(vc).right == (v == scalecert::Verdict::Overlapping), "trial " << trial);
            if (!posed) BOOST_TEST(k.engine->verdict(r1, r2) == v, "trial " << trial);
            // The distance: the least √E − R when apart (the nearest double right, 1e-6 off wrong), else 0.
            const long double dist = state < 0 ? least : 0;
            if (state < 0 && dist < 1e-3) continue;
            BOOST_TEST(
                k.rules->judge(at(ClaimType::Distance, r1, r2, exact_from_double(static_cast<double>(dist)))).right,
                "trial " << trial);
            BOOST_TEST(!k.rules
                            ->judge(at(ClaimType::Distance, r1, r2,
                                       exact_from_double(static_cast<double>(dist * (1 + 1e-6L)) + 1e-6)))
                            .right,
                       "trial " << trial);
            values += 2;
            ++right_values;
            // A witness: the first sphere's centre of A, in A; in B when within a part of it.
            TypedClaim w = at(ClaimType::Witness, r1, r2);
            w.point = A.centre_at(0, r1);
            w.with_verdict = false;
            bool inB = false;
            for (size_t b = 0; b < B.parts(); ++b) {
                const auto [E, m] = hull_to(B, b, r2, w.point);
                inB = inB || E <= m * m;
            }
            BOOST_TEST(k.rules->judge(w).right == inB, "trial " << trial);
        }
    }
    BOOST_TEST_MESSAGE("sphere sets: verdicts " << verdicts[0] << " separated, " << verdicts[1] << " touching, "
                                                << verdicts[2] << " overlapping; " << values << " values, "
                                                << right_values << " right");
    BOOST_TEST(verdicts[0] > 50);
    BOOST_TEST(verdicts[2] > 50);
    BOOST_TEST(values > 500);
}

// The filters in doubles (boxes, supports) only skip pairs they prove apart or farther than the
// nearest: on a robot-like set of 120 spheres against a 60-point hull at 40 poses (rational
// rotations), the verdict and the nearest pair's value equal those of every pair judged exactly.
BOOST_AUTO_TEST_CASE(filters_skip_only_what_they_prove) {
    std::mt19937_64 g(59);
    std::uniform_int_distribution<int> c(-40, 40), small(-3, 3), rad(2, 6);
    std::string centres, radii, hull;
    for (int k = 0; k < 120; ++k) {
        const int s = k - 60;  // along a line in x, wobbling in y and z
        centres += std::string(k ? ", " : "") + "[\"" + std::to_string(s) + "/20\", \"" + std::to_string(small(g)) +
                   "/40\", \"" + std::to_string(small(g)) + "/40\"]";
        radii += std::string(k ? ", " : "") + "\"" + std::to_string(rad(g)) + "/40\"";
    }
    for (int k = 0; k < 60; ++k)
        hull += std::string(k ? ", " : "") + "[\"" + std::to_string(c(g)) + "/80\", \"" + std::to_string(c(g)) +
                "/80\", \"" + std::to_string(c(g)) + "/80\"]";
    const auto sc = std::make_shared<const ExactScene>(
        parse_scene_text("{\"P1\": {\"spheres\": {\"centres\": [" + centres + "], \"radii\": [" + radii +
                             "]}}, \"P2\": {\"vertices\": [" + hull + "], \"seed\": [0, 0, 0]}}",
                         "robot.json", ".", with_parts()));
    RoundedParts J(*sc, "robot.json");
    long met = 0, apart = 0;
    for (int p = 0; p < 40; ++p) {
        long w, x, y, z;
        do w = small(g), x = small(g), y = small(g), z = small(g);
        while (w * w + x * x + y * y + z * z == 0);
        const Q n(w * w + x * x + y * y + z * z);
        const long R[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                              {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                              {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
        RoundedParts::Poses pose;
        Pose& m = pose[1].emplace();
        for (size_t r = 0; r < 3; ++r) {
            for (size_t a = 0; a < 3; ++a) m[r][a] = Q(R[r][a]) / n;
            m[r][3] = q(c(g), 20);
        }
        const Q r1 = q(rho_of(p), 4), r2 = q(4 + p % 5, 4);
        // Every pair, exactly: the union's state and the least √E − R (compared exactly).
        int state = -1, ba = -1;
        RoundedParts::PairState best;
        for (int a = 0; a < static_cast<int>(J.parts(0)); ++a) {
            RoundedParts::PairState st = J.pair_state(a, 0, r1, r2, pose);
            state = std::max(state, st.verdict == scalecert::Verdict::Separated  ? -1
                                    : st.verdict == scalecert::Verdict::Touching ? 0
                                                                                 : 1);
            if (st.verdict != scalecert::Verdict::Separated) continue;
            if (ba < 0 ||
                sign_two_sqrts(best.R - st.R, Q(1), st.hulls.distance.squared, Q(-1), best.hulls.distance.squared) < 0)
                ba = a, best = std::move(st);
        }
        const scalecert::Verdict v = state < 0    ? scalecert::Verdict::Separated
                                     : state == 0 ? scalecert::Verdict::Touching
                                                  : scalecert::Verdict::Overlapping;
        BOOST_TEST(J.verdict(r1, r2, pose).verdict == v, "pose " << p);
        const RoundedParts::Nearest e = J.nearest(r1, r2, pose);
        if (state >= 0) {
            ++met;
            BOOST_TEST(e.state.verdict != scalecert::Verdict::Separated, "pose " << p);
            continue;
        }
        ++apart;
        // The same value s√E − R (another pair may tie).
        BOOST_TEST(sign_two_sqrts(best.R - e.state.R, Q(1), e.state.hulls.distance.squared, Q(-1),
                                  best.hulls.distance.squared) == 0,
                   "pose " << p << ": nearest " << e.a << " against " << ba);
    }
    BOOST_TEST_MESSAGE("robot-like: " << met << " poses meeting, " << apart << " apart; counts " << J.counts().boxed
                                      << " filtered, " << J.counts().exact << " exact");
    BOOST_TEST(met > 5);
    BOOST_TEST(apart > 5);
}

// Golden data on the hand case (a_sphere_set_against_a_box_by_hand): the set crosses ρ1 × I2
// where 7ρ1/2 = 6 − ρ2, a line here (the second sphere against the box's face), so every sample's
// touching pair (found exactly at these dyadic ρ1) is (ρ1, 6 − 7ρ1/2), its pair (1, 0).
BOOST_AUTO_TEST_CASE(golden_samples_on_parts) {
    Opened k = open(R"({"P1": {"spheres": {"centres": [[0,0,0],[3,0,0]], "radii": [1, "1/2"]}, "seed": [0,0,0]},
                        "P2": {"box": [1,1,1], "pose": [[1,0,0,6],[0,1,0,0],[0,0,1,0]]}, "I1": [1, 2], "I2": [1, 2]})");
    const GoldenAnswers g = k.engine->golden(GoldenPoints{9, {4}});
    int crossing = 0;
    for (const Json& s : g.curve["samples"]) {
        const Q x(s["rho1"].get<std::string>());
        const Q y = 6 - Q(7, 2) * x;  // the touching ρ2
        if (!s["crosses"].get<bool>()) {
            BOOST_TEST((y < 1 || y > 2));
            continue;
        }
        ++crossing;
        BOOST_TEST(Q(s["touching"].get<std::string>()) == y);
    }
    BOOST_TEST(crossing == 2);  // ρ1 = 5/4 and 11/8 among 1, 9/8, ..., 2
    for (const Json& q : g.queries) {
        BOOST_TEST(q["pair_signed_distance"]["pair"] == Json::array({1, 0}));
        const Q x(q["rho1"].get<std::string>()), y(q["rho2"].get<std::string>());
        const Q gap = 6 - y - Q(7, 2) * x;  // the pair's signed distance, by hand
        BOOST_TEST(q["verdict_at_doubles"] == (sgn(gap) > 0    ? "separated"
                                               : sgn(gap) == 0 ? "touching"
                                                               : "overlapping"));
    }
}

// Scales where doubles underflow (the hostile review's cases): the filters stand aside and the
// exact judgement decides. Spheres of radii 2/D and 7/D about centres 9/D apart, every seed at
// the origin (D = 5·2^1074: radii below the least double): 9ρ2 against 2ρ1 + 7ρ2, so at (ρ, ρ)
// they touch for every ρ, 10^300 too. Spheres of radius 1/10 at (2, 0, 0) and (0, 3/2, 0) against one at 0: at
// (10^-163, 10^-163) (squared distances below the least double) the distance is 13/10·10^-163.
BOOST_AUTO_TEST_CASE(underflowing_scales_are_judged_exactly) {
    const std::string D = to_exact_string(Q(Z(5) << 1074));
    Opened k = open(R"({"P1": {"spheres": {"centres": [[0, 0, 0]], "radii": ["2/)" + D +
                    R"("]}, "seed": [0, 0, 0]}, "P2": {"spheres": {"centres": [["9/)" + D +
                    R"(", 0, 0]], "radii": ["7/)" + D + R"("]}, "seed": [0, 0, 0]}})");
    Z ten300 = 1;
    for (int e = 0; e < 300; ++e) ten300 *= 10;
    BOOST_TEST(k.engine->verdict(q(1), q(1)) == scalecert::Verdict::Touching);
    BOOST_TEST(k.engine->verdict(Q(ten300), Q(ten300)) == scalecert::Verdict::Touching);
    // 9ρ2 against 2ρ1 + 7ρ2: apart when ρ2 > ρ1, overlapping when ρ1 > ρ2.
    BOOST_TEST(k.engine->verdict(Q(ten300), Q(ten300 + 1)) == scalecert::Verdict::Separated);
    BOOST_TEST(k.engine->verdict(Q(ten300 + 1), Q(ten300)) == scalecert::Verdict::Overlapping);
    Opened t = open(R"({"P1": {"spheres": {"centres": [[0, 0, 0]], "radii": ["1/10"]}, "seed": [0, 0, 0]},
                        "P2": {"spheres": {"centres": [[2, 0, 0], [0, "3/2", 0]], "radii": ["1/10", "1/10"]},
                               "seed": [0, 0, 0]}})");
    Z ten163 = 1;
    for (int e = 0; e < 163; ++e) ten163 *= 10;
    const Q rho = Q(1) / Q(ten163);
    TypedClaim d = at(ClaimType::Distance, rho, rho, Q(13, 10) * rho);
    const Judged j = t.rules->judge(d);
    BOOST_TEST(j.right);
    BOOST_TEST(j.part2 == 1);
    d.value = Q(18, 10) * rho;  // the other sphere's
    BOOST_TEST(!t.rules->judge(d).right);
}
