// Deadline: a cooperative time limit for long loops. Work calls check(stage) at the
// head of its loops; once the limit has passed, check throws DeadlineExceeded naming
// the stage, and the caller reports the work as stopped (tessellate_model: the face
// goes to failed_faces with defect "timeout"). Seconds are wall time from
// construction (std::chrono::steady_clock). A default Deadline never expires.
// A cancel flag, when given, makes the deadline pass as soon as it is set (from any
// thread): the same checks stop cancelled work.
// Not thread-safe: one Deadline per thread of work (each face has its own).
#pragma once

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>

namespace trimkit::mesh {

// Thrown by Deadline::check once the limit has passed. what():
// "stopped after 0.52 s in trim loop repair (limit 0.5 s)", or when cancelled
// "cancelled after 0.1 s in kd subdivision".
class DeadlineExceeded : public std::runtime_error {
public:
    DeadlineExceeded(const std::string& stage, double elapsed, double limit, bool cancelled = false);
    const std::string& stage() const { return stage_; }
    bool cancelled() const { return cancelled_; }  // by the cancel flag, not the time
    double elapsed() const { return elapsed_; }  // seconds spent when stopped
    double limit() const { return limit_; }      // the limit, seconds

private:
    std::string stage_;
    double elapsed_;
    double limit_;
    bool cancelled_;
};

class Deadline {
public:
    // check() reads the clock once every kCheckStride calls: a read costs about as
    // much as the cheapest loop body that checks (a segment pair test), and 256
    // bodies take well under a millisecond.
    static constexpr unsigned kCheckStride = 256;

    Deadline() = default;  // no limit
    // A limit of `seconds` from now; seconds <= 0 or infinite: no time limit.
    // `cancel`: expired() once it is set (nullptr: none).
    explicit Deadline(double seconds, const std::atomic<bool>* cancel = nullptr);

    bool limited() const { return limited_ || cancel_; }
    double limit() const { return limit_; }  // seconds; 0 when not limited
    double elapsed() const;                  // seconds since construction
    bool expired() const;                    // reads the clock (and the cancel flag)
    bool cancelled() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }

    // Throws DeadlineExceeded(stage, ...) if the limit has passed (the clock is read
    // on every kCheckStride-th call).
    void check(const char* stage) {
        if (limited() && ++calls_ % kCheckStride == 0 && expired()) stop(stage);
    }
    // The same, reading the clock now (for loops whose bodies are long).
    void check_now(const char* stage) {
        if (limited() && expired()) stop(stage);
    }

private:
    [[noreturn]] void stop(const char* stage) const;

    using Clock = std::chrono::steady_clock;
    Clock::time_point start_ = Clock::now();
    Clock::time_point end_{};
    double limit_ = 0.0;
    bool limited_ = false;
    const std::atomic<bool>* cancel_ = nullptr;
    unsigned calls_ = 0;
};

// Calls deadline->check(stage) when there is a deadline (loops whose deadline is optional).
inline void check_deadline(Deadline* deadline, const char* stage) {
    if (deadline) deadline->check(stage);
}

// Calls deadline->check_now(stage) when there is a deadline.
inline void check_deadline_now(Deadline* deadline, const char* stage) {
    if (deadline) deadline->check_now(stage);
}

}  // namespace trimkit::mesh
