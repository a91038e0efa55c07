#pragma once
// The keyboard. The book's UserControl reacts to key codes from onkeydown; our
// programs replay a script of key presses instead, so every run is repeatable.
//
// Script grammar: tokens separated by spaces, each  KEY[*COUNT][@FRAME]
//   KEY    a letter, a digit, `comma` (or `,`), `up`, `down` or `slash` (or `/`);
//          case-insensitive
//   COUNT  press it COUNT times (>= 1)
//   FRAME  press it before frame FRAME (0-based); a token without @ happens at the
//          frame of the token before it (frame 0 at the start)
// Example: "f*3 g@10 up e*5@20"
// A token that starts with "drag:" is a drag of the pointer, one point a frame, with the
// same optional @FRAME (pointer.h): "drag:100,50*3/120,50@10". Before a frame the page
// gets that frame's key presses first, then its pointer's event.

#include <bitset>
#include <cstddef>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "pointer.h"

namespace browser {

// The keys in rows, letters, digits, the rest (the layout would put one on a line).
// Slash came last, for a page that had given every letter a job and needed one more:
// a key of its own, whatever that page makes of it (its --help says).
// clang-format off
enum class Key {
    A, B, C, D, E, F, G, H, I, J, K, L, M, N, O, P, Q, R, S, T, U, V, W, X, Y, Z,
    Digit0, Digit1, Digit2, Digit3, Digit4, Digit5, Digit6, Digit7, Digit8, Digit9,
    Comma, Up, Down, Slash,
};
// clang-format on

inline constexpr int kKeyCount = static_cast<int>(Key::Slash) + 1;

// The key's name as a script writes it ("f", "7", "comma", "up", "slash").
std::string key_name(Key key);
std::optional<Key> parse_key(std::string_view name);
// 0..9 for Digit0..Digit9, nothing for any other key.
std::optional<int> digit_value(Key key);

struct KeyScriptError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

// The keys one page's script reacts to: what its --help lists, what a key script for it
// may press, and what its live window passes on from the keyboard.
class KeySet {
public:
    KeySet() = default;
    // Key names separated by spaces; "a-z" and "0-9" style ranges stand for every key
    // between their two ends ("0-9 up down f g"). Throws KeyScriptError naming a bad word.
    static KeySet parse(std::string_view names);

    bool contains(Key key) const { return members_.test(static_cast<std::size_t>(key)); }
    bool empty() const { return members_.none(); }
    void add(const KeySet& other) { members_ |= other.members_; }
    // The members in the order of Key, letters first, three or more neighbouring
    // digits as a range: "a, d, e, f, 0-9, comma, up".
    std::string text() const;

private:
    std::bitset<kKeyCount> members_;
};

class KeyScript {
public:
    // Limits that keep a typo ("f*1000000000") from making a run allocate or loop for ages.
    static constexpr int kMaxCount = 2'000;
    static constexpr int kMaxFrame = 10'000'000;
    // In all, over every token: a press may add an object to the page's world, and every
    // later step may work on every pair of objects.
    static constexpr int kMaxPresses = 2'000;
    // The frames the pointer is held down, over every drag: a drag costs the page
    // nothing the keys' limits guard against, but its points are kept in memory.
    static constexpr int kMaxDragPoints = 1'000'000;

    KeyScript() = default;
    // Throws KeyScriptError with one line naming the token and listing the valid keys.
    static KeyScript parse(std::string_view script);

    // Keys pressed before frame `frame`, in script order.
    std::vector<Key> pressesAt(int frame) const;
    // How many presses there are in all.
    std::size_t pressCount() const;
    // How many presses there are of the keys in `keys`.
    std::size_t pressCount(const KeySet& keys) const;
    // The first and the last frame any key is pressed at, or a drag has a point at (-1
    // for an empty script). A drag's release, one frame after its last point, may come
    // after a run's last frame: the run ends with the pointer held.
    int firstFrame() const;
    int lastFrame() const;
    bool empty() const { return presses_.empty() && drags_.empty(); }

    // What the pointer does before `frame`: a press, a move or a release, or nothing.
    std::vector<PointerEvent> pointerAt(int frame) const;
    // Adds a drag (pointer.h) that starts after the last one ended; throws
    // KeyScriptError when it does not.
    void drag(Drag drag);
    const std::vector<Drag>& drags() const { return drags_; }
    // The first key of the script, in frame order, that `keys` does not hold.
    std::optional<Key> firstKeyOutside(const KeySet& keys) const;

    // Adds a press before `frame`, after the ones already there.
    void press(int frame, Key key);
    // The script as text that parse() reads back to the same presses: every token
    // carries its frame, and a key pressed several times in a row is one KEY*COUNT
    // token ("f@12 d*3@40 comma@40"); each drag is one token, after the keys of its
    // first frame ("drag:100,50*3/120,50@40"). "" for an empty script.
    std::string text() const;
    friend bool operator==(const KeyScript&, const KeyScript&) = default;

private:
    std::map<int, std::vector<Key>> presses_;
    std::vector<Drag> drags_;  // in the order of their frames, none overlapping
};

}  // namespace browser
