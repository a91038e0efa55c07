#include "scene_writer.h"

#include <charconv>
#include <fstream>
#include <system_error>

#include "png_io.h"  // FileError

namespace bench {
namespace {

// The shortest text that reads back to exactly `value`.
std::string number(double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

// Built by appending: g++ 12 warns falsely (-Wrestrict) about "text" + std::string.
std::string vector(browser::Vec2 v) {
    std::string text = "[";
    return text.append(number(v.x)).append(", ").append(number(v.y)).append("]");
}
std::string flag(bool on) { return on ? "true" : "false"; }
std::string word(std::string_view text) {
    std::string quoted = "\"";
    return quoted.append(text).append("\"");
}

std::string world_json(const browser::WorldSettings& w) {
    std::string text = "{";
    text += "\"width\": " + number(w.width) + ", \"height\": " + number(w.height);
    text += ", \"gravity\": " + vector(w.gravity) + ", \"dt\": " + number(w.dt);
    text += ", \"relaxation_iterations\": " + std::to_string(w.relaxation_iterations);
    text += ", \"correction_rate\": " + number(w.correction_rate);
    text += ", \"movement\": " + flag(w.movement) + ", \"positional_correction\": " + flag(w.positional_correction);
    text += ", \"remove_out_of_bounds\": " + flag(w.remove_out_of_bounds);
    text += ",\n            \"substeps\": " + std::to_string(w.substeps);
    text += ", \"integrator\": " + word(browser::knob_name(w.integrator));
    text += ", \"broad_phase\": " + word(browser::knob_name(w.broad_phase));
    text += ", \"friction_model\": " + word(browser::knob_name(w.friction_model));
    text += ", \"rotation\": " + flag(w.rotation) + ", \"friction\": " + flag(w.friction) + "}";
    return text;
}

// Size, mass, friction and restitution always; angle and motion only when not 0.
std::string body_json(const browser::BodyDescription& b) {
    std::string text = "{\"shape\": " + word(browser::shape_name(b.shape)) + ", \"center\": " + vector(b.center);
    if (b.shape == browser::ShapeKind::circle) {
        text += ", \"radius\": " + number(b.radius);
    } else {
        text += ", \"width\": " + number(b.width) + ", \"height\": " + number(b.height);
    }
    text += ", \"mass\": " + number(b.mass) + ", \"friction\": " + number(b.friction);
    text += ", \"restitution\": " + number(b.restitution);
    if (b.angle != 0.0) text += ", \"angle\": " + number(b.angle);
    if (b.velocity != browser::Vec2{}) text += ", \"velocity\": " + vector(b.velocity);
    if (b.angular_velocity != 0.0) text += ", \"angular_velocity\": " + number(b.angular_velocity);
    return text + "}";
}

}  // namespace

std::string scene_json(const browser::SceneDescription& scene) {
    std::string text = "{\n  \"world\": " + world_json(scene.world) + ",\n  \"bodies\": [";
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        text += i == 0 ? "\n    " : ",\n    ";
        text += body_json(scene.bodies[i]);
    }
    return text + "\n  ]\n}\n";
}

void write_scene(const std::filesystem::path& file, const browser::SceneDescription& scene) {
    std::filesystem::path partial = file;
    partial += ".partial";
    {
        std::ofstream out(partial, std::ios::binary);
        out << scene_json(scene);
        if (!out.flush()) throw browser::FileError("cannot write scene file \"" + partial.string() + "\"");
    }
    std::error_code error;
    std::filesystem::rename(partial, file, error);
    if (error) {
        std::filesystem::remove(partial, error);
        throw browser::FileError("cannot write scene file \"" + file.string() + "\"");
    }
}

}  // namespace bench
