#include "io/occt_support.h"

#include <mutex>

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <OSD.hxx>

namespace trimkit::io {

OcctSignalGuard::OcctSignalGuard() {
    for (int s = 1; s < NSIG; ++s) sigaction(s, nullptr, &saved_[s]);
    OSD::SetSignal(OSD_SignalMode_Set, /*theFloatingSignal=*/false);
}

OcctSignalGuard::~OcctSignalGuard() {
    for (int s = 1; s < NSIG; ++s)
        if (s != SIGKILL && s != SIGSTOP) sigaction(s, &saved_[s], nullptr);
}

void silence_occt_stdout() {
    static std::once_flag once;
    std::call_once(once, [] {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    });
}

std::string failure_text(const Standard_Failure& e) {
    const char* text = e.GetMessageString();
    return std::string(e.DynamicType()->Name()) + (text && *text ? std::string(": ") + text : "");
}

Eigen::Affine3d to_eigen(const gp_Trsf& t) {
    Eigen::Affine3d out = Eigen::Affine3d::Identity();
    for (int r = 1; r <= 3; ++r) {
        for (int c = 1; c <= 3; ++c) out.matrix()(r - 1, c - 1) = t.Value(r, c);
        out.matrix()(r - 1, 3) = t.Value(r, 4);
    }
    return out;
}

}  // namespace trimkit::io
