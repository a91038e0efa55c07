#pragma once
// A fresh, empty folder for one test under the system's temporary folder, removed again
// when the test ends. The name carries the process id and a counter, so tests running
// in parallel (ctest -j) never share a folder.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <unistd.h>

namespace test {

struct ScratchFolder {
    std::filesystem::path path;

    explicit ScratchFolder(std::string_view name) {
        static int counter = 0;
        std::string leaf(name);
        leaf.append("-").append(std::to_string(::getpid())).append("-").append(std::to_string(++counter));
        path = std::filesystem::temp_directory_path() / leaf;
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    // The names of the files in the folder, sorted.
    std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const auto& entry : std::filesystem::directory_iterator(path))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const std::filesystem::path file = path / name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }
};

}  // namespace test
