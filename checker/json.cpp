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
// nlohmann's SAX parser in strict mode without comments; this handler builds the tree itself so
// that it can reject duplicate keys (nlohmann keeps the last) and nesting deeper than kMaxDepth.
class StrictTree : public nlohmann::json_sax<J> {
  public:
    J root;
    std::string error;
    bool null() override { return put(J(nullptr)); }
    bool boolean(bool v) override { return put(J(v)); }
    bool number_integer(number_integer_t v) override { return put(J(v)); }
    bool number_unsigned(number_unsigned_t v) override { return put(J(v)); }
    bool number_float(number_float_t v, const string_t&) override { return put(J(v)); }
    bool string(string_t& s) override { return put(J(std::move(s))); }
    bool binary(binary_t&) override { return fail("binary values are not JSON"); }
    bool start_object(std::size_t) override { return open(J::object()); }
    bool start_array(std::size_t) override { return open(J::array()); }
    bool end_object() override {
        stack_.pop_back();
        return true;
    }
    bool end_array() override {
        stack_.pop_back();
        return true;
    }
    bool key(string_t& k) override {
        if (stack_.back()->contains(k)) return fail("duplicate key \"" + printable(k) + "\"");
        key_ = std::move(k);
        return true;
    }
    bool parse_error(std::size_t pos, const std::string&, const nlohmann::detail::exception&) override {
        if (error.empty()) error = "not strict JSON (RFC 8259) near byte " + std::to_string(pos);
        return false;
    }

  private:
    std::vector<J*> stack_;
    std::string key_;
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
        stack_.push_back(place(std::move(v)));
        return true;
    }
};
}  // namespace

J parse_strict(const std::string& text) {
    // nlohmann's reader stops at a NUL byte as at the end of the input: what follows one would
    // go unread. A byte-order mark is not JSON either (RFC 8259 forbids writing one).
    if (text.find('\0') != std::string::npos) throw Unreadable{"not strict JSON: a NUL byte in the text"};
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) throw Unreadable{"not strict JSON: a byte-order mark"};
    StrictTree t;
    if (!J::sax_parse(text, &t, J::input_format_t::json, true, false))
        throw Unreadable{t.error.empty() ? "not strict JSON" : t.error};
    return std::move(t.root);
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
