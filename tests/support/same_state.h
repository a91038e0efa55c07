#pragma once
// Bit-identical runs: two worlds that must move alike, compared body by body in every
// bit of what a state dump holds (== on doubles: the runs start from the same numbers,
// so nothing but a different sequence of operations can part them).

#include <cstddef>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core.h"

namespace test {

// What a state dump holds for one body.
struct BodyState {
    engine::Vec2 center;
    double angle;
    engine::Vec2 velocity;
    double angular_velocity;
    friend bool operator==(const BodyState&, const BodyState&) = default;
};

inline std::vector<BodyState> stateOf(const engine::Core& core) {
    std::vector<BodyState> state;
    for (std::size_t i = 0; i < core.objectCount(); ++i) {
        const engine::RigidShape& shape = core.object(i);
        state.push_back({shape.center(), shape.angle(), shape.velocity(), shape.angularVelocity()});
    }
    return state;
}

// Fails at the first body whose state differs in any bit.
inline void requireSameState(const engine::Core& reference, const engine::Core& other, const std::string& what,
                             long step) {
    const std::vector<BodyState> expected = stateOf(reference);
    const std::vector<BodyState> got = stateOf(other);
    INFO(what << ", step " << step);
    REQUIRE(got.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (got[i] == expected[i]) continue;
        FAIL("body " << i << " differs: centre (" << got[i].center.x << ", " << got[i].center.y << ") against ("
                     << expected[i].center.x << ", " << expected[i].center.y << ")");
    }
}

}  // namespace test
