// The FCL and Bullet adapters (include/scalecert/fcl.hpp, bullet.hpp) against the real libraries:
// FCL 0.7 and Bullet 3.24 collide two unit cubes, the adapters turn their results into claims, and
// the judgements are checked against values derived by hand. Built against the public header and
// scalecert::core alone, as a user's program is.
#include "scalecert/bullet.hpp"
#include "scalecert/fcl.hpp"

#include <boost/test/unit_test.hpp>
#include <btBulletCollisionCommon.h>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/broadphase/default_broadphase_callbacks.h>

#include <cmath>
#include <memory>
#include <vector>

namespace {
using R = scalecert::Rational;

// A unit cube [-1/2, 1/2]^3 as an fcl::Convex (its six faces, outward).
std::shared_ptr<fcl::Convexd> fcl_cube() {
    auto v = std::make_shared<std::vector<fcl::Vector3d>>();
    for (int i = 0; i < 8; ++i) v->emplace_back(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
    auto f = std::make_shared<std::vector<int>>(
        std::vector<int>{4, 0, 2, 3, 1, 4, 4, 5, 7, 6, 4, 0, 1, 5, 4, 4, 2, 6, 7, 3, 4, 0, 4, 6, 2, 4, 1, 3, 7, 5});
    return std::make_shared<fcl::Convexd>(v, 6, f);
}
fcl::Transform3d moved(double x, double y, double z) {
    fcl::Transform3d t = fcl::Transform3d::Identity();
    t.translation() << x, y, z;
    return t;
}
scalecert::Judgements judge(const scalecert::Scene& s, const std::vector<scalecert::Claim>& c, R abs = 0, R rel = 0) {
    scalecert::ClaimOptions o;
    o.abs_tolerance = abs;
    o.tolerance = rel;
    return scalecert::Analysis(s).certify(c, o);
}
}  // namespace

// Two unit cubes, P2 at (3, 0.1, 0.2): 2 apart along x (D² = 4, by hand); at (0.75, 0.1, 0.2): they
// overlap by 1/4 along x (by 0.9 along y, 0.8 along z), so the depth is 1/4 along +x.
BOOST_AUTO_TEST_CASE(fcl_results_by_hand) {
    const auto cube = fcl_cube();
    const scalecert::Scene scene = scalecert::fcl_scene<double>(*cube, *cube);
    BOOST_TEST(scene.points(0).size() == 8u);
    const fcl::Transform3d t1 = fcl::Transform3d::Identity(), apart = moved(3, 0.1, 0.2), deep = moved(0.75, 0.1, 0.2);
    const R abs("1/1000000000");

    fcl::DistanceRequestd dq(true);  // nearest points
    fcl::DistanceResultd dr;
    fcl::CollisionObjectd a(cube, t1), b(cube, apart), c(cube, deep);
    fcl::distance(&a, &b, dq, dr);
    std::vector<scalecert::Claim> claims = scalecert::fcl_claims(dq, dr, t1, apart);
    BOOST_TEST_REQUIRE(claims.size() == 1u);
    BOOST_TEST((claims[0].kind == scalecert::ClaimKind::Distance));
    BOOST_TEST((claims[0].pose2->at(0)[3] == 3));
    BOOST_TEST((claims[0].pose2->at(1)[3] == scalecert::exact(0.1)));
    scalecert::Judgements j = judge(scene, claims, abs);
    BOOST_TEST(j.items[0].right);
    BOOST_TEST((*j.items[0].exact_squared == 4));
    BOOST_TEST(*j.items[0].closest_right);
    // The same result with the distance 1e-6 too large is wrong.
    fcl::DistanceResultd off = dr;
    off.min_distance += 1e-6;
    BOOST_TEST(!judge(scene, scalecert::fcl_claims(dq, off, t1, apart), abs).items[0].right);

    // Overlapping: collide (libccd) finds one contact, depth 1/4 along +x (from o1 to o2).
    fcl::CollisionRequestd cq(4, true);
    fcl::CollisionResultd cr;
    fcl::collide(&a, &c, cq, cr);
    claims = scalecert::fcl_claims(cq, cr, t1, deep);
    BOOST_TEST_REQUIRE(claims.size() == 2u);
    j = judge(scene, claims, abs);
    BOOST_TEST((claims[0].verdict == scalecert::ClaimedVerdict::Intersecting));
    BOOST_TEST(j.items[0].right);
    BOOST_TEST(j.items[1].right);
    BOOST_TEST((*j.items[1].exact_squared == R(1, 16)));
    BOOST_TEST(*j.items[1].direction_right);
    // Apart, collide finds nothing: not_overlapping, right.
    fcl::CollisionResultd none;
    fcl::collide(&a, &b, cq, none);
    claims = scalecert::fcl_claims(cq, none, t1, apart);
    BOOST_TEST_REQUIRE(claims.size() == 1u);
    BOOST_TEST((claims[0].verdict == scalecert::ClaimedVerdict::NotOverlapping));
    BOOST_TEST(judge(scene, claims).items[0].right);

    // distance() on the overlapping pair: −1, FCL's word for a collision, is the verdict
    // intersecting; the signed solver's value is a signed distance, −1/4 exactly.
    fcl::DistanceResultd d1;
    fcl::distance(&a, &c, dq, d1);
    claims = scalecert::fcl_claims(dq, d1, t1, deep);
    BOOST_TEST((claims[0].kind == scalecert::ClaimKind::Verdict));
    BOOST_TEST(judge(scene, claims).items[0].right);
    fcl::DistanceRequestd sq(true, true);
    fcl::DistanceResultd d2;
    fcl::distance(&a, &c, sq, d2);
    claims = scalecert::fcl_claims(sq, d2, t1, deep);
    BOOST_TEST((claims[0].kind == scalecert::ClaimKind::SignedDistance));
    j = judge(scene, claims, abs);
    BOOST_TEST(j.items[0].right);
    BOOST_TEST(j.items[0].exact == -0.25);

    // The indep solver on the overlapping cubes: its depth, read by magnitude, and its normal are
    // wrong (the depth is 1/4 along x; along its normal u the cubes' Minkowski difference reaches
    // far more than 1/4), and the judgement says which parts.
    fcl::CollisionRequestd iq(4, true);
    iq.gjk_solver_type = fcl::GST_INDEP;
    fcl::CollisionResultd ir;
    fcl::collide(&a, &c, iq, ir);
    claims = scalecert::fcl_claims(iq, ir, t1, deep);
    BOOST_TEST_REQUIRE(claims.size() == 2u);
    BOOST_TEST(sgn(claims[1].value) > 0);
    j = judge(scene, claims, abs);
    BOOST_TEST(j.items[0].right);  // it did find the collision
    if (std::fabs(ir.getContact(0).penetration_depth) != 0.25) BOOST_TEST(!*j.items[1].value_right);
    BOOST_TEST((*j.items[1].exact_squared == R(1, 16)));
}

// P2 turned 45 degrees about z (c, s the doubles of cos and sin) at (2, 0, 0): its edge reaches
// 2 − (c + s)/2 in x, so D = 3/2 − (c + s)/2 ≈ 3/2 − √2/2. FCL's Box and Convex make one scene;
// FCL's distance on each is judged right exactly when it is within 10^-6 of that.
BOOST_AUTO_TEST_CASE(fcl_at_a_turned_pose) {
    const std::shared_ptr<fcl::CollisionGeometryd> cube = fcl_cube(), box = std::make_shared<fcl::Boxd>(1, 1, 1);
    const scalecert::Scene s1 = scalecert::fcl_scene<double>(*cube, *cube),
                           s2 = scalecert::fcl_scene<double>(*box, *box);
    fcl::Transform3d t1 = fcl::Transform3d::Identity(), t2 = moved(2, 0, 0);
    t2.linear() = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const double by_hand = 1.5 - (t2.linear()(0, 0) + t2.linear()(1, 0)) / 2;
    BOOST_TEST(std::fabs(by_hand - (1.5 - std::sqrt(0.5))) < 1e-15);
    for (const auto& shape : {cube, box}) {
        fcl::CollisionObjectd a(shape, t1), b(shape, t2);
        fcl::DistanceRequestd dq;
        fcl::DistanceResultd dr;
        fcl::distance(&a, &b, dq, dr);
        const std::vector<scalecert::Claim> claims = scalecert::fcl_claims(dq, dr, t1, t2);
        for (const scalecert::Scene* s : {&s1, &s2}) {
            const scalecert::Judgements j = judge(*s, claims, R("1/1000000"));
            BOOST_TEST(std::fabs(j.items[0].exact - by_hand) < 1e-15);
            BOOST_TEST(j.items[0].right == (std::fabs(dr.min_distance - by_hand) <= 1e-6),
                       "FCL's distance " << dr.min_distance << ", by hand " << by_hand);
        }
    }
}

// A box pair's collide() gives a contact per corner, each with its own depth: the adapter claims
// the deepest as the pair's depth (the others are shallower, not the pair's). Two unit boxes, P2
// turned 0.02 rad about x at z = 0.9.
// A robot of three fcl::Sphere objects of radius 1/2 at x = 0, 1, 2 and a box of side 2 centred
// at (4, 0, 0), in a DynamicAABBTree manager: the last sphere reaches 5/2 and the box starts at 3,
// so they are 1/2 apart; moved to x = 4 − 1 − 1/4 the box is 1/4 deep in the last sphere.
BOOST_AUTO_TEST_CASE(fcl_broad_phase_on_a_sphere_set_by_hand) {
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> spheres;
    fcl::DynamicAABBTreeCollisionManagerd manager;
    std::vector<const fcl::CollisionObjectd*> robot;
    for (int k = 0; k < 3; ++k) {
        fcl::Transform3d t = fcl::Transform3d::Identity();
        t.translation() = fcl::Vector3d(k, 0, 0);
        spheres.push_back(std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Sphered>(0.5), t));
        manager.registerObject(spheres.back().get());
        robot.push_back(spheres.back().get());
    }
    manager.setup();
    fcl::Transform3d tb = fcl::Transform3d::Identity();
    tb.translation() = fcl::Vector3d(4, 0, 0);
    fcl::CollisionObjectd box(std::make_shared<fcl::Boxd>(2, 2, 2), tb);
    auto judged = [&](double x) {
        tb.translation() = fcl::Vector3d(x, 0, 0);
        box.setTransform(tb);
        box.computeAABB();
        fcl::DefaultCollisionData<double> cd;
        manager.collide(&box, &cd, fcl::DefaultCollisionFunction);
        fcl::DefaultDistanceData<double> dd;
        manager.distance(&box, &dd, fcl::DefaultDistanceFunction);
        const scalecert::Scene s = scalecert::fcl_parts_scene<double>(robot, {&box});
        BOOST_TEST(s.part_count(0) == 3u);
        BOOST_TEST(s.part_radius(0, 2) == R(1, 2));
        scalecert::Claim v;
        v.kind = scalecert::ClaimKind::Verdict;
        v.verdict = cd.result.isCollision() ? scalecert::ClaimedVerdict::Intersecting
                                            : scalecert::ClaimedVerdict::NotOverlapping;
        scalecert::Claim d;
        d.kind = scalecert::ClaimKind::Distance;
        d.value = scalecert::exact(std::max(0.0, dd.result.min_distance));
        scalecert::ClaimOptions opt;
        opt.tolerance = scalecert::parse_rational("1/1000000");
        return scalecert::Analysis(s).certify({v, d}, opt);
    };
    const scalecert::Judgements apart = judged(4);
    BOOST_TEST(apart.wrong == 0);
    BOOST_TEST(apart.items[1].exact == 0.5);
    BOOST_TEST(apart.items[1].part1 == 2);
    const scalecert::Judgements deep = judged(2.75);
    BOOST_TEST(deep.wrong == 0);
    BOOST_TEST(deep.items[1].exact == 0.0);  // they meet
    BOOST_TEST((*deep.items[0].exact_verdict == scalecert::Verdict::Overlapping));
}

BOOST_AUTO_TEST_CASE(fcl_box_manifold_claims_its_deepest_contact) {
    auto box = std::make_shared<fcl::Boxd>(1, 1, 1);
    fcl::Transform3d t1 = fcl::Transform3d::Identity(), t2 = moved(0, 0, 0.9);
    t2.linear() = Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitX()).toRotationMatrix();
    fcl::CollisionObjectd a(box, t1), b(box, t2);
    fcl::CollisionRequestd cq(8, true);
    fcl::CollisionResultd cr;
    fcl::collide(&a, &b, cq, cr);
    BOOST_TEST_REQUIRE(cr.numContacts() > 1u);
    double deepest = 0;
    for (size_t i = 0; i < cr.numContacts(); ++i) deepest = std::max(deepest, cr.getContact(i).penetration_depth);
    const std::vector<scalecert::Claim> claims = scalecert::fcl_claims(cq, cr, t1, t2);
    BOOST_TEST_REQUIRE(claims.size() == 2u);  // the verdict and one depth
    BOOST_TEST((claims[1].value == scalecert::exact(deepest)));
    // The exact depth is at most the lowest corner's depth along z, (c + s)/2 − 0.4 with c, s of
    // 0.02 rad (a translation along z separates them by that much), and more than 0.
    const scalecert::Judgements j = judge(scalecert::fcl_scene<double>(*box, *box), claims, R("1/1000000000"));
    const double along_z = (t2.linear()(1, 1) + t2.linear()(2, 1)) / 2 - 0.4;
    BOOST_TEST(j.items[1].exact > 0);
    BOOST_TEST(j.items[1].exact <= along_z + 1e-15);
    BOOST_TEST(*j.items[1].value_right == (std::fabs(deepest - j.items[1].exact) <= 1e-9));
    BOOST_TEST(j.items[1].right == (*j.items[1].value_right && *j.items[1].direction_right));
}

// What the FCL adapter refuses (a cylinder, a transform with a NaN) and what it judges wrong (a NaN
// in a result: no answer).
BOOST_AUTO_TEST_CASE(fcl_refusals_and_no_answers) {
    fcl::Cylinderd can(1, 2);
    const auto cube = fcl_cube();
    BOOST_CHECK_THROW(scalecert::fcl_points<double>(can), scalecert::InputError);
    fcl::Transform3d bad = moved(NAN, 0, 0);
    BOOST_CHECK_THROW(scalecert::fcl_pose(bad), scalecert::InputError);
    fcl::DistanceRequestd dq;
    fcl::DistanceResultd dr;
    dr.min_distance = NAN;
    const std::vector<scalecert::Claim> c = scalecert::fcl_claims(dq, dr, moved(0, 0, 0), moved(3, 0, 0));
    BOOST_TEST(c[0].no_answer == "value");
    const scalecert::Judgements j = judge(scalecert::fcl_scene<double>(*cube, *cube), c);
    BOOST_TEST(!j.items[0].right);
}

namespace {
// Bullet's unit cube, collision margin 0.
std::unique_ptr<btConvexHullShape> bullet_cube() {
    auto h = std::make_unique<btConvexHullShape>();
    for (int i = 0; i < 8; ++i) h->addPoint(btVector3(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5));
    h->setMargin(0);
    return h;
}
btTransform bt_moved(btScalar x, btScalar y, btScalar z) {
    btTransform t;
    t.setIdentity();
    t.setOrigin(btVector3(x, y, z));
    return t;
}
}  // namespace

// The same two cubes in Bullet: its collision world's manifold, and btGjkEpaSolver2.
BOOST_AUTO_TEST_CASE(bullet_results_by_hand) {
    const auto cube = bullet_cube();
    const btTransform A = bt_moved(0, 0, 0), apart = bt_moved(3, 0.1f, 0.2f), deep = bt_moved(0.75f, 0.1f, 0.2f);
    const scalecert::Scene scene = scalecert::bullet_scene(*cube, *cube);
    const R abs("1/1000000");

    // The manifold at the overlap: its deepest point claims S = −1/4 and a depth 1/4 along +x.
    btDefaultCollisionConfiguration cfg;
    btCollisionDispatcher dispatcher(&cfg);
    btDbvtBroadphase broadphase;
    btCollisionWorld world(&dispatcher, &broadphase, &cfg);
    btCollisionObject oa, ob;
    oa.setCollisionShape(cube.get());
    ob.setCollisionShape(cube.get());
    oa.setWorldTransform(A);
    ob.setWorldTransform(deep);
    world.addCollisionObject(&oa);
    world.addCollisionObject(&ob);
    world.performDiscreteCollisionDetection();
    BOOST_TEST_REQUIRE(dispatcher.getNumManifolds() == 1);
    const btPersistentManifold& m = *dispatcher.getManifoldByIndexInternal(0);
    BOOST_TEST_REQUIRE(m.getNumContacts() > 0);
    std::vector<scalecert::Claim> claims = scalecert::bullet_claims(m);
    BOOST_TEST_REQUIRE(claims.size() == 2u);
    scalecert::Judgements j = judge(scalecert::bullet_scene(m), claims, abs);
    BOOST_TEST(j.items[0].right);
    BOOST_TEST(j.items[0].exact == -0.25);
    BOOST_TEST(j.items[1].right);
    BOOST_TEST(*j.items[1].direction_right);
    BOOST_TEST((*j.items[1].exact_squared == R(1, 16)));
    world.removeCollisionObject(&oa);
    world.removeCollisionObject(&ob);

    // btGjkEpaSolver2::Distance apart: 2, witnesses on each cube.
    btGjkEpaSolver2::sResults r;
    BOOST_TEST_REQUIRE(btGjkEpaSolver2::Distance(cube.get(), A, cube.get(), apart, btVector3(1, 0, 0), r));
    claims = scalecert::bullet_distance_claims(r, A, apart);
    j = judge(scene, claims, abs);
    BOOST_TEST(j.items[0].right);
    BOOST_TEST((*j.items[0].exact_squared == 4));
    // Penetration on the overlap: whatever EPA answers is judged against the depth 1/4.
    btGjkEpaSolver2::Penetration(cube.get(), A, cube.get(), deep, btVector3(1, 0, 0), r);
    claims = scalecert::bullet_penetration_claims(r, A, deep);
    BOOST_TEST_REQUIRE((claims[0].kind == scalecert::ClaimKind::PenetrationDepth));
    j = judge(scene, claims, abs);
    BOOST_TEST((*j.items[0].exact_squared == R(1, 16)));
    BOOST_TEST(j.items[0].right == (std::fabs(-r.distance - 0.25) <= 1e-6 && std::fabs(r.normal.x() + 1) <= 1e-6));
}

// Bullet's margins: a box's lies inside its half-extents (0.5 − 0.04), a sphere's is its radius; a
// cylinder is refused.
BOOST_AUTO_TEST_CASE(bullet_margins_and_refusals) {
    btBoxShape box(btVector3(0.5, 0.5, 0.5));  // Bullet's default margin, 0.04
    const std::vector<scalecert::Point> p = scalecert::bullet_points(box);
    BOOST_TEST(p.size() == 8u);
    BOOST_TEST((p[7][0] == scalecert::exact(static_cast<double>(btScalar(0.5) - btScalar(0.04)))));
    BOOST_TEST((scalecert::bullet_radius(box) == scalecert::exact(static_cast<double>(btScalar(0.04)))));
    btSphereShape ball(1);
    BOOST_TEST((scalecert::bullet_radius(ball) == 1));
    BOOST_TEST(scalecert::bullet_points(ball).size() == 1u);
    btCylinderShape can(btVector3(1, 1, 1));
    BOOST_CHECK_THROW(scalecert::bullet_points(can), scalecert::InputError);
    // Two btBoxShapes in a manifold are sharp boxes at their full half-extents (Bullet's box-box
    // algorithm; found by the new-user review): corner to corner, 0.98 apart in x and y, they
    // overlap by 0.02, where the boxes rounded by the margin would be √2·0.06 − 0.08 apart.
    btDefaultCollisionConfiguration cfg;
    btCollisionDispatcher dispatcher(&cfg);
    btDbvtBroadphase broadphase;
    btCollisionWorld world(&dispatcher, &broadphase, &cfg);
    btCollisionObject oa, ob;
    oa.setCollisionShape(&box);
    ob.setCollisionShape(&box);
    oa.setWorldTransform(bt_moved(0, 0, 0));
    ob.setWorldTransform(bt_moved(0.98f, 0.98f, 0));
    world.addCollisionObject(&oa);
    world.addCollisionObject(&ob);
    world.performDiscreteCollisionDetection();
    BOOST_TEST_REQUIRE(dispatcher.getNumManifolds() == 1);
    const btPersistentManifold& m = *dispatcher.getManifoldByIndexInternal(0);
    BOOST_TEST_REQUIRE(m.getNumContacts() > 0);
    const scalecert::Judgements j = judge(scalecert::bullet_scene(m), scalecert::bullet_claims(m), R("1/1000000"));
    const double half = static_cast<double>(box.getHalfExtentsWithMargin().x());  // 0.46 + 0.04 in btScalars
    const double overlap = 2 * half - static_cast<double>(btScalar(0.98f));
    BOOST_TEST(std::fabs(j.items[0].exact + overlap) <= 1e-15);
    BOOST_TEST(j.items[0].right == (std::fabs(m.getContactPoint(0).getDistance() + overlap) <= 1e-6));
    world.removeCollisionObject(&oa);
    world.removeCollisionObject(&ob);
}

// Objects with a radius as FCL and Bullet collide them (CLAIMS.md, "Objects with a radius"): a
// sphere of radius 1 at 0 and one of radius 2 on the x axis; a capsule of radius 1/4 and
// half-length 1 along z against a unit cube; Bullet's hull cubes inflated by their default
// margin. Each exact value is derived here, and each judgement is that the result lies within the
// tolerance of it.
BOOST_AUTO_TEST_CASE(round_shapes_by_hand) {
    const R abs("1/1000000");
    auto within = [](double said, double exact) { return std::fabs(said - exact) <= 1e-6; };
    // FCL: at 5 apart the distance is 5 − 3 = 2; at 2.5 the depth is 1/2 along x.
    auto one = std::make_shared<fcl::Sphered>(1), two = std::make_shared<fcl::Sphered>(2);
    fcl::CollisionObjectd a(one, moved(0, 0, 0)), b(two, moved(5, 0, 0));
    fcl::DistanceRequestd dq;
    fcl::DistanceResultd dr;
    fcl::distance(&a, &b, dq, dr);
    const scalecert::Scene spheres = scalecert::fcl_scene<double>(*one, *two);
    scalecert::Judgements j = judge(spheres, scalecert::fcl_claims(dq, dr, a.getTransform(), b.getTransform()), abs);
    BOOST_TEST(j.items[0].exact == 2);
    BOOST_TEST(j.items[0].right == within(dr.min_distance, 2));
    b.setTransform(moved(2.5, 0, 0));
    fcl::CollisionRequestd cq(1, true);
    fcl::CollisionResultd cr;
    fcl::collide(&a, &b, cq, cr);
    BOOST_TEST_REQUIRE(cr.numContacts() > 0u);
    j = judge(spheres, scalecert::fcl_claims(cq, cr, a.getTransform(), b.getTransform()), abs);
    BOOST_TEST(j.items[0].right);  // intersecting
    BOOST_TEST(j.items[1].exact == 0.5);
    const auto& n = cr.getContact(0).normal;
    BOOST_TEST(j.items[1].right == (within(cr.getContact(0).penetration_depth, 0.5) && within(n[0], 1) &&
                                    within(n[1], 0) && within(n[2], 0)));
    // An FCL capsule (radius 1/4, lz 2) against the unit cube centred at (0.7, 0, 0): its face
    // x = 0.2 is 0.2 from the axis, so S = 0.2 − 0.25 = −0.05 (0.7 − 0.5 in doubles: exact to 1e-16).
    auto cap = std::make_shared<fcl::Capsuled>(0.25, 2);
    const auto cube = fcl_cube();
    fcl::CollisionObjectd c(cap, moved(0, 0, 0)), d(cube, moved(0.7, 0, 0));
    fcl::DistanceRequestd sq;
    sq.enable_signed_distance = true;
    fcl::DistanceResultd sr;
    fcl::distance(&c, &d, sq, sr);
    j = judge(scalecert::fcl_scene<double>(*cap, *cube),
              scalecert::fcl_claims(sq, sr, c.getTransform(), d.getTransform()), abs);
    BOOST_TEST(std::fabs(j.items[0].exact + 0.05) <= 1e-15);
    BOOST_TEST(j.items[0].right == within(sr.min_distance, -0.05));

    // Bullet: the two spheres 2.5 apart, a manifold of distance −1/2; two hull cubes with the default
    // margin whose faces touch, inflated they overlap by twice the margin.
    btSphereShape s1(1), s2(2);
    btDefaultCollisionConfiguration cfg;
    btCollisionDispatcher dispatcher(&cfg);
    btDbvtBroadphase broadphase;
    btCollisionWorld world(&dispatcher, &broadphase, &cfg);
    btCollisionObject oa, ob;
    oa.setCollisionShape(&s1);
    ob.setCollisionShape(&s2);
    oa.setWorldTransform(bt_moved(0, 0, 0));
    ob.setWorldTransform(bt_moved(2.5, 0, 0));
    world.addCollisionObject(&oa);
    world.addCollisionObject(&ob);
    world.performDiscreteCollisionDetection();
    BOOST_TEST_REQUIRE(dispatcher.getNumManifolds() == 1);
    const btPersistentManifold& m = *dispatcher.getManifoldByIndexInternal(0);
    BOOST_TEST_REQUIRE(m.getNumContacts() > 0);
    j = judge(scalecert::bullet_scene(m), scalecert::bullet_claims(m), abs);
    BOOST_TEST(j.items[0].exact == -0.5);
    BOOST_TEST(j.items[0].right == within(m.getContactPoint(0).getDistance(), -0.5));
    world.removeCollisionObject(&oa);
    world.removeCollisionObject(&ob);
    auto hull = bullet_cube();
    hull->setMargin(btScalar(0.04));
    const double margin2 = 2 * static_cast<double>(btScalar(0.04));
    btCollisionObject oc, od;
    oc.setCollisionShape(hull.get());
    od.setCollisionShape(hull.get());
    oc.setWorldTransform(bt_moved(0, 0, 0));
    od.setWorldTransform(bt_moved(1, 0, 0));
    world.addCollisionObject(&oc);
    world.addCollisionObject(&od);
    world.performDiscreteCollisionDetection();
    const btPersistentManifold& mh = *dispatcher.getManifoldByIndexInternal(0);
    BOOST_TEST_REQUIRE(mh.getNumContacts() > 0);
    j = judge(scalecert::bullet_scene(mh), scalecert::bullet_claims(mh), abs);
    BOOST_TEST(j.items[0].exact == -margin2);
    BOOST_TEST(j.items[0].right == within(mh.getContactPoint(0).getDistance(), -margin2));
    world.removeCollisionObject(&oc);
    world.removeCollisionObject(&od);
    // btGjkEpaSolver2: Distance ignores the margins (the hulls 2 apart at x = 3), Penetration
    // counts them (at x = 3/4 the depth is 1/4 + twice the margin).
    btGjkEpaSolver2::sResults r;
    const btTransform A = bt_moved(0, 0, 0), apart = bt_moved(3, 0, 0), deep = bt_moved(0.75f, 0, 0);
    BOOST_TEST_REQUIRE(btGjkEpaSolver2::Distance(hull.get(), A, hull.get(), apart, btVector3(1, 0, 0), r));
    j = judge(scalecert::bullet_scene(*hull, *hull, false), scalecert::bullet_distance_claims(r, A, apart), abs);
    BOOST_TEST(j.items[0].exact == 2);
    BOOST_TEST(j.items[0].right == within(r.distance, 2));
    btGjkEpaSolver2::Penetration(hull.get(), A, hull.get(), deep, btVector3(1, 0, 0), r);
    j = judge(scalecert::bullet_scene(*hull, *hull), scalecert::bullet_penetration_claims(r, A, deep), abs);
    BOOST_TEST(std::fabs(j.items[0].exact - (0.25 + margin2)) <= 1e-15);
    BOOST_TEST(j.items[0].right == (within(-r.distance, 0.25 + margin2) && within(r.normal.x(), -1) &&
                                    within(r.normal.y(), 0) && within(r.normal.z(), 0)));
}
