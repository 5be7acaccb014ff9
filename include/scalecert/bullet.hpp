// Bullet as it runs: Bullet's contact manifolds and its GJK/EPA results as scalecert claims, at the
// transforms the program used (docs/library.md, "FCL and Bullet as they run"; the conventions:
// certificates/CLAIMS.md, "Engines' conventions"). Header-only; include it where the program has
// Bullet, and link scalecert::core and Bullet.
//
//   world.performDiscreteCollisionDetection();
//   const btPersistentManifold& m = *dispatcher.getManifoldByIndexInternal(0);
//   scalecert::Analysis a(scalecert::bullet_scene(m));
//   auto j = a.certify(scalecert::bullet_claims(m));
//
// P1 is body 0 (A), P2 body 1 (B), each its shape in its own frame; every claim carries the two
// world transforms as poses, their btScalars read exactly. btConvexHullShape (its points as
// scaled), btBoxShape, btSphereShape and btCapsuleShape are judged, each inflated by its collision
// margin as Bullet's manifolds and btGjkEpaSolver2::Penetration collide it (an object with a
// radius: a hull's 0.04 by default; a box's margin lies inside its half-extents; a sphere's and a
// capsule's margin is their radius), except two boxes in a manifold, which Bullet collides sharp
// (bullet_scene(manifold)). btGjkEpaSolver2::Distance ignores margins: judge its results on
// bullet_scene(a, b, false).
#pragma once
#include "scalecert/scalecert.hpp"

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <LinearMath/btTransform.h>

#include <cmath>
#include <string>
#include <vector>

namespace scalecert {

namespace bullet_detail {
// A btScalar the program held, exactly; a NaN or an infinity is no answer in `field`.
inline Rational number(btScalar x, Claim& c, const char* field) {
    if (std::isfinite(static_cast<double>(x))) return exact(static_cast<double>(x));
    if (c.no_answer.empty()) c.no_answer = field;
    return 0;
}
inline Point point(const btVector3& v, Claim& c, const char* field) {
    return {number(v.x(), c, field), number(v.y(), c, field), number(v.z(), c, field)};
}
inline Point negated(const btVector3& v, Claim& c, const char* field) {
    Point p = point(v, c, field);
    for (Rational& x : p) x = -x;
    return p;
}
}  // namespace bullet_detail

// A transform's btScalars, exactly: v -> basis·v + origin. InputError for a NaN or an infinity.
inline Pose bullet_pose(const btTransform& tf) {
    Pose p;
    for (int r = 0; r < 3; ++r)
        for (int q = 0; q < 4; ++q) {
            const double x = static_cast<double>(q < 3 ? tf.getBasis()[r][q] : tf.getOrigin()[r]);
            if (!std::isfinite(x)) throw InputError("bullet_pose: the transform holds a NaN or an infinity");
            p[r][q] = exact(x);
        }
    return p;
}

// The points of a shape Bullet holds, in its own frame, without its margin: a btConvexHullShape's
// points as scaled (getScaledPoint, the btScalars Bullet collides), a btBoxShape's eight corners
// within its margin (getHalfExtentsWithoutMargin), a btSphereShape's centre, a btCapsuleShape's
// axis (± getHalfHeight along its up axis). Other shapes are refused in one line (InputError).
inline std::vector<Point> bullet_points(const btCollisionShape& shape) {
    std::vector<Point> out;
    auto add = [&](const btVector3& v) {
        if (!std::isfinite(static_cast<double>(v.x())) || !std::isfinite(static_cast<double>(v.y())) ||
            !std::isfinite(static_cast<double>(v.z())))
            throw InputError("bullet_points: a point holds a NaN or an infinity");
        out.push_back(
            {exact(static_cast<double>(v.x())), exact(static_cast<double>(v.y())), exact(static_cast<double>(v.z()))});
    };
    switch (shape.getShapeType()) {
    case CONVEX_HULL_SHAPE_PROXYTYPE: {
        const auto& hull = static_cast<const btConvexHullShape&>(shape);
        for (int i = 0; i < hull.getNumPoints(); ++i) add(hull.getScaledPoint(i));
        return out;
    }
    case BOX_SHAPE_PROXYTYPE: {
        const btVector3& h = static_cast<const btBoxShape&>(shape).getHalfExtentsWithoutMargin();
        for (int k = 0; k < 8; ++k)
            add(btVector3(k & 1 ? h.x() : -h.x(), k & 2 ? h.y() : -h.y(), k & 4 ? h.z() : -h.z()));
        return out;
    }
    case SPHERE_SHAPE_PROXYTYPE: add(btVector3(0, 0, 0)); return out;
    case CAPSULE_SHAPE_PROXYTYPE: {
        const auto& c = static_cast<const btCapsuleShape&>(shape);
        btVector3 e(0, 0, 0);
        e[c.getUpAxis()] = c.getHalfHeight();
        add(-e);
        if (c.getHalfHeight() != 0) add(e);
        return out;
    }
    default:
        throw InputError(std::string("bullet_points: Bullet shape ") + shape.getName() +
                         " is not judged; btConvexHullShape, btBoxShape, btSphereShape and btCapsuleShape are");
    }
}

// The radius Bullet collides around bullet_points: the collision margin (a sphere's and a
// capsule's is its radius). InputError for a NaN, an infinity or a negative margin.
inline Rational bullet_radius(const btCollisionShape& shape) {
    const double m = static_cast<double>(shape.getMargin());
    if (!std::isfinite(m) || m < 0)
        throw InputError("bullet_radius: collision margin " + std::to_string(m) + " (expected a finite margin >= 0)");
    return exact(m);
}

// The scene of two shapes, each in its own frame (scaling ranges [1, 1]): with `margins`, each
// inflated by its margin (bullet_radius), as Bullet's manifolds and Penetration collide them;
// without, the shapes btGjkEpaSolver2::Distance measures. Of a manifold's bodies, with margins.
inline Scene bullet_scene(const btCollisionShape& a, const btCollisionShape& b, bool margins = true) {
    const Rational r1 = margins ? bullet_radius(a) : Rational(0), r2 = margins ? bullet_radius(b) : Rational(0);
    if (sgn(r1) == 0 && sgn(r2) == 0) return Scene(bullet_points(a), bullet_points(b), {}, {});
    return Scene::with_radii(bullet_points(a), bullet_points(b), {r1, r2});
}
// A manifold's: Bullet's dispatcher collides two btBoxShapes by btBoxBoxCollisionAlgorithm, as
// sharp boxes of their full half-extents (margin included, not rounded); every other pair as
// bullet_scene(a, b) has it.
inline Scene bullet_scene(const btPersistentManifold& m) {
    const btCollisionShape &a = *m.getBody0()->getCollisionShape(), &b = *m.getBody1()->getCollisionShape();
    if (a.getShapeType() != BOX_SHAPE_PROXYTYPE || b.getShapeType() != BOX_SHAPE_PROXYTYPE) return bullet_scene(a, b);
    auto corners = [](const btBoxShape& s) {
        const btVector3 h = s.getHalfExtentsWithMargin();
        std::vector<Point> out;
        for (int k = 0; k < 8; ++k) {
            const btVector3 v(k & 1 ? h.x() : -h.x(), k & 2 ? h.y() : -h.y(), k & 4 ? h.z() : -h.z());
            for (int i = 0; i < 3; ++i)
                if (!std::isfinite(static_cast<double>(v[i])))
                    throw InputError("bullet_scene: a box's half-extent is a NaN or an infinity");
            out.push_back({exact(static_cast<double>(v.x())), exact(static_cast<double>(v.y())),
                           exact(static_cast<double>(v.z()))});
        }
        return out;
    };
    return Scene(corners(static_cast<const btBoxShape&>(a)), corners(static_cast<const btBoxShape&>(b)), {}, {});
}

// A contact manifold (CLAIMS.md, "Engines' conventions", Bullet), at its bodies' world transforms:
// without points, the verdict not_overlapping; with points, the deepest point's distance as the
// signed_distance value, and where it is < 0 a penetration_depth of −distance in the direction
// −normalWorldOnB (the normal on B points toward A: moving B along its negation separates them).
// The other points' distances and the positions are not claims.
inline std::vector<Claim> bullet_claims(const btPersistentManifold& m) {
    Claim at;
    at.pose1 = bullet_pose(m.getBody0()->getWorldTransform());
    at.pose2 = bullet_pose(m.getBody1()->getWorldTransform());
    if (m.getNumContacts() == 0) {
        Claim v = at;
        v.kind = ClaimKind::Verdict;
        v.verdict = ClaimedVerdict::NotOverlapping;
        return {v};
    }
    int deepest = 0;
    bool nan = false;
    for (int i = 0; i < m.getNumContacts(); ++i) {
        nan = nan || std::isnan(static_cast<double>(m.getContactPoint(i).getDistance()));
        if (m.getContactPoint(i).getDistance() < m.getContactPoint(deepest).getDistance()) deepest = i;
    }
    const btManifoldPoint& p = m.getContactPoint(deepest);
    std::vector<Claim> out;
    Claim s = at;
    s.kind = ClaimKind::SignedDistance;
    s.value = bullet_detail::number(nan ? btScalar(NAN) : p.getDistance(), s, "value");
    out.push_back(s);
    if (p.getDistance() < 0) {
        Claim d = at;
        d.kind = ClaimKind::PenetrationDepth;
        d.value = bullet_detail::number(-p.getDistance(), d, "value");
        d.direction = bullet_detail::negated(p.m_normalWorldOnB, d, "direction");
        out.push_back(d);
    }
    return out;
}

// btGjkEpaSolver2::Distance's result for shapes at transforms a, b (on the shapes without their
// margins: bullet_scene(a, b, false)): separated, a distance with its witnesses as the closest
// points; penetrating, the verdict intersecting; a failure, no answer (the verdict claim is
// judged wrong).
inline std::vector<Claim> bullet_distance_claims(const btGjkEpaSolver2::sResults& r, const btTransform& a,
                                                 const btTransform& b) {
    Claim c;
    c.pose1 = bullet_pose(a);
    c.pose2 = bullet_pose(b);
    if (r.status == btGjkEpaSolver2::sResults::Separated) {
        c.kind = ClaimKind::Distance;
        c.value = bullet_detail::number(r.distance, c, "value");
        c.closest = std::array<Point, 2>{bullet_detail::point(r.witnesses[0], c, "closest"),
                                         bullet_detail::point(r.witnesses[1], c, "closest")};
    } else {
        c.kind = ClaimKind::Verdict;
        c.verdict = ClaimedVerdict::Intersecting;
        if (r.status != btGjkEpaSolver2::sResults::Penetrating) c.no_answer = "status";
    }
    return {c};
}

// btGjkEpaSolver2::Penetration's result (with margins, its default): penetrating, a
// penetration_depth of −distance in the
// direction −normal (Bullet's normal points from B toward A); separated, the verdict
// not_overlapping; a failure, no answer.
inline std::vector<Claim> bullet_penetration_claims(const btGjkEpaSolver2::sResults& r, const btTransform& a,
                                                    const btTransform& b) {
    Claim c;
    c.pose1 = bullet_pose(a);
    c.pose2 = bullet_pose(b);
    if (r.status == btGjkEpaSolver2::sResults::Penetrating) {
        c.kind = ClaimKind::PenetrationDepth;
        c.value = bullet_detail::number(-r.distance, c, "value");
        c.direction = bullet_detail::negated(r.normal, c, "direction");
    } else {
        c.kind = ClaimKind::Verdict;
        c.verdict = ClaimedVerdict::NotOverlapping;
        if (r.status != btGjkEpaSolver2::sResults::Separated) c.no_answer = "status";
    }
    return {c};
}

}  // namespace scalecert
