#pragma once
// The simulated clock that stands in for Date.now(): time moves only when the browser
// says a frame has passed, so a run gives the same numbers on every machine.

namespace browser {

class Clock {
public:
    explicit Clock(double frame_ms) : frame_ms_(frame_ms) {}
    double nowMs() const { return static_cast<double>(frames_) * frame_ms_; }
    double frameMs() const { return frame_ms_; }
    void advanceFrame() { ++frames_; }

private:
    double frame_ms_;
    long long frames_ = 0;  // time is frames * frame_ms, never a running sum, so it cannot drift
};

}  // namespace browser
