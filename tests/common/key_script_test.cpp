// The key script: the repeatable stand-in for a reader's keyboard.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "keys.h"

using browser::Key;
using browser::KeyScript;
using browser::KeyScriptError;

namespace {

using Keys = std::vector<Key>;

// The message of the error `script` throws, or "" when it parses.
std::string error_of(const std::string& script) {
    try {
        KeyScript::parse(script);
    } catch (const KeyScriptError& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST_CASE("key_script: every key has a name that parses back to it") {
    for (int i = 0; i < browser::kKeyCount; ++i) {
        const Key key = static_cast<Key>(i);
        INFO(key_name(key));
        CHECK(browser::parse_key(browser::key_name(key)) == key);
    }
    CHECK(browser::key_name(Key::F) == "f");
    CHECK(browser::key_name(Key::Digit7) == "7");
    CHECK(browser::key_name(Key::Comma) == "comma");
    CHECK(browser::key_name(Key::Up) == "up");
    CHECK(browser::key_name(Key::Down) == "down");
    CHECK(browser::key_name(Key::Slash) == "slash");
    CHECK(browser::kKeyCount == 26 + 10 + 4);
}

TEST_CASE("key_script: key names are case-insensitive and comma and slash have two spellings") {
    CHECK(browser::parse_key("G") == Key::G);
    CHECK(browser::parse_key("UP") == Key::Up);
    CHECK(browser::parse_key("Down") == Key::Down);
    CHECK(browser::parse_key("CoMmA") == Key::Comma);
    CHECK(browser::parse_key(",") == Key::Comma);
    CHECK(browser::parse_key("Slash") == Key::Slash);
    CHECK(browser::parse_key("/") == Key::Slash);
    CHECK_FALSE(browser::parse_key("\\").has_value());
    CHECK_FALSE(browser::parse_key("").has_value());
    CHECK_FALSE(browser::parse_key("left").has_value());
    CHECK_FALSE(browser::parse_key("ff").has_value());
    CHECK_FALSE(browser::parse_key(".").has_value());
}

TEST_CASE("key_script: digit_value gives the digit of digit keys only") {
    CHECK(browser::digit_value(Key::Digit0) == 0);
    CHECK(browser::digit_value(Key::Digit9) == 9);
    CHECK_FALSE(browser::digit_value(Key::Z).has_value());
    CHECK_FALSE(browser::digit_value(Key::Comma).has_value());
}

TEST_CASE("key_script: an empty script presses nothing") {
    for (const char* script : {"", "   ", " \t\n "}) {
        const KeyScript keys = KeyScript::parse(script);
        CHECK(keys.empty());
        CHECK(keys.lastFrame() == -1);
        CHECK(keys.pressesAt(0).empty());
    }
}

TEST_CASE("key_script: tokens without @ come at frame 0 in script order") {
    const KeyScript keys = KeyScript::parse("f g up");
    CHECK(keys.pressesAt(0) == Keys{Key::F, Key::G, Key::Up});
    CHECK(keys.pressesAt(1).empty());
    CHECK(keys.lastFrame() == 0);
}

TEST_CASE("key_script: counts repeat a key") {
    const KeyScript keys = KeyScript::parse("f*3 g");
    CHECK(keys.pressesAt(0) == Keys{Key::F, Key::F, Key::F, Key::G});
}

TEST_CASE("key_script: @ sets the frame and later tokens carry it over") {
    const KeyScript keys = KeyScript::parse("f*3 g@10 up e*2@20 down");
    CHECK(keys.pressesAt(0) == Keys{Key::F, Key::F, Key::F});
    CHECK(keys.pressesAt(10) == Keys{Key::G, Key::Up});
    CHECK(keys.pressesAt(20) == Keys{Key::E, Key::E, Key::Down});
    CHECK(keys.pressesAt(5).empty());
    CHECK(keys.pressesAt(21).empty());
    CHECK(keys.lastFrame() == 20);
}

TEST_CASE("key_script: a frame named twice collects presses in script order") {
    const KeyScript keys = KeyScript::parse("a@4 b@2 c@4");
    CHECK(keys.pressesAt(4) == Keys{Key::A, Key::C});
    CHECK(keys.pressesAt(2) == Keys{Key::B});
    CHECK(keys.lastFrame() == 4);
}

TEST_CASE("key_script: mixed case, digits, comma and any whitespace") {
    const KeyScript keys = KeyScript::parse("  F*2@1\tUp\n, comma*2@3 7 ,*1@3 ");
    CHECK(keys.pressesAt(1) == Keys{Key::F, Key::F, Key::Up, Key::Comma});
    CHECK(keys.pressesAt(3) == Keys{Key::Comma, Key::Comma, Key::Digit7, Key::Comma});
}

TEST_CASE("key_script: the limits themselves are accepted") {
    const std::string count = std::to_string(KeyScript::kMaxCount);
    const std::string frame = std::to_string(KeyScript::kMaxFrame);
    const KeyScript keys = KeyScript::parse("x*" + count + "@" + frame);
    CHECK(keys.pressesAt(KeyScript::kMaxFrame).size() == static_cast<std::size_t>(KeyScript::kMaxCount));
    CHECK(keys.pressCount() == static_cast<std::size_t>(KeyScript::kMaxPresses));
}

TEST_CASE("key_script: more presses in all than a run can afford are refused, however they are spread") {
    // kMaxPresses - 1 in one token, then two more: one past the limit.
    const std::string script = "f*" + std::to_string(KeyScript::kMaxPresses - 1) + " g h@3";
    const std::string message = error_of(script);
    CHECK(message == "the script presses more than " + std::to_string(KeyScript::kMaxPresses) +
                         " keys in all (each press may add an object that every later step works on)");
    CHECK(KeyScript::parse("f*" + std::to_string(KeyScript::kMaxPresses - 1) + " g").pressCount() ==
          static_cast<std::size_t>(KeyScript::kMaxPresses));
}

TEST_CASE("key_script: a token with control characters or bytes that are not UTF-8 is shown escaped") {
    const std::string message = error_of("f\x1b[2J g\xff");
    CHECK(message.find('\x1b') == std::string::npos);
    CHECK_THAT(message, Catch::Contains(R"("f\x1b[2J")"));
    CHECK(error_of("g\xff").find(R"("g\xff")") != std::string::npos);
}

TEST_CASE("key_script: every bad token is named in a one-line message with the valid keys") {
    const std::string too_many = "f*" + std::to_string(KeyScript::kMaxCount + 1);
    const std::string too_late = "f@" + std::to_string(KeyScript::kMaxFrame + 1);
    // A table, kept in rows (the layout would put one token on a line).
    // clang-format off
    const char* const bad_tokens[] = {
        "q!",   "left", "ff",   "f*0",  "f*-1", "f*x",  "f*",   "f*2*3", "f*+2", "f*1.5",
        "f@",   "f@-1", "f@x",  "f@1@2", "f@3*2", "f@+1", "f@1e3", "*3",   "@5",   "*2@5",
        "99999999999999999999", "f*99999999999999999999", "f@99999999999999999999",
    };
    // clang-format on
    std::vector<std::string> tokens(std::begin(bad_tokens), std::end(bad_tokens));
    tokens.push_back(too_many);
    tokens.push_back(too_late);
    for (const std::string& token : tokens) {
        // A good token before it must not hide the error.
        const std::string message = error_of("g@2 " + token + " h");
        INFO("token: " << token << "\nmessage: " << message);
        CHECK_THAT(message, Catch::Contains("\"" + token + "\""));
        CHECK_THAT(message, Catch::Contains("a-z, 0-9, comma, up, down, slash"));
        CHECK(message.find('\n') == std::string::npos);
    }
}

TEST_CASE("key_script: the message says what is wrong with the token") {
    CHECK_THAT(error_of("q*x"), Catch::Contains("count must be a whole number"));
    CHECK_THAT(error_of("f*0"), Catch::Contains("count must be a whole number"));
    CHECK_THAT(error_of("f@-1"), Catch::Contains("frame must be a whole number"));
    CHECK_THAT(error_of("left@3"), Catch::Contains("unknown key \"left\""));
    CHECK_THAT(error_of("@3"), Catch::Contains("key name must come first"));
}

TEST_CASE("key_script: a key set reads names and ranges, and lists its keys in Key order") {
    const browser::KeySet set = browser::KeySet::parse("  w a s d\t0-9 UP down , f-h / ");
    for (const Key key :
         {Key::W, Key::A, Key::S, Key::D, Key::Up, Key::Down, Key::Comma, Key::F, Key::G, Key::H, Key::Slash}) {
        INFO(browser::key_name(key));
        CHECK(set.contains(key));
    }
    for (int digit = 0; digit <= 9; ++digit)
        CHECK(set.contains(static_cast<Key>(static_cast<int>(Key::Digit0) + digit)));
    CHECK_FALSE(set.contains(Key::E));
    CHECK_FALSE(set.contains(Key::I));
    // Letters one by one, three or more neighbouring digits as a range.
    CHECK(set.text() == "a, d, f, g, h, s, w, 0-9, comma, up, down, slash");
    CHECK(browser::KeySet::parse("1 2 5").text() == "1, 2, 5");
    CHECK(browser::KeySet::parse("3-5").text() == "3-5");
    CHECK(browser::KeySet::parse("").empty());
    CHECK(browser::KeySet::parse("").text().empty());
    CHECK_THROWS_AS(browser::KeySet::parse("f left"), KeyScriptError);
    CHECK_THROWS_AS(browser::KeySet::parse("9-0"), KeyScriptError);  // backwards
    CHECK_THROWS_AS(browser::KeySet::parse("a-9"), KeyScriptError);  // across letters and digits
    CHECK_THROWS_AS(browser::KeySet::parse(",-a"), KeyScriptError);
}

TEST_CASE("key_script: the first key outside a set, in frame order") {
    const browser::KeySet keys = browser::KeySet::parse("f g 0-9");
    CHECK_FALSE(KeyScript::parse("f g@3 7*2").firstKeyOutside(keys).has_value());
    CHECK(KeyScript::parse("q@9 f x@2").firstKeyOutside(keys) == Key::X);  // frame 2 before frame 9
    CHECK_FALSE(KeyScript().firstKeyOutside(keys).has_value());
}

TEST_CASE("key_script: a script written as text reads back to the same presses") {
    KeyScript script;
    script.press(12, Key::F);
    script.press(40, Key::D);
    script.press(40, Key::D);
    script.press(40, Key::D);
    script.press(40, Key::Comma);
    script.press(40, Key::D);
    script.press(0, Key::Up);
    // Frames in order; a run of one key is one KEY*COUNT token; order within a frame kept.
    CHECK(script.text() == "up@0 f@12 d*3@40 comma@40 d@40");
    CHECK(KeyScript::parse(script.text()) == script);
    CHECK(KeyScript::parse(script.text()).pressesAt(40) == Keys{Key::D, Key::D, Key::D, Key::Comma, Key::D});
    CHECK(KeyScript().text().empty());
    CHECK(KeyScript::parse(KeyScript().text()).empty());

    // More presses in a row than one token's count may hold are split over tokens.
    KeyScript held;
    for (int i = 0; i < KeyScript::kMaxCount + 5; ++i) held.press(7, Key::S);
    CHECK(held.text() == "s*" + std::to_string(KeyScript::kMaxCount) + "@7 s*5@7");
    // One token may hold as many presses as a whole script: that many and more are
    // refused on replay, in one line, like any script too long.
    static_assert(KeyScript::kMaxCount == KeyScript::kMaxPresses);
    CHECK_THROWS_AS(KeyScript::parse(held.text()), browser::KeyScriptError);
}
