// The only translation unit that includes CGAL's hull code (it compiles slowly).
#ifndef CGAL_USE_GMPXX
#define CGAL_USE_GMPXX 1
#endif
#include "scalecert/polyhedron.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <cmath>
#include <algorithm>

namespace scalecert {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
static_assert(std::is_same<K::FT::Exact_type, mpq_class>::value, "Epeck must run on mpq_class");

namespace {
// The hull's triangles as input indices, for any CGAL kernel whose points we can key exactly.
template <class Kernel, class Key, class ToPoint, class ToKey>
std::vector<std::array<int, 3>> hull_with(const std::vector<Vec3z>& pts, ToPoint to_point, ToKey to_key) {
    using Point = typename Kernel::Point_3;
    std::vector<Point> cp;
    cp.reserve(pts.size());
    std::vector<std::pair<Key, int>> index;  // exact coordinates -> first input index, sorted
    index.reserve(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        cp.push_back(to_point(pts[i]));
        index.push_back({to_key(cp.back()), static_cast<int>(i)});
    }
    std::sort(index.begin(), index.end());  // equal points: the first input index comes first
    auto lookup = [&](const Key& k) {
        auto it = std::lower_bound(index.begin(), index.end(), k, [](const std::pair<Key, int>& e, const Key& x) { return e.first < x; });
        if (it == index.end() || !(it->first == k)) throw std::logic_error("hull point not among the input");
        return it->second;
    };
    CGAL::Surface_mesh<Point> mesh;
    CGAL::convex_hull_3(cp.begin(), cp.end(), mesh);
    std::vector<std::array<int, 3>> tris;
    for (auto f : mesh.faces()) {
        std::array<int, 3> t{};
        int k = 0;
        for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
            if (k < 3) t[k] = lookup(to_key(mesh.point(v)));
            ++k;
        }
        if (k != 3) throw std::logic_error("convex_hull_3 returned a non-triangle");
        tris.push_back(t);
    }
    return tris;
}

bool all_exact_doubles(const std::vector<Vec3z>& pts) {
    for (const Vec3z& v : pts)
        for (const Z& c : v)
            if (mpz_sizeinbase(c.get_mpz_t(), 2) > 53) return false;
    return true;
}
}  // namespace

std::vector<std::array<int, 3>> hull_triangles(const std::vector<Vec3z>& pts) {
    // Integers of at most 53 bits are exact doubles: Epick, whose predicates are exact (filtered),
    // and the hull needs no constructions. Otherwise Epeck on mpq_class.
    if (all_exact_doubles(pts)) {
        using KI = CGAL::Exact_predicates_inexact_constructions_kernel;
        return hull_with<KI, std::array<double, 3>>(
            pts, [](const Vec3z& p) { return KI::Point_3(p[0].get_d(), p[1].get_d(), p[2].get_d()); },
            [](const KI::Point_3& p) { return std::array<double, 3>{p.x(), p.y(), p.z()}; });
    }
    return hull_with<K, Vec3q>(
        pts, [](const Vec3z& p) { return K::Point_3(K::FT(Q(p[0])), K::FT(Q(p[1])), K::FT(Q(p[2]))); },
        [](const K::Point_3& p) { return Vec3q{CGAL::exact(p.x()), CGAL::exact(p.y()), CGAL::exact(p.z())}; });
}

}  // namespace scalecert
