// tools/decompose: closed OFF meshes to objects made of convex parts, exactly.
//
//   decompose A.off                 the object's JSON fragment: {"parts": [...], "seed": [...]}
//   decompose A.off B.off           a whole scene: P1 from A, P2 from B scaled by a power of two to
//                                   A's size and placed beside it along x (as tools/real_mesh_audit.py
//                                   places its pairs), I1 = I2 = [1/2, 2]
//   options: --max-faces N (default 2000), --out FILE (default: standard output)
//
// The OFF coordinates are read as exact decimals (fractions), the mesh becomes a Nef polyhedron on
// CGAL's exact kernel, and CGAL's convex_decomposition_3 cuts it into convex volumes; each volume's
// vertices are written as exact rationals (strings "n/d"). The seed of each object is the mean of
// its mesh's vertices. Cost: building the Nef polyhedron and decomposing it grow quickly with the
// faces (convex_decomposition_3 makes O(r^2) pieces for r reflex edges, each cut an exact Nef
// operation); a few hundred faces take seconds to minutes on one core. A mesh that is not closed,
// not a manifold polygon mesh, or has more than --max-faces faces is refused in one line, exit 2.
//
// Built only when asked: cmake -DSCALECERT_BUILD_DECOMPOSE=ON, target `decompose`.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/convex_decomposition_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = K::FT;
using ET = FT::ET;
using Point = K::Point_3;
using Polyhedron = CGAL::Polyhedron_3<K>;
using Nef = CGAL::Nef_polyhedron_3<K>;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

[[noreturn]] void refuse(const std::string& why) {
    std::cerr << "decompose: " << why << "\n";
    std::exit(2);
}

// A decimal ("-1.25e-3", "7") as an exact rational.
ET decimal(const std::string& s) {
    std::string mant = s, digits;
    long exp10 = 0;
    auto e = mant.find_first_of("eE");
    if (e != std::string::npos) {
        exp10 = std::stol(mant.substr(e + 1));
        mant = mant.substr(0, e);
    }
    bool neg = false;
    std::size_t i = 0;
    if (i < mant.size() && (mant[i] == '-' || mant[i] == '+')) neg = mant[i++] == '-';
    bool dot = false;
    for (; i < mant.size(); ++i) {
        char c = mant[i];
        if (c == '.' && !dot)
            dot = true;
        else if (c >= '0' && c <= '9') {
            digits += c;
            if (dot) --exp10;
        } else
            refuse("not a number: " + s);
    }
    if (digits.empty()) refuse("not a number: " + s);
    // Leading zeros would read as octal (gmpxx's base 0), and "n/d" unreduced is not canonical:
    // an integer and a power of ten, divided, are canonical in every exact type.
    auto nz = digits.find_first_not_of('0');
    digits = nz == std::string::npos ? "0" : digits.substr(nz);
    std::string num = (neg ? "-" : "") + digits, den = "1";
    if (exp10 > 0)
        num += std::string(exp10, '0');
    else if (exp10 < 0)
        den += std::string(-exp10, '0');
    return ET(num) / ET(den);
}

struct Mesh {
    std::vector<std::array<ET, 3>> points;
    std::vector<std::vector<std::size_t>> faces;
};

Mesh read_off(const std::string& path) {
    std::ifstream in(path);
    if (!in) refuse("cannot read " + path);
    std::vector<std::string> words;
    std::string line;
    while (std::getline(in, line)) {
        auto h = line.find('#');
        if (h != std::string::npos) line.resize(h);
        std::istringstream ls(line);
        std::string w;
        while (ls >> w) words.push_back(w);
    }
    if (words.empty() || words[0] != "OFF" || words.size() < 4) refuse(path + " is not an OFF file");
    std::size_t nv = std::stoul(words[1]), nf = std::stoul(words[2]), at = 4;
    Mesh m;
    if (words.size() < at + 3 * nv) refuse(path + " is cut short");
    for (std::size_t v = 0; v < nv; ++v, at += 3)
        m.points.push_back({decimal(words[at]), decimal(words[at + 1]), decimal(words[at + 2])});
    for (std::size_t f = 0; f < nf; ++f) {
        if (at >= words.size()) refuse(path + " is cut short");
        std::size_t k = std::stoul(words[at++]);
        std::vector<std::size_t> face;
        for (std::size_t j = 0; j < k; ++j) {
            if (at >= words.size()) refuse(path + " is cut short");
            std::size_t v = std::stoul(words[at++]);
            if (v >= nv) refuse(path + ": a face names vertex " + std::to_string(v));
            face.push_back(v);
        }
        // colours or other per-face values up to the line's end are not kept: OFF faces in CGAL's
        // data have none.
        m.faces.push_back(face);
    }
    return m;
}

std::string str(const ET& x) {
    std::ostringstream o;
    o << x;
    return "\"" + o.str() + "\"";
}

struct Parts {
    std::vector<std::vector<std::array<ET, 3>>> parts;
    std::array<ET, 3> seed;
};

Parts decompose(const Mesh& m, const std::string& name, std::size_t max_faces) {
    if (m.faces.size() > max_faces)
        refuse(name + " has " + std::to_string(m.faces.size()) + " faces, more than --max-faces " +
               std::to_string(max_faces) + " (Nef decomposition would take too long)");
    std::vector<Point> pts;
    for (auto& p : m.points) pts.emplace_back(FT(p[0]), FT(p[1]), FT(p[2]));
    auto faces = m.faces;
    Polyhedron P;
    if (!PMP::is_polygon_soup_a_polygon_mesh(faces)) refuse(name + " is not a manifold polygon mesh");
    PMP::polygon_soup_to_polygon_mesh(pts, faces, P);
    if (!CGAL::is_closed(P)) refuse(name + " is not closed");
    PMP::triangulate_faces(P);  // a Nef polyhedron needs planar facets: OFF quads need not be
    if (!PMP::is_outward_oriented(P)) PMP::reverse_face_orientations(P);
    Nef N(P);
    if (!N.is_simple() && N.number_of_volumes() < 2) refuse(name + " does not bound a volume");
    CGAL::convex_decomposition_3(N);
    Parts out;
    auto ci = N.volumes_begin();
    ++ci;  // the outer volume
    for (; ci != N.volumes_end(); ++ci) {
        if (!ci->mark()) continue;
        Polyhedron Q;
        N.convert_inner_shell_to_polyhedron(ci->shells_begin(), Q);
        std::map<std::array<ET, 3>, int> seen;
        std::vector<std::array<ET, 3>> part;
        for (auto v = Q.vertices_begin(); v != Q.vertices_end(); ++v) {
            std::array<ET, 3> p{CGAL::exact(v->point().x()), CGAL::exact(v->point().y()), CGAL::exact(v->point().z())};
            if (seen.emplace(p, 0).second) part.push_back(p);
        }
        out.parts.push_back(part);
    }
    std::array<ET, 3> s{ET(0), ET(0), ET(0)};
    for (auto& p : m.points)
        for (int k = 0; k < 3; ++k) s[k] += p[k];
    for (int k = 0; k < 3; ++k) s[k] /= ET(static_cast<long>(m.points.size()));
    out.seed = s;
    return out;
}

// CGAL's own checks (a self-intersecting mesh, a ray that hits nothing) become a refusal, exit 2.
Parts guarded(const Mesh& m, const std::string& name, std::size_t max_faces) {
    try {
        return decompose(m, name, max_faces);
    } catch (const std::exception& e) {
        std::string w = e.what();
        for (auto& c : w)
            if (c == '\n') c = ' ';
        refuse(name + ": CGAL could not decompose it: " + w);
    }
}

std::string object_json(const Parts& p) {
    std::ostringstream o;
    o << "{\"parts\": [";
    for (std::size_t i = 0; i < p.parts.size(); ++i) {
        o << (i ? ",\n    " : "\n    ") << "{\"vertices\": [";
        for (std::size_t j = 0; j < p.parts[i].size(); ++j) {
            auto& v = p.parts[i][j];
            o << (j ? "," : "") << "[" << str(v[0]) << "," << str(v[1]) << "," << str(v[2]) << "]";
        }
        o << "]}";
    }
    o << "],\n  \"seed\": [" << str(p.seed[0]) << "," << str(p.seed[1]) << "," << str(p.seed[2]) << "]}";
    return o.str();
}

void box(const Mesh& m, std::array<ET, 3>& lo, std::array<ET, 3>& hi) {
    lo = hi = m.points.at(0);
    for (auto& p : m.points)
        for (int k = 0; k < 3; ++k) {
            if (p[k] < lo[k]) lo[k] = p[k];
            if (p[k] > hi[k]) hi[k] = p[k];
        }
}

ET size(const std::array<ET, 3>& lo, const std::array<ET, 3>& hi) {
    ET s = hi[0] - lo[0];
    for (int k = 1; k < 3; ++k)
        if (hi[k] - lo[k] > s) s = hi[k] - lo[k];
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> files;
    std::size_t max_faces = 2000;
    std::string out_path;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--max-faces" && i + 1 < argc)
            max_faces = std::stoul(argv[++i]);
        else if (a == "--out" && i + 1 < argc)
            out_path = argv[++i];
        else if (!a.empty() && a[0] == '-') {
            std::cerr << "usage: decompose A.off [B.off] [--max-faces N] [--out FILE]\n";
            return 2;
        } else
            files.push_back(a);
    }
    if (files.empty() || files.size() > 2) {
        std::cerr << "usage: decompose A.off [B.off] [--max-faces N] [--out FILE]\n";
        return 2;
    }
    std::string text;
    Mesh A = read_off(files[0]);
    if (files.size() == 1) {
        Parts pa = guarded(A, files[0], max_faces);
        text = object_json(pa) + "\n";
        std::cerr << files[0] << ": " << A.faces.size() << " faces, " << pa.parts.size() << " parts\n";
    } else {
        Mesh B = read_off(files[1]);
        std::array<ET, 3> la, ha, lb, hb;
        box(A, la, ha);
        box(B, lb, hb);
        ET sa = size(la, ha), sb = size(lb, hb), k(1);
        while (sb * k * 2 <= sa) k *= 2;
        while (sb * k > sa * 2) k /= 2;
        std::array<ET, 3> shift;
        for (int c = 0; c < 3; ++c) shift[c] = (la[c] + ha[c]) / 2 - (lb[c] + hb[c]) / 2 * k;
        shift[0] += (sa + sb * k) / 2;
        for (auto& p : B.points)
            for (int c = 0; c < 3; ++c) p[c] = p[c] * k + shift[c];
        Parts pa = guarded(A, files[0], max_faces), pb = guarded(B, files[1], max_faces);
        std::cerr << files[0] << ": " << A.faces.size() << " faces, " << pa.parts.size() << " parts; " << files[1]
                  << ": " << B.faces.size() << " faces, " << pb.parts.size() << " parts\n";
        text = "{\"P1\": " + object_json(pa) + ",\n \"P2\": " + object_json(pb) +
               ",\n \"I1\": [\"1/2\", 2], \"I2\": [\"1/2\", 2]}\n";
    }
    if (out_path.empty())
        std::cout << text;
    else {
        std::ofstream o(out_path);
        o << text;
        if (!o) refuse("cannot write " + out_path);
    }
    return 0;
}
