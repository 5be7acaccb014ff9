// A strict RFC 8259 JSON reader that keeps every number's text as written (so that 0.1 can be
// read as 1/10): for scene and claims files.
#pragma once
#include "numeric/limits.hpp"

#include <string>
#include <vector>

namespace scalecert::internal {

// A JSON tree; numbers and strings keep their text.
struct JNode {
    enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
    std::string text;          // number as written, string value, or "true" / "false"
    std::vector<JNode> items;  // array items, or object values
    std::vector<std::string> keys;
    const JNode* find(const std::string& k) const {
        for (size_t i = 0; i < keys.size(); ++i)
            if (keys[i] == k) return &items[i];
        return nullptr;
    }
};

// A malformed document: the byte offset and the problem.
struct JsonError {
    size_t pos;
    std::string what;
};

// No comments, no leading zeros, no bare keys, no trailing commas, UTF-8 only, duplicate keys
// rejected (a file must not mean two things), at most 64 levels of nesting and kMaxJsonValues
// values. Throws JsonError. With `non_numbers`, also the tokens NaN, Infinity and -Infinity
// (what Python's json.dumps writes for non-finite floats), as Number nodes with that text: for
// claims files, where a program's non-finite output is a wrong answer, not a malformed file.
JNode parse_strict_json(const std::string& text, bool non_numbers = false);

// The length of the well-formed UTF-8 sequence (shortest form, no surrogates, at most U+10FFFF)
// that starts at s[i] (i < s.size()), or 0 when none does.
size_t utf8_sequence_length(const std::string& s, size_t i);
// Whether s is well-formed UTF-8 throughout.
bool is_utf8(const std::string& s);

}  // namespace scalecert::internal
