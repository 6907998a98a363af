#include "io/occt_support.h"

#include <csignal>
#include <cstddef>
#include <mutex>

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <OSD.hxx>

namespace trimkit::io {

namespace {

// The handlers' own stack: OCCT's handler builds an exception and unwinds its error
// handler chain, far less than this.
constexpr std::size_t kSignalStackBytes = 256 * 1024;

}  // namespace

OcctSignalGuard::OcctSignalGuard() {
    for (int s = 1; s < NSIG; ++s) sigaction(s, nullptr, &saved_[s]);
    OSD::SetSignal(OSD_SignalMode_Set, /*theFloatingSignal=*/false);
    // Use this thread's alternate stack if it has one (Blender's or Python's), else ours.
    if (sigaltstack(nullptr, &saved_stack_) == 0 && (saved_stack_.ss_flags & SS_DISABLE)) {
        signal_stack_.resize(kSignalStackBytes);
        stack_t ours{};
        ours.ss_sp = signal_stack_.data();
        ours.ss_size = signal_stack_.size();
        own_stack_ = sigaltstack(&ours, nullptr) == 0;
    }
    for (int s : {SIGSEGV, SIGBUS}) {
        struct sigaction action;
        if (sigaction(s, nullptr, &action) != 0) continue;
        action.sa_flags |= SA_ONSTACK;
        sigaction(s, &action, nullptr);
    }
}

OcctSignalGuard::~OcctSignalGuard() {
    for (int s = 1; s < NSIG; ++s)
        if (s != SIGKILL && s != SIGSTOP) sigaction(s, &saved_[s], nullptr);
    if (own_stack_) {
        stack_t off{};
        off.ss_flags = SS_DISABLE;
        sigaltstack(&off, nullptr);
    }
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
