#pragma once
// How Catch prints a colour when a pixel check fails: "(255, 165, 0) orange", the
// channels and, for the page's named colours, the name, never {?}. Included by the
// fixtures the pixel checks use (stage_fixture.h, world_fixture.h, legend_color.h), so
// it is declared before any check in a test program compares two colours.

#include <catch2/catch.hpp>

#include <string>

#include "image.h"

namespace Catch {
template <>
struct StringMaker<browser::Color> {
    static std::string convert(const browser::Color& color) {
        std::string text = "(";
        text += std::to_string(color.r);
        text += ", ";
        text += std::to_string(color.g);
        text += ", ";
        text += std::to_string(color.b);
        if (color.a != 255) {
            text += ", alpha ";
            text += std::to_string(color.a);
        }
        text += ")";
        namespace colors = browser::colors;
        const struct {
            browser::Color color;
            const char* name;
        } named[] = {{colors::kBlack, "black"}, {colors::kWhite, "white"}, {colors::kBlue, "blue"},
                     {colors::kRed, "red"},     {colors::kGreen, "green"}, {colors::kOrange, "orange"},
                     {colors::kGray, "gray"}};
        for (const auto& entry : named) {
            if (entry.color == color) {
                text += " ";
                text += entry.name;
            }
        }
        return text;
    }
};
}  // namespace Catch
