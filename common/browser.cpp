#include "browser.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <system_error>

#include "png_io.h"

namespace browser {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFinalPicture = "final.png";

std::string frame_picture_name(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    return name;
}

// "out/s1_1/" and "out/s1_1" name the same folder; without the trailing separator
// the staging folder lands beside it rather than inside it.
fs::path folder_path(const fs::path& given) {
    fs::path path = given.lexically_normal();
    if (!path.has_filename() && path.has_parent_path()) path = path.parent_path();
    return path;
}

// Replacing a folder deletes it, so only a folder an earlier run wrote (it holds
// final.png) or an empty one may go; a mistyped --out must not wipe someone's files.
void check_replaceable(const fs::path& out) {
    const std::string name = out.filename().string();
    if (name.empty() || name == "." || name == "..") {
        throw FileError("the current folder, its parent or the root cannot be replaced; name a folder inside it");
    }
    if (!fs::exists(out)) return;
    if (!fs::is_directory(out)) throw FileError("it exists and is not a folder");
    if (!fs::is_empty(out) && !fs::exists(out / kFinalPicture)) {
        throw FileError("it is a folder that a run did not write (it has no " + std::string(kFinalPicture) +
                         "), so it is left alone; remove it or choose another --out");
    }
}

void save(const Document& document, const fs::path& path) {
    write_png(path, render_page(document));
}

// Moves `staging` to `out`, keeping the old `out` aside until the move has worked.
void replace_folder(const fs::path& staging, const fs::path& out, const std::string& suffix) {
    if (!fs::exists(out)) {
        fs::rename(staging, out);
        return;
    }
    fs::path old = out;
    old += ".old" + suffix;
    fs::remove_all(old);
    fs::rename(out, old);
    try {
        fs::rename(staging, out);
    } catch (...) {
        std::error_code ignored;
        fs::rename(old, out, ignored);
        throw;
    }
    std::error_code ignored;  // the pictures are in place; a leftover old folder is only litter
    fs::remove_all(old, ignored);
}

std::string summary(int pictures, const fs::path& out, const std::vector<std::string>& frame_names) {
    std::string text = "wrote " + std::to_string(pictures) + (pictures == 1 ? " picture" : " pictures") +
                       " to " + (out / "").string() + " (" + kFinalPicture;
    if (frame_names.size() == 1) text += ", " + frame_names.front();
    if (frame_names.size() == 2) text += ", " + frame_names.front() + ", " + frame_names.back();
    if (frame_names.size() > 2) text += ", " + frame_names.front() + " ... " + frame_names.back();
    return text + ")";
}

}  // namespace

int run(PageScripts& scripts, Window& window, const Options& options) {
    Document& document = window.document;
    Clock& clock = window.clock;
    const fs::path out = folder_path(options.out_dir);
    // The process id keeps two runs into the same folder from sharing a staging folder.
    std::string suffix = "-";
    suffix += std::to_string(::getpid());
    fs::path staging = out;
    staging += ".partial" + suffix;

    bool staging_made = false;
    const auto discard_staging = [&] {
        std::error_code ignored;
        if (staging_made) fs::remove_all(staging, ignored);
    };

    std::string reason;
    try {
        check_replaceable(out);
        if (out.has_parent_path()) fs::create_directories(out.parent_path());
        fs::remove_all(staging);  // left over from a crashed run that had our process id
        fs::create_directory(staging);
        staging_made = true;

        std::vector<std::string> frame_names;
        for (int k = 0; k < options.frames; ++k) {
            clock.advanceFrame();
            for (const Key key : options.keys.pressesAt(k)) scripts.onKeyDown(key);
            scripts.onAnimationFrame();
            if (options.every > 0 && k % options.every == 0) {
                frame_names.push_back(frame_picture_name(k));
                save(document, staging / frame_names.back());
            }
        }
        save(document, staging / kFinalPicture);

        replace_folder(staging, out, suffix);
        staging_made = false;
        std::cout << summary(static_cast<int>(frame_names.size()) + 1, out, frame_names) << '\n';
        return 0;
    } catch (const FileError& error) {
        reason = error.what();
    } catch (const fs::filesystem_error& error) {
        reason = error.code().message();
    } catch (...) {
        discard_staging();  // a page script failed: not ours to report, but no litter either
        throw;
    }
    discard_staging();
    std::cerr << "cannot write pictures to \"" << out.string() << "\": " << reason << '\n';
    return 1;
}

}  // namespace browser
