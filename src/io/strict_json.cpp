#include "io/strict_json.hpp"

#include "numeric/exact.hpp"

#include <cstdlib>
#include <cstring>
#include <unordered_set>

namespace scalecert::internal {
namespace {

// A strict RFC 8259 reader: no comments, no leading zeros, no bare keys, no trailing commas,
// UTF-8 only, duplicate keys rejected (a file must not mean two things), and at most kMaxDepth
// levels of nesting (scenes need 4), so neither the reader nor the tree's destructor can exhaust
// the stack, and at most kMaxJsonValues values, so the tree stays within about 1 GB. Throws
// JsonError with the byte offset.
constexpr int kMaxDepth = 64;

class StrictJson {
  public:
    StrictJson(const std::string& t, bool non_numbers) : s_(t), non_numbers_(non_numbers) {}
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
    const bool non_numbers_;
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
        if (i_ < s_.size() && s_[i_] == c) {
            ++i_;
            return true;
        }
        return false;
    }
    void literal(const char* word) {
        for (const char* p = word; *p; ++p)
            if (!eat(*p)) fail("unexpected character");
    }
    bool digit() const { return i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9'; }
    void value(JNode& n, int depth) {
        if (i_ >= s_.size()) fail("unexpected end of the file");
        if (++values_ > kMaxJsonValues)
            fail("more than " + std::to_string(kMaxJsonValues) + " JSON values (the limit)");
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
                    if (!seen.insert(k).second) {
                        i_ = at;
                        fail("duplicate key " + in_quotes(k));
                    }
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
        if (c == '"') {
            n.kind = JNode::String;
            n.text = string();
            return;
        }
        if (c == 't') {
            literal("true");
            n.kind = JNode::Bool;
            n.text = "true";
            return;
        }
        if (c == 'f') {
            literal("false");
            n.kind = JNode::Bool;
            n.text = "false";
            return;
        }
        if (c == 'n') {
            literal("null");
            return;
        }
        if (non_numbers_ && (c == 'N' || c == 'I' || (c == '-' && i_ + 1 < s_.size() && s_[i_ + 1] == 'I'))) {
            n.kind = JNode::Number;
            n.text = c == 'N' ? "NaN" : c == 'I' ? "Infinity" : "-Infinity";
            literal(n.text.c_str());
            return;
        }
        if (c == '-' || (c >= '0' && c <= '9')) {
            n.kind = JNode::Number;
            n.text = number();
            return;
        }
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
        if (cp < 0x80)
            out += static_cast<char>(cp);
        else if (cp < 0x800) {
            out += static_cast<char>(0xC0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += static_cast<char>(0xE0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (cp >> 18));
            out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }
    // One UTF-8 sequence starting at i_ (well-formed, shortest form, no surrogates), copied.
    void utf8_sequence(std::string& out) {
        const size_t n = utf8_sequence_length(s_, i_);
        if (n == 0) fail("invalid UTF-8");
        out.append(s_, i_, n);
        i_ += n;
    }
    std::string string() {
        ++i_;  // the opening quote
        std::string out;
        for (;;) {
            if (i_ >= s_.size()) fail("unterminated string");
            const unsigned char c = static_cast<unsigned char>(s_[i_]);
            if (c == '"') {
                ++i_;
                return out;
            }
            if (c < 0x20) fail("control character in a string");
            if (c >= 0x80) {
                utf8_sequence(out);
                continue;
            }
            if (c != '\\') {
                out += static_cast<char>(c);
                ++i_;
                continue;
            }
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

}  // namespace

size_t utf8_sequence_length(const std::string& s, size_t i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) return 1;
    const int n = c >= 0xC2 && c <= 0xDF ? 1 : c >= 0xE0 && c <= 0xEF ? 2 : c >= 0xF0 && c <= 0xF4 ? 3 : -1;
    if (n < 0 || i + static_cast<size_t>(n) >= s.size()) return 0;
    unsigned cp = c & (0x3F >> n);
    for (int k = 1; k <= n; ++k) {
        const unsigned char d = static_cast<unsigned char>(s[i + static_cast<size_t>(k)]);
        if ((d & 0xC0) != 0x80) return 0;
        cp = cp << 6 | (d & 0x3F);
    }
    if ((n == 2 && cp < 0x800) || (n == 3 && (cp < 0x10000 || cp > 0x10FFFF)) || (cp >= 0xD800 && cp <= 0xDFFF))
        return 0;
    return static_cast<size_t>(n) + 1;
}

bool is_utf8(const std::string& s) {
    for (size_t i = 0, n = 0; i < s.size(); i += n)
        if ((n = utf8_sequence_length(s, i)) == 0) return false;
    return true;
}

JNode parse_strict_json(const std::string& text, bool non_numbers) { return StrictJson(text, non_numbers).parse(); }

}  // namespace scalecert::internal
