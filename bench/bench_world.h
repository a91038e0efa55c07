#pragma once
// A world the bench can step, time and look at: a chapter 5 stage's engine
// (stage_engine.h) or Box2D as the reference (box2d_world.h). The measures only ever
// see a Snapshot, so one measure serves every engine.

#include <cstddef>
#include <optional>
#include <vector>

#include "collision_oracle.h"
#include "thread_clock.h"
#include "vec2.h"

namespace bench {

using lib::Vec2;

// One body as the measures see it, in the scene's units (px, s, rad). The outline is
// the collision oracle's, so overlaps are worked out without the engine's own code.
struct BodyState {
    oracle::Shape shape;
    bool is_static = false;
    double mass = 0.0;     // 0 for a static body
    double inertia = 0.0;  // about the centre, mass px^2; 0 for a static body
    Vec2 velocity;
    double angular_velocity = 0.0;
};
using Snapshot = std::vector<BodyState>;

class BenchWorld {
public:
    virtual ~BenchWorld() = default;

    // Runs `steps` fixed steps and adds the processor time they took to seconds().
    void run(long steps) {
        const double start = thread_cpu_seconds();
        advance(steps);
        seconds_ += thread_cpu_seconds() - start;
        steps_ += steps;
    }
    // Runs `steps` fixed steps that count for nothing: a warm-up, or settling.
    void run_untimed(long steps) { advance(steps); }
    long steps() const { return steps_; }
    double seconds() const { return seconds_; }

    virtual Snapshot snapshot() const = 0;

    // Pairs looked at per fixed step, every relaxation pass counted, on average over
    // every step run (timed or not): those the broad phase considered (candidates), those
    // whose exact narrow-phase test was computed, those whose exact test the skip rule
    // saved (broad_phase.h), and the passes run. Nothing where the engine does not count
    // them (stage 5.1, the book's, and Box2D).
    struct PairCounts {
        double candidates = 0.0;
        double narrow_tests = 0.0;
        double skipped_tests = 0.0;
        double passes = 0.0;
    };
    virtual std::optional<PairCounts> pair_counts() const { return std::nullopt; }

    // The collision events a game read after each step, per fixed step on average over
    // every step run (timed or not): nothing where no one reads them (5.7 on, with
    // WorldDescription::events on, is the only engine that tells them).
    struct EventCounts {
        double begins = 0.0;
        double ends = 0.0;
        double hits = 0.0;
    };
    virtual std::optional<EventCounts> event_counts() const { return std::nullopt; }

    // How many of the moving bodies are awake, where the engine sleeps (Box2D with its
    // sleeping on, for 5.5's studies); nothing where it does not say.
    virtual std::optional<std::size_t> awake_count() const { return std::nullopt; }

protected:
    virtual void advance(long steps) = 0;

private:
    long steps_ = 0;
    double seconds_ = 0.0;
};

}  // namespace bench
