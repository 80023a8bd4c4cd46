#include "interrupt.h"

#include <signal.h>

namespace lutbake::cli {

namespace {

// One process, one bake: the token lives as long as the program, so that a
// signal arriving while a guard is being destroyed still finds it.
CancellationToken interruptToken;
struct sigaction previousInt, previousTerm;

extern "C" void OnInterrupt(int signal) { interruptToken.Cancel(signal); }

}  // namespace

InterruptGuard::InterruptGuard() {
  struct sigaction action = {};
  action.sa_handler = OnInterrupt;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: the next signal takes the default action (ends the process).
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, &previousInt);
  sigaction(SIGTERM, &action, &previousTerm);
  // A signal ignored when we started (nohup, a shell's background job)
  // stays ignored, as the shell asked.
  if (previousInt.sa_handler == SIG_IGN) sigaction(SIGINT, &previousInt, nullptr);
  if (previousTerm.sa_handler == SIG_IGN) sigaction(SIGTERM, &previousTerm, nullptr);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &previousInt, nullptr);
  sigaction(SIGTERM, &previousTerm, nullptr);
}

const CancellationToken &InterruptGuard::token() const { return interruptToken; }

std::string SignalName(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

void IgnoreFileSizeSignal() { ::signal(SIGXFSZ, SIG_IGN); }

}  // namespace lutbake::cli
