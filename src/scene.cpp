#include "scalecert/scene.hpp"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

namespace scalecert {
namespace {

// A JSON tree that keeps every number's text as written, so that 0.1 can be read as 1/10.
struct JNode {
    enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
    std::string text;         // number as written, or string value
    bool integer_token = false;
    std::vector<JNode> items;  // array items, or object values
    std::vector<std::string> keys;
    const JNode* find(const std::string& k) const {
        for (size_t i = 0; i < keys.size(); ++i)
            if (keys[i] == k) return &items[i];
        return nullptr;
    }
};

// nlohmann's lexer turns number tokens into doubles (and rejects 1e999 as an overflow), so every
// number token outside strings is first wrapped as a string carrying a marker; the tree builder
// turns it back into a number with its text intact. `map` records (new offset, old offset) pairs
// so that error positions still name bytes of the user's file.
const std::string kNumMark = "\\u0000#";  // JSON escape for NUL, then '#'
const std::string kNumMarkDecoded = std::string(1, '\0') + "#";

std::string quote_numbers(const std::string& in, std::vector<std::pair<size_t, size_t>>& map) {
    std::string out;
    out.reserve(in.size() + in.size() / 4);
    bool in_str = false;
    for (size_t i = 0; i < in.size(); ++i) {
        char c = in[i];
        if (in_str) {
            out += c;
            if (c == '\\' && i + 1 < in.size()) out += in[++i];
            else if (c == '"') in_str = false;
            continue;
        }
        if (c == '"') { in_str = true; out += c; continue; }
        if (c == '-' || (c >= '0' && c <= '9')) {
            size_t j = i;
            while (j < in.size() && (std::isdigit(static_cast<unsigned char>(in[j])) || std::strchr("+-.eE", in[j]))) ++j;
            out += '"' + kNumMark + in.substr(i, j - i) + '"';
            map.push_back({out.size(), j});
            i = j - 1;
            continue;
        }
        out += c;
    }
    return out;
}

size_t original_position(size_t pos, const std::vector<std::pair<size_t, size_t>>& map) {
    size_t shift_new = 0, shift_old = 0;
    for (const auto& [n, o] : map) {
        if (n > pos) break;
        shift_new = n;
        shift_old = o;
    }
    return shift_old + (pos - shift_new);
}

class TreeBuilder : public nlohmann::json_sax<nlohmann::json> {
public:
    JNode root;
    size_t error_pos = 0;
    bool null() override { return put(JNode{}); }
    bool boolean(bool) override { JNode n; n.kind = JNode::Bool; return put(std::move(n)); }
    bool number_integer(number_integer_t v) override { return num(std::to_string(v), true); }
    bool number_unsigned(number_unsigned_t v) override { return num(std::to_string(v), true); }
    bool number_float(number_float_t, const string_t& s) override { return num(s, false); }
    bool string(string_t& s) override {
        if (s.compare(0, kNumMarkDecoded.size(), kNumMarkDecoded) == 0) {
            std::string t = s.substr(kNumMarkDecoded.size());
            return num(t, t.find_first_of(".eE") == std::string::npos);
        }
        JNode n; n.kind = JNode::String; n.text = s; return put(std::move(n));
    }
    bool binary(binary_t&) override { return false; }
    bool start_object(std::size_t) override { return open(JNode::Object); }
    bool key(string_t& k) override { stack_.back()->keys.push_back(k); return true; }
    bool end_object() override { stack_.pop_back(); return true; }
    bool start_array(std::size_t) override { return open(JNode::Array); }
    bool end_array() override { stack_.pop_back(); return true; }
    bool parse_error(std::size_t pos, const std::string&, const nlohmann::detail::exception&) override {
        error_pos = pos;
        return false;
    }

private:
    std::vector<JNode*> stack_;
    bool started_ = false;
    bool num(const std::string& s, bool integer) {
        JNode n; n.kind = JNode::Number; n.text = s; n.integer_token = integer;
        return put(std::move(n));
    }
    bool put(JNode n) {
        if (stack_.empty()) { root = std::move(n); started_ = true; return true; }
        stack_.back()->items.push_back(std::move(n));
        return true;
    }
    bool open(JNode::Kind k) {
        JNode n; n.kind = k;
        if (stack_.empty()) { root = std::move(n); stack_.push_back(&root); return true; }
        stack_.back()->items.push_back(std::move(n));
        stack_.push_back(&stack_.back()->items.back());
        return true;
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

std::string read_file(const std::string& path, const std::string& what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open " + what);
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw InputError(path + ": cannot read " + what);
    return ss.str();
}

// OFF: "OFF" header (optionally with counts on the same line), "nv nf ne", nv vertex lines.
// Faces are not needed: the polyhedron is the convex hull of the vertices.
std::vector<Vec3q> read_off(const std::string& path, const ReadOptions& opt) {
    std::string text = read_file(path, "OFF file");
    std::vector<std::string> tokens;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        auto hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        std::istringstream ls(line);
        std::string t;
        while (ls >> t) tokens.push_back(t);
    }
    Reader r{path, opt};
    if (tokens.empty() || tokens[0] != "OFF") r.fail("", "malformed OFF file: it does not start with OFF");
    auto count = [&](size_t i, const char* what) -> size_t {
        if (i >= tokens.size()) r.fail("", std::string("malformed OFF file: missing ") + what);
        const std::string& t = tokens[i];
        if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos)
            r.fail("", std::string("malformed OFF file: bad ") + what + " '" + t + "'");
        return std::stoul(t);
    };
    size_t nv = count(1, "vertex count");
    count(2, "face count");
    count(3, "edge count");
    if (tokens.size() < 4 + 3 * nv) r.fail("", "malformed OFF file: fewer than the " + std::to_string(nv) + " vertices announced");
    std::vector<Vec3q> pts(nv);
    for (size_t i = 0; i < nv; ++i)
        for (int k = 0; k < 3; ++k)
            pts[i][k] = r.number_text(tokens[4 + 3 * i + k], false,
                                      [&] { return "vertex " + std::to_string(i) + " coordinate " + std::to_string(k); });
    return pts;
}

}  // namespace

Scene parse_scene_text(const std::string& text, const std::string& name, const std::string& base_dir,
                       const ReadOptions& opt) {
    TreeBuilder tb;
    std::vector<std::pair<size_t, size_t>> map;
    bool ok = nlohmann::json::sax_parse(quote_numbers(text, map), &tb, nlohmann::json::input_format_t::json, true, true);
    Reader r{name, opt};
    if (!ok) r.fail("", "malformed JSON near byte " + std::to_string(original_position(tb.error_pos, map)));
    const JNode& root = tb.root;
    if (root.kind != JNode::Object) r.fail("", "the scene must be a JSON object");
    Scene sc;
    const char* pname[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        const JNode* p = root.find(pname[i]);
        if (!p) r.fail("", std::string("missing field \"") + pname[i] + "\"");
        if (p->kind != JNode::Object) r.fail(pname[i], "expected an object with \"vertices\" or \"off\"");
        PolyInput& in = sc.P[i];
        const JNode* verts = p->find("vertices");
        const JNode* off = p->find("off");
        if (verts && off) r.fail(pname[i], "give either \"vertices\" or \"off\", not both");
        if (verts) {
            if (verts->kind != JNode::Array) r.fail(std::string(pname[i]) + ".vertices", "expected an array of points");
            in.points.reserve(verts->items.size());
            for (size_t j = 0; j < verts->items.size(); ++j)
                in.points.push_back(r.point(verts->items[j], [&] { return std::string(pname[i]) + ".vertices[" + std::to_string(j) + "]"; }));
        } else if (off) {
            if (off->kind != JNode::String) r.fail(std::string(pname[i]) + ".off", "expected a file name");
            std::string path = off->text;
            if (!path.empty() && path[0] != '/' && !base_dir.empty()) path = base_dir + "/" + path;
            in.points = read_off(path, opt);
        } else {
            r.fail(pname[i], "missing field \"vertices\" (or \"off\")");
        }
        if (in.points.size() < 4)
            r.fail(pname[i], "fewer than 4 vertices (" + std::to_string(in.points.size()) + ")");
        if (const JNode* s = p->find("seed")) {
            in.seed = r.point(*s, std::string(pname[i]) + ".seed");
            in.seed_given = true;
        } else {
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
    const char* iname[2] = {"I1", "I2"};
    for (int i = 0; i < 2; ++i) {
        const JNode* n = root.find(iname[i]);
        if (!n) r.fail("", std::string("missing field \"") + iname[i] + "\"");
        if (n->kind != JNode::Array || n->items.size() != 2) r.fail(iname[i], "expected [lo, hi]");
        sc.lo[i] = r.number(n->items[0], std::string(iname[i]) + "[0]");
        sc.hi[i] = r.number(n->items[1], std::string(iname[i]) + "[1]");
        if (sgn(sc.lo[i]) <= 0) r.fail(iname[i], "lo must be > 0 (got " + to_exact_string(sc.lo[i]) + ")");
        if (sc.lo[i] > sc.hi[i]) r.fail(iname[i], "lo > hi");
    }
    return sc;
}

Scene load_scene(const std::string& path, const ReadOptions& opt) {
    std::string text = read_file(path, "scene file");
    std::string dir;
    auto slash = path.rfind('/');
    if (slash != std::string::npos) dir = path.substr(0, slash);
    return parse_scene_text(text, path, dir.empty() ? "." : dir, opt);
}

}  // namespace scalecert
