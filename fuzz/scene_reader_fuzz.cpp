// Fuzz target: the scene reader (common/scene_file.cpp) with 5.3's world keys, the
// most a scene can set. The input is the scene file's text, as --scene reads it.
//
// Properties, besides "no crash, no sanitizer report, no exception but SceneError":
//  - a refusal is one line, and leaves the world's settings as they were;
//  - every body of an accepted scene is one the engine builds: its shape's
//    constructor, rotate and setVelocity take it without an InvalidShape.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "circle.h"
#include "fuzz_check.h"
#include "rectangle.h"
#include "scene_file.h"
#include "scene_io.h"

namespace {

void build(const engine::BodyDescription& body) {
    const engine::PhysicalAttributes attributes{
        .mass = body.mass, .friction = body.friction, .restitution = body.restitution};
    try {
        if (body.shape == engine::ShapeType::Circle) {
            engine::Circle circle(body.center, body.radius, attributes);
            circle.rotate(body.angle);
            circle.setVelocity(body.velocity);
        } else {
            engine::Rectangle rectangle(body.center, body.width, body.height, attributes);
            rectangle.rotate(body.angle);
            rectangle.setVelocity(body.velocity);
        }
    } catch (const engine::InvalidShape& refused) {
        fuzz::property_failed("an accepted body is one the engine builds:", refused.what());
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    engine::WorldSettings world = engine::kBookWorld;
    std::vector<engine::BodyDescription> bodies;
    const browser::SceneList body_list = engine::bodyList(bodies);
    try {
        browser::read_scene_text(text, "fuzz.json", engine::worldKeys(world), {&body_list, 1});
        for (const engine::BodyDescription& body : bodies) build(body);
    } catch (const browser::SceneError& refusal) {
        fuzz::require(fuzz::one_line(refusal.what()), "a refusal is one line:", refusal.what());
        fuzz::require(world == engine::kBookWorld, "a refused scene changes no setting");
    }
    return 0;
}
