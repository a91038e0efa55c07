#include "state_dump.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "number_format.h"

namespace browser {

namespace fs = std::filesystem;

bool is_plain_word(std::string_view text) {
    return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
}

NonFiniteState::NonFiniteState(long step, std::size_t index, std::string_view kind)
    : std::runtime_error("step " + std::to_string(step) + ": body " + std::to_string(index) + " (" + std::string(kind) +
                         ") has a position or velocity that is not a finite number; the scene is beyond what this "
                         "engine can compute, and nothing was written") {}

StateDump::StateDump(fs::path path, const fs::path& out, std::span<const fs::path> inputs)
    : file_(std::move(path), "state dump", out, inputs) {}

void StateDump::row(long step, std::size_t index, std::string_view kind, lib::Vec2 center, double angle,
                    lib::Vec2 velocity, double angular_velocity) {
    write_row(step, index, std::nullopt, kind, center, angle, velocity, angular_velocity);
}

void StateDump::row(long step, std::size_t index, std::uint64_t id, std::string_view kind, lib::Vec2 center,
                    double angle, lib::Vec2 velocity, double angular_velocity) {
    write_row(step, index, id, kind, center, angle, velocity, angular_velocity);
}

void StateDump::write_row(long step, std::size_t index, std::optional<std::uint64_t> id, std::string_view kind,
                          lib::Vec2 center, double angle, lib::Vec2 velocity, double angular_velocity) {
    if (file_.finished()) throw std::logic_error("StateDump::row after finish()");
    if (!is_plain_word(kind)) {
        std::string message = "StateDump::row: a kind must be a plain word, not \"";
        throw std::invalid_argument(message.append(kind).append("\""));
    }
    if (with_ids_ && *with_ids_ != id.has_value()) {
        throw std::logic_error(id ? "StateDump::row: an id, where the first row had none"
                                  : "StateDump::row: no id, where the first row had one");
    }
    std::string line;
    if (!with_ids_) {
        with_ids_ = id.has_value();
        line.append(id ? kDumpHeaderWithIds : kDumpHeader).append("\n");
    }
    line.append(std::to_string(step)).append(",").append(std::to_string(index));
    if (id) line.append(",").append(std::to_string(*id));
    line.append(",").append(kind);
    for (const double value : {center.x, center.y, angle, velocity.x, velocity.y, angular_velocity}) {
        line += ',';
        append_round_trip(line, value);
    }
    line += '\n';
    file_.write(line);
}

void StateDump::finish() {
    if (file_.finished()) return;
    if (!with_ids_) file_.write(std::string(kDumpHeader) + "\n");  // no body in the whole run: no id either
    file_.finish();
}

}  // namespace browser
