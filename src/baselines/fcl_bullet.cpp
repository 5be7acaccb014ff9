// FCL (GJK through libccd, and FCL's own GJK) and Bullet (GJK/EPA) as baselines, as their users
// call them, on the scaled polyhedra. Kept in one translation unit: their headers are heavy.
// Built as a module (libscalecert_fcl_bullet.so) that the tools load on first use
// (fcl_bullet_loader.cpp): FCL alone brings 29,000 relocations, which every start of the
// scalecert command would otherwise pay. The module uses no scalecert symbol, only its headers.
#include "baselines/baselines.hpp"

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <fcl/geometry/shape/convex.h>
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
        for (const D3& p : s_.P[i].pts) v->emplace_back(c[0] + rho * (p[0] - c[0]), c[1] + rho * (p[1] - c[1]), c[2] + rho * (p[2] - c[2]));
        return std::make_shared<fcl::Convexd>(v, nfaces_[i], faces_[i]);
    }
    int classify(double r1, double r2) const override {
        fcl::CollisionObjectd a(shape(0, r1), fcl::Transform3d::Identity()), b(shape(1, r2), fcl::Transform3d::Identity());
        fcl::CollisionRequestd req;
        req.gjk_solver_type = type_;
        fcl::CollisionResultd res;
        fcl::collide(&a, &b, req, res);
        return res.isCollision() ? -1 : 1;
    }
    // distance() with nearest points when separated; collide() with a contact (its depth and
    // normal, from P1 towards P2) when not. The depth is taken as returned: FCL 0.7's own GJK
    // (GST_INDEP) returns it negated (−1.5 where libccd's gives 1.5), which the audit reports.
    std::optional<Measure> measure(double r1, double r2, bool separated) const override {
        fcl::CollisionObjectd a(shape(0, r1), fcl::Transform3d::Identity()), b(shape(1, r2), fcl::Transform3d::Identity());
        Measure m;
        if (separated) {
            fcl::DistanceRequestd req(true);
            req.gjk_solver_type = type_;
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
            shape_[i].setMargin(0);  // no collision margin: the shapes exactly as given
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
            if (!btGjkEpaSolver2::Distance(&shape_[0], xf_[0], &shape_[1], xf_[1], btVector3(1, 0, 0), res)) return std::nullopt;
            m.value = res.distance;
            m.closest = std::array<D3, 2>{d3(res.witnesses[0]), d3(res.witnesses[1])};
            return m;
        }
        if (!btGjkEpaSolver2::Penetration(&shape_[0], xf_[0], &shape_[1], xf_[1], btVector3(1, 0, 0), res)) return std::nullopt;
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

}  // namespace

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
