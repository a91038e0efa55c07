#pragma once
// Text a reader gave (an option's value, a path, a key script, a word from a scene file)
// shown inside a message. Every refusal is one line on stderr, whatever the text holds: a
// line break, a terminal's escape sequence, bytes that are not UTF-8, or a value a
// megabyte long. So such text is never printed raw, but through these two functions.

#include <cstddef>
#include <string>
#include <string_view>

namespace browser {

// The longest text shown, in characters; a longer one keeps its start and its end (the
// end of a path names the file), joined by "...".
inline constexpr std::size_t kLongestShown = 120;

// `text` made safe for one line: control characters as C escapes (\n, \t, \x1b), bytes
// that are not UTF-8 as \xNN, a backslash doubled; printable text, UTF-8 included, as it
// is; then shortened to kLongestShown characters.
std::string printable(std::string_view text);

// printable(text) cut at the last space that keeps it within `longest` characters, "..."
// marking the cut: a message of ours (a parser's) that is cut reads as whole words.
std::string first_words(std::string_view text, std::size_t longest);

// printable(text) in double quotes, a quote inside it escaped: "--frames: must be ...
// (got "12\n")".
std::string in_quotes(std::string_view text);

}  // namespace browser
