// compare_png EXPECTED ACTUAL [--diff FILE] [--diff-dir DIR] [--channel N] [--share X]
//
// Checks pictures against reference pictures by their decoded pixels. EXPECTED and
// ACTUAL are two PNG files, or two folders: then every *.png in EXPECTED must have a
// matching file of the same name in ACTUAL (extra files in ACTUAL are ignored).
// Exit status: 0 all match, 1 some picture differs or is missing, 2 bad usage or a file
// that cannot be read or written.
//
// By default pictures match only pixel for pixel: the page is deterministic (a simulated
// clock, seeded randomness, one rasterizer), so our stages need no slack, and any slack
// lets a stage that lacks a feature drawing a few pixels (a collision test the next
// stage adds, whose lines take about 130 pixels) pass the next stage's pictures. --channel
// and --share are for pictures made elsewhere.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <CLI/CLI.hpp>

#include "image_compare.h"
#include "interruption.h"
#include "message_text.h"
#include "output_folder.h"  // kManifest
#include "png_io.h"
#include "write_guard.h"

namespace fs = std::filesystem;

namespace {

constexpr int kMatch = 0, kDifferent = 1, kTrouble = 2;
constexpr const char* kProgram = "compare_png";

struct Settings {
    fs::path expected, actual;
    fs::path diff_file;  // --diff: for two files, always written
    fs::path diff_dir;   // --diff-dir: DIR/<name>, written only for pictures that differ
    browser::Tolerance tolerance{.channel = 0, .pixel_share = 0.0};
};

std::string size_text(const browser::Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

// " in x 310-402, y 120-180": where to look, in the picture's pixels.
std::string region_text(const browser::PixelBox& box) {
    if (box.empty()) return "";
    return " in x " + std::to_string(box.left) + "-" + std::to_string(box.right) + ", y " + std::to_string(box.top) +
           "-" + std::to_string(box.bottom);
}

// --diff-dir DIR keeps a manifest of the diff pictures it wrote there (output_folder.h's
// format), under a first line of its own; only those it replaces or removes. A folder
// whose manifest is another program's (a stage run's --out) is not compare_png's to
// write in: its pictures are the run's.
constexpr const char* kDiffManifestHeader =
    "# compare_png --diff-dir: the diff pictures it wrote here, the only files it replaces or removes";

bool is_our_manifest(const fs::path& dir) {
    // Read only as a regular file: a FIFO would wait for ever.
    std::error_code error;
    if (!fs::is_regular_file(fs::symlink_status(dir / browser::kManifest, error))) return false;
    std::ifstream manifest(dir / browser::kManifest);
    std::string first;
    return std::getline(manifest, first) && first == kDiffManifestHeader;
}

bool has_manifest(const fs::path& dir) {
    std::error_code error;
    return fs::exists(fs::symlink_status(dir / browser::kManifest, error));
}

// Whether this program wrote DIR/name before.
bool wrote_before(const fs::path& file) {
    const fs::path dir = file.parent_path();
    return is_our_manifest(dir) && browser::manifest_names(dir).contains(file.filename().string());
}

// An old diff picture would mislead once the pictures match: removed when this program
// wrote it and it is still a plain file (write_guard.h's rule), never what a link leads to.
void remove_old_diff(const fs::path& file) {
    if (!wrote_before(file)) return;
    try {
        browser::check_may_write(file, browser::WriteTarget::file);
    } catch (const browser::OutputRefused&) {
        return;
    }
    std::error_code ignored;
    fs::remove(file, ignored);
}

// Writes `name`'s diff picture into DIR: a new file, or one this program wrote before.
void write_diff_in_dir(const fs::path& dir, const std::string& name, const browser::Image& diff,
                       std::span<const fs::path> inputs) {
    const fs::path file = dir / name;
    browser::check_may_write(file, browser::WriteTarget::file, inputs);
    const bool ours = wrote_before(file);
    std::error_code error;
    if (!ours && fs::exists(fs::symlink_status(file, error))) {
        throw browser::OutputRefused("it holds a file compare_png did not write (not in " +
                                     std::string(browser::kManifest) + "); move it away or name another --diff-dir");
    }
    if (!has_manifest(dir)) {
        std::ofstream manifest(dir / browser::kManifest, std::ios::binary);
        manifest << kDiffManifestHeader << '\n';
        if (!manifest) {
            throw fs::filesystem_error("cannot write the manifest", dir / browser::kManifest,
                                       std::make_error_code(std::errc::io_error));
        }
    }
    browser::write_png(file, diff);
    if (!ours) browser::OutputFolder::add_to_manifest(dir, name);
}

// Compares one pair, prints its line and writes the diff picture where asked.
int compare_pair(const std::string& name, const fs::path& expected_path, const fs::path& actual_path,
                 const Settings& settings) {
    browser::Image expected, actual;
    try {
        expected = browser::read_png(expected_path);
        actual = browser::read_png(actual_path);
    } catch (const browser::FileError& error) {
        std::cerr << kProgram << ": " << error.what() << "\n";
        return kTrouble;
    }

    const browser::ImageDifference difference = browser::compare_images(expected, actual, settings.tolerance);
    const bool match = difference.within(settings.tolerance);
    std::ostringstream line;
    line << name << ": ";
    if (!difference.same_size) line << "size " << size_text(actual) << ", expected " << size_text(expected) << "; ";
    line << "differing pixels " << difference.differing_pixels << " (" << std::fixed << std::setprecision(4)
         << 100.0 * difference.differing_share << "%)" << region_text(difference.region)
         << ", largest channel difference " << difference.largest_channel_difference << ": "
         << (match ? "OK" : "DIFFERENT");
    std::cout << line.str() << "\n";

    std::optional<fs::path> diff_path;
    if (!settings.diff_file.empty()) diff_path = settings.diff_file;
    if (!settings.diff_dir.empty()) {
        const fs::path in_dir = settings.diff_dir / name;
        if (match) {
            remove_old_diff(in_dir);
        } else {
            diff_path = in_dir;
        }
    }
    if (diff_path) {
        const fs::path inputs[] = {expected_path, actual_path};
        try {
            if (settings.diff_dir.empty()) {
                browser::check_may_write(*diff_path, browser::WriteTarget::file, inputs);
                browser::write_png(*diff_path, difference.diff);
            } else {
                write_diff_in_dir(settings.diff_dir, name, difference.diff, inputs);
            }
        } catch (const browser::OutputRefused& refused) {
            std::cerr << kProgram << ": cannot write " << browser::in_quotes(diff_path->string()) << ": "
                      << refused.what() << "\n";
            return kTrouble;
        } catch (const browser::FileError& error) {
            std::cerr << kProgram << ": " << error.what() << "\n";
            return kTrouble;
        } catch (const fs::filesystem_error& error) {
            std::cerr << kProgram << ": cannot list the diff in " << browser::in_quotes(settings.diff_dir.string())
                      << ": " << error.code().message() << "\n";
            return kTrouble;
        }
        std::cout << "  diff: " << diff_path->string() << "\n";
    }
    return match ? kMatch : kDifferent;
}

int compare_folders(const Settings& settings) {
    std::vector<std::string> names;
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(settings.expected, error)) {
        if (entry.path().extension() == ".png") names.push_back(entry.path().filename().string());
    }
    if (error) {
        std::cerr << kProgram << ": cannot list " << settings.expected.string() << ": " << error.message() << "\n";
        return kTrouble;
    }
    if (names.empty()) {  // most likely a wrong folder, which must not pass as "all match"
        std::cerr << kProgram << ": no *.png files in " << settings.expected.string() << "\n";
        return kTrouble;
    }
    std::sort(names.begin(), names.end());

    int status = kMatch;
    for (const std::string& name : names) {
        browser::stop_if_interrupted();
        const fs::path actual = settings.actual / name;
        int outcome = kDifferent;
        if (fs::exists(actual, error)) outcome = compare_pair(name, settings.expected / name, actual, settings);
        else std::cout << name << ": MISSING from " << settings.actual.string() << "\n";
        status = std::max(status, outcome);
    }
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    Settings settings;
    CLI::App app{
        "Compares PNG pictures by their pixels: two files, or every *.png of the folder "
        "EXPECTED with the file of the same name in the folder ACTUAL.",
        kProgram};
    app.add_option("EXPECTED", settings.expected, "reference PNG file or folder")->required()->type_name("PATH");
    app.add_option("ACTUAL", settings.actual, "PNG file or folder to check")->required()->type_name("PATH");
    auto* diff =
        app.add_option("--diff", settings.diff_file, "write the diff picture of two files here")->type_name("FILE");
    app.add_option("--diff-dir", settings.diff_dir, "write DIR/<name> for each picture that differs")
        ->type_name("DIR")
        ->excludes(diff);
    app.add_option("--channel", settings.tolerance.channel,
                   "a pixel differs when a channel differs by more than N (0-255)")
        ->type_name("N")
        ->capture_default_str()
        ->check(CLI::Range(0, 255));
    app.add_option("--share", settings.tolerance.pixel_share,
                   "pictures match while at most this share of pixels differs (0-1)")
        ->type_name("X")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) return app.exit(error);  // --help
        std::cerr << kProgram << ": " << error.what() << " (see " << kProgram << " --help)\n";
        return kTrouble;
    }

    // CLI11's range lets NaN through: no comparison with it is false.
    if (!std::isfinite(settings.tolerance.pixel_share)) {
        std::cerr << kProgram << ": --share: must be a number from 0 to 1 (see " << kProgram << " --help)\n";
        return kTrouble;
    }
    std::error_code error;
    const bool folders = fs::is_directory(settings.expected, error);
    for (const fs::path& path : {settings.expected, settings.actual}) {
        if (!fs::exists(path, error)) {
            std::cerr << kProgram << ": " << path.string() << " does not exist\n";
            return kTrouble;
        }
    }
    if (fs::is_directory(settings.actual, error) != folders) {
        std::cerr << kProgram << ": EXPECTED and ACTUAL must be two files or two folders\n";
        return kTrouble;
    }
    if (folders && !settings.diff_file.empty()) {
        std::cerr << kProgram << ": --diff names one file; use --diff-dir to compare folders\n";
        return kTrouble;
    }
    try {
        const fs::path inputs[] = {settings.expected, settings.actual};
        if (!settings.diff_file.empty())
            browser::check_may_write(settings.diff_file, browser::WriteTarget::file, inputs);
        if (!settings.diff_dir.empty()) {
            browser::check_may_write(settings.diff_dir, browser::WriteTarget::folder, inputs);
            if (has_manifest(settings.diff_dir) && !is_our_manifest(settings.diff_dir)) {
                throw browser::OutputRefused("its " + std::string(browser::kManifest) +
                                             " is another program's (a run's --out folder, whose pictures are "
                                             "the run's); name a folder of its own for the diff pictures");
            }
        }
    } catch (const browser::OutputRefused& refused) {
        const fs::path& named = settings.diff_file.empty() ? settings.diff_dir : settings.diff_file;
        std::cerr << kProgram << ": cannot write " << browser::in_quotes(named.string()) << ": " << refused.what()
                  << "\n";
        return kTrouble;
    }
    if (!settings.diff_dir.empty()) {
        fs::create_directories(settings.diff_dir, error);
        if (error) {
            std::cerr << kProgram << ": cannot create " << settings.diff_dir.string() << ": " << error.message()
                      << "\n";
            return kTrouble;
        }
    }

    // Ctrl-C or SIGTERM lets the picture being written finish (or removes its partial
    // file) and ends the program by that signal, with no half-written file behind.
    browser::note_interruptions();
    const int status =
        folders ? compare_folders(settings)
                : compare_pair(settings.expected.filename().string(), settings.expected, settings.actual, settings);
    browser::stop_if_interrupted();
    return status;
}
