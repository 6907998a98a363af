// ReadOptions: the limits and the progress report of one model read (read_model,
// read_step, read_brep, read_iges). A read that passes `timeout` seconds of wall
// time, or whose `cancel` flag is set, stops at its next check and throws
// ReadStopped; nothing of the partial model is returned. Progress is a fraction in
// [0, 1], non-decreasing, reported from the reading thread (OCCT may report from its
// own worker threads, never two at once).
#pragma once

#include <atomic>
#include <functional>
#include <stdexcept>
#include <string>

#include "geom/error.h"

namespace trimkit::io {

// Default ReadOptions::timeout, seconds: the largest shared STEP file reads in a few
// seconds; a damaged one can keep OCCT's healing busy for minutes.
constexpr double kDefaultReadTimeout = 120.0;

// Who reads STEP: Open CASCADE (with its healing), trimkit's own reader
// (io/read_step_native.h: single parts of the kinds it translates; others refused), or
// trimkit's own with Open CASCADE for the files it does not take on.
enum class StepReader { kOcct, kOwn, kAuto };

struct ReadOptions {
    double timeout = kDefaultReadTimeout;        // seconds; 0 = no limit
    StepReader step_reader = StepReader::kOcct;
    std::function<void(double)> progress;        // fraction read; empty = none
    const std::atomic<bool>* cancel = nullptr;   // set from any thread to stop the read
};

// A read stopped by its timeout or its cancel flag. what():
// "FILE: reading stopped after 120 s (read timeout)" or "FILE: reading cancelled after 0.3 s".
// Not a geom::ReadError, so that readers which skip a bad entity on a ReadError (and
// carry on) let it through; the CLI reports it as bad input (exit 2) and Python sees
// _trimkit.ReadStopped, a subclass of _trimkit.ReadError.
class ReadStopped : public std::runtime_error {
public:
    ReadStopped(const std::string& file, bool cancelled, double seconds);
    const std::string& file() const { return file_; }
    bool cancelled() const { return cancelled_; }  // false: the timeout
    double seconds() const { return seconds_; }   // wall time when stopped

private:
    std::string file_;
    bool cancelled_;
    double seconds_;
};

}  // namespace trimkit::io
