#pragma once
// Ctrl-C (SIGINT) and kill's SIGTERM in the middle of a run. Their default action ends
// the process at once, which would leave the staging folder "<out>.partial-<pid>" and a
// dump's partial file behind. So while a run writes, the first of them is only noted;
// the run stops after the frame it came in, its staging folder and partial files are
// removed, and then the process ends by that same signal (a shell shows 130 or 143), as
// an interrupted program should. A second signal ends it at once.
//
// Only a power cut or SIGKILL can still leave leftovers; the next run into the same
// place removes those of a process that is gone (remove_stale_leftovers).

#include <filesystem>
#include <string>

namespace browser {

// Notes SIGINT and SIGTERM from now on, instead of dying of them. Idempotent.
void note_interruptions();

// The signal that came in since note_interruptions(), or 0.
int pending_interruption();

// Removes every path registered with a Leftover, then ends the process by `signal`'s
// default action.
[[noreturn]] void end_by_interruption(int signal);

// Ends the process as end_by_interruption() does when a signal is pending; else nothing.
void stop_if_interrupted();

// A file or folder to remove should the run be interrupted; registered for its lifetime.
class Leftover {
public:
    explicit Leftover(std::filesystem::path path);
    ~Leftover();
    Leftover(const Leftover&) = delete;
    Leftover& operator=(const Leftover&) = delete;

private:
    std::filesystem::path path_;
};

// "-<pid>": the end of the names of this process's staging folders and partial files
// ("<out>.partial-<pid>"), by which remove_stale_leftovers tells whose they are.
std::string process_suffix();

// Removes, beside `target`, what runs that are gone left of their own: every
// "<target's name><marker><pid>" (marker ".partial-", say) whose process id names no
// living process. A name with anything else after the marker is not ours, and stays.
void remove_stale_leftovers(const std::filesystem::path& target, const std::string& marker);

}  // namespace browser
