// The only translation unit that includes CGAL's hull code (it compiles slowly).
#ifndef CGAL_USE_GMPXX
#define CGAL_USE_GMPXX 1
#endif
#include "geometry/polyhedron.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Extreme_points_traits_adapter_3.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <numeric>

namespace scalecert::internal {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
static_assert(std::is_same<K::FT::Exact_type, mpq_class>::value, "Epeck must run on mpq_class");

namespace {
// The hull's triangles as input indices. CGAL runs on the indices of the first copies of the
// distinct points (through its extreme-points traits adapter) and writes an indexed triangle set
// whose vertices are those indices: no mesh, no lookup of coordinates.
template <class Kernel, class ToPoint>
std::vector<std::array<int, 3>> hull_with(const std::vector<Vec3z>& pts, ToPoint to_point) {
    using Point = typename Kernel::Point_3;
    std::vector<Point> cp;
    cp.reserve(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) cp.push_back(to_point(i));
    std::vector<std::size_t> first(pts.size());
    std::iota(first.begin(), first.end(), std::size_t{0});
    std::sort(first.begin(), first.end(),
              [&](std::size_t a, std::size_t b) { return pts[a] < pts[b] || (pts[a] == pts[b] && a < b); });
    first.erase(std::unique(first.begin(), first.end(), [&](std::size_t a, std::size_t b) { return pts[a] == pts[b]; }),
                first.end());
    std::vector<std::size_t> verts;
    std::vector<std::array<std::size_t, 3>> faces;
    const auto traits =
        CGAL::make_extreme_points_traits_adapter(CGAL::make_property_map(cp), CGAL::Convex_hull_traits_3<Kernel>());
    using It = std::vector<std::size_t>::iterator;
    // CGAL 5.5's overload with traits has a template parameter it cannot deduce: all are named.
    CGAL::convex_hull_3<It, std::size_t, decltype(verts), decltype(faces), decltype(traits)>(first.begin(), first.end(),
                                                                                             verts, faces, traits);
    std::vector<std::array<int, 3>> tris;
    tris.reserve(faces.size());
    for (const auto& f : faces)
        tris.push_back({static_cast<int>(verts[f[0]]), static_cast<int>(verts[f[1]]), static_cast<int>(verts[f[2]])});
    // For exactly four distinct points CGAL 5.5 writes the tetrahedron into an indexed triangle
    // set inside out (its mesh version swaps two corners; this one does not): orient it here.
    if (first.size() == 4 && tris.size() == 4) {
        const auto& t = tris[0];
        int d = -1;  // the corner not on triangle t
        for (std::size_t q : first)
            if (static_cast<int>(q) != t[0] && static_cast<int>(q) != t[1] && static_cast<int>(q) != t[2])
                d = static_cast<int>(q);
        if (sgn(dotz(cross(sub(pts[t[1]], pts[t[0]]), sub(pts[t[2]], pts[t[0]])), sub(pts[d], pts[t[0]]))) > 0)
            for (auto& tri : tris) std::swap(tri[1], tri[2]);
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

std::vector<std::array<int, 3>> hull_triangles(const std::vector<Vec3z>& pts, const std::vector<Vec3q>& given) {
    // Integers of at most 53 bits are exact doubles: Epick, whose predicates are exact (filtered),
    // and the hull needs no constructions. Otherwise Epeck on mpq_class, on the points as given
    // (the integers divided by one positive scale: the same orientations), whose interval
    // filters work where the integers' would overflow the double range (a common denominator of
    // thousands of bits).
    if (all_exact_doubles(pts)) {
        using KI = CGAL::Exact_predicates_inexact_constructions_kernel;
        return hull_with<KI>(
            pts, [&](size_t i) { return KI::Point_3(pts[i][0].get_d(), pts[i][1].get_d(), pts[i][2].get_d()); });
    }
    return hull_with<K>(
        pts, [&](size_t i) { return K::Point_3(K::FT(given[i][0]), K::FT(given[i][1]), K::FT(given[i][2])); });
}

}  // namespace scalecert::internal
