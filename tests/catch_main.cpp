// The one Catch2 main() every test executable links.
#define CATCH_CONFIG_MAIN
// Catch wraps its report at 80 columns, which breaks a check's sentence ("normal of the
// corner case R1: expected (-0.6, -0.8), got (0.6, 0.8)") mid-number; the code's own
// lines are 120 wide.
#define CATCH_CONFIG_CONSOLE_WIDTH 120
#include <catch2/catch.hpp>
