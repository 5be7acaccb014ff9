// FCL (GJK through libccd, and FCL's own GJK) and Bullet (GJK/EPA) as baselines, as their users
// call them, on the scaled polyhedra. Kept in one translation unit: their headers are heavy.
// Built as a module (libscalecert_fcl_bullet.so) that the tools load on first use
// (fcl_bullet_loader.cpp): FCL alone brings 29,000 relocations, which every start of the
// scalecert command would otherwise pay. The module uses no scalecert symbol, only its headers.
#include "baselines/baselines.hpp"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/broadphase/default_broadphase_callbacks.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

namespace scalecert::internal::fp {

namespace {

class Fcl : public Method {
  public:
    Fcl(const Model& m, const FpScene& s, fcl::GJKSolverType type) : s_(s), type_(type) {
        for (int i = 0; i < 2; ++i) {
            auto faces = std::make_shared<std::vector<int>>();
            for (const Face& f : m.P[i].faces) {
                faces->push_back(static_cast<int>(f.verts.size()));
                for (int v : f.verts) faces->push_back(v);
            }
            faces_[i] = faces;
            nfaces_[i] = static_cast<int>(m.P[i].faces.size());
        }
    }
    std::string name() const override { return type_ == fcl::GST_LIBCCD ? "fcl-gjk-libccd" : "fcl-gjk-indep"; }
    std::shared_ptr<fcl::CollisionGeometryd> shape(int i, double rho) const {
        auto v = std::make_shared<std::vector<fcl::Vector3d>>();
        const D3& c = s_.P[i].seed;
        for (const D3& p : s_.P[i].pts)
            v->emplace_back(c[0] + rho * (p[0] - c[0]), c[1] + rho * (p[1] - c[1]), c[2] + rho * (p[2] - c[2]));
        return std::make_shared<fcl::Convexd>(v, nfaces_[i], faces_[i]);
    }
    int classify(double r1, double r2) const override {
        fcl::CollisionObjectd a(shape(0, r1), fcl::Transform3d::Identity()),
            b(shape(1, r2), fcl::Transform3d::Identity());
        fcl::CollisionRequestd req;
        req.gjk_solver_type = type_;
        req.gjk_tolerance = s_.settings.fcl_gjk_tolerance;
        fcl::CollisionResultd res;
        fcl::collide(&a, &b, req, res);
        return res.isCollision() ? -1 : 1;
    }
    // distance() with nearest points when separated; collide() with a contact (its depth and
    // normal, from P1 towards P2) when not. The depth is taken as returned: FCL 0.7's own GJK
    // (GST_INDEP) returns it negated (−1.5 where libccd's gives 1.5), which the audit reports.
    std::optional<Measure> measure(double r1, double r2, bool separated) const override {
        fcl::CollisionObjectd a(shape(0, r1), fcl::Transform3d::Identity()),
            b(shape(1, r2), fcl::Transform3d::Identity());
        Measure m;
        if (separated) {
            fcl::DistanceRequestd req(true);
            req.gjk_solver_type = type_;
            req.distance_tolerance = s_.settings.fcl_distance_tolerance;
            fcl::DistanceResultd res;
            fcl::distance(&a, &b, req, res);
            if (!(res.min_distance >= 0)) return std::nullopt;
            m.value = res.min_distance;
            const auto& p = res.nearest_points;
            m.closest = std::array<D3, 2>{D3{p[0][0], p[0][1], p[0][2]}, D3{p[1][0], p[1][1], p[1][2]}};
            return m;
        }
        fcl::CollisionRequestd req(1, true);
        req.gjk_solver_type = type_;
        req.gjk_tolerance = s_.settings.fcl_gjk_tolerance;
        fcl::CollisionResultd res;
        fcl::collide(&a, &b, req, res);
        if (res.numContacts() == 0) return std::nullopt;
        const fcl::Contactd& c = res.getContact(0);
        m.depth = true;
        m.value = c.penetration_depth;
        m.direction = D3{c.normal[0], c.normal[1], c.normal[2]};
        return m;
    }

  private:
    FpScene s_;
    fcl::GJKSolverType type_;
    std::shared_ptr<const std::vector<int>> faces_[2];
    int nfaces_[2];
};

class Bullet : public Method {
  public:
    explicit Bullet(const FpScene& s) : s_(s) {
        for (int i = 0; i < 2; ++i) {
            const D3& c = s.P[i].seed;
            for (const D3& p : s.P[i].pts) shape_[i].addPoint(btVector3(p[0] - c[0], p[1] - c[1], p[2] - c[2]), false);
            shape_[i].recalcLocalAabb();
            shape_[i].setMargin(s.settings.bullet_margin);  // 0 by default: the shapes exactly as given
            xf_[i].setIdentity();
            xf_[i].setOrigin(btVector3(c[0], c[1], c[2]));
        }
    }
    std::string name() const override { return "bullet-gjk-epa"; }
    int classify(double r1, double r2) const override {
        shape_[0].setLocalScaling(btVector3(r1, r1, r1));
        shape_[1].setLocalScaling(btVector3(r2, r2, r2));
        btGjkEpaSolver2::sResults res;
        bool separated = btGjkEpaSolver2::Distance(&shape_[0], xf_[0], &shape_[1], xf_[1], btVector3(1, 0, 0), res);
        return separated && res.distance > 0 ? 1 : -1;
    }
    // Distance() with its witness points when separated; Penetration() (EPA) when not. Its normal
    // points from P2 towards P1 (stacked cubes: (0,0,−1) for P2 above P1), so it is negated here.
    std::optional<Measure> measure(double r1, double r2, bool separated) const override {
        shape_[0].setLocalScaling(btVector3(r1, r1, r1));
        shape_[1].setLocalScaling(btVector3(r2, r2, r2));
        btGjkEpaSolver2::sResults res;
        Measure m;
        auto d3 = [](const btVector3& v) { return D3{v.x(), v.y(), v.z()}; };
        if (separated) {
            if (!btGjkEpaSolver2::Distance(&shape_[0], xf_[0], &shape_[1], xf_[1], btVector3(1, 0, 0), res))
                return std::nullopt;
            m.value = res.distance;
            m.closest = std::array<D3, 2>{d3(res.witnesses[0]), d3(res.witnesses[1])};
            return m;
        }
        if (!btGjkEpaSolver2::Penetration(&shape_[0], xf_[0], &shape_[1], xf_[1], btVector3(1, 0, 0), res))
            return std::nullopt;
        m.depth = true;
        m.value = -res.distance;
        m.direction = d3(-res.normal);
        return m;
    }

  private:
    FpScene s_;
    mutable btConvexHullShape shape_[2];
    btTransform xf_[2];
};

// ---- Objects made of convex parts -------------------------------------------------------------

// Bullet's compound shape, as its users build and query one. Each object is a btCompoundShape
// whose children are btConvexHullShapes of its parts (collision margin 0), with the points given
// relative to the object's seed and identity child transforms; the object's collision object sits
// at the seed. Scaling: each child's local scaling is set to (ρ, ρ, ρ), which scales it about the
// seed exactly as the paper does, and its node in the compound's AABB tree refreshed. (The
// compound's own setLocalScaling multiplies each child's scaling by new/old, whose rounding would
// make a verdict depend on the query before it.) The query: btCollisionWorld::contactPairTest,
// which runs the dispatcher's compound-compound algorithm (children pruned by their AABB trees,
// each child pair by GJK/EPA); a contact at distance < 0 is overlapping, = 0 touching, none or
// > 0 separated.
class BulletCompound : public Method {
  public:
    explicit BulletCompound(const CompoundFp& s) : dispatcher_(&config_), world_(&dispatcher_, &broadphase_, &config_) {
        for (int i = 0; i < 2; ++i) {
            const D3& c = s.seed[i];
            compound_[i] = std::make_unique<btCompoundShape>(true, static_cast<int>(s.parts[i].size()));
            for (const CompoundFp::Part& part : s.parts[i]) {
                auto h = std::make_unique<btConvexHullShape>();
                for (const D3& p : part.pts) h->addPoint(btVector3(p[0] - c[0], p[1] - c[1], p[2] - c[2]), false);
                h->recalcLocalAabb();
                h->setMargin(s.settings.bullet_margin);
                btTransform t;
                t.setIdentity();
                compound_[i]->addChildShape(t, h.get());
                hulls_[i].push_back(std::move(h));
            }
            compound_[i]->setMargin(s.settings.bullet_margin);
            btTransform xf;
            xf.setIdentity();
            xf.setOrigin(btVector3(c[0], c[1], c[2]));
            object_[i].setCollisionShape(compound_[i].get());
            object_[i].setWorldTransform(xf);
        }
    }
    std::string name() const override { return "bullet-compound"; }
    int classify(double r1, double r2) const override {
        scale(r1, r2);
        Contacts cb;
        world_.contactPairTest(&object_[0], &object_[1], cb);
        if (cb.count == 0 || cb.least > 0) return 1;
        return cb.least == 0 ? 0 : -1;
    }
    // The distance: btGjkEpaSolver2::Distance over every child pair, the least, with its witnesses.
    std::optional<Measure> measure(double r1, double r2, bool separated) const override {
        if (!separated) return std::nullopt;
        scale(r1, r2);
        std::optional<Measure> best;
        for (int a = 0; a < compound_[0]->getNumChildShapes(); ++a)
            for (int b = 0; b < compound_[1]->getNumChildShapes(); ++b) {
                btGjkEpaSolver2::sResults res;
                const auto* A = static_cast<const btConvexShape*>(compound_[0]->getChildShape(a));
                const auto* B = static_cast<const btConvexShape*>(compound_[1]->getChildShape(b));
                if (!btGjkEpaSolver2::Distance(A, object_[0].getWorldTransform() * compound_[0]->getChildTransform(a),
                                               B, object_[1].getWorldTransform() * compound_[1]->getChildTransform(b),
                                               btVector3(1, 0, 0), res))
                    return std::nullopt;  // a pair GJK finds meeting: no distance
                if (!best || res.distance < best->value) {
                    Measure m;
                    m.value = res.distance;
                    auto d3 = [](const btVector3& v) { return D3{v.x(), v.y(), v.z()}; };
                    m.closest = std::array<D3, 2>{d3(res.witnesses[0]), d3(res.witnesses[1])};
                    best = m;
                }
            }
        return best;
    }

    // btCollisionWorld::contactPairTest's manifold points: each names its child shapes (the
    // parts), its distance (< 0: a depth) and its normal on the second object, pointing at the
    // first; the deepest point of each part pair is its contact (deepest_per_pair).
    std::vector<PartContact> contacts(double r1, double r2) const override {
        scale(r1, r2);
        Deepest cb(&object_[0]);
        world_.contactPairTest(&object_[0], &object_[1], cb);
        return deepest_per_pair(cb.all);
    }

  private:
    struct Deepest : btCollisionWorld::ContactResultCallback {
        explicit Deepest(const btCollisionObject* first) : first(first) {}
        const btCollisionObject* first;
        std::vector<PartContact> all;
        btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper* w0, int, int index0,
                                 const btCollisionObjectWrapper*, int, int index1) override {
            if (!(cp.getDistance() < 0)) return 0;
            const bool swap = w0->getCollisionObject() != first;        // the points name P2's part first
            const btVector3 n = cp.m_normalWorldOnB * (swap ? -1 : 1);  // from P2 towards P1
            PartContact c;
            c.part1 = swap ? index1 : index0;
            c.part2 = swap ? index0 : index1;
            c.depth = -cp.getDistance();
            c.direction = {-n.x(), -n.y(), -n.z()};
            all.push_back(c);
            return 0;
        }
    };
    struct Contacts : btCollisionWorld::ContactResultCallback {
        long count = 0;
        btScalar least = 0;
        btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper*, int, int,
                                 const btCollisionObjectWrapper*, int, int) override {
            if (count++ == 0 || cp.getDistance() < least) least = cp.getDistance();
            return 0;
        }
    };
    void scale(double r1, double r2) const {
        const double r[2] = {r1, r2};
        for (int i = 0; i < 2; ++i) {
            const btScalar s = static_cast<btScalar>(r[i]);
            const btVector3 v(s, s, s);
            for (int k = 0; k < compound_[i]->getNumChildShapes(); ++k) {
                compound_[i]->getChildShape(k)->setLocalScaling(v);
                compound_[i]->updateChildTransform(k, compound_[i]->getChildTransform(k), false);
            }
            compound_[i]->recalculateLocalAabb();
        }
    }
    btDefaultCollisionConfiguration config_;
    btCollisionDispatcher dispatcher_;
    btDbvtBroadphase broadphase_;
    mutable btCollisionWorld world_;
    std::vector<std::unique_ptr<btConvexHullShape>> hulls_[2];
    std::unique_ptr<btCompoundShape> compound_[2];
    mutable btCollisionObject object_[2];
};

// FCL has no compound of convex shapes: its users put one CollisionObject per part into a
// broad-phase manager per object and collide the managers. Here two DynamicAABBTreeCollisionManagers
// of fcl::Convex parts, scaled about the seed (FCL's Convex has no scaling: the parts are rebuilt
// at each (ρ1, ρ2), as the convex FCL baseline rebuilds its shapes); manager1->collide(manager2)
// with FCL's default callback (stops at the first colliding pair) and manager1->distance(manager2)
// with its default distance callback (the least over the pairs the trees do not prune).
class FclCompound : public Method {
  public:
    FclCompound(const CompoundFp& s, fcl::GJKSolverType type) : s_(s), type_(type) {
        for (int i = 0; i < 2; ++i)
            for (const CompoundFp::Part& part : s.parts[i]) {
                auto faces = std::make_shared<std::vector<int>>();
                for (const std::vector<int>& f : part.faces) {
                    faces->push_back(static_cast<int>(f.size()));
                    faces->insert(faces->end(), f.begin(), f.end());
                }
                faces_[i].push_back(faces);
            }
    }
    std::string name() const override {
        return type_ == fcl::GST_LIBCCD ? "fcl-compound-libccd" : "fcl-compound-indep";
    }
    int classify(double r1, double r2) const override {
        Scene sc(*this, r1, r2);
        fcl::DefaultCollisionData<double> data;
        data.request.gjk_solver_type = type_;
        data.request.gjk_tolerance = s_.settings.fcl_gjk_tolerance;
        sc.manager[0].collide(&sc.manager[1], &data, fcl::DefaultCollisionFunction<double>);
        return data.result.isCollision() ? -1 : 1;
    }
    // collide() with contacts (one per colliding part pair, FCL's GJK/EPA), every pair: its
    // normal points from the first object's part to the second's.
    std::vector<PartContact> contacts(double r1, double r2) const override {
        Scene sc(*this, r1, r2);
        fcl::DefaultCollisionData<double> data;
        data.request.gjk_solver_type = type_;
        data.request.gjk_tolerance = s_.settings.fcl_gjk_tolerance;
        data.request.enable_contact = true;
        data.request.num_max_contacts = 1000000;
        sc.manager[0].collide(&sc.manager[1], &data, fcl::DefaultCollisionFunction<double>);
        std::vector<PartContact> all;
        for (size_t k = 0; k < data.result.numContacts(); ++k) {
            const fcl::Contactd& c = data.result.getContact(k);
            const int i1 = sc.part_of(c.o1), i2 = sc.part_of(c.o2);
            if (i1 < 0 || i2 < 0) continue;
            const bool swap = sc.object_of(c.o1) == 1;
            PartContact p;
            p.part1 = swap ? i2 : i1;
            p.part2 = swap ? i1 : i2;
            p.depth = c.penetration_depth;
            const fcl::Vector3d n = c.normal * (swap ? -1.0 : 1.0);
            p.direction = {n[0], n[1], n[2]};
            all.push_back(p);
        }
        return deepest_per_pair(all);
    }
    std::optional<Measure> measure(double r1, double r2, bool separated) const override {
        if (!separated) return std::nullopt;
        Scene sc(*this, r1, r2);
        Nearest data;
        data.request.enable_nearest_points = true;
        data.request.gjk_solver_type = type_;
        data.request.distance_tolerance = s_.settings.fcl_distance_tolerance;
        sc.manager[0].distance(&sc.manager[1], &data, nearest);
        if (!data.any || !(data.least >= 0) || !std::isfinite(data.least)) return std::nullopt;
        Measure m;
        m.value = data.least;
        m.closest = data.points;
        return m;
    }

  private:
    // The parts at (ρ1, ρ2) as collision objects in one manager per object.
    struct Scene {
        std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects[2];
        fcl::DynamicAABBTreeCollisionManagerd manager[2];
        Scene(const FclCompound& f, double r1, double r2) {
            const double r[2] = {r1, r2};
            for (int i = 0; i < 2; ++i) {
                std::vector<fcl::CollisionObjectd*> list;
                for (size_t k = 0; k < f.s_.parts[i].size(); ++k) {
                    objects[i].push_back(
                        std::make_unique<fcl::CollisionObjectd>(f.shape(i, k, r[i]), fcl::Transform3d::Identity()));
                    objects[i].back()->setUserData(&kObject[i]);
                    list.push_back(objects[i].back().get());
                }
                manager[i].registerObjects(list);
                manager[i].setup();
            }
        }
        // The object (0, 1) and part of a part's geometry, or −1.
        int object_of(const fcl::CollisionGeometryd* g) const { return locate(g).first; }
        int part_of(const fcl::CollisionGeometryd* g) const { return locate(g).second; }
        std::pair<int, int> locate(const fcl::CollisionGeometryd* g) const {
            for (int i = 0; i < 2; ++i)
                for (size_t k = 0; k < objects[i].size(); ++k)
                    if (objects[i][k]->collisionGeometry().get() == g) return {i, static_cast<int>(k)};
            return {-1, -1};
        }
    };
    std::shared_ptr<fcl::CollisionGeometryd> shape(int i, size_t k, double rho) const {
        auto v = std::make_shared<std::vector<fcl::Vector3d>>();
        const D3& c = s_.seed[i];
        for (const D3& p : s_.parts[i][k].pts)
            v->emplace_back(c[0] + rho * (p[0] - c[0]), c[1] + rho * (p[1] - c[1]), c[2] + rho * (p[2] - c[2]));
        return std::make_shared<fcl::Convexd>(v, static_cast<int>(s_.parts[i][k].faces.size()), faces_[i][k]);
    }
    // FCL's default distance callback (fcl::distance on each pair the trees bring, the least kept,
    // stopping at a distance <= 0), which also notes which nearest point lies on P1: the managers
    // may hand a pair over in either order.
    static inline int kObject[2] = {0, 1};
    struct Nearest {
        fcl::DistanceRequestd request;
        bool any = false;
        double least = 0;
        std::array<D3, 2> points;
    };
    static bool nearest(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data, double& dist) {
        auto* d = static_cast<Nearest*>(data);
        fcl::DistanceResultd res;
        fcl::distance(o1, o2, d->request, res);
        if (!d->any || res.min_distance < d->least) {
            const bool swap = o1->getUserData() == &kObject[1];
            const auto& p = res.nearest_points[swap ? 1 : 0];
            const auto& q = res.nearest_points[swap ? 0 : 1];
            d->any = true;
            d->least = res.min_distance;
            d->points = {D3{p[0], p[1], p[2]}, D3{q[0], q[1], q[2]}};
        }
        dist = d->least;
        return dist <= 0;
    }
    CompoundFp s_;
    fcl::GJKSolverType type_;
    std::vector<std::shared_ptr<const std::vector<int>>> faces_[2];
};

// ---- Objects with a radius ----------------------------------------------------------------------

// A sphere's centre or a capsule's ends at ρ: s + ρ(p − s).
D3 scaled_point(const RoundedFp::Object& o, int k, double rho) {
    const D3& p = o.pts[static_cast<size_t>(k)];
    const D3& c = o.seed;
    return {c[0] + rho * (p[0] - c[0]), c[1] + rho * (p[1] - c[1]), c[2] + rho * (p[2] - c[2])};
}
// A capsule's pose at ρ: its ends' midpoint, and the rotation taking z to its axis (FCL's capsule
// and Bullet's btCapsuleShapeZ lie along z); its length |b − a|.
struct CapsulePose {
    Eigen::Vector3d centre;
    Eigen::Quaterniond turn;
    double length;
};
CapsulePose capsule_pose(const RoundedFp::Object& o, double rho) {
    const D3 a = scaled_point(o, o.ends[0], rho), b = scaled_point(o, o.ends[1], rho);
    const Eigen::Vector3d A(a[0], a[1], a[2]), B(b[0], b[1], b[2]);
    return {(A + B) / 2, Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), B - A), (B - A).norm()};
}

// FCL on objects with a radius: fcl::Sphere (radius ρr, at the scaled point), fcl::Capsule (radius
// ρr, between the scaled ends) and fcl::Convex for a hull without a radius (scaled as the convex
// baseline scales it); collide() as on convex scenes. rounded_fcl_why_not says where it cannot.
class RoundedFcl : public Method {
  public:
    RoundedFcl(const RoundedFp& s, fcl::GJKSolverType type) : s_(s), type_(type) {
        for (int i = 0; i < 2; ++i) {
            auto faces = std::make_shared<std::vector<int>>();
            for (const std::vector<int>& f : s.P[i].faces) {
                faces->push_back(static_cast<int>(f.size()));
                faces->insert(faces->end(), f.begin(), f.end());
            }
            faces_[i] = faces;
        }
    }
    std::string name() const override { return type_ == fcl::GST_LIBCCD ? "fcl-gjk-libccd" : "fcl-gjk-indep"; }
    int classify(double r1, double r2) const override {
        const std::unique_ptr<fcl::CollisionObjectd> a = object(0, r1), b = object(1, r2);
        fcl::CollisionRequestd req;
        req.gjk_solver_type = type_;
        req.gjk_tolerance = s_.settings.fcl_gjk_tolerance;
        fcl::CollisionResultd res;
        fcl::collide(a.get(), b.get(), req, res);
        return res.isCollision() ? -1 : 1;
    }

  private:
    std::unique_ptr<fcl::CollisionObjectd> object(int i, double rho) const {
        const RoundedFp::Object& o = s_.P[i];
        fcl::Transform3d t = fcl::Transform3d::Identity();
        if (o.shape == RoundedFp::Shape::Sphere) {
            const D3 c = scaled_point(o, o.ends[0], rho);
            t.translation() = fcl::Vector3d(c[0], c[1], c[2]);
            return std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Sphered>(rho * o.radius), t);
        }
        if (o.shape == RoundedFp::Shape::Capsule) {
            const CapsulePose p = capsule_pose(o, rho);
            t.linear() = p.turn.toRotationMatrix();
            t.translation() = p.centre;
            return std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Capsuled>(rho * o.radius, p.length),
                                                           t);
        }
        auto v = std::make_shared<std::vector<fcl::Vector3d>>();
        const D3& c = o.seed;
        for (const D3& p : o.pts)
            v->emplace_back(c[0] + rho * (p[0] - c[0]), c[1] + rho * (p[1] - c[1]), c[2] + rho * (p[2] - c[2]));
        return std::make_unique<fcl::CollisionObjectd>(
            std::make_shared<fcl::Convexd>(v, static_cast<int>(o.faces.size()), faces_[i]), t);
    }
    RoundedFp s_;
    fcl::GJKSolverType type_;
    std::shared_ptr<const std::vector<int>> faces_[2];
};

// Bullet on objects with a radius: btSphereShape (radius ρr, at the scaled point), btCapsuleShapeZ
// (radius ρr, between the scaled ends) and btConvexHullShape (points about the seed, local scaling
// ρ) whose collision margin is ρr (--bullet-margin for a hull without a radius). Bullet inflates a
// shape by its margin (a sphere's and a capsule's margin is their radius):
// btGjkEpaSolver2::Distance measures the shapes without their margins, and, as Bullet's
// btGjkPairDetector does, the two margins are taken off that distance. Separated when what is
// left is > 0; GJK finding the shapes without margins meeting is a collision.
class RoundedBullet : public Method {
  public:
    explicit RoundedBullet(const RoundedFp& s) : s_(s) {
        for (int i = 0; i < 2; ++i) {
            const D3& c = s.P[i].seed;
            for (const D3& p : s.P[i].pts) hull_[i].addPoint(btVector3(p[0] - c[0], p[1] - c[1], p[2] - c[2]), false);
            hull_[i].recalcLocalAabb();
        }
    }
    std::string name() const override { return "bullet-gjk-epa"; }
    int classify(double r1, double r2) const override {
        Posed a = posed(0, r1), b = posed(1, r2);
        btGjkEpaSolver2::sResults res;
        const bool apart = btGjkEpaSolver2::Distance(a.shape, a.xf, b.shape, b.xf, btVector3(1, 0, 0), res);
        return apart && res.distance - (a.shape->getMargin() + b.shape->getMargin()) > 0 ? 1 : -1;
    }

  private:
    struct Posed {
        const btConvexShape* shape;
        btTransform xf;
        std::unique_ptr<btConvexShape> own;
    };
    Posed posed(int i, double rho) const {
        const RoundedFp::Object& o = s_.P[i];
        Posed p;
        p.xf.setIdentity();
        if (o.shape == RoundedFp::Shape::Sphere) {
            const D3 c = scaled_point(o, o.ends[0], rho);
            p.own = std::make_unique<btSphereShape>(rho * o.radius);
            p.xf.setOrigin(btVector3(c[0], c[1], c[2]));
        } else if (o.shape == RoundedFp::Shape::Capsule) {
            const CapsulePose c = capsule_pose(o, rho);
            p.own = std::make_unique<btCapsuleShapeZ>(rho * o.radius, c.length);
            p.xf.setOrigin(btVector3(c.centre[0], c.centre[1], c.centre[2]));
            p.xf.setRotation(btQuaternion(c.turn.x(), c.turn.y(), c.turn.z(), c.turn.w()));
        } else {
            hull_[i].setLocalScaling(btVector3(rho, rho, rho));
            hull_[i].setMargin(o.rounded ? rho * o.radius : s_.settings.bullet_margin);
            p.xf.setOrigin(btVector3(o.seed[0], o.seed[1], o.seed[2]));
            p.shape = &hull_[i];
            return p;
        }
        p.shape = p.own.get();
        return p;
    }
    RoundedFp s_;
    mutable btConvexHullShape hull_[2];
};

}  // namespace

std::unique_ptr<Method> make_compound_module(const CompoundFp& s, int kind) {
    if (kind == 0) return std::make_unique<BulletCompound>(s);
    return std::make_unique<FclCompound>(s, kind == 1 ? fcl::GST_LIBCCD : fcl::GST_INDEP);
}

}  // namespace scalecert::internal::fp

// The module's entry points (fcl_bullet_loader.cpp declares them).
extern "C" __attribute__((visibility("default"))) scalecert::internal::fp::Method* scalecert_make_fcl(
    const scalecert::internal::Model* m, const scalecert::internal::fp::FpScene* s, bool libccd) {
    using namespace scalecert::internal::fp;
    return new Fcl(*m, *s, libccd ? fcl::GST_LIBCCD : fcl::GST_INDEP);
}
extern "C" __attribute__((visibility("default"))) scalecert::internal::fp::Method* scalecert_make_bullet(
    const scalecert::internal::fp::FpScene* s) {
    return new scalecert::internal::fp::Bullet(*s);
}
extern "C" __attribute__((visibility("default"))) scalecert::internal::fp::Method* scalecert_make_compound(
    const scalecert::internal::fp::CompoundFp* s, int kind) {
    return scalecert::internal::fp::make_compound_module(*s, kind).release();
}
extern "C" __attribute__((visibility("default"))) scalecert::internal::fp::Method* scalecert_make_rounded(
    const scalecert::internal::fp::RoundedFp* s, int kind) {
    using namespace scalecert::internal::fp;
    if (kind == 0) return new RoundedBullet(*s);
    return new RoundedFcl(*s, kind == 1 ? fcl::GST_LIBCCD : fcl::GST_INDEP);
}
