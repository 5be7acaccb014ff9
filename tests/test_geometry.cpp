#define BOOST_TEST_MODULE geometry
#include <boost/test/unit_test.hpp>

#include "support.hpp"

using namespace scalecert;

namespace {
std::vector<Vec3q> cube_with_clutter() {
    std::vector<Vec3q> p;
    for (int x : {0, 2}) for (int y : {0, 2}) for (int z : {0, 2}) p.push_back({Q(x), Q(y), Q(z)});
    p.push_back({Q(1), Q(1), Q(1)});  // interior
    p.push_back({Q(1), Q(1), Q(2)});  // face centre
    p.push_back({Q(1), Q(0), Q(0)});  // edge midpoint
    p.push_back({Q(2), Q(2), Q(2)});  // duplicate of vertex 7
    p.push_back({Q(1, 2), Q(3, 2), Q(0)});  // inside the bottom face
    return p;
}
}  // namespace

BOOST_AUTO_TEST_CASE(cube_faces_are_merged_and_clutter_dropped) {
    Polyhedron P = build_polyhedron(cube_with_clutter(), "P1");
    BOOST_TEST(P.vertices.size() == 8u);
    BOOST_TEST(P.edges.size() == 12u);
    BOOST_TEST(P.faces.size() == 6u);
    std::vector<int> expect{0, 1, 2, 3, 4, 5, 6, 7};  // the corners, first copies
    BOOST_TEST(P.vertices == expect);
    for (const Face& f : P.faces) {
        BOOST_TEST(f.verts.size() == 4u);
        int nz = 0;
        for (const Z& c : f.normal) nz += c != 0;
        BOOST_TEST(nz == 1);  // axis-aligned unit normals
        // counter-clockwise seen from outside: consecutive cross products point along the normal
        for (size_t k = 0; k < 4; ++k) {
            const Vec3q& a = P.points[f.verts[k]];
            const Vec3q& b = P.points[f.verts[(k + 1) % 4]];
            const Vec3q& c = P.points[f.verts[(k + 2) % 4]];
            BOOST_TEST(sgn(dot(cross(sub(b, a), sub(c, b)), to_q(f.normal))) > 0);
        }
    }
    BOOST_TEST(P.strictly_inside({Q(1), Q(1), Q(1)}));
    BOOST_TEST(!P.strictly_inside({Q(1), Q(1), Q(2)}));
}

BOOST_AUTO_TEST_CASE(octahedron_counts_and_support) {
    std::vector<Vec3q> p;
    for (int k = 0; k < 3; ++k)
        for (int s : {-1, 1}) {
            Vec3q v{Q(0), Q(0), Q(0)};
            v[k] = s;
            p.push_back(v);
        }
    Polyhedron P = build_polyhedron(p, "P");
    BOOST_TEST(P.vertices.size() == 6u);
    BOOST_TEST(P.edges.size() == 12u);
    BOOST_TEST(P.faces.size() == 8u);
    Q val;
    auto top = P.argmax({Z(0), Z(0), Z(1)}, &val);
    BOOST_TEST(top == std::vector<int>{5});
    BOOST_TEST(val == 1);
    auto face = P.argmax({Z(1), Z(1), Z(1)}, &val);
    BOOST_TEST(face == (std::vector<int>{1, 3, 5}));
    auto edge = P.argmax({Z(1), Z(1), Z(0)}, &val);
    BOOST_TEST(edge == (std::vector<int>{1, 3}));
}

BOOST_AUTO_TEST_CASE(flat_input_is_rejected) {
    std::vector<Vec3q> p{{Q(0), Q(0), Q(0)}, {Q(1), Q(0), Q(0)}, {Q(0), Q(1), Q(0)}, {Q(1), Q(1), Q(0)}};
    BOOST_CHECK_THROW(build_polyhedron(p, "P1"), InputError);
}

BOOST_AUTO_TEST_CASE(random_hulls_contain_every_point_and_satisfy_euler) {
    std::mt19937 g(11);
    for (int t = 0; t < 40; ++t) {
        auto pts = test::random_points(g, 5 + t % 20, 5, 3, {Q(0), Q(0), Q(0)});
        Polyhedron P = build_polyhedron(pts, "P");
        BOOST_TEST(P.vertices.size() + P.faces.size() == P.edges.size() + 2);
        for (const Face& f : P.faces) {
            Q off = dot(to_q(f.normal), P.points[f.verts[0]]);
            for (int v : f.verts) BOOST_TEST(dot(to_q(f.normal), P.points[v]) == off);
            for (const Vec3q& q : pts) BOOST_TEST(dot(to_q(f.normal), q) <= off);
        }
        // Every input point that is not a convex combination of the others is a vertex: check the
        // converse by brute force — a vertex maximises some face-normal sum strictly.
        for (int v : P.vertices) {
            Vec3z dir{Z(0), Z(0), Z(0)};
            for (const Face& f : P.faces)
                if (std::count(f.verts.begin(), f.verts.end(), v))
                    for (int k = 0; k < 3; ++k) dir[k] += f.normal[k];
            auto am = P.argmax(dir);
            BOOST_TEST(am == std::vector<int>{v});
        }
    }
}
