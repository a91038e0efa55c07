#pragma once
// A seeded generator standing in for Math.random(): numbers in [0, 1), the same
// sequence for the same seed on every machine and compiler (the conversion to double
// is spelled out here rather than left to std::uniform_real_distribution, whose
// algorithm the standard library may choose).

#include <cstdint>
#include <random>

namespace browser {

class Random {
public:
    static constexpr std::uint64_t kDefaultSeed = 2017;  // the book's year of publication

    explicit Random(std::uint64_t seed = kDefaultSeed) : engine_(seed) {}

    // Like Math.random(): uniform in [0, 1), 53 random bits.
    double next() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

private:
    std::mt19937_64 engine_;
};

}  // namespace browser
