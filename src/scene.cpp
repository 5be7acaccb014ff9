#include "scalecert/scene.hpp"

#include "scalecert/mesh.hpp"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <unordered_set>

namespace scalecert::internal {
namespace {

// A JSON tree that keeps every number's text as written, so that 0.1 can be read as 1/10.
struct JNode {
    enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
    std::string text;         // number as written, or string value
    std::vector<JNode> items;  // array items, or object values
    std::vector<std::string> keys;
    const JNode* find(const std::string& k) const {
        for (size_t i = 0; i < keys.size(); ++i)
            if (keys[i] == k) return &items[i];
        return nullptr;
    }
};

// A strict RFC 8259 reader: no comments, no leading zeros, no bare keys, no trailing commas,
// UTF-8 only, duplicate keys rejected (a file must not mean two things), and at most kMaxDepth
// levels of nesting (scenes need 4), so neither the reader nor the tree's destructor can exhaust
// the stack, and at most kMaxJsonValues values, so the tree stays within about 1 GB. Throws
// JsonError with the byte offset.
constexpr int kMaxDepth = 64;
struct JsonError { size_t pos; std::string what; };

class StrictJson {
public:
    explicit StrictJson(const std::string& t) : s_(t) {}
    JNode parse() {
        JNode root;
        ws();
        value(root, 0);
        ws();
        if (i_ != s_.size()) unexpected("unexpected text after the JSON value");
        return root;
    }

private:
    const std::string& s_;
    size_t i_ = 0;
    size_t values_ = 0;
    [[noreturn]] void fail(const std::string& what) const { throw JsonError{i_, what}; }
    [[noreturn]] void unexpected(const std::string& what) const {
        fail(i_ < s_.size() && s_[i_] == '/' ? "comments are not JSON (RFC 8259)" : what);
    }
    void ws() {
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) ++i_;
    }
    bool eat(char c) {
        if (i_ < s_.size() && s_[i_] == c) { ++i_; return true; }
        return false;
    }
    void literal(const char* word) {
        for (const char* p = word; *p; ++p)
            if (!eat(*p)) fail("unexpected character");
    }
    bool digit() const { return i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9'; }
    void value(JNode& n, int depth) {
        if (i_ >= s_.size()) fail("unexpected end of the file");
        if (++values_ > kMaxJsonValues) fail("more than " + std::to_string(kMaxJsonValues) + " JSON values (the limit)");
        const char c = s_[i_];
        if (c == '{' || c == '[') {
            if (depth >= kMaxDepth) fail("nested deeper than " + std::to_string(kMaxDepth) + " levels");
            ++i_;
            n.kind = c == '{' ? JNode::Object : JNode::Array;
            const char close = c == '{' ? '}' : ']';
            ws();
            if (eat(close)) return;
            std::unordered_set<std::string> seen;  // the object's keys: duplicates found in O(1)
            for (;;) {
                ws();
                if (n.kind == JNode::Object) {
                    if (i_ >= s_.size() || s_[i_] != '"') unexpected("expected a string key");
                    const size_t at = i_;
                    std::string k = string();
                    if (!seen.insert(k).second) { i_ = at; fail("duplicate key " + quoted(k)); }
                    n.keys.push_back(std::move(k));
                    ws();
                    if (!eat(':')) fail("expected ':'");
                    ws();
                }
                n.items.emplace_back();
                value(n.items.back(), depth + 1);
                ws();
                if (eat(close)) return;
                if (!eat(',')) unexpected(std::string("expected ',' or '") + close + "'");
            }
        }
        if (c == '"') { n.kind = JNode::String; n.text = string(); return; }
        if (c == 't') { literal("true"); n.kind = JNode::Bool; return; }
        if (c == 'f') { literal("false"); n.kind = JNode::Bool; return; }
        if (c == 'n') { literal("null"); return; }
        if (c == '-' || (c >= '0' && c <= '9')) { n.kind = JNode::Number; n.text = number(); return; }
        unexpected("unexpected character");
    }
    // -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
    std::string number() {
        const size_t b = i_;
        eat('-');
        if (eat('0')) {
            if (digit()) fail("a number has a leading zero");
        } else if (digit()) {
            while (digit()) ++i_;
        } else {
            fail("malformed number");
        }
        if (eat('.')) {
            if (!digit()) fail("malformed number");
            while (digit()) ++i_;
        }
        if (eat('e') || eat('E')) {
            if (!eat('+')) eat('-');
            if (!digit()) fail("malformed number");
            while (digit()) ++i_;
        }
        return s_.substr(b, i_ - b);
    }
    unsigned hex4() {
        unsigned v = 0;
        for (int k = 0; k < 4; ++k, ++i_) {
            if (i_ >= s_.size() || !std::isxdigit(static_cast<unsigned char>(s_[i_]))) fail("malformed \\u escape");
            const char h = s_[i_];
            v = v * 16 + static_cast<unsigned>(h <= '9' ? h - '0' : (h | 0x20) - 'a' + 10);
        }
        return v;
    }
    static void utf8(std::string& out, unsigned cp) {
        if (cp < 0x80) out += static_cast<char>(cp);
        else if (cp < 0x800) { out += static_cast<char>(0xC0 | (cp >> 6)); out += static_cast<char>(0x80 | (cp & 0x3F)); }
        else if (cp < 0x10000) { out += static_cast<char>(0xE0 | (cp >> 12)); out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F)); out += static_cast<char>(0x80 | (cp & 0x3F)); }
        else { out += static_cast<char>(0xF0 | (cp >> 18)); out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F)); out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F)); out += static_cast<char>(0x80 | (cp & 0x3F)); }
    }
    // One UTF-8 sequence starting at i_ (well-formed, shortest form, no surrogates), copied.
    void utf8_sequence(std::string& out) {
        const unsigned char c = static_cast<unsigned char>(s_[i_]);
        const int n = c >= 0xC2 && c <= 0xDF ? 1 : c >= 0xE0 && c <= 0xEF ? 2 : c >= 0xF0 && c <= 0xF4 ? 3 : -1;
        if (n < 0 || i_ + static_cast<size_t>(n) >= s_.size()) fail("invalid UTF-8");
        unsigned cp = c & (0x3F >> n);
        for (int k = 1; k <= n; ++k) {
            const unsigned char d = static_cast<unsigned char>(s_[i_ + static_cast<size_t>(k)]);
            if ((d & 0xC0) != 0x80) fail("invalid UTF-8");
            cp = cp << 6 | (d & 0x3F);
        }
        if ((n == 2 && cp < 0x800) || (n == 3 && (cp < 0x10000 || cp > 0x10FFFF)) || (cp >= 0xD800 && cp <= 0xDFFF)) fail("invalid UTF-8");
        out.append(s_, i_, static_cast<size_t>(n) + 1);
        i_ += static_cast<size_t>(n) + 1;
    }
    std::string string() {
        ++i_;  // the opening quote
        std::string out;
        for (;;) {
            if (i_ >= s_.size()) fail("unterminated string");
            const unsigned char c = static_cast<unsigned char>(s_[i_]);
            if (c == '"') { ++i_; return out; }
            if (c < 0x20) fail("control character in a string");
            if (c >= 0x80) { utf8_sequence(out); continue; }
            if (c != '\\') { out += static_cast<char>(c); ++i_; continue; }
            if (++i_ >= s_.size()) fail("unterminated string");
            const char e = s_[i_++];
            switch (e) {
                case '"': out += '"'; break;
                case '\\': out += '\\'; break;
                case '/': out += '/'; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'n': out += '\n'; break;
                case 'r': out += '\r'; break;
                case 't': out += '\t'; break;
                case 'u': {
                    unsigned cp = hex4();
                    if (cp >= 0xDC00 && cp <= 0xDFFF) fail("unpaired surrogate in a \\u escape");
                    if (cp >= 0xD800 && cp <= 0xDBFF) {
                        if (!eat('\\') || !eat('u')) fail("unpaired surrogate in a \\u escape");
                        unsigned lo = hex4();
                        if (lo < 0xDC00 || lo > 0xDFFF) fail("unpaired surrogate in a \\u escape");
                        cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                    }
                    utf8(out, cp);
                    break;
                }
                default: --i_; fail("invalid escape in a string");
            }
        }
    }
};

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
    static std::string text_of(const F& w) { return w(); }
    template <class W>
    Q number_text(const std::string& text, bool is_string, const W& where) const {
        try {
            return parse_number(text, opt.binary_doubles && !is_string);
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


Scene parse_scene_text(const std::string& text, const std::string& name, const std::string& base_dir,
                       const ReadOptions& opt) {
    Reader r{name, opt};
    JNode tree;
    try {
        tree = StrictJson(text).parse();
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
            if (!ok) r.fail(where, "unknown field " + quoted(k) + " (expected " + [&] {
                std::string l;
                for (const char* n : known) l += (l.empty() ? "" : ", ") + std::string(n);
                return l;
            }() + ")");
        }
    };
    only(root, "", {"P1", "P2", "I1", "I2"});
    Scene sc;
    const char* pname[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        const JNode* p = root.find(pname[i]);
        if (!p) r.fail("", std::string("missing field \"") + pname[i] + "\"");
        if (p->kind != JNode::Object) r.fail(pname[i], "expected an object with \"vertices\" or \"off\"");
        only(*p, pname[i], {"vertices", "off", "mesh", "seed"});
        PolyInput& in = sc.P[i];
        const JNode* verts = p->find("vertices");
        const JNode* off = p->find("off");
        const JNode* mesh = p->find("mesh");
        if ((verts != nullptr) + (off != nullptr) + (mesh != nullptr) > 1) r.fail(pname[i], "give one of \"vertices\", \"mesh\" and \"off\"");
        if (mesh) off = mesh;
        if (verts) {
            if (verts->kind != JNode::Array) r.fail(std::string(pname[i]) + ".vertices", "expected an array of points");
            if (verts->items.size() > kMaxPoints) r.fail(std::string(pname[i]) + ".vertices", "more than " + std::to_string(kMaxPoints) + " points (the limit)");
            in.points.reserve(verts->items.size());
            for (size_t j = 0; j < verts->items.size(); ++j)
                in.points.push_back(r.point(verts->items[j], [&] { return std::string(pname[i]) + ".vertices[" + std::to_string(j) + "]"; }));
        } else if (off) {
            const std::string key = std::string(pname[i]) + (mesh ? ".mesh" : ".off");
            if (off->kind != JNode::String) r.fail(key, "expected a file name");
            if (!opt.allow_off_files) r.fail(key, "mesh files are not read here");
            std::string path = off->text;
            if (!path.empty() && path[0] != '/' && !base_dir.empty()) path = base_dir + "/" + path;
            // "mesh": OFF, OBJ, PLY or STL by extension; "off": an OFF file whatever its name.
            in.points = mesh ? read_mesh(path, opt) : parse_mesh(read_input(path, "OFF file", kMaxSceneBytes), MeshFormat::Off, path, opt);
        } else {
            r.fail(pname[i], "missing field \"vertices\" (or \"mesh\", \"off\")");
        }
        if (const JNode* s = p->find("seed")) {
            in.seed = r.point(*s, std::string(pname[i]) + ".seed");
            in.seed_given = true;
        }
    }
    const char* iname[2] = {"I1", "I2"};
    for (int i = 0; i < 2; ++i) {
        const JNode* n = root.find(iname[i]);
        if (!n) r.fail("", std::string("missing field \"") + iname[i] + "\"");
        if (n->kind != JNode::Array || n->items.size() != 2) r.fail(iname[i], "expected [lo, hi]");
        sc.lo[i] = r.number(n->items[0], std::string(iname[i]) + "[0]");
        sc.hi[i] = r.number(n->items[1], std::string(iname[i]) + "[1]");
    }
    finish_scene(sc, name);
    return sc;
}

void check_scene(const Scene& sc, const std::string& name) {
    const char* pname[2] = {"P1", "P2"};
    const char* iname[2] = {"I1", "I2"};
    for (int i = 0; i < 2; ++i) {
        const size_t n = sc.P[i].points.size();
        if (n < 4) throw InputError(name + ": " + pname[i] + ": fewer than 4 vertices (" + std::to_string(n) + ")");
        if (n > kMaxPoints) throw InputError(name + ": " + pname[i] + ": more than " + std::to_string(kMaxPoints) + " points (the limit)");
    }
    for (int i = 0; i < 2; ++i) {
        if (sgn(sc.lo[i]) <= 0) throw InputError(name + ": " + iname[i] + ": lo must be > 0 (got " + quoted(to_exact_string(sc.lo[i])) + ")");
        if (sc.lo[i] > sc.hi[i]) throw InputError(name + ": " + iname[i] + ": lo > hi");
    }
}

void finish_scene(Scene& sc, const std::string& name) {
    check_scene(sc, name);
    for (PolyInput& in : sc.P) {
        if (in.seed_given) continue;
        // The mean, summed in integers while the coordinates are integers.
        Vec3q c{Q(0), Q(0), Q(0)};
        Z zs[3] = {0, 0, 0};
        for (const Vec3q& v : in.points)
            for (int k = 0; k < 3; ++k) {
                if (v[k].get_den() == 1) zs[k] += v[k].get_num();
                else c[k] += v[k];
            }
        for (int k = 0; k < 3; ++k) c[k] = (c[k] + Q(zs[k])) / Q(static_cast<long>(in.points.size()));
        in.seed = c;
    }
}

Scene load_scene(const std::string& path, const ReadOptions& opt) {
    std::string text = read_input(path, "scene file", kMaxSceneBytes);
    std::string dir;
    auto slash = path.rfind('/');
    if (slash != std::string::npos) dir = path.substr(0, slash);
    return parse_scene_text(text, path, dir.empty() ? "." : dir, opt);
}

}  // namespace scalecert::internal
