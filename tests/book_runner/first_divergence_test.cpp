// first_divergence on dumps written by hand: which step, body and field it names, the
// tolerance it allows, the dumps it refuses, and the errata entries it points to.

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include "dump_divergence.h"
#include "known_differences.h"

using browser::DivergenceKind;

namespace {

const std::string kHeader = "step,index,shape,cx,cy,angle,vx,vy,angular_velocity\n";

std::vector<browser::DumpRow> dump(const std::string& rows) {
    std::istringstream in(kHeader + rows);
    return browser::parse_dump(in, "test.csv");
}

// A box and a circle as built (step 0), and after one update.
const std::string kStart =
    "0,0,rectangle,100,50,0,0,0,0\n"
    "0,1,circle,300,60,0,6,0,0.5\n";
const std::string kStep1Box = "1,0,rectangle,100,50.1,0,0,1,0\n";
const std::string kStep1Circle = "1,1,circle,300.1,60,0.01,6,0,0.5\n";

std::string readText(const char* file) {
    std::ifstream in(file);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("the tolerance is absolute plus relative to the larger number", "[first_divergence_test]") {
    const browser::DumpTolerance tolerance{.absolute = 1e-9, .relative = 1e-9};
    // 1e-9 + 1e-9 * 100 = 1.01e-7 around 100.
    CHECK(browser::agree(100, 100 + 1.00e-7, tolerance));
    CHECK_FALSE(browser::agree(100, 100 + 1.02e-7, tolerance));
    // Around 0 only the absolute part is left.
    CHECK(browser::agree(0, 0.9e-9, tolerance));
    CHECK_FALSE(browser::agree(0, 1.1e-9, tolerance));
}

TEST_CASE("identical dumps, and dumps within the tolerance, do not diverge", "[first_divergence_test]") {
    const auto a = dump(kStart + kStep1Box + kStep1Circle);
    CHECK_FALSE(browser::first_divergence(a, a).has_value());
    const auto b = dump(kStart + "1,0,rectangle,100,50.100000000001,0,0,1,0\n" + kStep1Circle);
    CHECK_FALSE(browser::first_divergence(a, b).has_value());
    // nan is the same as nan (both runs blew up alike), and differs from any number.
    const auto nan_a = dump(kStart + "1,0,rectangle,100,nan,0,0,1,0\n" + kStep1Circle);
    CHECK_FALSE(browser::first_divergence(nan_a, nan_a).has_value());
    REQUIRE(browser::first_divergence(nan_a, a).has_value());
}

TEST_CASE("names the first step, the first body and its first field that differ", "[first_divergence_test]") {
    const auto a = dump(kStart + kStep1Box + kStep1Circle +
                        "2,0,rectangle,100,50.3,0,0,2,0\n2,1,circle,300.2,60.1,0.02,6,1,0.5\n");
    // Step 1 agrees; at step 2 the circle's cy and vy differ, then the box's vx.
    const auto b = dump(kStart + kStep1Box + kStep1Circle +
                        "2,0,rectangle,100,50.3,0,0.5,2,0\n2,1,circle,300.2,60,0.02,6,1.5,0.5\n");
    const auto found = browser::first_divergence(a, b);
    REQUIRE(found.has_value());
    CHECK(found->kind == DivergenceKind::value);
    CHECK(found->step == 2);
    CHECK(found->index == 0);
    CHECK(found->shape == "rectangle");
    CHECK(found->field == "vx");
    CHECK(found->a == 0);
    CHECK(found->b == 0.5);
    REQUIRE(found->differing.size() == 2);
    CHECK(found->differing[1].index == 1);
    CHECK(found->differing[1].field == "cy");

    const std::string text = browser::describe(*found, "ours.csv", "book.csv", {});
    CHECK_THAT(text, Catch::Contains("step 2, body 0 (rectangle): vx is 0 in ours.csv and 0.5 in book.csv"));
    CHECK_THAT(text, Catch::Contains("body 1 (circle, cy)"));
}

TEST_CASE("a body only one dump has, a shape that differs, a run that stops", "[first_divergence_test]") {
    const auto a = dump(kStart + kStep1Box + kStep1Circle);
    SECTION("a body gone from one list") {
        const auto found = browser::first_divergence(a, dump(kStart + kStep1Box));
        REQUIRE(found.has_value());
        CHECK(found->kind == DivergenceKind::extra_body);
        CHECK(found->step == 1);
        CHECK(found->index == 1);
        CHECK(found->shape == "circle");
        CHECK(found->a_is_longer);
        CHECK(found->bodies_before_b == 2);
        CHECK(found->bodies_b == 1);
    }
    SECTION("a rectangle where the other has a circle") {
        const auto found =
            browser::first_divergence(a, dump(kStart + kStep1Box + "1,1,rectangle,300.1,60,0.01,6,0,0.5\n"));
        REQUIRE(found.has_value());
        CHECK(found->kind == DivergenceKind::shape);
        CHECK(found->index == 1);
    }
    SECTION("one run has no more steps") {
        const auto found = browser::first_divergence(dump(kStart), a);
        REQUIRE(found.has_value());
        CHECK(found->kind == DivergenceKind::steps_end);
        CHECK(found->step == 1);
        CHECK_FALSE(found->a_is_longer);
    }
    SECTION("a different start is a different scene, whatever the stage") {
        const auto found =
            browser::first_divergence(a, dump("0,0,rectangle,100,51,0,0,0,0\n0,1,circle,300,60,0,6,0,0.5\n"));
        REQUIRE(found.has_value());
        CHECK(found->step == 0);
        CHECK_FALSE(errata::known_difference(*found, "4.4").has_value());
        CHECK_THAT(browser::describe(*found, "a", "b", {}), Catch::Contains("same scene file"));
    }
}

TEST_CASE("files that are not state dumps are refused with their line", "[first_divergence_test]") {
    auto refused = [](const std::string& text) {
        std::istringstream in(text);
        try {
            browser::parse_dump(in, "bad.csv");
        } catch (const browser::DumpError& error) {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    CHECK_THAT(refused("x,y\n"), Catch::StartsWith("bad.csv:1: not a state dump"));
    CHECK_THAT(refused(kHeader + "0,0,rectangle,1,2,3\n"),
               Catch::StartsWith("bad.csv:2: a row has 9 fields, this has 6"));
    CHECK_THAT(refused(kHeader + "0,0,Triangle,1,2,3,4,5,6\n"), Catch::Contains("the shape must be a plain word"));
    CHECK_THAT(refused(kHeader + "0,0,circle,1,2,x,4,5,6\n"), Catch::Contains("angle is not a number"));
    // Bodies numbered 0, 2: a row is missing; a step that goes back; a dump not starting at step 0.
    CHECK_THAT(refused(kHeader + "0,0,circle,1,2,3,4,5,6\n0,2,circle,1,2,3,4,5,6\n"),
               Catch::StartsWith("bad.csv:3: rows must go"));
    CHECK_THAT(refused(kHeader + "0,0,circle,1,2,3,4,5,6\n1,0,circle,1,2,3,4,5,6\n0,0,circle,1,2,3,4,5,6\n"),
               Catch::StartsWith("bad.csv:4:"));
    CHECK_THAT(refused(kHeader + "1,0,circle,1,2,3,4,5,6\n"), Catch::StartsWith("bad.csv:2:"));
    CHECK(refused(kHeader + kStart) == "accepted");
}

TEST_CASE("a dump with ids (5.4 on) reads, and compares body by body with one without", "[first_divergence_test]") {
    const std::string with_ids = "step,index,id,shape,cx,cy,angle,vx,vy,angular_velocity\n";
    std::istringstream in(with_ids + "0,0,1,rectangle,100,50,0,0,0,0\n0,1,2,circle,300,60,0,6,0,0.5\n" +
                          "1,0,1,rectangle,100,50.1,0,0,1,0\n1,1,2,circle,300.1,60,0.01,6,0,0.5\n");
    const auto ids = browser::parse_dump(in, "ids.csv");
    REQUIRE(ids.size() == 4);
    CHECK(ids[1].id == 2u);
    CHECK(ids[1].shape == "circle");
    CHECK(ids[1].values[5] == 0.5);
    CHECK_FALSE(dump(kStart)[0].id.has_value());
    CHECK_FALSE(browser::first_divergence(ids, dump(kStart + kStep1Box + kStep1Circle)).has_value());
    const auto moved = dump(kStart + kStep1Box + "1,1,circle,300.1,60,0.01,6,0,0.7\n");
    const auto divergence = browser::first_divergence(ids, moved);
    REQUIRE(divergence.has_value());
    CHECK(divergence->index == 1);
    CHECK(divergence->field == "angular_velocity");

    std::istringstream short_row(with_ids + "0,0,rectangle,100,50,0,0,0,0\n");
    CHECK_THROWS_WITH(browser::parse_dump(short_row, "bad.csv"), "bad.csv:2: a row has 10 fields, this has 9");
    std::istringstream bad_id(with_ids + "0,0,x,rectangle,100,50,0,0,0,0\n");
    CHECK_THROWS_WITH(browser::parse_dump(bad_id, "bad.csv"), "bad.csv:2: the id must be a whole number");
}

TEST_CASE("the errata entry that explains a divergence, by stage and sign", "[first_divergence_test]") {
    const auto a = dump(kStart + kStep1Box + kStep1Circle);
    const auto spun = dump(kStart + kStep1Box + "1,1,circle,300.1,60,0.01,6,0,0.7\n");
    const auto circle = browser::first_divergence(a, spun);
    REQUIRE(circle.has_value());
    // A circle's numbers: its inertia, which only the angular impulse of 4.4 on uses.
    REQUIRE(errata::known_difference(*circle, "4.4").has_value());
    CHECK(errata::known_difference(*circle, "4.4")->heading == "Circle inertia (fixed, 4.1 on)");
    CHECK(errata::known_difference(*circle, "5.1")->heading == "Circle inertia (fixed, 4.1 on)");
    CHECK_FALSE(errata::known_difference(*circle, "4.3").has_value());
    CHECK_THAT(errata::explanation(*circle, "4.4"),
               Catch::Contains("known difference: docs/errata.md#circle-inertia-fixed-41-on"));
    CHECK_THAT(errata::explanation(*circle, "4.3"), Catch::Contains("no entry of docs/errata.md"));

    // A box's numbers are no circle's inertia.
    const auto box = browser::first_divergence(a, dump(kStart + "1,0,rectangle,100,50.1,0,0,1,0.1\n" + kStep1Circle));
    REQUIRE(box.has_value());
    CHECK_FALSE(errata::known_difference(*box, "4.4").has_value());

    // A body leaving the list, and a run that stops: the book's 5.1 removal and frozen page.
    const auto removed = browser::first_divergence(a, dump(kStart + kStep1Box));
    CHECK(errata::known_difference(*removed, "5.1")->heading ==
          "Out-of-bounds removal no longer skips the next shape's step (5.1)");
    CHECK_FALSE(errata::known_difference(*removed, "4.4").has_value());
    const auto stopped = browser::first_divergence(a, dump(kStart));
    CHECK(errata::known_difference(*stopped, "5.1")->heading ==
          "The selection survives the removal of the selected shape (fixed, 5.1)");
}

TEST_CASE("every errata entry the table names is a heading of docs/errata.md", "[first_divergence_test]") {
    const std::string errata = readText(ERRATA_FILE);
    REQUIRE_FALSE(errata.empty());
    for (const errata::KnownDifference& known : errata::known_differences()) {
        INFO(known.heading);
        CHECK_THAT(errata, Catch::Contains("\n### " + std::string(known.heading) + "\n"));
    }
    CHECK(errata::heading_anchor("Circle inertia (fixed, 4.1 on)") == "circle-inertia-fixed-41-on");
    CHECK(errata::heading_anchor("Out-of-bounds removal no longer skips the next shape's step (5.1)") ==
          "out-of-bounds-removal-no-longer-skips-the-next-shapes-step-51");
}

TEST_CASE("an infinity is the same as itself only, never a finite number, however large the tolerance",
          "[first_divergence_test]") {
    // The book runner writes inf when the book's code overflows (issue 36: called equal).
    const auto finite = dump(kStart + "1,0,rectangle,100,50.1,0,0,1,0\n" + kStep1Circle);
    const auto overflowed = dump(kStart + "1,0,rectangle,100,inf,0,0,1,0\n" + kStep1Circle);
    const auto below = dump(kStart + "1,0,rectangle,100,-inf,0,0,1,0\n" + kStep1Circle);
    const browser::DumpTolerance loose{.absolute = 1e6, .relative = 1};
    const auto found = browser::first_divergence(finite, overflowed, loose);
    REQUIRE(found.has_value());
    CHECK(found->field == "cy");
    CHECK_THAT(browser::describe(*found, "a", "b", loose), !Catch::Contains("nan"));
    // inf against itself is no divergence ("they differ by nan" once said it was).
    CHECK_FALSE(browser::first_divergence(overflowed, overflowed).has_value());
    REQUIRE(browser::first_divergence(overflowed, below).has_value());
}

TEST_CASE("a dump may hold columns first_divergence does not compare, in any place", "[first_divergence_test]") {
    // A body's id, as a later stage's dump may add (the physics fields are what is compared).
    std::istringstream with_id(
        "step,id,index,shape,cx,cy,angle,vx,vy,angular_velocity\n"
        "0,7,0,rectangle,100,50,0,0,0,0\n0,8,1,circle,300,60,0,6,0,0.5\n"
        "1,7,0,rectangle,100,50.1,0,0,1,0\n1,8,1,circle,300.1,60,0.01,6,0,0.5\n");
    const auto a = browser::parse_dump(with_id, "id.csv");
    CHECK_FALSE(browser::first_divergence(a, dump(kStart + kStep1Box + kStep1Circle)).has_value());
    std::istringstream missing("step,index,shape,cx,cy,angle,vx,vy\n");
    CHECK_THROWS_WITH(browser::parse_dump(missing, "short.csv"), Catch::StartsWith("short.csv:1: not a state dump"));
}
