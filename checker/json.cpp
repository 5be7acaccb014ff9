#include "json.hpp"

#include <algorithm>
#include <set>
#include <utility>

namespace scalecert_check {
std::string printable(const std::string& s) {
    std::string out;
    for (unsigned char c : s.substr(0, 40)) out += (c < 0x20 || c == 0x7f) ? '?' : static_cast<char>(c);
    return s.size() > 40 ? out + "..." : out;
}

namespace {
// s as an integer written canonically: an optional "-", then "0" or a digit 1-9 and digits, and
// not "-0" (num() accepts exactly these integers: the form p, in lowest terms). Below 2^62 in
// magnitude into small, else into big. A string of at most 19 digits is below 10^19 < 2^64, so
// it accumulates in a uint64 without overflow; one of 20 or more (no leading zero) is at least
// 10^19 > 2^62: big, read by GMP.
bool canonical_int(const std::string& s, int64_t& small, mpz_class& big, bool& is_big) {
    const size_t b = !s.empty() && s[0] == '-' ? 1 : 0, d = s.size() - b;
    if (d == 0 || (s[b] == '0' && (d > 1 || b == 1))) return false;
    uint64_t v = 0;
    for (size_t i = b; i < s.size(); ++i) {
        const unsigned c = static_cast<unsigned>(static_cast<unsigned char>(s[i])) - '0';
        if (c > 9) return false;
        if (d <= 19) v = v * 10 + c;
    }
    is_big = d > 19 || v >= (uint64_t(1) << IntPoints::kSmallBits);
    if (!is_big)
        small = b ? -static_cast<int64_t>(v) : static_cast<int64_t>(v);  // |small| < 2^62
    else
        mpz_set_str(big.get_mpz_t(), s.c_str(), 10);
    return true;
}

// nlohmann's SAX parser in strict mode without comments; this handler builds the tree itself so
// that it can reject duplicate keys (nlohmann keeps the last) and nesting deeper than kMaxDepth,
// and, when `direct`, take the scene's vertex lists of integers into `points` (parse_certificate).
class StrictTree : public nlohmann::json_sax<J> {
  public:
    J root;
    std::vector<IntPoints> points;
    std::string error;
    explicit StrictTree(bool direct) : direct_(direct) {}
    bool null() override { return leave() && put(J(nullptr)); }
    bool boolean(bool v) override { return leave() && put(J(v)); }
    bool number_integer(number_integer_t v) override { return leave() && put(J(v)); }
    bool number_unsigned(number_unsigned_t v) override { return leave() && put(J(v)); }
    bool number_float(number_float_t v, const string_t&) override { return leave() && put(J(v)); }
    bool string(string_t& s) override {
        if (capture_ && coordinate(s)) return true;
        return leave() && put(J(std::move(s)));
    }
    bool binary(binary_t&) override { return fail("binary values are not JSON"); }
    bool start_object(std::size_t) override { return leave() && open(J::object()); }
    bool start_array(std::size_t) override {
        if (capture_ && read_ < 0) {  // a vertex begins
            read_ = 0;
            return true;
        }
        if (!leave()) return false;
        if (at_vertex_list()) return begin_capture();
        return open(J::array());
    }
    bool end_object() override {
        stack_.pop_back();
        levels_.pop_back();
        return true;
    }
    bool end_array() override {
        if (capture_) {
            if (read_ < 0) {  // the list ends: it stays in `points`
                capture_ = false;
                return true;
            }
            if (read_ == 3) {  // a vertex of three coordinates ends
                add_vertex();
                read_ = -1;
                return true;
            }
            leave();  // a vertex of fewer
        }
        stack_.pop_back();
        levels_.pop_back();
        return true;
    }
    bool key(string_t& k) override {
        if (stack_.back()->contains(k)) return fail("duplicate key \"" + printable(k) + "\"");
        key_ = std::move(k);
        return true;
    }
    bool parse_error(std::size_t pos, const std::string&, const nlohmann::detail::exception& e) override {
        // nlohmann's out_of_range.406: a number that RFC 8259 allows but a double cannot hold.
        if (error.empty())
            error = e.id == 406 ? "a JSON number past the double range near byte " + std::to_string(pos) +
                                      " (write exact numbers as strings: FORMAT.md)"
                                : "not strict JSON (RFC 8259) near byte " + std::to_string(pos);
        return false;
    }

  private:
    // Each open container, and how it sits in its parent: under a key (its name), or as an element.
    struct Level {
        std::string key;
        bool element;
    };
    std::vector<J*> stack_;
    std::vector<Level> levels_;
    std::string key_;
    const bool direct_;
    // While a vertex list is taken into points.back(): its marker in the tree, the coordinates
    // read of the current vertex (read_: -1 between vertices), each small or big.
    bool capture_ = false;
    J* marker_ = nullptr;
    int read_ = -1;
    int64_t small_[3] = {0, 0, 0};
    mpz_class big_[3];
    bool is_big_[3] = {false, false, false};

    bool fail(const std::string& why) {
        if (error.empty()) error = why;
        return false;
    }
    J* place(J v) {
        if (stack_.empty()) {
            root = std::move(v);
            return &root;
        }
        J& top = *stack_.back();
        if (top.is_array()) {
            top.push_back(std::move(v));
            return &top.back();
        }
        return &(top[key_] = std::move(v));
    }
    bool put(J v) {
        place(std::move(v));
        return true;
    }
    bool open(J v) {
        if (stack_.size() >= kMaxDepth) return fail("nested deeper than " + std::to_string(kMaxDepth) + " levels");
        const bool element = !stack_.empty() && stack_.back()->is_array();
        levels_.push_back({element ? std::string() : key_, element});
        stack_.push_back(place(std::move(v)));
        return true;
    }
    // An array opening at scene.P1.vertices or scene.P2.vertices (root, scene, P_i open: depth 3),
    // or at scene.P_i.parts[k].vertices (root, scene, P_i, parts, its element k: depth 5).
    bool keyed(size_t d, const char* k) const { return !levels_[d].element && levels_[d].key == k; }
    bool at_vertex_list() const {
        if (!direct_ || key_ != "vertices" || stack_.empty() || !stack_.back()->is_object()) return false;
        const size_t d = stack_.size();
        if (d != 3 && d != 5) return false;
        if (!keyed(1, "scene") || !(keyed(2, "P1") || keyed(2, "P2"))) return false;
        return d == 3 || (keyed(3, "parts") && levels_[4].element);
    }
    bool begin_capture() {
        // (at depth 3 or 5, far below kMaxDepth: the list and its vertices nest no deeper than the
        // tree would have held them)
        marker_ = place(J::binary(J::binary_t::container_type{}, points.size()));
        points.emplace_back();
        capture_ = true;
        read_ = -1;
        return true;
    }
    bool coordinate(const std::string& s) {
        if (read_ < 0 || read_ >= 3) return false;
        const int c = read_;
        if (!canonical_int(s, small_[c], big_[c], is_big_[c])) return false;
        ++read_;
        return true;
    }
    void add_vertex() {
        IntPoints& p = points.back();
        if (!is_big_[0] && !is_big_[1] && !is_big_[2]) {
            p.add_small(small_);
            return;
        }
        Z3 z;
        for (int c = 0; c < 3; ++c) z[c] = is_big_[c] ? big_[c] : z64(small_[c]);
        p.add_big(std::move(z));
    }
    std::string text_of(int c) const { return is_big_[c] ? big_[c].get_str() : std::to_string(small_[c]); }
    // The list being taken leaves the form: it goes into the tree as parse_strict builds it, so
    // far (every vertex read, and the coordinates read of the current one, each as the string it
    // was: a canonical integer is the decimal of its value), and stays open there for the event
    // that left the form. Returns true (for the && chains above).
    bool leave() {
        if (!capture_) return true;
        capture_ = false;
        IntPoints& p = points.back();
        J::array_t list(p.n);
        for (size_t q = 0; q < p.small(); ++q)
            list[static_cast<size_t>(p.point_at(q))] =
                J::array({J(std::to_string(p.x[0][q])), J(std::to_string(p.x[1][q])), J(std::to_string(p.x[2][q]))});
        for (size_t b = 0; b < p.big.size(); ++b)
            list[static_cast<size_t>(p.big[b])] =
                J::array({J(p.big_x[b][0].get_str()), J(p.big_x[b][1].get_str()), J(p.big_x[b][2].get_str())});
        points.pop_back();
        *marker_ = J(std::move(list));
        levels_.push_back({"vertices", false});
        stack_.push_back(marker_);
        if (read_ >= 0) {  // inside a vertex
            J v = J::array();
            for (int c = 0; c < read_; ++c) v.push_back(J(text_of(c)));
            marker_->push_back(std::move(v));
            levels_.push_back({std::string(), true});
            stack_.push_back(&marker_->back());
        }
        return true;
    }
};
}  // namespace

J parse_strict(const std::string& text) { return parse_certificate(text, false).root; }

Parsed parse_certificate(const std::string& text, bool direct) {
    // nlohmann's reader stops at a NUL byte as at the end of the input: what follows one would
    // go unread. A byte-order mark is not JSON either (RFC 8259 forbids writing one).
    if (text.find('\0') != std::string::npos) throw Unreadable{"not strict JSON: a NUL byte in the text"};
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) throw Unreadable{"not strict JSON: a byte-order mark"};
    StrictTree t(direct);
    if (!J::sax_parse(text, &t, J::input_format_t::json, true, false))
        throw Unreadable{t.error.empty() ? "not strict JSON" : t.error};
    return {std::move(t.root), std::move(t.points)};
}

IntPoints* captured(Context& cx, const J& j) {
    if (!j.is_binary() || !cx.points || !j.get_binary().has_subtype()) return nullptr;
    const auto k = j.get_binary().subtype();
    return k < cx.points->size() ? &(*cx.points)[static_cast<size_t>(k)] : nullptr;
}

void shape(Context& cx, const J& o, const std::string& where, std::initializer_list<const char*> required,
           std::initializer_list<const char*> optional) {
    cx.claim_lazy(o.is_object(), [&] { return (where.empty() ? std::string("the file") : where) + " is an object"; });
    for (const char* k : required)
        cx.claim_lazy(o.contains(k), [&] { return where + (where.empty() ? "" : ".") + k + " is present"; });
    for (auto it = o.begin(); it != o.end(); ++it) {
        bool known = false;
        for (const char* k : required) known = known || it.key() == k;
        for (const char* k : optional) known = known || it.key() == k;
        cx.claim_lazy(known, [&] {
            return (where.empty() ? std::string("the file") : where) + " has no field \"" + printable(it.key()) + "\"";
        });
    }
}

size_t index(Context& cx, const J& j, size_t n, const std::string& where) {
    return index_at(cx, j, n, [&] { return where; });
}

std::vector<int> index_list(Context& cx, const J& j, size_t n, const std::string& where) {
    cx.claim(j.is_array() && !j.empty(), where + " is a nonempty list of indices");
    std::vector<int> out;
    std::set<size_t> seen;
    for (size_t k = 0; k < j.size(); ++k) {
        size_t i = index(cx, j[k], n, where + "[" + std::to_string(k) + "]");
        cx.claim(seen.insert(i).second, where + " names each vertex once");
        out.push_back(static_cast<int>(i));
    }
    return out;
}

bool has(const std::vector<int>& v, int x) { return std::binary_search(v.begin(), v.end(), x); }

void annotation_string(Context& cx, const J& o, const char* key, const std::string& where) {
    if (o.contains(key)) cx.claim(at(o, key).is_string(), where + "." + key + " is a string");
}
}  // namespace scalecert_check
