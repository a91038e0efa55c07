#include "scene_json.h"

#include <charconv>
#include <fstream>
#include <system_error>

#include "png_io.h"  // FileError
#include "scene_file.h"
#include "stages.h"

namespace bench {
namespace {

// The shortest text that reads back to exactly `value`.
std::string number(double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

// Built by appending: g++ 12 warns falsely (-Wrestrict) about "text" + std::string.
std::string vector(Vec2 v) {
    std::string text = "[";
    return text.append(number(v.x)).append(", ").append(number(v.y)).append("]");
}
std::string flag(bool on) { return on ? "true" : "false"; }
std::string word(std::string_view text) {
    std::string quoted = "\"";
    return quoted.append(text).append("\"");
}

// Size, mass, friction and restitution always; angle and motion only when not 0.
std::string body_json(const BodyDescription& b) {
    std::string text = "{\"shape\": " + word(spelling(b.shape)) + ", \"center\": " + vector(b.center);
    if (b.shape == Shape::circle) {
        text += ", \"radius\": " + number(b.radius);
    } else {
        text += ", \"width\": " + number(b.width) + ", \"height\": " + number(b.height);
    }
    text += ", \"mass\": " + number(b.mass) + ", \"friction\": " + number(b.friction);
    text += ", \"restitution\": " + number(b.restitution);
    if (b.angle != 0.0) text += ", \"angle\": " + number(b.angle);
    if (b.velocity != Vec2{}) text += ", \"velocity\": " + vector(b.velocity);
    if (b.angular_velocity != 0.0) text += ", \"angular_velocity\": " + number(b.angular_velocity);
    return text + "}";
}

std::string world_json(const WorldDescription& world) {
    std::string text = "{";
    for (const WorldEntry& entry : world_entries(world)) {
        text.append(text.size() == 1 ? "" : ", ").append(word(entry.key)).append(": ").append(entry.value);
    }
    return text + "}";
}

}  // namespace

std::vector<WorldEntry> world_entries(const WorldDescription& w) {
    std::vector<WorldEntry> entries{{"width", number(w.width)},
                                    {"height", number(w.height)},
                                    {"gravity", vector(w.gravity)},
                                    {"dt", number(w.dt)},
                                    {"relaxation_iterations", std::to_string(w.relaxation_iterations)},
                                    {"correction_rate", number(w.correction_rate)},
                                    {"movement", flag(w.movement)},
                                    {"positional_correction", flag(w.positional_correction)},
                                    {"remove_out_of_bounds", flag(w.remove_out_of_bounds)}};
    if (w.broad_phase) entries.push_back({"broad_phase", word(spelling(*w.broad_phase))});
    if (w.substeps) entries.push_back({"substeps", std::to_string(*w.substeps)});
    if (w.integrator) entries.push_back({"integrator", word(spelling(*w.integrator))});
    if (w.friction_model) entries.push_back({"friction_model", word(spelling(*w.friction_model))});
    if (w.rotation) entries.push_back({"rotation", flag(*w.rotation)});
    if (w.friction) entries.push_back({"friction", flag(*w.friction)});
    if (w.solver) entries.push_back({"solver", word(spelling(*w.solver))});
    if (w.velocity_iterations) entries.push_back({"velocity_iterations", std::to_string(*w.velocity_iterations)});
    if (w.warm_starting) entries.push_back({"warm_starting", flag(*w.warm_starting)});
    if (w.position_method) entries.push_back({"position_method", word(spelling(*w.position_method))});
    if (w.restitution_threshold) entries.push_back({"restitution_threshold", number(*w.restitution_threshold)});
    if (w.sleep) entries.push_back({"sleep", flag(*w.sleep)});
    if (w.continuous) entries.push_back({"continuous", flag(*w.continuous)});
    return entries;
}

std::string scene_json(const SceneDescription& scene) {
    std::string text = "{\n  \"world\": " + world_json(scene.world) + ",\n  \"bodies\": [";
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        text += i == 0 ? "\n    " : ",\n    ";
        text += body_json(scene.bodies[i]);
    }
    return text + (scene.bodies.empty() ? "]\n}\n" : "\n  ]\n}\n");
}

void write_scene(const std::filesystem::path& file, const SceneDescription& scene) {
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

SceneDescription read_scene(const std::filesystem::path& file) {
    return stage_engine(Stage::s5_1)->read_scene(browser::scene_text(file), file.string());
}

}  // namespace bench
