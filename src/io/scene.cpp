#include "io/scene.hpp"
#include "io/files.hpp"

#include "io/mesh.hpp"
#include "io/strict_json.hpp"
#include "numeric/predicates.hpp"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <unordered_set>

namespace scalecert::internal {
namespace {

struct Reader {
    std::string file;
    ReadOptions opt;
    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw InputError(file + ": " + (where.empty() ? "" : where + ": ") + what);
    }
    // `where` names the place in the file; it is a string, or a function building one, called
    // only on an error (a scene has tens of thousands of numbers).
    static std::string text_of(const std::string& w) { return w; }
    template <class F>
    static std::string text_of(const F& w) {
        return w();
    }
    template <class W>
    Q number_text(const std::string& text, bool is_string, const W& where) const {
        try {
            return parse_number(text, is_string ? Numbers::Exact : opt.numbers, opt.inexact);
        } catch (const InputError& e) {
            fail(text_of(where), e.what());
        }
    }
    template <class W>
    Q number(const JNode& n, const W& where) const {
        if (n.kind == JNode::Number) return number_text(n.text, false, where);
        if (n.kind == JNode::String) return number_text(n.text, true, where);
        fail(text_of(where), "expected a number or a string such as \"3/7\"");
    }
    template <class W>
    Vec3q point(const JNode& n, const W& where) const {
        if (n.kind != JNode::Array || n.items.size() != 3) fail(text_of(where), "expected an array of 3 coordinates");
        auto at = [&](int k) { return [&where, k] { return text_of(where) + "[" + std::to_string(k) + "]"; }; };
        return {number(n.items[0], at(0)), number(n.items[1], at(1)), number(n.items[2], at(2))};
    }
};

// OFF: "OFF" header (optionally with counts on the same line), "nv nf ne", nv vertex lines.
// Faces are not needed: the polyhedron is the convex hull of the vertices.
}  // namespace

ExactScene parse_scene_text(const std::string& text, const std::string& name, const std::string& base_dir,
                            const ReadOptions& given) {
    long inexact = 0;
    ReadOptions opt = given;
    if (!opt.inexact) opt.inexact = &inexact;
    Reader r{name, opt};
    JNode tree;
    try {
        tree = parse_strict_json(text);
    } catch (const JsonError& e) {
        r.fail("", "malformed JSON near byte " + std::to_string(e.pos) + ": " + e.what);
    }
    const JNode& root = tree;
    if (root.kind != JNode::Object) r.fail("", "the scene must be a JSON object");
    // A misspelt key would otherwise be ignored silently.
    auto only = [&](const JNode& o, const std::string& where, std::initializer_list<const char*> known) {
        for (const std::string& k : o.keys) {
            bool ok = false;
            for (const char* n : known) ok = ok || k == n;
            if (!ok)
                r.fail(
                    where, "unknown field " + in_quotes(k) + " (expected " + [&] {
                        std::string l;
                        for (const char* n : known) l += (l.empty() ? "" : ", ") + std::string(n);
                        return l;
                    }() + ")");
        }
    };
    only(root, "", {"P1", "P2", "I1", "I2"});
    ExactScene sc;
    // An object's or a part's own "numbers": its points read so, counted apart for the note.
    auto reading = [&](const JNode& o, const std::string& where, const Reader& outer) {
        const JNode* n = o.find("numbers");
        if (!n) return outer;
        if (n->kind != JNode::String || (n->text != "double" && n->text != "float32" && n->text != "exact"))
            r.fail(where + ".numbers",
                   "expected \"double\", \"float32\" or \"exact\" (how this object's points are read)");
        Reader own = outer;
        own.opt.numbers = n->text == "double"    ? Numbers::Double
                          : n->text == "float32" ? Numbers::Float32
                                                 : Numbers::Exact;
        own.opt.inexact =
            own.opt.numbers == opt.numbers ? opt.inexact : &sc.inexact_by_reading[static_cast<size_t>(own.opt.numbers)];
        return own;
    };
    const char* pname[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        const JNode* p = root.find(pname[i]);
        if (!p) r.fail("", std::string("missing field \"") + pname[i] + "\"");
        if (p->kind != JNode::Object) r.fail(pname[i], "expected an object with \"vertices\" or \"off\"");
        PolyInput& in = sc.P[i];
        // The points of one convex body: "vertices", or a mesh file ("mesh": OFF, OBJ, PLY or STL by
        // extension; "off": an OFF file whatever its name). `where` names the object or the part.
        // With `groups` (an object's, not a part's), an OBJ "mesh" is read as a compound instead,
        // a part per group, into `into`. `part`: o is a part of "parts" (for the note on its groups).
        // `rd` reads the points (the object's or the part's own "numbers").
        auto body = [&](const Reader& rd, const JNode& o, const std::string& where, bool groups, PolyInput& into,
                        bool part = false) {
            std::vector<Vec3q>& pts = into.points;
            const JNode* verts = o.find("vertices");
            const JNode* off = o.find("off");
            const JNode* mesh = o.find("mesh");
            if ((verts != nullptr) + (off != nullptr) + (mesh != nullptr) > 1)
                r.fail(where, "give one of \"vertices\", \"mesh\" and \"off\"");
            if (mesh) off = mesh;
            if (verts) {
                if (verts->kind != JNode::Array) r.fail(where + ".vertices", "expected an array of points");
                if (verts->items.size() > kMaxPoints)
                    r.fail(where + ".vertices", "more than " + std::to_string(kMaxPoints) + " points (the limit)");
                pts.reserve(verts->items.size());
                for (size_t j = 0; j < verts->items.size(); ++j)
                    pts.push_back(
                        rd.point(verts->items[j], [&] { return where + ".vertices[" + std::to_string(j) + "]"; }));
            } else if (off) {
                const std::string key = where + (mesh ? ".mesh" : ".off");
                if (off->kind != JNode::String) r.fail(key, "expected a file name");
                if (!opt.allow_off_files) r.fail(key, "mesh files are not read here");
                if (groups && !mesh) r.fail(key, "an OFF file has no groups (parts from groups need an OBJ \"mesh\")");
                std::string path = off->text;
                if (!path.empty() && path[0] != '/' && !base_dir.empty()) path = base_dir + "/" + path;
                sc.files.push_back(path);
                if (groups) {
                    ReadOptions o2 = rd.opt;
                    o2.parts_from_groups = true;
                    read_mesh_object(path, o2, into);
                } else {
                    pts = mesh
                              ? read_mesh(path, rd.opt, &into.note, part)
                              : parse_mesh(read_input(path, "OFF file", kMaxSceneBytes), MeshFormat::Off, path, rd.opt);
                }
            } else {
                r.fail(where, "missing field \"vertices\" (or \"mesh\", \"off\")");
            }
        };
        // A shorthand in the object's frame (CLAIMS.md, "Objects with a radius"): "sphere": r (one
        // point with radius r); "capsule": {"radius", "half_length"} (the segment from (0, 0, −h)
        // to (0, 0, h) with radius r); "box": [hx, hy, hz] (its eight corners; a "radius" beside it
        // rounds it). False when the object has none.
        auto shape = [&](const Reader& rd, const JNode& o, const std::string& where, PolyInput& into) {
            const JNode *sphere = o.find("sphere"), *capsule = o.find("capsule"), *box = o.find("box");
            if (!sphere && !capsule && !box) return false;
            if ((sphere != nullptr) + (capsule != nullptr) + (box != nullptr) + (o.find("vertices") != nullptr) +
                    (o.find("mesh") != nullptr) + (o.find("off") != nullptr) >
                1)
                r.fail(where, "give one of \"vertices\", \"mesh\", \"off\", \"sphere\", \"capsule\" and \"box\"");
            if (o.find("parts_from_groups"))
                r.fail(where + ".parts_from_groups", "parts from groups need an OBJ \"mesh\"");
            const Q zero(0);
            if (sphere) {
                if (o.find("radius")) r.fail(where + ".radius", "a sphere's radius is its \"sphere\" value");
                into.radius = rd.number(*sphere, where + ".sphere");
                into.radius_given = true;
                if (sgn(into.radius) <= 0)
                    r.fail(where + ".sphere",
                           "a sphere's radius is > 0 (got " + in_quotes(to_exact_string(into.radius)) + ")");
                into.points = {Vec3q{zero, zero, zero}};
            } else if (capsule) {
                const std::string w = where + ".capsule";
                if (o.find("radius")) r.fail(where + ".radius", "a capsule's radius is its \"capsule\"'s \"radius\"");
                if (capsule->kind != JNode::Object) r.fail(w, "expected {\"radius\": r, \"half_length\": h}");
                only(*capsule, w, {"radius", "half_length"});
                const JNode *rn = capsule->find("radius"), *hn = capsule->find("half_length");
                if (!rn) r.fail(w, "missing field \"radius\"");
                if (!hn) r.fail(w, "missing field \"half_length\"");
                into.radius = rd.number(*rn, w + ".radius");
                into.radius_given = true;
                if (sgn(into.radius) <= 0)
                    r.fail(w + ".radius",
                           "a capsule's radius is > 0 (got " + in_quotes(to_exact_string(into.radius)) + ")");
                const Q h = rd.number(*hn, w + ".half_length");
                if (sgn(h) < 0)
                    r.fail(w + ".half_length", "a half-length is >= 0 (got " + in_quotes(to_exact_string(h)) + ")");
                into.points = {Vec3q{zero, zero, Q(-h)}};
                if (sgn(h) > 0) into.points.push_back(Vec3q{zero, zero, h});
            } else {
                const std::string w = where + ".box";
                if (box->kind != JNode::Array || box->items.size() != 3)
                    r.fail(w, "expected the half-extents [hx, hy, hz]");
                Q e[3];
                for (size_t k = 0; k < 3; ++k) {
                    e[k] = rd.number(box->items[k], w + "[" + std::to_string(k) + "]");
                    if (sgn(e[k]) <= 0)
                        r.fail(w + "[" + std::to_string(k) + "]",
                               "a half-extent is > 0 (got " + in_quotes(to_exact_string(e[k])) + ")");
                }
                for (int c = 0; c < 8; ++c)
                    into.points.push_back(
                        Vec3q{c & 1 ? e[0] : Q(-e[0]), c & 2 ? e[1] : Q(-e[1]), c & 4 ? e[2] : Q(-e[2])});
            }
            return true;
        };
        // An object's "radius" beside its points (its shorthand's, for a sphere or a capsule).
        auto radius = [&](const Reader& rd, const JNode& o, const std::string& where, PolyInput& into) {
            const JNode* n = o.find("radius");
            if (!n) return;
            into.radius = rd.number(*n, where + ".radius");
            into.radius_given = true;
            if (sgn(into.radius) < 0)
                r.fail(where + ".radius", "a radius is >= 0 (got " + in_quotes(to_exact_string(into.radius)) + ")");
        };
        if (const JNode* spheres = p->find("spheres")) {
            // A sphere set (CLAIMS.md, "Objects with a radius"): a part per centre, one point with
            // its radius.
            only(*p, pname[i], {"spheres", "seed", "pose", "numbers"});
            const Reader rd = reading(*p, pname[i], r);
            const std::string where = std::string(pname[i]) + ".spheres";
            if (!opt.allow_parts)
                r.fail(where, "a sphere set is an object made of parts, which `curve` and `grid` do not read");
            if (spheres->kind != JNode::Object)
                r.fail(where, "expected {\"centres\": [[x, y, z], ...], \"radii\": [r, ...]}");
            only(*spheres, where, {"centres", "radii"});
            const JNode *cs = spheres->find("centres"), *rs = spheres->find("radii");
            if (!cs) r.fail(where, "missing field \"centres\"");
            if (!rs) r.fail(where, "missing field \"radii\"");
            if (cs->kind != JNode::Array || cs->items.empty())
                r.fail(where + ".centres", "expected a nonempty list of points");
            if (rs->kind != JNode::Array || rs->items.size() != cs->items.size())
                r.fail(where + ".radii",
                       "expected a list of " + std::to_string(cs->items.size()) + " radii (one a centre)");
            if (cs->items.size() > kMaxParts)
                r.fail(where + ".centres", "more than " + std::to_string(kMaxParts) + " spheres (the limit on parts)");
            for (size_t k = 0; k < cs->items.size(); ++k) {
                const Vec3q c = rd.point(cs->items[k], [&] { return where + ".centres[" + std::to_string(k) + "]"; });
                const std::string wr = where + ".radii[" + std::to_string(k) + "]";
                Q rk = rd.number(rs->items[k], wr);
                if (sgn(rk) <= 0) r.fail(wr, "a sphere's radius is > 0 (got " + in_quotes(to_exact_string(rk)) + ")");
                in.parts.push_back({c});
                in.points.push_back(c);
                in.part_radii.push_back(std::move(rk));
            }
        } else if (const JNode* parts = p->find("parts")) {
            only(*p, pname[i], {"parts", "radius", "seed", "pose", "numbers"});
            const Reader object_reader = reading(*p, pname[i], r);
            const std::string where = std::string(pname[i]) + ".parts";
            // The object's "radius" is each part's without its own.
            PolyInput whole;
            radius(object_reader, *p, pname[i], whole);
            std::vector<Q> radii;
            if (!opt.allow_parts)
                r.fail(where,
                       "an object made of parts is read by `scalecert region`, `query`, `partition`, `classify`, "
                       "`certify-fp`, `golden` and `audit`; "
                       "`curve` and `grid` are for two convex objects (`scalecert region` gives where "
                       "objects made of parts meet)");
            if (parts->kind != JNode::Array || parts->items.empty()) r.fail(where, "expected a nonempty list of parts");
            if (parts->items.size() > kMaxParts)
                r.fail(where, "more than " + std::to_string(kMaxParts) + " parts (the limit)");
            std::map<std::string, size_t> named;  // each name and its part
            size_t merged = 0;                    // parts whose OBJ mesh has several groups with faces
            for (size_t k = 0; k < parts->items.size(); ++k) {
                const std::string w = where + "[" + std::to_string(k) + "]";
                const JNode& part = parts->items[k];
                if (part.kind != JNode::Object) r.fail(w, "expected an object with \"vertices\" or \"mesh\"");
                only(part, w, {"name", "vertices", "off", "mesh", "sphere", "capsule", "box", "radius", "numbers"});
                if (const JNode* n = part.find("name")) {
                    if (n->kind != JNode::String) r.fail(w + ".name", "expected a string (the part's name)");
                    if (n->text.empty())
                        r.fail(w + ".name", "an empty name (leave \"name\" out for a part without one)");
                    if (const auto [at, fresh] = named.emplace(n->text, k); !fresh)
                        r.fail(w + ".name", in_quotes(n->text) + " names " + where + "[" + std::to_string(at->second) +
                                                "] too (the parts of an object have distinct names)");
                    in.part_names.resize(k + 1);
                    in.part_names[k] = n->text;
                }
                PolyInput one;
                const Reader part_reader = reading(part, w, object_reader);
                if (!shape(part_reader, part, w, one)) body(part_reader, part, w, false, one, true);
                radius(part_reader, part, w, one);
                radii.push_back(one.radius_given ? one.radius : whole.radius);
                // Said once per object, for the first such part.
                if (!one.note.empty() && merged++ == 0) in.note = w + ": " + one.note;
                in.parts.push_back(std::move(one.points));
                if (in.points.size() + in.parts.back().size() > kMaxPoints)
                    r.fail(where, "more than " + std::to_string(kMaxPoints) + " points in all (the limit)");
                in.points.insert(in.points.end(), in.parts.back().begin(), in.parts.back().end());
            }
            if (!in.part_names.empty()) in.part_names.resize(in.parts.size());
            for (const Q& x : radii)
                if (sgn(x) > 0) {
                    in.part_radii = std::move(radii);
                    break;
                }
            if (merged > 1)
                in.note += " (and " + std::to_string(merged - 1) + " more " + (merged == 2 ? "part" : "parts") +
                           " of " + pname[i] + " so read)";
        } else {
            only(*p, pname[i],
                 {"vertices", "off", "mesh", "sphere", "capsule", "box", "radius", "seed", "parts_from_groups", "pose",
                  "numbers"});
            // An OBJ "mesh" as a compound: --parts-from-groups (which leaves other meshes, having no
            // groups, one convex object each), or this object's "parts_from_groups".
            const JNode* mesh = p->find("mesh");
            const bool is_obj = mesh && mesh->kind == JNode::String && [&] {
                try {
                    return mesh_format_of(mesh->text) == MeshFormat::Obj;
                } catch (const InputError&) {
                    return false;  // an unknown format: refused when read, with its path
                }
            }();
            bool groups = opt.parts_from_groups && is_obj && !p->find("vertices") && !p->find("off");
            if (const JNode* g = p->find("parts_from_groups")) {
                const std::string w = std::string(pname[i]) + ".parts_from_groups";
                if (g->kind != JNode::Bool) r.fail(w, "expected true or false");
                if (!opt.allow_parts)
                    r.fail(w,
                           "not read by `curve` and `grid`, which are for two convex objects (drop the key: "
                           "the mesh is then read as one convex object)");
                groups = g->text == "true";
                if (groups && !p->find("mesh")) r.fail(w, "parts from groups need an OBJ \"mesh\"");
                if (groups && mesh && mesh->kind == JNode::String && !is_obj)
                    r.fail(w, "parts from groups need an OBJ \"mesh\" (" + in_quotes(mesh->text) +
                                  ": OFF, PLY and STL files have no groups)");
            }
            const Reader rd = reading(*p, pname[i], r);
            if (!shape(rd, *p, pname[i], in)) body(rd, *p, pname[i], groups, in);
            radius(rd, *p, pname[i], in);
        }
        if (const JNode* s = p->find("seed")) {
            in.seed = r.point(*s, std::string(pname[i]) + ".seed");
            in.seed_given = true;
        }
        if (const JNode* ps = p->find("pose")) {
            const std::string w = std::string(pname[i]) + ".pose";
            if (ps->kind != JNode::Array || ps->items.size() != 3)
                r.fail(w, "expected 3 rows [r1, r2, r3, t] (the matrix [R | t])");
            Pose m;
            for (int row = 0; row < 3; ++row) {
                const JNode& rw = ps->items[static_cast<size_t>(row)];
                const std::string wr = w + "[" + std::to_string(row) + "]";
                if (rw.kind != JNode::Array || rw.items.size() != 4) r.fail(wr, "expected 4 numbers [r1, r2, r3, t]");
                for (int k = 0; k < 4; ++k)
                    m[static_cast<size_t>(row)][static_cast<size_t>(k)] =
                        r.number(rw.items[static_cast<size_t>(k)], [&] { return wr + "[" + std::to_string(k) + "]"; });
            }
            apply_pose(m, in, name + ": " + w);
        }
    }
    const char* iname[2] = {"I1", "I2"};
    for (int i = 0; i < 2; ++i) {
        const JNode* n = root.find(iname[i]);
        if (!n) {  // no scaling: the objects as they are
            sc.lo[i] = sc.hi[i] = 1;
            continue;
        }
        if (n->kind != JNode::Array || n->items.size() != 2) r.fail(iname[i], "expected [lo, hi]");
        sc.lo[i] = r.number(n->items[0], std::string(iname[i]) + "[0]");
        sc.hi[i] = r.number(n->items[1], std::string(iname[i]) + "[1]");
    }
    finish_scene(sc, name);
    sc.inexact_numbers = *opt.inexact;
    sc.numbers = opt.numbers;
    return sc;
}

bool pose_singular(const Pose& m) {
    double d[3][3];
    for (size_t r = 0; r < 3; ++r)
        for (size_t c = 0; c < 3; ++c) d[r][c] = m[r][c].get_d();
    if (filter::pose_certainly_nonsingular(d)) return false;
    Z L = 1, a[3][3];
    for (size_t r = 0; r < 3; ++r)
        for (size_t c = 0; c < 3; ++c) lcm_into(L, m[r][c].get_den());
    for (size_t r = 0; r < 3; ++r)
        for (size_t c = 0; c < 3; ++c) a[r][c] = over(m[r][c], L);
    return sgn(Z(a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                 a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))) == 0;
}

void apply_pose(const Pose& m, PolyInput& in, const std::string& where) {
    if (pose_singular(m))
        throw InputError(where + ": its 3x3 part R is singular (determinant 0): the object would be flat");
    // A moved coordinate is a number the engine reads like any other: past the limit for one
    // number it is refused at the first vertex, before the work its size would cost.
    auto moved = [&m, &where](const Vec3q& v) {
        Vec3q out;
        for (size_t row = 0; row < 3; ++row) {
            out[row] = m[row][0] * v[0] + m[row][1] * v[1] + m[row][2] * v[2] + m[row][3];
            if (mpz_sizeinbase(out[row].get_num_mpz_t(), 2) > kMaxNumberBits ||
                mpz_sizeinbase(out[row].get_den_mpz_t(), 2) > kMaxNumberBits)
                throw InputError(where + ": a moved coordinate has more than " + std::to_string(kMaxNumberBits) +
                                 " bits in its numerator or denominator (the limit for one number)");
        }
        return out;
    };
    for (Vec3q& v : in.points) v = moved(v);
    for (auto& part : in.parts)
        for (Vec3q& v : part) v = moved(v);
    if (in.seed_given) in.seed = moved(in.seed);
}

std::vector<std::string> scene_notes(const ExactScene& sc) {
    std::vector<std::string> n;
    for (const PolyInput& p : sc.P)
        if (!p.note.empty()) n.push_back(p.note);
    if (sc.inexact_numbers > 0)
        n.push_back(std::to_string(sc.inexact_numbers) + (sc.inexact_numbers == 1 ? " number" : " numbers") +
                    " written as decimals " + (sc.inexact_numbers == 1 ? "is" : "are") + " not " +
                    (sc.numbers == Numbers::Float32 ? "a float32" : "a double") +
                    " exactly: read as the binary value a program reading " +
                    (sc.inexact_numbers == 1 ? "it" : "them") +
                    " holds (--numbers exact reads decimals as written; "
                    "a JSON string such as \"0.1\" is exact always)");
    for (size_t k = 0; k < sc.inexact_by_reading.size(); ++k)
        if (const long c = sc.inexact_by_reading[k]; c > 0)
            n.push_back(std::to_string(c) + (c == 1 ? " number" : " numbers") + " of objects whose \"numbers\" is \"" +
                        numbers_name(static_cast<Numbers>(k)) + "\" " + (c == 1 ? "is" : "are") + " not " +
                        (k == static_cast<size_t>(Numbers::Float32) ? "a float32" : "a double") +
                        " exactly: read as the binary value a program reading " + (c == 1 ? "it" : "them") + " holds");
    return n;
}

const std::string& part_name(const PolyInput& in, size_t k) {
    static const std::string none;
    return k < in.part_names.size() ? in.part_names[k] : none;
}

std::string part_name_suffix(const PolyInput& in, size_t k) {
    const std::string& n = part_name(in, k);
    return n.empty() ? "" : " (" + in_quotes(n) + ")";
}

std::string part_label(int i, const PolyInput& in, size_t k) {
    return "P" + std::to_string(i + 1) + ".parts[" + std::to_string(k) + "]" + part_name_suffix(in, k);
}

void check_scene(const ExactScene& sc, const std::string& name) {
    const char* pname[2] = {"P1", "P2"};
    const char* iname[2] = {"I1", "I2"};
    for (int i = 0; i < 2; ++i) {
        // A part with a radius > 0 may be one point (a sphere).
        for (size_t k = 0; k < sc.P[i].parts.size(); ++k)
            if (sc.P[i].parts[k].empty() || (sc.P[i].parts[k].size() < 4 && sgn(sc.P[i].part_radius(k)) <= 0))
                throw InputError(name + ": " + part_label(i, sc.P[i], k) + ": fewer than 4 vertices (" +
                                 std::to_string(sc.P[i].parts[k].size()) + ")" +
                                 (sc.P[i].parts[k].empty() ? "" : " and no radius > 0 (a part with one may have 1)"));
        const size_t n = sc.P[i].points.size();
        // With a radius > 0 one point will do (a sphere); without, the hull must have an interior.
        if (n < 1 || (n < 4 && !sc.P[i].has_radius()))
            throw InputError(
                name + ": " + pname[i] + ": fewer than 4 vertices (" + std::to_string(n) + ")" +
                (sc.P[i].radius_given && n > 0 ? " and no radius > 0 (an object with one may have 1)" : ""));
        if (n > kMaxPoints)
            throw InputError(name + ": " + pname[i] + ": more than " + std::to_string(kMaxPoints) +
                             " points (the limit)");
    }
    for (int i = 0; i < 2; ++i) {
        if (sgn(sc.lo[i]) <= 0)
            throw InputError(name + ": " + iname[i] + ": lo must be > 0 (got " + in_quotes(to_exact_string(sc.lo[i])) +
                             ")");
        if (sc.lo[i] > sc.hi[i]) throw InputError(name + ": " + iname[i] + ": lo > hi");
    }
}

void finish_scene(ExactScene& sc, const std::string& name) {
    check_scene(sc, name);
    for (PolyInput& in : sc.P) {
        if (in.seed_given) continue;
        // The mean, summed in integers while the coordinates are integers.
        Vec3q c{Q(0), Q(0), Q(0)};
        Z zs[3] = {0, 0, 0};
        for (const Vec3q& v : in.points)
            for (int k = 0; k < 3; ++k) {
                if (v[k].get_den() == 1)
                    zs[k] += v[k].get_num();
                else
                    c[k] += v[k];
            }
        for (int k = 0; k < 3; ++k) c[k] = (c[k] + Q(zs[k])) / Q(static_cast<long>(in.points.size()));
        in.seed = c;
    }
}

ExactScene load_scene(const std::string& path, const ReadOptions& opt) {
    std::string text = read_input(path, "scene file", kMaxSceneBytes);
    std::string dir;
    auto slash = path.rfind('/');
    if (slash != std::string::npos) dir = path.substr(0, slash);
    return parse_scene_text(text, path, dir.empty() ? "." : dir, opt);
}

}  // namespace scalecert::internal
