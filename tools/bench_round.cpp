// scalecert-bench --round: objects with a radius (CLAIMS.md, "Objects with a radius") judged
// against FCL producing the same outputs in the same run. 1,000 pairs at random poses held as
// doubles: sphere-sphere, sphere-capsule, capsule-capsule, and a 1,000-point hull rounded by 1/20
// against a sphere. FCL computes each pair's signed distance (fcl::Sphere, fcl::Capsule; the
// rounded hull as an fcl::Convex, its distance less the radius, the same output), and scalecert
// judges those 1,000 outputs as signed_distance claims through the typed API (Analysis::certify,
// via the FCL adapter). Best of 3 (1 with --quick).
#include "scalecert/fcl.hpp"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/broadphase/default_broadphase_callbacks.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

template <class F>
double best_of(int reps, F&& f) {
    double best = 1e300;
    for (int r = 0; r < reps; ++r) {
        const auto t0 = Clock::now();
        f();
        best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
    }
    return best;
}

fcl::Transform3d random_pose(std::mt19937_64& g, double spread) {
    std::normal_distribution<double> n(0, 1);
    std::uniform_real_distribution<double> u(-spread, spread);
    Eigen::Quaterniond q(n(g), n(g), n(g), n(g));
    q.normalize();
    fcl::Transform3d t = fcl::Transform3d::Identity();
    t.linear() = q.toRotationMatrix();
    t.translation() = fcl::Vector3d(u(g), u(g), u(g));
    return t;
}

}  // namespace

int round_bench(bool quick) {
    const int reps = quick ? 1 : 3;
    std::mt19937_64 g(57);
    // The shapes: two spheres, two capsules, a 1,000-point hull (points on a unit sphere).
    auto s1 = std::make_shared<fcl::Sphered>(0.5), s2 = std::make_shared<fcl::Sphered>(0.3);
    auto c1 = std::make_shared<fcl::Capsuled>(0.25, 1.0), c2 = std::make_shared<fcl::Capsuled>(0.2, 1.5);
    std::normal_distribution<double> n(0, 1);
    auto pts = std::make_shared<std::vector<fcl::Vector3d>>();
    std::vector<scalecert::Point> hull_points;
    for (int k = 0; k < 1000; ++k) {
        double x = n(g), y = n(g), z = n(g);
        const double l = std::sqrt(x * x + y * y + z * z);
        pts->push_back(fcl::Vector3d(x / l, y / l, z / l));
        hull_points.push_back({scalecert::exact(x / l), scalecert::exact(y / l), scalecert::exact(z / l)});
    }
    // FCL's Convex wants faces; the distance uses the vertices alone (GJK), so one dummy face.
    auto faces = std::make_shared<std::vector<int>>(std::vector<int>{3, 0, 1, 2});
    auto hull = std::make_shared<fcl::Convexd>(pts, 1, faces);
    const double hull_radius = 0.05;

    struct Pair {
        std::shared_ptr<fcl::CollisionGeometryd> a, b;
        fcl::Transform3d ta, tb;
        int kind;  // 0 sphere-sphere, 1 sphere-capsule, 2 capsule-capsule, 3 rounded hull-sphere
    };
    std::vector<Pair> pairs;
    for (int i = 0; i < 1000; ++i) {
        const int kind = i % 4;
        Pair p{kind == 2   ? std::shared_ptr<fcl::CollisionGeometryd>(c1)
               : kind == 3 ? std::shared_ptr<fcl::CollisionGeometryd>(hull)
                           : std::shared_ptr<fcl::CollisionGeometryd>(s1),
               kind == 0 || kind == 3 ? std::shared_ptr<fcl::CollisionGeometryd>(s2)
                                      : std::shared_ptr<fcl::CollisionGeometryd>(kind == 1 ? c1 : c2),
               random_pose(g, 0.1), random_pose(g, 1.5), kind};
        pairs.push_back(p);
    }
    // FCL: the signed distance of each pair (the rounded hull's: its Convex's less 1/20).
    std::vector<double> said(pairs.size());
    auto fcl_run = [&] {
        fcl::DistanceRequestd req;
        req.enable_signed_distance = true;
        for (size_t i = 0; i < pairs.size(); ++i) {
            fcl::DistanceResultd res;
            fcl::distance(pairs[i].a.get(), pairs[i].ta, pairs[i].b.get(), pairs[i].tb, req, res);
            said[i] = res.min_distance - (pairs[i].kind == 3 ? hull_radius : 0);
        }
    };
    const double t_fcl = best_of(reps, fcl_run);
    double t_fcl_kind[4];
    for (int k = 0; k < 4; ++k)
        t_fcl_kind[k] = best_of(reps, [&] {
            fcl::DistanceRequestd req;
            req.enable_signed_distance = true;
            for (size_t i = 0; i < pairs.size(); ++i)
                if (pairs[i].kind == k) {
                    fcl::DistanceResultd res;
                    fcl::distance(pairs[i].a.get(), pairs[i].ta, pairs[i].b.get(), pairs[i].tb, req, res);
                    said[i] = res.min_distance - (k == 3 ? hull_radius : 0);
                }
        });
    // scalecert: the same 1,000 outputs as signed_distance claims at the pairs' poses, one scene
    // (and Analysis) per kind of pair.
    std::vector<scalecert::Analysis> analyses;
    analyses.emplace_back(scalecert::fcl_scene<double>(*s1, *s2));
    analyses.emplace_back(scalecert::fcl_scene<double>(*s1, *c1));
    analyses.emplace_back(scalecert::fcl_scene<double>(*c1, *c2));
    analyses.emplace_back(
        scalecert::Scene::with_radii(hull_points, {{0, 0, 0}}, {scalecert::exact(hull_radius), scalecert::exact(0.3)}));
    std::vector<std::vector<scalecert::Claim>> claims(4);
    for (size_t i = 0; i < pairs.size(); ++i) {
        scalecert::Claim c;
        c.kind = scalecert::ClaimKind::SignedDistance;
        c.value = scalecert::exact(said[i]);
        c.pose1 = scalecert::fcl_pose(pairs[i].ta);
        c.pose2 = scalecert::fcl_pose(pairs[i].tb);
        claims[static_cast<size_t>(pairs[i].kind)].push_back(c);
    }
    scalecert::ClaimOptions opt;
    opt.tolerance = scalecert::parse_rational("1/1000000000");
    opt.abs_tolerance = scalecert::parse_rational("1/1000000000");
    long wrong = 0;
    double t_ours_kind[4];
    for (int k = 0; k < 4; ++k)
        t_ours_kind[k] = best_of(
            reps, [&] { wrong = analyses[static_cast<size_t>(k)].certify(claims[static_cast<size_t>(k)], opt).wrong; });
    double t_ours = 0;
    for (double t : t_ours_kind) t_ours += t;
    // How far FCL is off (its GJK stops at a distance tolerance of 1e-6): the largest error per
    // kind, and how many are wrong at a relative 1e-5 (+ 1e-9 m) as well.
    long wrong_all = 0, wrong_loose = 0;
    double worst[4] = {0, 0, 0, 0};
    scalecert::ClaimOptions loose = opt;
    loose.tolerance = scalecert::parse_rational("1/100000");
    for (int k = 0; k < 4; ++k) {
        const auto& a = analyses[static_cast<size_t>(k)];
        const auto& cs = claims[static_cast<size_t>(k)];
        const scalecert::Judgements j = a.certify(cs, opt);
        wrong_all += j.wrong;
        wrong_loose += a.certify(cs, loose).wrong;
        for (size_t i = 0; i < j.items.size(); ++i)
            worst[k] = std::max(worst[k], std::fabs(cs[i].value.get_d() - j.items[i].exact));
    }
    const char* names[4] = {"250 sphere-sphere", "250 sphere-capsule", "250 capsule-capsule",
                            "250 rounded 1,000-point hull-sphere"};
    std::printf("| measured | time | against FCL in the same run |\n|---|---|---|\n");
    std::printf("| FCL's signed distances, 1,000 pairs at random poses | %.3g s | 1 (baseline) |\n", t_fcl);
    std::printf(
        "| scalecert judging those 1,000 outputs (typed, signed_distance at their poses) | %.3g s | %.2fx FCL's "
        "time (target <= 2x); wrong: %ld of 1,000 at 1e-9, %ld at a relative 1e-5 |\n",
        t_ours, t_ours / t_fcl, wrong_all, wrong_loose);
    for (int k = 0; k < 4; ++k)
        std::printf("|   %s | %.3g s | %.2fx FCL's %.3g s; FCL off by up to %.2g |\n", names[k], t_ours_kind[k],
                    t_ours_kind[k] / t_fcl_kind[k], t_fcl_kind[k], worst[k]);
    return 0;
}

// scalecert-bench --robot: a robot of 1,000 spheres (one object of parts) against a 1,000-point
// hull (CLAIMS.md, "Parts with radii"), at 100 poses of the hull around the arm. FCL answers each
// pose as a motion planner asks it: a DynamicAABBTree broad phase over the spheres (set up once,
// as the robot stands still), then collide (any contact: the verdict) and distance (the least over
// the spheres), each narrow phase FCL's GJK on sphere and hull. scalecert judges FCL's 200
// outputs (a verdict and a distance per pose, at the hull's pose) through the typed API. Best of
// 3 (1 with --quick).
int robot_bench(bool quick) {
    const int reps = quick ? 1 : 3;
    std::mt19937_64 g(58);
    std::uniform_real_distribution<double> u(-1, 1), rr(0.03, 0.06);
    // The arm: 7 links of a random walk from the origin, 0.4 long each, 1,000 spheres along them.
    std::vector<fcl::Vector3d> joint{fcl::Vector3d(0, 0, 0)};
    for (int l = 0; l < 7; ++l) {
        fcl::Vector3d d(u(g), u(g), 0.5 + std::abs(u(g)));
        joint.push_back(joint.back() + 0.4 * d.normalized());
    }
    std::vector<fcl::Vector3d> centres;
    std::vector<double> radii;
    for (int k = 0; k < 1000; ++k) {
        const double s = 7.0 * k / 1000;
        const int l = static_cast<int>(s);
        centres.push_back(joint[static_cast<size_t>(l)] +
                          (s - l) * (joint[static_cast<size_t>(l) + 1] - joint[static_cast<size_t>(l)]));
        radii.push_back(rr(g));
    }
    // The obstacle: 1,000 points on an ellipsoid of semi-axes 0.3, 0.2, 0.15.
    std::normal_distribution<double> n(0, 1);
    auto pts = std::make_shared<std::vector<fcl::Vector3d>>();
    std::vector<scalecert::Point> hull_points;
    for (int k = 0; k < 1000; ++k) {
        double x = n(g), y = n(g), z = n(g);
        const double l = std::sqrt(x * x + y * y + z * z);
        x = 0.3 * x / l, y = 0.2 * y / l, z = 0.15 * z / l;
        pts->push_back(fcl::Vector3d(x, y, z));
        hull_points.push_back({scalecert::exact(x), scalecert::exact(y), scalecert::exact(z)});
    }
    auto faces = std::make_shared<std::vector<int>>(std::vector<int>{3, 0, 1, 2});  // GJK reads the vertices alone
    auto hull = std::make_shared<fcl::Convexd>(pts, 1, faces);
    // 100 poses of the hull: random rotations, centred near a random point of the arm.
    std::vector<fcl::Transform3d> poses;
    for (int p = 0; p < 100; ++p) {
        fcl::Transform3d t = random_pose(g, 0);
        const fcl::Vector3d& c = centres[static_cast<size_t>(std::uniform_int_distribution<int>(0, 999)(g))];
        t.translation() = c + fcl::Vector3d(0.35 * u(g), 0.35 * u(g), 0.35 * u(g));
        poses.push_back(t);
    }
    // FCL: the broad phase over the spheres, set up once (not timed).
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> spheres;
    fcl::DynamicAABBTreeCollisionManagerd manager;
    for (size_t k = 0; k < centres.size(); ++k) {
        fcl::Transform3d t = fcl::Transform3d::Identity();
        t.translation() = centres[k];
        spheres.push_back(std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Sphered>(radii[k]), t));
        manager.registerObject(spheres.back().get());
    }
    manager.setup();
    fcl::CollisionObjectd obstacle(hull);
    std::vector<int> hit(poses.size());
    std::vector<double> dist(poses.size());
    const double t_fcl = best_of(reps, [&] {
        for (size_t p = 0; p < poses.size(); ++p) {
            obstacle.setTransform(poses[p]);
            obstacle.computeAABB();
            fcl::DefaultCollisionData<double> cd;
            manager.collide(&obstacle, &cd, fcl::DefaultCollisionFunction);
            hit[p] = cd.result.isCollision();
            fcl::DefaultDistanceData<double> dd;
            manager.distance(&obstacle, &dd, fcl::DefaultDistanceFunction);
            dist[p] = dd.result.min_distance;
        }
    });
    // scalecert: one scene (the spheres as parts with radii, the hull as one part), its Analysis
    // made once (not timed, as FCL's setup); per pose a verdict claim (intersecting when FCL saw a
    // contact, else separated) and, when apart, a distance claim, with the hull at its pose.
    std::vector<std::vector<scalecert::Point>> parts1, parts2{hull_points};
    std::vector<scalecert::Rational> r1;
    for (size_t k = 0; k < centres.size(); ++k) {
        parts1.push_back(
            {{scalecert::exact(centres[k].x()), scalecert::exact(centres[k].y()), scalecert::exact(centres[k].z())}});
        r1.push_back(scalecert::exact(radii[k]));
    }
    const scalecert::Analysis a(
        scalecert::Scene::from_parts(parts1, parts2, {}, {}, std::nullopt, scalecert::Point{0, 0, 0}, {r1, {}}));
    std::vector<scalecert::Claim> claims;
    for (size_t p = 0; p < poses.size(); ++p) {
        scalecert::Claim v;
        v.kind = scalecert::ClaimKind::Verdict;
        v.verdict = hit[p] ? scalecert::ClaimedVerdict::Intersecting : scalecert::ClaimedVerdict::Separated;
        v.pose2 = scalecert::fcl_pose(poses[p]);
        claims.push_back(v);
        if (!hit[p]) {
            scalecert::Claim d = v;
            d.kind = scalecert::ClaimKind::Distance;
            d.value = scalecert::exact(dist[p]);
            claims.push_back(d);
        }
    }
    scalecert::ClaimOptions opt;
    opt.tolerance = scalecert::parse_rational("1/1000000000");
    opt.abs_tolerance = scalecert::parse_rational("1/1000000000");
    scalecert::Judgements j;
    const double t_ours = best_of(reps, [&] { j = a.certify(claims, opt); });
    long hits = 0, wrong_verdicts = 0, wrong_distances = 0, loose_wrong = 0;
    for (int h : hit) hits += h;
    for (size_t i = 0; i < claims.size(); ++i)
        if (!j.items[i].right) ++(claims[i].kind == scalecert::ClaimKind::Verdict ? wrong_verdicts : wrong_distances);
    // FCL's distances against a relative 10^-5 too (its GJK stops at a tolerance of 10^-6).
    scalecert::ClaimOptions loose = opt;
    loose.tolerance = scalecert::parse_rational("1/100000");
    const scalecert::Judgements jl = a.certify(claims, loose);
    double worst = 0, below = 0;  // FCL's largest error, and the most it fell below the exact distance
    for (size_t i = 0; i < claims.size(); ++i) {
        if (claims[i].kind != scalecert::ClaimKind::Distance) continue;
        loose_wrong += !jl.items[i].right;
        const double e = claims[i].value.get_d() - j.items[i].exact;
        worst = std::max(worst, std::fabs(e));
        below = std::max(below, -e);
    }
    std::printf("| measured | time | against FCL in the same run |\n|---|---|---|\n");
    std::printf(
        "| FCL: 1,000 spheres against a 1,000-point hull, 100 poses (%ld in contact), collide + distance "
        "through its DynamicAABBTree | %.3g s | 1 (baseline) |\n",
        hits, t_fcl);
    std::printf(
        "| scalecert judging those %zu outputs (verdicts and distances at the hull's poses) | %.3g s | "
        "%.2fx FCL's time (target <= 2x); wrong: %ld verdicts, %ld distances at 1e-9 (%ld at a relative 1e-5; FCL "
        "off by up to %.2g, below the exact distance by up to %.2g) |\n",
        claims.size(), t_ours, t_ours / t_fcl, wrong_verdicts, wrong_distances, loose_wrong, worst, below);
    return 0;
}
