// The only translation unit that includes CGAL's hull code (it compiles slowly).
#ifndef CGAL_USE_GMPXX
#define CGAL_USE_GMPXX 1
#endif
#include "scalecert/polyhedron.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <map>

namespace scalecert {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
static_assert(std::is_same<K::FT::Exact_type, mpq_class>::value, "Epeck must run on mpq_class");

std::vector<std::array<int, 3>> hull_triangles(const std::vector<Vec3q>& pts) {
    std::vector<K::Point_3> cp;
    cp.reserve(pts.size());
    std::map<Vec3q, int> index;  // exact coordinates -> first input index
    for (size_t i = 0; i < pts.size(); ++i) {
        cp.emplace_back(K::FT(pts[i][0]), K::FT(pts[i][1]), K::FT(pts[i][2]));
        index.emplace(pts[i], static_cast<int>(i));
    }
    CGAL::Surface_mesh<K::Point_3> mesh;
    CGAL::convex_hull_3(cp.begin(), cp.end(), mesh);
    std::vector<std::array<int, 3>> tris;
    for (auto f : mesh.faces()) {
        std::array<int, 3> t{};
        int k = 0;
        for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
            const K::Point_3& p = mesh.point(v);
            Vec3q q{CGAL::exact(p.x()), CGAL::exact(p.y()), CGAL::exact(p.z())};
            if (k < 3) t[k] = index.at(q);
            ++k;
        }
        if (k != 3) throw std::logic_error("convex_hull_3 returned a non-triangle");
        tris.push_back(t);
    }
    return tris;
}

}  // namespace scalecert
