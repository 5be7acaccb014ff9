// FCL as it runs: FCL 0.7's results as scalecert claims, at the transforms the program used
// (docs/library.md, "FCL and Bullet as they run"; the conventions: certificates/CLAIMS.md,
// "Engines' conventions"). Header-only; include it where the program has FCL, and link
// scalecert::core and FCL.
//
//   fcl::CollisionResultd res;
//   fcl::collide(&o1, &o2, req, res);
//   scalecert::Analysis a(scalecert::fcl_scene(*o1.collisionGeometry(), *o2.collisionGeometry()));
//   auto j = a.certify(scalecert::fcl_claims(req, res, o1.getTransform(), o2.getTransform()));
//
// P1 is the first object FCL was given, P2 the second, each in its own frame; every claim carries
// the two transforms as poses, their doubles read exactly. fcl::Box, fcl::Convex, fcl::Sphere and
// fcl::Capsule are judged (the last two as objects with a radius); cylinders, cones and
// ellipsoids are refused (InputError).
#pragma once
#include "scalecert/scalecert.hpp"

#include <fcl/fcl.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace scalecert {

namespace fcl_detail {
// A double the program held, exactly; a NaN or an infinity is no answer in `field`.
inline Rational number(double x, Claim& c, const char* field) {
    if (std::isfinite(x)) return exact(x);
    if (c.no_answer.empty()) c.no_answer = field;
    return 0;
}
template <class V>
Point point(const V& v, Claim& c, const char* field) {
    return {number(static_cast<double>(v[0]), c, field), number(static_cast<double>(v[1]), c, field),
            number(static_cast<double>(v[2]), c, field)};
}
template <class S>
Claim at(const ::fcl::Transform3<S>& tf1, const ::fcl::Transform3<S>& tf2);
}  // namespace fcl_detail

// A transform's doubles, exactly: v -> R·v + t. InputError for a NaN or an infinity.
template <class S>
Pose fcl_pose(const ::fcl::Transform3<S>& tf) {
    Pose p;
    for (int r = 0; r < 3; ++r)
        for (int q = 0; q < 4; ++q) {
            const double x = static_cast<double>(q < 3 ? tf.linear()(r, q) : tf.translation()(r));
            if (!std::isfinite(x)) throw InputError("fcl_pose: the transform holds a NaN or an infinity");
            p[r][q] = exact(x);
        }
    return p;
}

// The points of a geometry FCL holds, in its own frame: an fcl::Convex's vertices, an fcl::Box's
// eight corners (±side/2), an fcl::Sphere's centre, an fcl::Capsule's axis (0, 0, ±lz/2), the
// last two with their radius (fcl_radius). Other shapes are refused in one line (InputError).
template <class S>
std::vector<Point> fcl_points(const ::fcl::CollisionGeometry<S>& g) {
    std::vector<Point> out;
    auto add = [&](double x, double y, double z) {
        if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
            throw InputError("fcl_points: a vertex holds a NaN or an infinity");
        out.push_back({exact(x), exact(y), exact(z)});
    };
    switch (g.getNodeType()) {
    case ::fcl::GEOM_CONVEX:
        for (const auto& v : static_cast<const ::fcl::Convex<S>&>(g).getVertices())
            add(static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2]));
        return out;
    case ::fcl::GEOM_BOX: {
        const auto& side = static_cast<const ::fcl::Box<S>&>(g).side;
        for (int k = 0; k < 8; ++k)  // ±side/2: halving a double is exact (sides are not subnormal)
            add((k & 1 ? 0.5 : -0.5) * static_cast<double>(side[0]),
                (k & 2 ? 0.5 : -0.5) * static_cast<double>(side[1]),
                (k & 4 ? 0.5 : -0.5) * static_cast<double>(side[2]));
        return out;
    }
    case ::fcl::GEOM_SPHERE: add(0, 0, 0); return out;
    case ::fcl::GEOM_CAPSULE: {
        const double h = 0.5 * static_cast<double>(static_cast<const ::fcl::Capsule<S>&>(g).lz);  // exact
        add(0, 0, -h);
        if (h != 0) add(0, 0, h);
        return out;
    }
    case ::fcl::GEOM_CYLINDER:
    case ::fcl::GEOM_CONE:
    case ::fcl::GEOM_ELLIPSOID:
        throw InputError(
            "fcl_points: FCL's cylinders, cones and ellipsoids are not judged; fcl::Box, fcl::Convex, fcl::Sphere "
            "and fcl::Capsule are");
    default:
        throw InputError("fcl_points: FCL geometry of node type " + std::to_string(static_cast<int>(g.getNodeType())) +
                         " is not judged; fcl::Box, fcl::Convex, fcl::Sphere and fcl::Capsule are");
    }
}

// The radius around fcl_points that FCL collides: an fcl::Sphere's or fcl::Capsule's, else 0.
template <class S>
Rational fcl_radius(const ::fcl::CollisionGeometry<S>& g) {
    double r = 0;
    if (g.getNodeType() == ::fcl::GEOM_SPHERE) r = static_cast<double>(static_cast<const ::fcl::Sphere<S>&>(g).radius);
    if (g.getNodeType() == ::fcl::GEOM_CAPSULE)
        r = static_cast<double>(static_cast<const ::fcl::Capsule<S>&>(g).radius);
    if (!std::isfinite(r)) throw InputError("fcl_radius: a radius that is a NaN or an infinity");
    return exact(r);
}

// The scene of the two geometries, each in its own frame (scaling ranges [1, 1]); with a sphere or
// a capsule, a scene of objects with a radius (Scene::with_radii).
template <class S>
Scene fcl_scene(const ::fcl::CollisionGeometry<S>& g1, const ::fcl::CollisionGeometry<S>& g2) {
    const Rational r1 = fcl_radius(g1), r2 = fcl_radius(g2);
    if (sgn(r1) == 0 && sgn(r2) == 0) return Scene(fcl_points(g1), fcl_points(g2), {}, {});
    return Scene::with_radii(fcl_points(g1), fcl_points(g2), {r1, r2});
}

// FCL collision objects as one object made of parts (certificates/CLAIMS.md, "Parts with radii"),
// and others as the second: each object's geometry moved to its transform exactly (fcl_points
// taken to R·v + t in rationals) with its radius (fcl_radius), so a robot of fcl::Sphere objects is
// a sphere set. A broad-phase manager's answers are claims on it at (1, 1) without poses: collide's
// (any contact) the verdict intersecting or not_overlapping, distance's (the least) a distance.
template <class S>
Scene fcl_parts_scene(const std::vector<const ::fcl::CollisionObject<S>*>& objects1,
                      const std::vector<const ::fcl::CollisionObject<S>*>& objects2) {
    std::vector<std::vector<Point>> parts[2];
    std::array<std::vector<Rational>, 2> radii;
    bool rounded = false;
    const std::vector<const ::fcl::CollisionObject<S>*>* objects[2] = {&objects1, &objects2};
    for (int i = 0; i < 2; ++i)
        for (const ::fcl::CollisionObject<S>* o : *objects[i]) {
            if (!o || !o->collisionGeometry()) throw InputError("fcl_parts_scene: an object without a geometry");
            const Pose p = fcl_pose(o->getTransform());
            std::vector<Point> moved;
            for (const Point& v : fcl_points(*o->collisionGeometry())) {
                Point w;
                for (int r = 0; r < 3; ++r) w[r] = p[r][0] * v[0] + p[r][1] * v[1] + p[r][2] * v[2] + p[r][3];
                moved.push_back(w);
            }
            parts[i].push_back(std::move(moved));
            radii[i].push_back(fcl_radius(*o->collisionGeometry()));
            rounded = rounded || sgn(radii[i].back()) > 0;
        }
    if (!rounded) radii = {};
    return Scene::from_parts(std::move(parts[0]), std::move(parts[1]), {}, {}, {}, {}, std::move(radii));
}

// fcl::collide's result (CLAIMS.md, "Engines' conventions", FCL): the verdict intersecting when it
// found a collision, else not_overlapping; and the deepest contact's penetration_depth with its
// normal (from o1 to o2) as a penetration_depth claim (a box pair's manifold has a contact per
// corner, each with its own depth: the deepest is the pair's). FCL 0.7's indep solver writes a
// convex pair's depth negated: under GST_INDEP the depth claimed is its magnitude. Contact
// positions are not claims; a NaN depth anywhere is no answer.
template <class S>
std::vector<Claim> fcl_claims(const ::fcl::CollisionRequest<S>& request, const ::fcl::CollisionResult<S>& result,
                              const ::fcl::Transform3<S>& tf1, const ::fcl::Transform3<S>& tf2) {
    std::vector<Claim> out;
    Claim v = fcl_detail::at(tf1, tf2);
    v.kind = ClaimKind::Verdict;
    v.verdict = result.isCollision() ? ClaimedVerdict::Intersecting : ClaimedVerdict::NotOverlapping;
    out.push_back(v);
    if (result.numContacts() == 0) return out;
    auto depth_of = [&](size_t i) {
        const double d = static_cast<double>(result.getContact(i).penetration_depth);
        return request.gjk_solver_type == ::fcl::GST_INDEP ? std::fabs(d) : d;
    };
    size_t deepest = 0;
    bool nan = false;
    for (size_t i = 0; i < result.numContacts(); ++i) {
        nan = nan || std::isnan(depth_of(i));
        if (depth_of(i) > depth_of(deepest)) deepest = i;
    }
    Claim c = fcl_detail::at(tf1, tf2);
    c.kind = ClaimKind::PenetrationDepth;
    c.value = fcl_detail::number(nan ? NAN : depth_of(deepest), c, "value");
    c.direction = fcl_detail::point(result.getContact(deepest).normal, c, "direction");
    out.push_back(c);
    return out;
}

// fcl::distance's result: min_distance −1 is FCL's word for a collision (the verdict
// intersecting); with enable_signed_distance the value is a signed_distance; else a distance,
// with the nearest points (world frame) when enable_nearest_points asked for them.
template <class S>
std::vector<Claim> fcl_claims(const ::fcl::DistanceRequest<S>& request, const ::fcl::DistanceResult<S>& result,
                              const ::fcl::Transform3<S>& tf1, const ::fcl::Transform3<S>& tf2) {
    Claim c = fcl_detail::at(tf1, tf2);
    const double d = static_cast<double>(result.min_distance);
    if (request.enable_signed_distance) {
        c.kind = ClaimKind::SignedDistance;
        c.value = fcl_detail::number(d, c, "value");
    } else if (d == -1) {
        c.kind = ClaimKind::Verdict;
        c.verdict = ClaimedVerdict::Intersecting;
    } else {
        c.kind = ClaimKind::Distance;
        c.value = fcl_detail::number(d, c, "value");
        if (request.enable_nearest_points)
            c.closest = std::array<Point, 2>{fcl_detail::point(result.nearest_points[0], c, "closest"),
                                             fcl_detail::point(result.nearest_points[1], c, "closest")};
    }
    return {c};
}

template <class S>
Claim fcl_detail::at(const ::fcl::Transform3<S>& tf1, const ::fcl::Transform3<S>& tf2) {
    Claim c;
    c.pose1 = fcl_pose(tf1);
    c.pose2 = fcl_pose(tf2);
    return c;
}

}  // namespace scalecert
