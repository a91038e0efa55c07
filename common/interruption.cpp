#include "interruption.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cctype>
#include <charconv>
#include <system_error>
#include <vector>

namespace browser {
namespace {

namespace fs = std::filesystem;

volatile sig_atomic_t g_pending = 0;

// The first signal is noted; a second one, from a reader who will not wait, takes its
// default action at once. Both are async-signal-safe.
extern "C" void note_signal(int signal) {
    if (g_pending != 0) {
        ::signal(signal, SIG_DFL);
        ::raise(signal);
        return;
    }
    g_pending = signal;
}

// The registered leftovers. Only ever touched outside the signal handler.
std::vector<fs::path>& leftovers() {
    static std::vector<fs::path> paths;
    return paths;
}

bool process_is_gone(pid_t pid) { return ::kill(pid, 0) != 0 && errno == ESRCH; }

}  // namespace

void note_interruptions() {
    static bool installed = false;
    if (installed) return;
    installed = true;
    struct sigaction action {};
    action.sa_handler = note_signal;
    sigemptyset(&action.sa_mask);
    for (const int signal : {SIGINT, SIGTERM}) {
        // A signal the caller's parent told us to ignore (nohup, a background job) stays ignored.
        struct sigaction previous {};
        if (::sigaction(signal, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
        ::sigaction(signal, &action, nullptr);
    }
}

int pending_interruption() { return g_pending; }

void end_by_interruption(int signal) {
    for (const fs::path& path : leftovers()) {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
    ::signal(signal, SIG_DFL);
    ::raise(signal);
    ::_exit(128 + signal);  // a blocked signal: end the same way a shell would show it
}

void stop_if_interrupted() {
    if (const int signal = pending_interruption(); signal != 0) end_by_interruption(signal);
}

Leftover::Leftover(fs::path path) : path_(std::move(path)) { leftovers().push_back(path_); }

Leftover::~Leftover() {
    auto& paths = leftovers();
    if (const auto found = std::find(paths.begin(), paths.end(), path_); found != paths.end()) paths.erase(found);
}

void remove_stale_leftovers(const fs::path& target, const std::string& marker) {
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    const std::string prefix = target.filename().string() + marker;
    std::error_code error;
    fs::directory_iterator entries(folder, error);
    if (error) return;
    for (const fs::directory_entry& entry : entries) {
        const std::string name = entry.path().filename().string();
        if (!name.starts_with(prefix) || name.size() == prefix.size()) continue;
        const std::string_view digits = std::string_view(name).substr(prefix.size());
        pid_t pid = 0;
        const auto [end, failure] = std::from_chars(digits.data(), digits.data() + digits.size(), pid);
        if (failure != std::errc{} || end != digits.data() + digits.size() || pid <= 0) continue;
        if (pid == ::getpid() || !process_is_gone(pid)) continue;
        std::error_code ignored;
        fs::remove_all(entry.path(), ignored);
    }
}

std::string process_suffix() {
    std::string suffix = "-";  // appended: g++ 12 warns falsely about "-" + to_string
    suffix += std::to_string(::getpid());
    return suffix;
}

}  // namespace browser
