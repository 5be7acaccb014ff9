// FCL (GJK through libccd, and FCL's own GJK) and Bullet (GJK/EPA) as baselines, as their users
// call them, on the scaled polyhedra. Kept in one translation unit: their headers are heavy.
#include "scalecert/baselines.hpp"

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/collision.h>

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
    int classify(double r1, double r2) const override {
        std::shared_ptr<fcl::CollisionGeometryd> g[2];
        const double r[2] = {r1, r2};
        for (int i = 0; i < 2; ++i) {
            auto v = std::make_shared<std::vector<fcl::Vector3d>>();
            const D3& c = s_.P[i].seed;
            for (const D3& p : s_.P[i].pts) v->emplace_back(c[0] + r[i] * (p[0] - c[0]), c[1] + r[i] * (p[1] - c[1]), c[2] + r[i] * (p[2] - c[2]));
            g[i] = std::make_shared<fcl::Convexd>(v, nfaces_[i], faces_[i]);
        }
        fcl::CollisionObjectd a(g[0], fcl::Transform3d::Identity()), b(g[1], fcl::Transform3d::Identity());
        fcl::CollisionRequestd req;
        req.gjk_solver_type = type_;
        fcl::CollisionResultd res;
        fcl::collide(&a, &b, req, res);
        return res.isCollision() ? -1 : 1;
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

private:
    FpScene s_;
    mutable btConvexHullShape shape_[2];
    btTransform xf_[2];
};

}  // namespace

std::unique_ptr<Method> make_fcl(const Model& m, const FpScene& s, bool libccd) {
    return std::make_unique<Fcl>(m, s, libccd ? fcl::GST_LIBCCD : fcl::GST_INDEP);
}
std::unique_ptr<Method> make_bullet(const FpScene& s) { return std::make_unique<Bullet>(s); }

}  // namespace scalecert::internal::fp
