#include "io/read_monitor.h"

#include <algorithm>
#include <cmath>

namespace trimkit::io {
namespace {

// Progress is passed on in steps of at least this fraction (and at the end): a Python
// callback takes the GIL each time, and a bar cannot show finer steps.
constexpr double kReportStep = 0.005;

std::string seconds_text(double seconds) {
    return geom::format_value(seconds >= 10.0 ? std::round(seconds) : std::round(seconds * 100.0) / 100.0);
}

}  // namespace

ReadStopped::ReadStopped(const std::string& file, bool cancelled, double seconds)
    : std::runtime_error(file + ": " +
                         (cancelled ? "reading cancelled after " + seconds_text(seconds) + " s"
                                    : "reading stopped after " + seconds_text(seconds) + " s (read timeout)")),
      file_(file), cancelled_(cancelled), seconds_(seconds) {}

ReadMonitor::ReadMonitor(const std::string& file, const ReadOptions& options) : file_(file), options_(options) {}

double ReadMonitor::elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

bool ReadMonitor::stop_requested() const {
    if (options_.cancel && options_.cancel->load(std::memory_order_relaxed)) return true;
    return options_.timeout > 0.0 && std::isfinite(options_.timeout) && elapsed() >= options_.timeout;
}

void ReadMonitor::check() const {
    if (!stop_requested()) return;
    const bool cancelled = options_.cancel && options_.cancel->load(std::memory_order_relaxed);
    throw ReadStopped(file_, cancelled, elapsed());
}

void ReadMonitor::stage(double begin, double end) {
    begin_ = begin;
    end_ = std::max(begin, end);
}

void ReadMonitor::report(double fraction) {
    if (!options_.progress) return;
    const double f = begin_ + (end_ - begin_) * std::clamp(fraction, 0.0, 1.0);
    if (!(f >= reported_ + kReportStep || (f == 1.0 && reported_ < 1.0))) return;
    reported_ = f;
    options_.progress(f);
}

}  // namespace trimkit::io
