#include "io/mesh.hpp"
#include "io/strict_json.hpp"
#include "io/files.hpp"
#include "numeric/small_int.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>

namespace scalecert::internal {

namespace {
[[noreturn]] void fail(const std::string& name, const std::string& what) { throw InputError(name + ": " + what); }

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// A number written as text, as opt.numbers reads it (counted in opt.inexact when not as written).
Q text_number(const std::string& t, const std::string& name, const ReadOptions& opt, size_t vertex, int coord) {
    try {
        return parse_number(t, opt.numbers, opt.inexact);
    } catch (const InputError& e) {
        fail(name, "vertex " + std::to_string(vertex) + " coordinate " + std::to_string(coord) + ": " + e.what());
    }
}
Q binary_number(double v, const std::string& name, size_t vertex, int coord) {
    if (!std::isfinite(v))
        fail(name, "vertex " + std::to_string(vertex) + " coordinate " + std::to_string(coord) + ": not finite");
    return exact_from_double(v);
}

// Whitespace-separated tokens of each line, '#' comments removed (OFF, OBJ, ASCII STL).
template <class F>
void each_line(const std::string& text, F&& f) {
    size_t b = 0, no = 0;
    std::vector<std::string> tokens;
    while (b <= text.size()) {
        size_t e = text.find('\n', b);
        if (e == std::string::npos) e = text.size();
        ++no;
        tokens.clear();
        size_t i = b;
        while (i < e && text[i] != '#') {
            while (i < e && text[i] != '#' && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
            size_t s = i;
            while (i < e && text[i] != '#' && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
            if (i > s) tokens.emplace_back(text, s, i - s);
        }
        if (!tokens.empty() && !f(tokens, no)) return;
        b = e + 1;
    }
}

std::vector<Vec3q> parse_off(const std::string& text, const std::string& name, const ReadOptions& opt) {
    std::vector<std::string> tokens;
    each_line(text, [&](const std::vector<std::string>& t, size_t) {
        tokens.insert(tokens.end(), t.begin(), t.end());
        return true;
    });
    if (tokens.empty() || tokens[0] != "OFF") fail(name, "malformed OFF file: it does not start with OFF");
    auto count = [&](size_t i, const char* what) -> size_t {
        if (i >= tokens.size()) fail(name, std::string("malformed OFF file: missing ") + what);
        const std::string& t = tokens[i];
        if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos)
            fail(name, std::string("malformed OFF file: bad ") + what + " " + in_quotes(t));
        return std::stoul(t);
    };
    const size_t nv = count(1, "vertex count");
    if (nv > kMaxPoints) fail(name, "more than " + std::to_string(kMaxPoints) + " vertices (the limit)");
    count(2, "face count");
    count(3, "edge count");
    if (tokens.size() < 4 + 3 * nv)
        fail(name, "malformed OFF file: fewer than the " + std::to_string(nv) + " vertices announced");
    std::vector<Vec3q> pts(nv);
    for (size_t i = 0; i < nv; ++i)
        for (int k = 0; k < 3; ++k) pts[i][k] = text_number(tokens[4 + 3 * i + k], name, opt, i, k);
    return pts;
}

// OBJ: "v x y z [w]" lines (w ≠ 1 divides: homogeneous coordinates); everything else ignored.
std::vector<Vec3q> parse_obj(const std::string& text, const std::string& name, const ReadOptions& opt) {
    std::vector<Vec3q> pts;
    each_line(text, [&](const std::vector<std::string>& t, size_t no) {
        if (t[0] != "v") return true;
        // 'v x y z', 'v x y z w' (homogeneous) or 'v x y z r g b' (with a colour, ignored)
        if (t.size() != 4 && t.size() != 5 && t.size() != 7)
            fail(name, "line " + std::to_string(no) + ": expected 'v x y z', 'v x y z w' or 'v x y z r g b'");
        if (pts.size() >= kMaxPoints) fail(name, "more than " + std::to_string(kMaxPoints) + " vertices (the limit)");
        Vec3q v{text_number(t[1], name, opt, pts.size(), 0), text_number(t[2], name, opt, pts.size(), 1),
                text_number(t[3], name, opt, pts.size(), 2)};
        if (t.size() == 5) {
            Q w = text_number(t[4], name, opt, pts.size(), 3);
            if (sgn(w) == 0) fail(name, "line " + std::to_string(no) + ": w = 0 (a point at infinity)");
            for (Q& c : v) c /= w;
        }
        pts.push_back(std::move(v));
        return true;
    });
    if (pts.empty()) fail(name, "malformed OBJ file: no 'v' lines");
    return pts;
}

// OBJ groups as parts (mesh.hpp): the vertices first, read and checked as parse_obj reads them,
// then the 'o', 'g' and 'f' lines.
std::vector<std::vector<Vec3q>> parse_obj_groups(const std::string& text, const std::string& name,
                                                 const ReadOptions& opt, std::vector<std::string>& names) {
    const std::vector<Vec3q> pts = parse_obj(text, name, opt);
    std::vector<std::vector<Vec3q>> parts;
    names.clear();
    std::map<std::string, size_t> named;      // each group name with faces, and its line
    std::vector<size_t> last(pts.size(), 0);  // the last group (counted from 1) whose faces named each vertex
    std::vector<size_t> members;              // the vertices of the group being read
    size_t group = 1, group_line = 0, vertices_so_far = 0, total = 0;
    std::string group_name;
    auto label = [&] {
        return group_line == 0 ? std::string("the faces before any 'o' or 'g' line")
                               : "group " + in_quotes(group_name) + " (line " + std::to_string(group_line) + ")";
    };
    auto close = [&] {
        if (members.empty()) return;  // a group without faces
        if (parts.size() == kMaxParts)
            fail(name, "more than " + std::to_string(kMaxParts) + " groups with faces (the limit on parts)");
        total += members.size();
        if (total > kMaxPoints)
            fail(name, "more than " + std::to_string(kMaxPoints) + " points in all the groups (the limit)");
        std::sort(members.begin(), members.end());
        std::vector<Vec3q> part;
        part.reserve(members.size());
        for (size_t v : members) part.push_back(pts[v]);
        if (!affinely_3d(part))
            fail(name, label() + ": flat: the " + std::to_string(part.size()) +
                           " vertices of its faces span fewer than 3 dimensions (a part must be a solid)");
        // The group's name names its part: two parts of one name would name neither.
        if (!group_name.empty())
            if (const auto [at, fresh] = named.emplace(group_name, group_line); !fresh)
                fail(name, label() + ": the name of the group on line " + std::to_string(at->second) +
                               " too (a part per group: each group with faces needs its own name)");
        parts.push_back(std::move(part));
        names.push_back(group_name);
        members.clear();
    };
    each_line(text, [&](const std::vector<std::string>& t, size_t no) {
        if (t[0] == "v") {
            ++vertices_so_far;
        } else if (t[0] == "o" || t[0] == "g") {
            close();
            ++group;
            group_line = no;
            group_name.clear();
            for (size_t k = 1; k < t.size(); ++k) group_name += (k > 1 ? " " : "") + t[k];
            // A name is written into JSON documents and messages, so it must be text.
            if (!is_utf8(group_name)) fail(name, "line " + std::to_string(no) + ": the group's name is not UTF-8 text");
        } else if (t[0] == "f") {
            if (t.size() < 4) fail(name, "line " + std::to_string(no) + ": expected 'f' and at least 3 vertices");
            for (size_t k = 1; k < t.size(); ++k) {
                // 'v', 'v/vt', 'v//vn' or 'v/vt/vn': v counts from 1, or back from -1 (the last vertex so far).
                const std::string v = t[k].substr(0, t[k].find('/'));
                long long i = 0;
                const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), i);
                const bool number = ec == std::errc() && end == v.data() + v.size() && !v.empty();
                const long long n = static_cast<long long>(number && i < 0 ? vertices_so_far : pts.size());
                if (!number || i == 0 || i > n || i < -n)
                    fail(name, "line " + std::to_string(no) + ": face vertex " + in_quotes(t[k]) +
                                   " is not a vertex number (1 to " + std::to_string(pts.size()) + ", or -1 back to -" +
                                   std::to_string(vertices_so_far) + ")");
                const size_t at = static_cast<size_t>(i > 0 ? i - 1 : n + i);
                if (last[at] != group) {
                    last[at] = group;
                    members.push_back(at);
                }
            }
        }
        return true;
    });
    close();
    return parts;  // none when the file has no faces
}

// Vertices in order of first appearance, each once (STL writes every vertex in each triangle).
std::vector<Vec3q> unique_in_order(std::vector<Vec3q> raw, const std::string& name) {
    std::vector<size_t> order(raw.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return raw[a] < raw[b]; });
    std::vector<char> keep(raw.size(), 0);
    for (size_t k = 0; k < order.size(); ++k)
        if (k == 0 || raw[order[k]] != raw[order[k - 1]]) keep[order[k]] = 1;
    std::vector<Vec3q> out;
    for (size_t i = 0; i < raw.size(); ++i)
        if (keep[i]) out.push_back(std::move(raw[i]));
    if (out.size() > kMaxPoints)
        fail(name, "more than " + std::to_string(kMaxPoints) + " distinct vertices (the limit)");
    return out;
}

template <class T>
T load(const std::string& bytes, size_t at, bool big_endian) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, bytes.data() + at, sizeof(T));
    if (big_endian) std::reverse(b, b + sizeof(T));  // x86-64 is little-endian
    T v;
    std::memcpy(&v, b, sizeof(T));
    return v;
}

// STL: binary when the size is 84 + 50·(the count at byte 80), else ASCII ("vertex x y z").
constexpr size_t kMaxStlTriangles = 3 * kMaxPoints;
std::vector<Vec3q> parse_stl(const std::string& bytes, const std::string& name, const ReadOptions& opt) {
    std::vector<Vec3q> raw;
    if (bytes.size() >= 84) {
        const std::uint32_t n = load<std::uint32_t>(bytes, 80, false);
        if (bytes.size() == 84 + 50 * static_cast<std::uint64_t>(n)) {
            if (n > kMaxStlTriangles)
                fail(name, "more than " + std::to_string(kMaxStlTriangles) + " triangles (the limit)");
            raw.reserve(3 * static_cast<size_t>(n));
            for (size_t t = 0; t < n; ++t)
                for (int c = 0; c < 3; ++c) {
                    const size_t at = 84 + 50 * t + 12 + 12 * static_cast<size_t>(c);
                    Vec3q v;
                    for (int k = 0; k < 3; ++k)
                        v[k] = binary_number(load<float>(bytes, at + 4 * static_cast<size_t>(k), false), name,
                                             raw.size(), k);
                    raw.push_back(std::move(v));
                }
            if (raw.empty()) fail(name, "binary STL file with no triangles");
            return unique_in_order(std::move(raw), name);
        }
    }
    const size_t start = bytes.find_first_not_of(" \t\r\n");
    if (start == std::string::npos || lower(bytes.substr(start, 5)) != "solid")
        fail(name, "malformed STL file: neither binary (84 + 50 bytes a triangle) nor ASCII ('solid')");
    each_line(bytes, [&](const std::vector<std::string>& t, size_t no) {
        if (lower(t[0]) != "vertex") return true;
        if (t.size() != 4) fail(name, "line " + std::to_string(no) + ": expected 'vertex x y z'");
        if (raw.size() >= 3 * kMaxStlTriangles)
            fail(name, "more than " + std::to_string(kMaxStlTriangles) + " triangles (the limit)");
        raw.push_back({text_number(t[1], name, opt, raw.size(), 0), text_number(t[2], name, opt, raw.size(), 1),
                       text_number(t[3], name, opt, raw.size(), 2)});
        return true;
    });
    if (raw.empty()) fail(name, "malformed STL file: no 'vertex' lines");
    return unique_in_order(std::move(raw), name);
}

// PLY: the header's elements in order; the vertex element's x, y, z. Other elements before it are
// skipped (their list properties read for their sizes in binary files).
struct PlyProperty {
    std::string name, type, count_type;  // count_type: a list's count type, else empty
};
struct PlyElement {
    std::string name;
    size_t count = 0;
    std::vector<PlyProperty> props;
};
size_t ply_size(const std::string& type) {
    static const std::map<std::string, size_t> sizes = {{"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},
                                                        {"short", 2}, {"ushort", 2},  {"int16", 2},  {"uint16", 2},
                                                        {"int", 4},   {"uint", 4},    {"int32", 4},  {"uint32", 4},
                                                        {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
    auto it = sizes.find(type);
    return it == sizes.end() ? 0 : it->second;
}
// A binary PLY value at `at` as an exact rational (integers exactly, floats at their value).
Q ply_value(const std::string& bytes, size_t at, const std::string& type, bool be, bool& finite) {
    finite = true;
    if (type == "char" || type == "int8") return Q(load<std::int8_t>(bytes, at, be));
    if (type == "uchar" || type == "uint8") return Q(load<std::uint8_t>(bytes, at, be));
    if (type == "short" || type == "int16") return Q(load<std::int16_t>(bytes, at, be));
    if (type == "ushort" || type == "uint16") return Q(load<std::uint16_t>(bytes, at, be));
    if (type == "int" || type == "int32") return Q(static_cast<long>(load<std::int32_t>(bytes, at, be)));
    if (type == "uint" || type == "uint32") return Q(static_cast<unsigned long>(load<std::uint32_t>(bytes, at, be)));
    const double d = type == "float" || type == "float32" ? static_cast<double>(load<float>(bytes, at, be))
                                                          : load<double>(bytes, at, be);
    finite = std::isfinite(d);
    return finite ? exact_from_double(d) : Q(0);
}

std::vector<Vec3q> parse_ply(const std::string& bytes, const std::string& name, const ReadOptions& opt) {
    // The header: lines up to "end_header".
    size_t pos = 0, no = 0;
    std::string format;
    std::vector<PlyElement> elements;
    bool ended = false;
    while (!ended) {
        size_t e = bytes.find('\n', pos);
        if (e == std::string::npos) fail(name, "malformed PLY file: no end_header line");
        std::string line = bytes.substr(pos, e - pos);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        pos = e + 1;
        ++no;
        std::istringstream ls(line);
        std::vector<std::string> t;
        for (std::string w; ls >> w;) t.push_back(w);
        const std::string where = "line " + std::to_string(no) + ": ";
        if (no == 1) {
            if (t.size() != 1 || t[0] != "ply") fail(name, "malformed PLY file: it does not start with 'ply'");
            continue;
        }
        if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
        if (t[0] == "format") {
            if (t.size() != 3 || (t[1] != "ascii" && t[1] != "binary_little_endian" && t[1] != "binary_big_endian") ||
                t[2] != "1.0")
                fail(name, where + "unknown PLY format " + in_quotes(line));
            format = t[1];
        } else if (t[0] == "element") {
            if (t.size() != 3 || t[2].empty() || t[2].size() > 12 ||
                t[2].find_first_not_of("0123456789") != std::string::npos)
                fail(name, where + "expected 'element NAME COUNT'");
            elements.push_back({t[1], std::stoull(t[2]), {}});
        } else if (t[0] == "property") {
            if (elements.empty()) fail(name, where + "a property before any element");
            if (t.size() == 3 && ply_size(t[1]))
                elements.back().props.push_back({t[2], t[1], ""});
            else if (t.size() == 5 && t[1] == "list" && ply_size(t[2]) && ply_size(t[3]) &&
                     t[2].find("float") == std::string::npos && t[2] != "double")
                elements.back().props.push_back({t[4], t[3], t[2]});
            else
                fail(name, where + "malformed property " + in_quotes(line));
        } else if (t[0] == "end_header") {
            ended = true;
        } else {
            fail(name, where + "unknown header line " + in_quotes(line));
        }
    }
    if (format.empty()) fail(name, "malformed PLY file: no format line");
    const bool ascii = format == "ascii", be = format == "binary_big_endian";
    // Where x, y, z are in the vertex element.
    size_t which = elements.size();
    int coord[3] = {-1, -1, -1};
    for (size_t k = 0; k < elements.size() && which == elements.size(); ++k)
        if (elements[k].name == "vertex") which = k;
    if (which == elements.size()) fail(name, "malformed PLY file: no vertex element");
    const PlyElement& ve = elements[which];
    for (size_t p = 0; p < ve.props.size(); ++p)
        for (int c = 0; c < 3; ++c)
            if (ve.props[p].name == std::string(1, static_cast<char>('x' + c))) {
                if (!ve.props[p].count_type.empty())
                    fail(name, "malformed PLY file: vertex property " + ve.props[p].name + " is a list");
                coord[c] = static_cast<int>(p);
            }
    if (coord[0] < 0 || coord[1] < 0 || coord[2] < 0)
        fail(name, "malformed PLY file: the vertex element lacks x, y or z");
    if (ve.count > kMaxPoints) fail(name, "more than " + std::to_string(kMaxPoints) + " vertices (the limit)");
    std::vector<Vec3q> pts;
    pts.reserve(ve.count);
    if (ascii) {
        // One line per element instance; the elements before the vertex element are skipped.
        size_t skip = 0;
        for (size_t k = 0; k < which; ++k) skip += elements[k].count;
        size_t line_no = no;
        each_line(bytes.substr(pos), [&](const std::vector<std::string>& t, size_t) {
            ++line_no;
            if (skip > 0) {
                --skip;
                return true;
            }
            if (pts.size() == ve.count) return false;
            // Lists in the vertex element: a count, then that many values.
            std::vector<std::string> v;
            size_t i = 0;
            for (const PlyProperty& p : ve.props) {
                if (i >= t.size())
                    fail(name, "line " + std::to_string(line_no) + ": fewer values than the vertex properties");
                if (p.count_type.empty()) {
                    v.push_back(t[i++]);
                    continue;
                }
                const std::string& c = t[i++];
                if (c.empty() || c.size() > 6 || c.find_first_not_of("0123456789") != std::string::npos)
                    fail(name, "line " + std::to_string(line_no) + ": bad list count " + in_quotes(c));
                i += std::stoul(c);
                v.push_back("");
            }
            if (i > t.size())
                fail(name, "line " + std::to_string(line_no) + ": fewer values than the vertex properties");
            if (i < t.size())
                fail(name, "line " + std::to_string(line_no) + ": more values than the vertex properties");
            pts.push_back({text_number(v[static_cast<size_t>(coord[0])], name, opt, pts.size(), 0),
                           text_number(v[static_cast<size_t>(coord[1])], name, opt, pts.size(), 1),
                           text_number(v[static_cast<size_t>(coord[2])], name, opt, pts.size(), 2)});
            return true;
        });
    } else {
        size_t at = pos;
        auto need = [&](size_t n) {
            if (n > bytes.size() || at > bytes.size() - n) fail(name, "malformed PLY file: the data ends early");
        };
        for (size_t k = 0; k <= which; ++k) {
            const PlyElement& el = elements[k];
            if (el.props.empty()) continue;          // instances of no bytes: nothing to read
            for (size_t i = 0; i < el.count; ++i) {  // each reads at least one byte: at most the file's size
                Vec3q v;
                for (size_t p = 0; p < el.props.size(); ++p) {
                    const PlyProperty& pr = el.props[p];
                    if (!pr.count_type.empty()) {
                        need(ply_size(pr.count_type));
                        bool fin;
                        Q c = ply_value(bytes, at, pr.count_type, be, fin);
                        at += ply_size(pr.count_type);
                        if (sgn(c) < 0 || c > 1000000) fail(name, "malformed PLY file: a list count out of range");
                        const size_t n = static_cast<size_t>(c.get_num().get_ui()) * ply_size(pr.type);
                        need(n);
                        at += n;
                        continue;
                    }
                    need(ply_size(pr.type));
                    if (k == which)
                        for (int c = 0; c < 3; ++c)
                            if (coord[c] == static_cast<int>(p)) {
                                bool fin;
                                v[c] = ply_value(bytes, at, pr.type, be, fin);
                                if (!fin)
                                    fail(name, "vertex " + std::to_string(i) + " coordinate " + std::to_string(c) +
                                                   ": not finite");
                            }
                    at += ply_size(pr.type);
                }
                if (k == which) pts.push_back(std::move(v));
            }
            if (k < which && at > bytes.size()) fail(name, "malformed PLY file: the data ends early");
        }
    }
    if (pts.size() != ve.count)
        fail(name, "malformed PLY file: fewer than the " + std::to_string(ve.count) + " vertices announced");
    return pts;
}
}  // namespace

MeshFormat mesh_format_of(const std::string& path) {
    const auto dot = path.rfind('.');
    const std::string ext = dot == std::string::npos ? "" : lower(path.substr(dot + 1));
    if (ext == "off") return MeshFormat::Off;
    if (ext == "obj") return MeshFormat::Obj;
    if (ext == "ply") return MeshFormat::Ply;
    if (ext == "stl") return MeshFormat::Stl;
    throw InputError(path + ": unknown mesh format (expected .off, .obj, .ply or .stl)");
}

std::vector<Vec3q> parse_mesh(const std::string& bytes, MeshFormat f, const std::string& name, const ReadOptions& opt) {
    switch (f) {
    case MeshFormat::Off: return parse_off(bytes, name, opt);
    case MeshFormat::Obj: return parse_obj(bytes, name, opt);
    case MeshFormat::Ply: return parse_ply(bytes, name, opt);
    case MeshFormat::Stl: return parse_stl(bytes, name, opt);
    }
    throw InputError(name + ": unknown mesh format");
}

namespace {
// The 'o' and 'g' groups of an OBJ text that have faces (the faces before the first such line
// count as one), its lines read as parse_obj_groups reads them (a bare 'g' starts a group too).
size_t obj_groups_with_faces(const std::string& text) {
    size_t groups = 0;
    bool faces = false;
    each_line(text, [&](const std::vector<std::string>& t, size_t) {
        if (t[0] == "f") faces = true;
        if (t[0] == "o" || t[0] == "g") groups += faces, faces = false;
        return true;
    });
    return groups + faces;
}
}  // namespace

std::vector<Vec3q> read_mesh(const std::string& path, const ReadOptions& opt, std::string* note, bool part) {
    const MeshFormat f = mesh_format_of(path);
    const std::string bytes = read_input(path, "mesh file", kMaxSceneBytes);
    std::vector<Vec3q> pts = parse_mesh(bytes, f, path, opt);
    if (note && f == MeshFormat::Obj)
        if (const size_t g = obj_groups_with_faces(bytes); g >= 2)
            *note = path + ": " + std::to_string(g) + " groups with faces, read as one convex " +
                    (part ? "part (the hull of all its vertices); a part's mesh is one part: give each group a part "
                            "of its own, or read the file as the object's \"mesh\" with \"parts_from_groups\""
                          : "object (the hull of all its vertices); --parts-from-groups (the scene key "
                            "\"parts_from_groups\", from_meshes(..., parts_from_groups=true)) reads a convex part "
                            "per group");
    return pts;
}

std::vector<std::vector<Vec3q>> read_obj_groups(const std::string& path, const ReadOptions& opt,
                                                std::vector<std::string>* names) {
    const MeshFormat f = mesh_format_of(path);
    if (f != MeshFormat::Obj) {
        static const char* kind[] = {"an OFF", "an OBJ", "a PLY", "an STL"};
        throw InputError(path + ": parts from groups need an OBJ file (" + kind[static_cast<int>(f)] +
                         " file has no groups)");
    }
    std::vector<std::string> own;
    return parse_obj_groups(read_input(path, "mesh file", kMaxSceneBytes), path, opt, names ? *names : own);
}

void read_mesh_object(const std::string& path, const ReadOptions& opt, PolyInput& in) {
    if (!opt.parts_from_groups || mesh_format_of(path) != MeshFormat::Obj) {
        in.points = read_mesh(path, opt, &in.note);
        return;
    }
    in.parts = read_obj_groups(path, opt, &in.part_names);
    if (in.parts.empty()) {  // vertices only: no group has a face, and the file is one convex object
        in.part_names.clear();
        in.points = read_mesh(path, opt, &in.note);
        return;
    }
    if (std::all_of(in.part_names.begin(), in.part_names.end(), [](const std::string& n) { return n.empty(); }))
        in.part_names.clear();
    in.points.clear();
    for (const auto& part : in.parts) in.points.insert(in.points.end(), part.begin(), part.end());
}

}  // namespace scalecert::internal
