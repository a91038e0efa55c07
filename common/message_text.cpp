#include "message_text.h"

#include <cstdio>
#include <vector>

namespace browser {
namespace {

// The length of the UTF-8 character that starts `text`, or 0 when it does not start
// with one: a stray continuation byte, a sequence cut short, an overlong form, a
// surrogate or a code point past U+10FFFF (RFC 3629).
std::size_t utf8_length(std::string_view text) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(0);
    std::size_t length = 0;
    unsigned low = 0x80, high = 0xBF;  // the range of the second byte
    if (lead < 0x80) return 1;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        if (lead == 0xE0) low = 0xA0;   // overlong
        if (lead == 0xED) high = 0x9F;  // surrogates
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        if (lead == 0xF0) low = 0x90;   // overlong
        if (lead == 0xF4) high = 0x8F;  // past U+10FFFF
    } else {
        return 0;
    }
    if (text.size() < length || byte(1) < low || byte(1) > high) return 0;
    for (std::size_t i = 2; i < length; ++i) {
        if ((byte(i) & 0xC0) != 0x80) return 0;
    }
    return length;
}

std::string hex_escape(unsigned char c) {
    char escape[5];
    std::snprintf(escape, sizeof escape, "\\x%02x", c);
    return escape;
}

// Each character of `text` as it is shown: one piece per character, so that shortening
// never cuts an escape or a UTF-8 character in two.
std::vector<std::string> shown_characters(std::string_view text, bool escape_quote) {
    std::vector<std::string> pieces;
    std::size_t i = 0;
    while (i < text.size()) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const std::size_t length = utf8_length(text.substr(i));
        if (length == 0) {
            pieces.push_back(hex_escape(c));
            ++i;
            continue;
        }
        if (length > 1) {
            std::string piece(text.substr(i, length));
            // C1 controls (U+0080 to U+009F) move a terminal as C0 ones do.
            const auto second = static_cast<unsigned char>(text[i + 1]);
            if (c == 0xC2 && second < 0xA0) piece = hex_escape(c).append(hex_escape(second));
            pieces.push_back(piece);
            i += length;
            continue;
        }
        switch (c) {
            case '\n': pieces.emplace_back("\\n"); break;
            case '\r': pieces.emplace_back("\\r"); break;
            case '\t': pieces.emplace_back("\\t"); break;
            case '\\': pieces.emplace_back("\\\\"); break;
            case '"': pieces.emplace_back(escape_quote ? "\\\"" : "\""); break;
            default: pieces.push_back(c < 0x20 || c == 0x7F ? hex_escape(c) : std::string(1, static_cast<char>(c)));
        }
        ++i;
    }
    return pieces;
}

std::string joined(const std::vector<std::string>& pieces) {
    std::string text;
    if (pieces.size() <= kLongestShown) {
        for (const std::string& piece : pieces) text += piece;
        return text;
    }
    constexpr std::size_t kMark = 3;  // "..."
    const std::size_t head = (kLongestShown - kMark) / 2, tail = kLongestShown - kMark - head;
    for (std::size_t i = 0; i < head; ++i) text += pieces[i];
    text += "...";
    for (std::size_t i = pieces.size() - tail; i < pieces.size(); ++i) text += pieces[i];
    return text;
}

}  // namespace

std::string printable(std::string_view text) { return joined(shown_characters(text, false)); }

std::string first_words(std::string_view text, std::size_t longest) {
    const std::vector<std::string> pieces = shown_characters(text, false);
    std::string shown;
    if (pieces.size() <= longest) {
        for (const std::string& piece : pieces) shown += piece;
        return shown;
    }
    constexpr std::size_t kMark = 3;  // "..."
    std::size_t end = longest - kMark;
    while (end > 0 && pieces[end] != " ") --end;  // the space the cut falls on, or before
    if (end == 0) end = longest - kMark;          // one long word: cut inside it
    for (std::size_t i = 0; i < end; ++i) shown += pieces[i];
    return shown + "...";
}

// Built by appending: g++ 12 gives a false -Wrestrict warning for "\"" + text + "\"".
std::string in_quotes(std::string_view text) {
    std::string quoted = "\"";
    quoted.append(joined(shown_characters(text, true)));
    quoted += '"';
    return quoted;
}

}  // namespace browser
