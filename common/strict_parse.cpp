#include "strict_parse.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace browser {

std::string one_line(std::string text) {
    for (char& c : text) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return printable(text);
}

bool parse_strictly(CLI::App& app, const std::vector<std::string>& arguments) {
    std::vector<std::string> remaining = arguments;  // CLI11 consumes the list it is given
    try {
        app.parse(remaining);
    } catch (const CLI::CallForHelp&) {
        std::cout << app.help();
        return false;
    } catch (const CLI::ParseError& error) {
        throw UsageError(one_line(error.what()));
    }
    for (const CLI::Option* option : app.get_options()) {
        for (const std::string& value : option->results()) {
            if (value.starts_with("--")) {
                throw UsageError(option->get_name() + ": needs a value before " + in_quotes(value));
            }
        }
    }
    for (const std::string& word : app.remaining()) {
        if (word == "--") continue;  // the usual "end of options" mark: harmless
        throw UsageError((word.starts_with("-") ? "unknown option " : "unexpected argument ") + in_quotes(word) +
                         " (see --help)");
    }
    return true;
}

}  // namespace browser
