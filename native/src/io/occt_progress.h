// OcctProgress: a ReadMonitor as an OCCT progress indicator (compiled only with
// TRIMKIT_WITH_OCCT). Algorithms given its Start() range (STEP transfer with its
// shape healing, BRepTools::Read, ShapeFix) report their position to the monitor's
// current stage and stop at their next Message_ProgressScope::UserBreak() check once
// the monitor asks them to; the caller then calls monitor.check() to throw.
#pragma once

#include <Message_ProgressIndicator.hxx>

#include "io/read_monitor.h"

namespace trimkit::io {

class OcctProgress : public Message_ProgressIndicator {
public:
    explicit OcctProgress(ReadMonitor& monitor) : monitor_(monitor) {}

    Standard_Boolean UserBreak() override { return monitor_.stop_requested(); }
    void Show(const Message_ProgressScope&, const Standard_Boolean) override { monitor_.report(GetPosition()); }

private:
    ReadMonitor& monitor_;
};

}  // namespace trimkit::io
