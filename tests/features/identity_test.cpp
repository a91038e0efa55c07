// Bit for bit (stage 5.1 on): the stages after the book's last project make the book's
// method faster or add knobs, and with the book's settings they must compute exactly
// what 5.1 computes. The fingerprints below were recorded from stage 5.1 as it stood
// before 5.2's fast pass was written (commit 064fea9), by the hidden case "[.record]":
// every scene of the scene library and of the bench, 60 steps, the state after every
// step. Each stage from 5.1 on must give the same fingerprints, with every broad phase
// it has (all_pairs only on the smaller scenes: on the rains it tests 10^5 and more
// pairs a pass exactly).
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "browser.h"
#include "core.h"
#include "scene_io.h"

namespace identity_test {

namespace fs = std::filesystem;

namespace {

constexpr int kSteps = 60;
constexpr std::size_t kAllPairsUpTo = 200;  // bodies

// FNV-1a, 64 bits, over the bits of every number: any change in any last digit shows.
class Fingerprint {
public:
    void add(double value) {
        const auto bits = std::bit_cast<std::uint64_t>(value);
        for (int byte = 0; byte < 8; ++byte) {
            hash_ ^= (bits >> (8 * byte)) & 0xFF;
            hash_ *= kPrime;
        }
    }
    std::uint64_t value() const { return hash_; }

private:
    static constexpr std::uint64_t kPrime = 1099511628211ull;
    std::uint64_t hash_ = 14695981039346656037ull;
};

std::uint64_t fingerprint(const engine::Scene& scene) {
    const engine::WorldSettings& world = scene.world;
    browser::Window window(world.dt * 1000.0,
                           browser::Document{browser::Canvas(static_cast<int>(std::ceil(world.width)),
                                                             static_cast<int>(std::ceil(world.height)))});
    engine::Core core(window, world);
#if __has_include("contact_events.h")
    core.keepEvents(true);  // 5.7: the events watch the step and change nothing in it
#endif
    engine::buildScene(core, scene.bodies);
    Fingerprint print;
    for (int step = 0; step < kSteps; ++step) {
        core.update();
        print.add(static_cast<double>(core.objectCount()));
        for (std::size_t i = 0; i < core.objectCount(); ++i) {
            const engine::RigidShape& shape = core.object(i);
            for (double value : {shape.center().x, shape.center().y, shape.angle(), shape.velocity().x,
                                 shape.velocity().y, shape.angularVelocity()}) {
                print.add(value);
            }
        }
    }
    return print.value();
}

struct Recorded {
    const char* scene;  // "library/NAME.json" (ch5_demo/scenes/) or "bench/NAME.json" (bench/scenes/)
    std::uint64_t fingerprint;
};

const std::vector<Recorded> kRecorded = {
#include "identity_fingerprints.inc"
};

struct Folder {
    const char* name;
    fs::path path;
};
const Folder kFolders[] = {{"library", SCENE_LIBRARY_DIR}, {"bench", BENCH_SCENES_DIR}};

fs::path sceneFile(const std::string& name) {
    for (const Folder& folder : kFolders) {
        const std::string prefix = std::string(folder.name) + "/";
        if (name.starts_with(prefix)) return folder.path / name.substr(prefix.size());
    }
    return name;
}

std::vector<std::string> allScenes() {
    std::vector<std::string> names;
    for (const Folder& folder : kFolders) {
        for (const auto& entry : fs::directory_iterator(folder.path)) {
            if (entry.path().extension() == ".json") {
                names.push_back(std::string(folder.name) + "/" + entry.path().filename().string());
            }
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

TEST_CASE("identity: every shipped scene moves as the book's 5.1 moved it, to the last bit", "[identity]") {
    REQUIRE(kRecorded.size() == allScenes().size());  // a new scene needs its fingerprint
    for (const Recorded& recorded : kRecorded) {
        engine::Scene scene = engine::loadScene(sceneFile(recorded.scene));
#if __has_include("islands.h")
        scene.world.sleep = false;  // 5.5: a sleeping shape skips its steps; awake, all is as in 5.1
#endif
#if __has_include("continuous.h")
        scene.world.continuous = false;  // 5.6: a fast shape is swept; unswept, all is as in 5.1
#endif
#if __has_include("broad_phase.h")
        for (engine::BroadPhaseKind kind : {engine::BroadPhaseKind::bounding_circle, engine::BroadPhaseKind::grid,
                                            engine::BroadPhaseKind::all_pairs}) {
            if (kind == engine::BroadPhaseKind::all_pairs && scene.bodies.size() > kAllPairsUpTo) continue;
            engine::Scene with_kind = scene;
            with_kind.world.broad_phase = kind;
            INFO(recorded.scene << ", broad phase " << static_cast<int>(kind));
            CHECK(fingerprint(with_kind) == recorded.fingerprint);
        }
#else
        INFO(recorded.scene);
        CHECK(fingerprint(scene) == recorded.fingerprint);
#endif
    }
}

// Prints the table above, for the stage it is compiled with: tests/build/s5_1_tests "[.record]".
TEST_CASE("identity: record the fingerprints", "[.record]") {
    for (const std::string& name : allScenes()) {
        std::printf("    {\"%s\", 0x%016llxull},\n", name.c_str(),
                    static_cast<unsigned long long>(fingerprint(engine::loadScene(sceneFile(name)))));
    }
}

}  // namespace identity_test
