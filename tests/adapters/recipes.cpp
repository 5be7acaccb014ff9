// Tolerance recipes for FCL and Bullet on a robot part (docs/library.md, "FCL and Bullet as they
// run"): the Panda finger's collision mesh (certificates/scenes/compound/panda/finger.obj) against
// a 4 cm box at 1,000 random poses near contact, FCL 0.7 (libccd GJK/MPR) and Bullet 3.24
// (btGjkEpaSolver2, single precision) queried as a program would, their results turned into claims
// by scalecert/fcl.hpp and bullet.hpp, and every claim judged exactly. Prints, per engine and
// output, how many were judged and the least tolerance that makes them all right. A measurement,
// not a test: it asserts nothing.
//   adapter_recipes [FINGER.obj]
#include "scalecert/bullet.hpp"
#include "scalecert/fcl.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using R = scalecert::Rational;

// How many of the claims are right at each tolerance T (relative T and absolute T metres: the
// finger is 5 cm long), and the worst relative error of a value.
void say(const char* what, const scalecert::Analysis& a, const std::vector<scalecert::Claim>& claims) {
    std::printf("%s: %zu claims; right", what, claims.size());
    double worst = 0;
    for (const char* t : {"0", "1e-12", "1e-9", "1e-6", "1e-3"}) {
        scalecert::ClaimOptions o;
        o.tolerance = o.abs_tolerance = scalecert::parse_rational(t);
        const scalecert::Judgements j = a.certify(claims, o);
        std::printf(" %s %ld,", t, static_cast<long>(claims.size()) - j.wrong);
        if (std::string(t) == "0")
            for (const auto& k : j.items)
                if (k.exact_squared) worst = std::max(worst, k.rel_error);
    }
    std::printf(" worst relative error %.3g\n", worst);
}
}  // namespace

int main(int argc, char** argv) {
    const std::string path =
        argc > 1 ? argv[1] : std::string(SCALECERT_SOURCE_DIR) + "/certificates/scenes/compound/panda/finger.obj";
    std::ifstream in(path);
    std::vector<K::Point_3> pts;
    for (std::string line; std::getline(in, line);) {
        std::istringstream s(line);
        std::string tag;
        double x, y, z;
        if (s >> tag && tag == "v" && s >> x >> y >> z) pts.emplace_back(x, y, z);
    }
    if (pts.size() < 4) return std::fprintf(stderr, "adapter_recipes: %s: no mesh\n", path.c_str()), 2;
    // fcl::Convex needs the hull's faces (its support walks them past 32 vertices): CGAL's hull.
    CGAL::Surface_mesh<K::Point_3> hull;
    CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
    auto verts = std::make_shared<std::vector<fcl::Vector3d>>();
    auto faces = std::make_shared<std::vector<int>>();
    for (auto v : hull.vertices()) verts->emplace_back(hull.point(v).x(), hull.point(v).y(), hull.point(v).z());
    int nfaces = 0;
    for (auto f : hull.faces()) {
        faces->push_back(3);
        for (auto v : CGAL::vertices_around_face(hull.halfedge(f), hull)) faces->push_back(static_cast<int>(v));
        ++nfaces;
    }
    auto finger = std::make_shared<fcl::Convexd>(verts, nfaces, faces);
    auto cube = std::make_shared<fcl::Boxd>(0.04, 0.04, 0.04);
    const scalecert::Analysis scene(scalecert::fcl_scene<double>(*finger, *cube));
    btConvexHullShape bfinger, bcube;
    for (const auto& v : *verts)
        bfinger.addPoint(
            btVector3(static_cast<btScalar>(v[0]), static_cast<btScalar>(v[1]), static_cast<btScalar>(v[2])));
    for (int k = 0; k < 8; ++k)
        bcube.addPoint(btVector3(k & 1 ? 0.02f : -0.02f, k & 2 ? 0.02f : -0.02f, k & 4 ? 0.02f : -0.02f));
    bfinger.setMargin(0);
    bcube.setMargin(0);
    const scalecert::Analysis bscene(scalecert::bullet_scene(bfinger, bcube));

    std::mt19937_64 g(1);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<scalecert::Claim> fd, fc, fdepth, bd, bdepth, bverdict;
    for (int i = 0; i < 1000; ++i) {
        // The cube within a few centimetres of the finger's middle, turned at random.
        fcl::Transform3d t1 = fcl::Transform3d::Identity(), t2 = fcl::Transform3d::Identity();
        t2.linear() = fcl::Quaterniond(u(g), u(g), u(g), u(g)).normalized().toRotationMatrix();
        t2.translation() << 0.03 * u(g), 0.03 * u(g), 0.03 + 0.03 * u(g);
        fcl::CollisionObjectd o1(finger, t1), o2(cube, t2);
        fcl::DistanceRequestd dq(true);
        fcl::DistanceResultd dr;
        fcl::distance(&o1, &o2, dq, dr);
        for (const auto& c : scalecert::fcl_claims(dq, dr, t1, t2))
            (c.kind == scalecert::ClaimKind::Distance ? fd : fc).push_back(c);
        fcl::CollisionRequestd cq(1, true);
        fcl::CollisionResultd cr;
        fcl::collide(&o1, &o2, cq, cr);
        for (const auto& c : scalecert::fcl_claims(cq, cr, t1, t2))
            (c.kind == scalecert::ClaimKind::PenetrationDepth ? fdepth : fc).push_back(c);
        // Bullet at the same poses, as floats (its btScalar).
        btTransform a, b;
        a.setIdentity();
        b.setIdentity();
        btMatrix3x3 basis;
        for (int r = 0; r < 3; ++r)
            basis[r] = btVector3(static_cast<btScalar>(t2.linear()(r, 0)), static_cast<btScalar>(t2.linear()(r, 1)),
                                 static_cast<btScalar>(t2.linear()(r, 2)));
        b.setBasis(basis);
        b.setOrigin(btVector3(static_cast<btScalar>(t2.translation()[0]), static_cast<btScalar>(t2.translation()[1]),
                              static_cast<btScalar>(t2.translation()[2])));
        btGjkEpaSolver2::sResults r;
        btGjkEpaSolver2::Distance(&bfinger, a, &bcube, b, btVector3(1, 0, 0), r);
        for (const auto& c : scalecert::bullet_distance_claims(r, a, b))
            (c.kind == scalecert::ClaimKind::Distance ? bd : bverdict).push_back(c);
        if (r.status == btGjkEpaSolver2::sResults::Penetrating) {
            btGjkEpaSolver2::Penetration(&bfinger, a, &bcube, b, btVector3(1, 0, 0), r);
            for (const auto& c : scalecert::bullet_penetration_claims(r, a, b))
                (c.kind == scalecert::ClaimKind::PenetrationDepth ? bdepth : bverdict).push_back(c);
        }
    }
    std::printf("the Panda finger (%zu hull vertices) and a 4 cm box, 1,000 random poses (seed 1)\n", verts->size());
    std::printf("(right at tolerance T: --tolerance T and --abs-tolerance T metres)\n");
    say("FCL distance(), libccd GJK: distances with nearest points", scene, fd);
    say("FCL collide() and distance() = -1: verdicts", scene, fc);
    say("FCL collide(), libccd MPR: penetration depths with normals", scene, fdepth);
    say("Bullet btGjkEpaSolver2::Distance: distances with witnesses", bscene, bd);
    say("Bullet Distance and Penetration: verdicts", bscene, bverdict);
    say("Bullet btGjkEpaSolver2::Penetration: depths with normals", bscene, bdepth);
}
