// first_divergence A.csv B.csv [--stage X.Y] [--absolute T] [--relative T]
//
// Compares two state dumps (--dump of a stage program, or tools/book_runner's dump of
// the book's own code on the same scene and keys) and names the first step, body and
// field where they differ beyond the tolerance, with the docs/errata.md entry that
// explains it when one is known for book project X.Y (docs/book_runner.md).
// Exit status: 0 the dumps agree, 1 they differ, 2 bad usage or a file that is not a
// state dump.

#include <cctype>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "dump_divergence.h"
#include "known_differences.h"

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
    app.add_option("--absolute", tolerance.absolute, "absolute tolerance (default 1e-9)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--relative", tolerance.relative, "tolerance relative to the larger number (default 1e-9)")
        ->check(CLI::NonNegativeNumber);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) return app.exit(error);
        std::cerr << "first_divergence: " << error.what() << " (--help lists the options)\n";
        return kTrouble;
    }
    try {
        const auto divergence =
            browser::first_divergence(browser::read_dump(file_a), browser::read_dump(file_b), tolerance);
        if (!divergence) {
            std::cout << "no divergence: " << file_a << " and " << file_b << " agree at every step\n";
            return kAgree;
        }
        std::cout << browser::describe(*divergence, file_a, file_b, tolerance);
        if (divergence->step > 0) std::cout << errata::explanation(*divergence, stage);
        return kDiffer;
    } catch (const browser::DumpError& error) {
        std::cerr << "first_divergence: " << error.what() << '\n';
        return kTrouble;
    }
}
