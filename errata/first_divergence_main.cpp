// first_divergence A.csv B.csv [--stage X.Y] [--absolute T] [--relative T]
//
// Compares two state dumps (--dump of a stage program, or tools/book_runner's dump of
// the book's own code on the same scene and keys) and names the first step, body and
// field where they differ beyond the tolerance, with the docs/errata.md entry that
// explains it when one is known for book project X.Y (docs/book_runner.md).
// Exit status: 0 the dumps agree, 1 they differ, 2 bad usage or a file that is not a
// state dump.

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <new>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "dump_divergence.h"
#include "known_differences.h"
#include "message_text.h"

namespace {
constexpr int kAgree = 0, kDiffer = 1, kTrouble = 2;
}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Where two state dumps first differ, and the errata entry that explains it"};
    std::string file_a, file_b, stage;
    browser::DumpTolerance tolerance;
    app.add_option("A", file_a, "the first dump (e.g. our stage's --dump)")->required();
    app.add_option("B", file_b, "the second dump (e.g. tools/book_runner's)")->required();
    app.add_option("--stage", stage,
                   "the book project both ran, X.Y (4.1 to 5.1): looks the difference up in docs/errata.md")
        ->check([](const std::string& text) {
            return text.size() == 3 && text[1] == '.' && std::isdigit(static_cast<unsigned char>(text[0])) &&
                           std::isdigit(static_cast<unsigned char>(text[2]))
                       ? std::string()
                       : std::string("a book project is X.Y, such as 4.4");
        });
    // A tolerance is a plain number: NaN would make every comparison fail, and one that
    // is refused is named in a few characters, not in the 300 digits of a huge double.
    const auto tolerance_check = [](double most) {
        return [most](const std::string& text) {
            double value = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            const bool number = !text.empty() && error == std::errc{} && end == text.data() + text.size();
            if (number && std::isfinite(value) && value >= 0 && value <= most) return std::string();
            std::ostringstream range;
            range << "must be a number from 0 to " << most << " (got " << browser::in_quotes(text) << ")";
            return range.str();
        };
    };
    app.add_option("--absolute", tolerance.absolute, "absolute tolerance (default 1e-9), 0 to 1e6")
        ->check(tolerance_check(1e6));
    app.add_option("--relative", tolerance.relative, "tolerance relative to the larger number (default 1e-9), 0 to 1")
        ->check(tolerance_check(1));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) return app.exit(error);
        std::cerr << "first_divergence: " << browser::printable(error.what()) << " (--help lists the options)\n";
        return kTrouble;
    }
    try {
        const auto divergence = browser::first_divergence(std::filesystem::path(file_a), file_b, tolerance);
        const std::string name_a = browser::printable(file_a), name_b = browser::printable(file_b);
        if (!divergence) {
            std::cout << "no divergence: " << name_a << " and " << name_b << " agree at every step\n";
            return kAgree;
        }
        std::cout << browser::describe(*divergence, name_a, name_b, tolerance);
        if (divergence->step > 0) std::cout << errata::explanation(*divergence, stage);
        return kDiffer;
    } catch (const browser::DumpError& error) {
        std::cerr << "first_divergence: " << error.what() << '\n';
        return kTrouble;
    } catch (const std::bad_alloc&) {
        std::cerr << "first_divergence: out of memory\n";
        return kTrouble;
    }
}
