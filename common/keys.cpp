#include "keys.h"

#include <algorithm>
#include <charconv>

#include "message_text.h"

namespace browser {
namespace {

constexpr int kLetterCount = 26;
constexpr int kDigitCount = 10;
constexpr const char* kValidKeys = "keys: a-z, 0-9, comma, up, down, slash; drag:X,Y/X,Y...";
constexpr std::string_view kDragPrefix = "drag:";

// The whole of `text` as a number in [low, high], or nothing: no sign, no spaces, no
// trailing characters, so "3x", "+3" and "" are all rejected.
std::optional<int> whole_number(std::string_view text, int low, int high) {
    int value = 0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc{} || stop != end || value < low || value > high) {
        return std::nullopt;
    }
    return value;
}

[[noreturn]] void reject(std::string_view token, const std::string& reason) {
    throw KeyScriptError("bad key script token " + in_quotes(token) + ": " + reason + " (" + kValidKeys + ")");
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

}  // namespace

std::string key_name(Key key) {
    const int index = static_cast<int>(key);
    if (key >= Key::A && key <= Key::Z) return std::string(1, static_cast<char>('a' + index));
    if (const auto digit = digit_value(key)) return std::string(1, static_cast<char>('0' + *digit));
    switch (key) {
        case Key::Comma: return "comma";
        case Key::Up: return "up";
        case Key::Down: return "down";
        case Key::Slash: return "slash";
        default: return "?";  // unreachable: every letter and digit returned above
    }
}

std::optional<Key> parse_key(std::string_view name) {
    std::string lower(name);
    for (char& c : lower) {
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    }
    if (lower.size() == 1) {
        const char c = lower[0];
        if (c >= 'a' && c <= 'z') return static_cast<Key>(static_cast<int>(Key::A) + (c - 'a'));
        if (c >= '0' && c <= '9') return static_cast<Key>(static_cast<int>(Key::Digit0) + (c - '0'));
        if (c == ',') return Key::Comma;
        if (c == '/') return Key::Slash;
        return std::nullopt;
    }
    if (lower == "comma") return Key::Comma;
    if (lower == "up") return Key::Up;
    if (lower == "down") return Key::Down;
    if (lower == "slash") return Key::Slash;
    return std::nullopt;
}

std::optional<int> digit_value(Key key) {
    const int offset = static_cast<int>(key) - static_cast<int>(Key::Digit0);
    if (offset < 0 || offset >= kDigitCount) return std::nullopt;
    return offset;
}

KeyScript KeyScript::parse(std::string_view script) {
    static_assert(static_cast<int>(Key::Digit0) == kLetterCount, "letters come first in Key");

    KeyScript result;
    int frame = 0;  // carried from one token to the next, as the grammar says
    int presses = 0;
    int drag_points = 0;
    std::size_t pos = 0;
    while (pos < script.size()) {
        if (is_space(script[pos])) {
            ++pos;
            continue;
        }
        std::size_t end = pos;
        while (end < script.size() && !is_space(script[end])) ++end;
        const std::string_view token = script.substr(pos, end - pos);
        pos = end;

        // drag:POINTS[@FRAME] (pointer.h): the frame as a key's, then the points.
        if (token.starts_with(kDragPrefix)) {
            std::string_view points = token.substr(kDragPrefix.size());
            if (const auto at = points.find('@'); at != std::string_view::npos) {
                const auto parsed = whole_number(points.substr(at + 1), 0, kMaxFrame);
                if (!parsed) reject(token, "frame must be a whole number from 0 to " + std::to_string(kMaxFrame));
                frame = *parsed;
                points = points.substr(0, at);
            }
            DragPoints parsed = parse_drag_points(points, static_cast<std::size_t>(kMaxDragPoints - drag_points));
            if (!parsed.refusal.empty()) reject(token, parsed.refusal);
            drag_points += static_cast<int>(parsed.points.size());
            try {
                result.drag({frame, std::move(parsed.points)});
            } catch (const KeyScriptError& error) {
                reject(token, error.what());
            }
            continue;
        }
        // KEY[*COUNT][@FRAME]: everything after the first '@' is the frame, so a stray
        // '*' or second '@' there is reported as a bad frame.
        std::string_view rest = token;
        if (const auto at = rest.find('@'); at != std::string_view::npos) {
            const auto parsed = whole_number(rest.substr(at + 1), 0, kMaxFrame);
            if (!parsed) reject(token, "frame must be a whole number from 0 to " + std::to_string(kMaxFrame));
            frame = *parsed;
            rest = rest.substr(0, at);
        }
        int count = 1;
        if (const auto star = rest.find('*'); star != std::string_view::npos) {
            const auto parsed = whole_number(rest.substr(star + 1), 1, kMaxCount);
            if (!parsed) reject(token, "count must be a whole number from 1 to " + std::to_string(kMaxCount));
            count = *parsed;
            rest = rest.substr(0, star);
        }
        if (rest.empty()) reject(token, "a key name must come first");
        const auto key = parse_key(rest);
        if (!key) reject(token, "unknown key " + in_quotes(rest));
        if (count > kMaxPresses - presses) {
            throw KeyScriptError("the script presses more than " + std::to_string(kMaxPresses) +
                                 " keys in all (each press may add an object that every later step works on)");
        }
        presses += count;

        result.presses_[frame].insert(result.presses_[frame].end(), count, *key);
    }
    return result;
}

KeySet KeySet::parse(std::string_view names) {
    KeySet set;
    std::size_t pos = 0;
    while (pos < names.size()) {
        if (is_space(names[pos])) {
            ++pos;
            continue;
        }
        std::size_t end = pos;
        while (end < names.size() && !is_space(names[end])) ++end;
        const std::string_view word = names.substr(pos, end - pos);
        pos = end;

        // "x-y" with one letter or digit at each end is a range; "-" alone is no key.
        std::optional<Key> first, last;
        if (word.size() == 3 && word[1] == '-') {
            first = parse_key(word.substr(0, 1));
            last = parse_key(word.substr(2, 1));
            const bool same_kind = first && last && digit_value(*first).has_value() == digit_value(*last).has_value() &&
                                   *first != Key::Comma && *last != Key::Comma;
            if (!same_kind || *first > *last) {
                throw KeyScriptError("bad key range " + in_quotes(word) + " (a range is a-z or 0-9 style)");
            }
        } else {
            first = last = parse_key(word);
            if (!first) throw KeyScriptError("unknown key " + in_quotes(word) + " (" + kValidKeys + ")");
        }
        for (int k = static_cast<int>(*first); k <= static_cast<int>(*last); ++k) {
            set.members_.set(static_cast<std::size_t>(k));
        }
    }
    return set;
}

std::string KeySet::text() const {
    std::string text;
    auto append = [&](const std::string& part) {
        if (!text.empty()) text += ", ";
        text += part;
    };
    for (int k = 0; k < kKeyCount; ++k) {
        const Key key = static_cast<Key>(k);
        if (!contains(key)) continue;
        // Three or more digits in a row read best as a range; letters are listed one by
        // one, since "d-h" hides which keys a reader can press.
        int end = k + 1;
        if (digit_value(key)) {
            while (end < kKeyCount && digit_value(static_cast<Key>(end)) && contains(static_cast<Key>(end))) ++end;
        }
        if (end - k >= 3) {
            append(key_name(key) + "-" + key_name(static_cast<Key>(end - 1)));
            k = end - 1;
        } else {
            append(key_name(key));
        }
    }
    return text;
}

std::vector<Key> KeyScript::pressesAt(int frame) const {
    const auto found = presses_.find(frame);
    return found == presses_.end() ? std::vector<Key>{} : found->second;
}

std::size_t KeyScript::pressCount() const {
    std::size_t count = 0;
    for (const auto& [frame, pressed] : presses_) count += pressed.size();
    return count;
}

std::size_t KeyScript::pressCount(const KeySet& keys) const {
    std::size_t count = 0;
    for (const auto& [frame, pressed] : presses_) {
        count += static_cast<std::size_t>(
            std::count_if(pressed.begin(), pressed.end(), [&](Key key) { return keys.contains(key); }));
    }
    return count;
}

int KeyScript::firstFrame() const {
    int first = presses_.empty() ? -1 : presses_.begin()->first;
    if (!drags_.empty() && (first < 0 || drags_.front().frame < first)) first = drags_.front().frame;
    return first;
}

int KeyScript::lastFrame() const {
    const int last = presses_.empty() ? -1 : presses_.rbegin()->first;
    return drags_.empty() ? last : std::max(last, drags_.back().releaseFrame() - 1);
}

std::vector<PointerEvent> KeyScript::pointerAt(int frame) const {
    std::vector<PointerEvent> events;
    // The drags about `frame`: the one that ends there, and the one that starts there.
    auto drag = std::lower_bound(drags_.begin(), drags_.end(), frame,
                                 [](const Drag& d, int at) { return d.releaseFrame() < at; });
    for (; drag != drags_.end() && drag->frame <= frame; ++drag) {
        if (const auto event = drag->eventAt(frame)) events.push_back(*event);
    }
    return events;
}

void KeyScript::drag(Drag drag) {
    if (drag.points.empty()) throw KeyScriptError("a drag needs at least one point");
    if (!drags_.empty() && drag.frame < drags_.back().releaseFrame()) {
        throw KeyScriptError("it starts before frame " + std::to_string(drags_.back().releaseFrame()) +
                             ", where the drag before it is let go");
    }
    drags_.push_back(std::move(drag));
}

std::optional<Key> KeyScript::firstKeyOutside(const KeySet& keys) const {
    for (const auto& [frame, pressed] : presses_) {
        for (const Key key : pressed) {
            if (!keys.contains(key)) return key;
        }
    }
    return std::nullopt;
}

void KeyScript::press(int frame, Key key) { presses_[frame].push_back(key); }

std::string KeyScript::text() const {
    std::string text;
    auto drag = drags_.begin();
    // The drags that start before `frame`'s keys, or at the end, all that are left.
    const auto dragsBefore = [&](int frame) {
        for (; drag != drags_.end() && drag->frame < frame; ++drag) {
            if (!text.empty()) text += ' ';
            text += drag_text(*drag) + '@' + std::to_string(drag->frame);
        }
    };
    for (const auto& [frame, pressed] : presses_) {
        dragsBefore(frame);
        std::size_t i = 0;
        while (i < pressed.size()) {
            // A run longer than parse() takes as one count is written as several tokens.
            std::size_t repeat = i + 1;
            while (repeat < pressed.size() && pressed[repeat] == pressed[i] &&
                   repeat - i < static_cast<std::size_t>(kMaxCount)) {
                ++repeat;
            }
            if (!text.empty()) text += ' ';
            text += key_name(pressed[i]);
            if (repeat - i > 1) text += '*' + std::to_string(repeat - i);
            text += '@' + std::to_string(frame);
            i = repeat;
        }
    }
    dragsBefore(kMaxFrame + 1);
    return text;
}

}  // namespace browser
