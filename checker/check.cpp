#include "check.hpp"

#include "formats.hpp"
#include "json.hpp"

#include <new>
#include <stdexcept>

namespace scalecert_check {
int check_text(const std::string& text, std::string& message, Context& cx) {
    cx.start(text.size());
    try {
        if (text.size() > kMaxFileBytes) throw Unreadable{"larger than " + std::to_string(kMaxFileBytes) + " bytes"};
        Parsed parsed = parse_certificate(text, cx.direct_points);
        struct Release {  // cx.points are this file's only while it is checked
            Context& cx;
            ~Release() { cx.points = nullptr; }
        } release{cx};
        cx.points = &parsed.points;
        const J& c = parsed.root;
        try {
            cx.claim(c.is_object() && c.contains("format") && c["format"] == J("scalecert-2"), "format is scalecert-2");
            cx.claim(c.contains("kind") && c["kind"].is_string(), "kind is present");
            const std::string kind = c["kind"].get<std::string>();
            if (kind == "partition")
                check_partition(cx, c);
            else if (kind == "query")
                check_query(cx, c);
            else if (kind == "judgements")
                check_judgements(cx, c);
            else if (kind == "compound_partition")
                check_compound_partition(cx, c);
            else if (kind == "compound_judgements")
                check_compound_judgements(cx, c);
            else
                cx.claim(false,
                         "kind is partition, query, judgements, compound_partition or compound_judgements "
                         "(got '" +
                             printable(kind) + "': not a certificate)");
        } catch (const Invalid& e) {
            message = "invalid: " + e.what;
            return 1;
        } catch (const J::exception& e) {
            message = std::string("invalid: mistyped field (") + e.what() + ")";
            return 1;
        }
    } catch (const Unreadable& e) {
        message = "error: " + e.what;
        return 2;
    } catch (const std::bad_alloc&) {
        message = "error: out of memory";
        return 2;
    } catch (const std::length_error&) {
        message = "error: out of memory";
        return 2;
    }
    message = "valid: " + std::to_string(cx.claims) + " claims checked" + cx.summary;
    return 0;
}

int check_text(const std::string& text, std::string& message) {
    Context cx;
    return check_text(text, message, cx);
}
}  // namespace scalecert_check
