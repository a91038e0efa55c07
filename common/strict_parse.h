#pragma once
// The house rules for reading a command line with CLI11, shared by the stage programs
// and the bench: every mistake is one line that names the option, and nothing a reader
// types is quietly ignored or taken for something else.

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "message_text.h"  // in_quotes

namespace CLI {
class App;
}

namespace browser {

// A bad command line: the text after "program: " on the one line a program prints.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// CLI11's messages are made for its own multi-line report; we print one line, with
// what the reader typed in it made printable (message_text.h).
std::string one_line(std::string text);

// Parses `arguments` (as CLI11 takes them: last first, without the program name) into
// `app`. Returns false when --help was asked for, after printing the help on stdout.
// Throws UsageError for what CLI11 refuses, and for two slips it would let through: an
// option that swallowed the next option as its value ("--out --frames 5" would make a
// folder named "--frames"), and words left over.
bool parse_strictly(CLI::App& app, const std::vector<std::string>& arguments);

}  // namespace browser
