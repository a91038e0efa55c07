#pragma once
// A check made by a helper but reported at the test's line. Catch's CHECK names the
// line it is written on, so a check inside a helper used by ten cases names the helper
// ten times and the reader cannot tell which case failed. A helper that takes
//   std::source_location where = std::source_location::current()
// as its last parameter learns the line that called it, and reports there:
//
//   test::checkedAt(where, "normal", passed, "normal of R1: expected (-0.6, -0.8), got (0.6, 0.8)");
//
// prints, on failure,
//   rectangle_circle_collision_test.cpp:63: FAILED:
//     CHECK( normal )
//   with expansion:
//     normal of R1: expected (-0.6, -0.8), got (0.6, 0.8)

#include <catch2/catch.hpp>

#include <ostream>
#include <source_location>
#include <string>
#include <utility>

namespace test {

namespace detail {
// What Catch prints under "with expansion": the sentence the helper wrote.
class Sentence final : public Catch::ITransientExpression {
public:
    Sentence(bool passed, std::string text) : ITransientExpression(false, passed), text_(std::move(text)) {}
    void streamReconstructedExpression(std::ostream& out) const override { out << text_; }

private:
    std::string text_;
};
}  // namespace detail

// Records one check at `where`: passed or failed, `quantity` (a string literal: Catch
// keeps it as it is) in the CHECK( ) line and `text` under it. `stop` makes a failure
// end the test case, as REQUIRE does.
inline void checkedAt(const std::source_location& where, const char* quantity, bool passed, std::string text,
                      bool stop = false) {
    Catch::AssertionHandler handler(
        stop ? "REQUIRE" : "CHECK", Catch::SourceLineInfo(where.file_name(), where.line()), quantity,
        stop ? Catch::ResultDisposition::Normal : Catch::ResultDisposition::ContinueOnFailure);
    handler.handleExpr(detail::Sentence(passed, std::move(text)));
    handler.complete();
}

}  // namespace test
