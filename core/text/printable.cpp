#include "core/text/printable.h"

#include <algorithm>
#include <cstdio>

namespace collide {
namespace {

bool continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

// The length of the well-formed UTF-8 sequence of a printable character at text[i] (RFC 3629:
// no overlong form, no surrogate, nothing above U+10FFFF), or 0. The C1 controls U+0080 to
// U+009F are not printable: some terminals act on them as on ESC sequences.
std::size_t printable_utf8_length(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[i + k]); };
    const unsigned char lead = byte(0);
    std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : 2;
    if (lead < 0xC2 || lead > 0xF4 || i + length > text.size()) return 0;
    for (std::size_t k = 1; k < length; ++k)
        if (!continuation(byte(k))) return 0;
    if (lead == 0xC2 && byte(1) < 0xA0) return 0;                                // C1 control
    if ((lead == 0xE0 && byte(1) < 0xA0) || (lead == 0xF0 && byte(1) < 0x90)) return 0;  // overlong
    if ((lead == 0xED && byte(1) >= 0xA0) || (lead == 0xF4 && byte(1) >= 0x90)) return 0;  // surrogate, > U+10FFFF
    return length;
}

}  // namespace

std::string printable(std::string_view text, LineBreaks line_breaks) {
    std::string out;
    out.reserve(text.size());
    char hex[5];
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if ((c >= 0x20 && c < 0x7f) || (c == '\n' && line_breaks == LineBreaks::kept)) {
            out += text[i++];
        } else if (const std::size_t n = c >= 0x80 ? printable_utf8_length(text, i) : 0) {
            out.append(text.substr(i, n));
            i += n;
        } else {
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
            ++i;
        }
    }
    return out;
}

std::string printable_tail(std::string_view text, std::size_t max_chars, LineBreaks line_breaks) {
    if (text.size() <= max_chars) return printable(text, line_breaks);
    return "..." + printable(text.substr(text.size() - max_chars), line_breaks);
}

bool has_control_character(std::string_view text) {
    return std::any_of(text.begin(), text.end(), [](char ch) {
        const auto c = static_cast<unsigned char>(ch);
        return c < 0x20 || c == 0x7f;
    });
}

}  // namespace collide
