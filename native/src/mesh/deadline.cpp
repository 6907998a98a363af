#include "mesh/deadline.h"

#include <cmath>

#include "geom/error.h"

namespace trimkit::mesh {

DeadlineExceeded::DeadlineExceeded(const std::string& stage, double elapsed, double limit, bool cancelled)
    : std::runtime_error((cancelled ? "cancelled after " : "stopped after ") +
                         geom::format_value(std::round(elapsed * 1000.0) / 1000.0) + " s in " + stage +
                         (cancelled ? std::string() : " (limit " + geom::format_value(limit) + " s)")),
      stage_(stage), elapsed_(elapsed), limit_(limit), cancelled_(cancelled) {}

Deadline::Deadline(double seconds, const std::atomic<bool>* cancel) : cancel_(cancel) {
    if (!(seconds > 0.0) || !std::isfinite(seconds)) return;
    limited_ = true;
    limit_ = seconds;
    end_ = start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

double Deadline::elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

bool Deadline::expired() const { return cancelled() || (limited_ && Clock::now() >= end_); }

void Deadline::stop(const char* stage) const {
    if (cancelled()) throw DeadlineExceeded(stage, elapsed(), 0.0, true);
    throw DeadlineExceeded(stage, elapsed(), limit_);
}

}  // namespace trimkit::mesh
