// METIS (through CHOLMOD's ordering) must not take over SIGINT and SIGTERM.
//
// METIS 5's GKlib installs, for the length of every METIS call, a SIGTERM (and SIGABRT) handler
// that frees METIS's memory and longjmps out of it (gk_sigtrap / gk_sigcatch), through
// __sysv_signal, and restores the old handler with System V one-shot semantics afterwards. A
// SIGTERM during the ordering of a large 3D system was therefore swallowed (CHOLMOD went on
// without METIS, on memory GKlib had freed: SIGSEGV 6-8 s later, issue 36) and the next one got
// the default action. This definition in the executable interposes GKlib's __sysv_signal calls:
// SIGINT and SIGTERM stay with rheomag's interrupt handling (core/interrupt.hpp); other signals
// (GKlib's SIGABRT for its out-of-memory path) get what __sysv_signal does. Exported from the
// executable by app/CMakeLists.txt (--export-dynamic-symbol).

#include <signal.h>

#include "core/interrupt.hpp"

extern "C" __sighandler_t __sysv_signal(int signal_number, __sighandler_t handler) {
  struct sigaction old {};
  if ((signal_number == SIGINT || signal_number == SIGTERM) &&
      rheomag::interrupt_handling_installed()) {
    if (sigaction(signal_number, nullptr, &old) != 0) return SIG_ERR;
    return old.sa_handler;  // reported as replaced; left as it is
  }
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_NODEFER;
  if (sigaction(signal_number, &action, &old) != 0) return SIG_ERR;
  return old.sa_handler;
}
