#pragma once
// Runs the stage's own program (STAGE_PROGRAM, set by cmake/Stage.cmake) the way a
// reader does, and reads back the state dump it writes (--dump FILE, common/state_dump.h).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <csignal>

#include <sys/wait.h>
#include <unistd.h>

#include "scratch_folder.h"

namespace test {

// g++ and clang both define __SANITIZE_ADDRESS__ under -fsanitize=address (clang from 14 on).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool underAddressSanitizer = true;
#else
inline constexpr bool underAddressSanitizer = false;
#endif

struct ProgramRun {
    int status = -1;         // the exit status; -1 when the program did not exit normally
    std::string error_text;  // what it printed to stderr
};

inline std::string quoted(const std::filesystem::path& path) {
    std::string text = "'";
    text += path.string();
    text += "'";
    return text;
}

inline std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `arguments` as they would follow the program's name in a shell; its output goes to
// files in `folder`. `before` is shell text run first in the same shell ("cd DIR && ",
// "ulimit -v KB; ").
inline ProgramRun runStageProgram(const ScratchFolder& folder, const std::string& arguments,
                                  const std::string& before = "") {
    // Not "127 == 0" when the program is not there: the build that makes it.
    if (!std::filesystem::exists(STAGE_PROGRAM)) {
        FAIL("the stage's program " << STAGE_PROGRAM << " is not built: cmake --build <build folder> --target "
                                    << std::filesystem::path(STAGE_PROGRAM).filename().string());
    }
    const std::filesystem::path out = folder.path / "stdout.txt", err = folder.path / "stderr.txt";
    std::string command = before + quoted(STAGE_PROGRAM);
    command.append(" ").append(arguments).append(" >").append(quoted(out)).append(" 2>").append(quoted(err));
    const int raw = std::system(command.c_str());
    ProgramRun run;
    if (raw != -1 && WIFEXITED(raw)) run.status = WEXITSTATUS(raw);
    run.error_text = readText(err);
    return run;
}

// A shell command started in the background; its process id. A command that starts
// with "exec " makes the id its program's own, so that a signal sent to it reaches the
// program. own_group puts it in a process group of its own, whose id is the same, so
// that a test can signal the group as Ctrl-C does.
inline pid_t startShell(const std::string& command, bool own_group = false) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        if (own_group) ::setpgid(0, 0);
        // The signals a test sends must reach the program, whatever the test runner ignores.
        ::signal(SIGINT, SIG_DFL);
        ::signal(SIGTERM, SIG_DFL);
        ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    if (own_group) ::setpgid(pid, pid);  // whichever of the two runs first
    return pid;
}

// The program started in the background, as runStageProgram runs it; its process id.
inline pid_t startStageProgram(const ScratchFolder& folder, const std::string& arguments) {
    const std::filesystem::path out = folder.path / "stdout.txt", err = folder.path / "stderr.txt";
    std::string command = "exec ";
    command.append(quoted(STAGE_PROGRAM)).append(" ").append(arguments);
    command.append(" >").append(quoted(out)).append(" 2>").append(quoted(err));
    return startShell(command);
}

inline bool isOneLine(const std::string& text) { return !text.empty() && text.find('\n') == text.size() - 1; }

// A refused run: status 2, one line that mentions `says`, and nothing new in `folder`
// beyond what was there and the captured output.
inline void checkRefused(const ScratchFolder& folder, const std::string& command, const std::string& says,
                         const std::string& before = "") {
    std::vector<std::string> files = folder.files();
    for (const char* output : {"stdout.txt", "stderr.txt"}) {
        if (std::find(files.begin(), files.end(), output) == files.end()) files.push_back(output);
    }
    std::sort(files.begin(), files.end());
    const ProgramRun run = runStageProgram(folder, command, before);
    INFO(command << "\n" << run.error_text);
    CHECK(run.status == 2);
    CHECK(isOneLine(run.error_text));
    CHECK_THAT(run.error_text, Catch::Contains(says));
    CHECK(folder.files() == files);
}

// One line of a state dump: step,index,shape,cx,cy,angle,vx,vy,angular_velocity, and
// from 5.4 on the body's id after the index (common/state_dump.h).
struct DumpRow {
    long step = 0;
    std::size_t index = 0;
    std::optional<std::uint64_t> id;
    std::string shape;
    double cx = 0, cy = 0, angle = 0, vx = 0, vy = 0, angular_velocity = 0;
};

// Every row after the header. A field that does not read completely fails the test.
inline std::vector<DumpRow> readDump(const std::filesystem::path& file) {
    std::istringstream text(readText(file));
    std::string line;
    std::getline(text, line);
    const bool ids = line == "step,index,id,shape,cx,cy,angle,vx,vy,angular_velocity";
    REQUIRE((ids || line == "step,index,shape,cx,cy,angle,vx,vy,angular_velocity"));
    std::vector<DumpRow> rows;
    while (std::getline(text, line)) {
        std::vector<std::string> field;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) field.push_back(cell);
        std::optional<std::uint64_t> id;
        if (ids) {
            REQUIRE(field.size() == 10);
            std::size_t used = 0;
            id = std::stoull(field[2], &used);
            REQUIRE(used == field[2].size());
            field.erase(field.begin() + 2);
        }
        REQUIRE(field.size() == 9);
        const auto number = [](const std::string& cell) {
            std::size_t used = 0;
            const double value = std::stod(cell, &used);
            REQUIRE(used == cell.size());
            return value;
        };
        rows.push_back({std::stol(field[0]), std::stoul(field[1]), id, field[2], number(field[3]), number(field[4]),
                        number(field[5]), number(field[6]), number(field[7]), number(field[8])});
    }
    return rows;
}

}  // namespace test
