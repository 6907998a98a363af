// Small pieces every Open CASCADE reader of io shares (compiled only with
// TRIMKIT_WITH_OCCT): a guard that turns OCCT's memory faults into exceptions,
// OCCT's stdout printer removed, exception text, and OCCT -> Eigen conversions.
#pragma once

#include <csignal>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>

namespace trimkit::io {

// While alive, OCCT's signal handlers are installed so that a memory fault inside it
// (OCCT 7.6 dereferences null handles for some broken references) jumps to
// OCC_CATCH_SIGNALS and is thrown as a Standard_Failure instead of killing the
// process, Blender included. The process's own handlers are restored afterwards.
class OcctSignalGuard {
public:
    OcctSignalGuard();
    ~OcctSignalGuard();
    OcctSignalGuard(const OcctSignalGuard&) = delete;
    OcctSignalGuard& operator=(const OcctSignalGuard&) = delete;

private:
    struct sigaction saved_[NSIG] = {};
    // A stack of its own for the signal handlers of this thread (sigaltstack), so that a
    // fault from a stack overflow (OCCT 7.6 recurses without bound through some damaged
    // STEP assemblies) still reaches OCCT's handler, which runs on it and jumps back to
    // OCC_CATCH_SIGNALS, instead of the kernel killing the process.
    std::vector<char> signal_stack_;
    stack_t saved_stack_{};
    bool own_stack_ = false;
};

// Runs `f` (calls into OCCT) under OCCT's signal catcher in a frame of its own and
// returns what it returns. A memory fault inside `f` jumps (longjmp) back to this frame
// only, skipping the destructors of what `f` made, and leaves it as a Standard_Failure
// thrown here, so the frames above (documents, readers, faces of ours) unwind as after
// any exception. Keep `f` to OCCT calls: our objects made inside it are lost on a fault.
// Scopes nest: the innermost one alive catches. Needs an OcctSignalGuard alive.
#if !defined(OCC_CONVERT_SIGNALS)
#error "OCC_CONVERT_SIGNALS must be defined (native/src/io/CMakeLists.txt) for OCC_CATCH_SIGNALS to catch signals"
#endif
template <class F>
auto occt_guarded(F&& f) -> decltype(f()) {
    OCC_CATCH_SIGNALS
    return f();
}

// OCCT's default messenger prints transfer messages on stdout, which would corrupt
// `trimkit ... --json` output; drops that printer once per process.
void silence_occt_stdout();

// "Standard_DomainError: message" for an OCCT exception.
std::string failure_text(const Standard_Failure& e);

inline Eigen::Vector3d to_eigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Eigen::Affine3d to_eigen(const gp_Trsf& t);

// Knots with each value repeated by its multiplicity (OCCT stores them apart), 1-based.
template <class Get, class Mult>
std::vector<double> expanded_knots(int count, Get knot, Mult multiplicity) {
    std::vector<double> U;
    for (int i = 1; i <= count; ++i)
        for (int k = 0; k < multiplicity(i); ++k) U.push_back(knot(i));
    return U;
}

}  // namespace trimkit::io
