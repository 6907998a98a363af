// ReadMonitor: one read's ReadOptions at work. Readers call check() between steps
// (entities, faces) and report(fraction) as they go; an OCCT algorithm asks
// stop_requested() through its progress indicator (occt_progress.h). The read's
// progress is split into stages: stage(begin, end) maps the fractions reported next
// onto [begin, end] of the whole.
#pragma once

#include <chrono>
#include <string>

#include "io/read_options.h"

namespace trimkit::io {

class ReadMonitor {
public:
    ReadMonitor(const std::string& file, const ReadOptions& options);

    // True once the timeout has passed or the cancel flag is set. Thread-safe.
    bool stop_requested() const;
    // Throws ReadStopped when stop_requested().
    void check() const;
    // Seconds since the read began.
    double elapsed() const;

    // Fractions reported next lie in [begin, end] of the whole read.
    void stage(double begin, double end);
    // Reports `fraction` of the current stage (clamped to [0, 1]; never backwards).
    // Not thread-safe (OCCT serialises its calls).
    void report(double fraction);

    const std::string& file() const { return file_; }

private:
    using Clock = std::chrono::steady_clock;
    std::string file_;
    ReadOptions options_;
    Clock::time_point start_ = Clock::now();
    double begin_ = 0.0, end_ = 1.0, reported_ = -1.0;
};

}  // namespace trimkit::io
