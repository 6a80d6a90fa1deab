#include "cli/interrupt.hpp"

#include <csignal>
#include <string>

#include "cli/exit_codes.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

namespace {

volatile std::sig_atomic_t gSignal = 0;

extern "C" void onSignal(int signal) { gSignal = signal; }

}  // namespace

void installInterruptHandlers() {
  struct sigaction action = {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool interruptRequested() { return gSignal != 0; }

void stopIfInterrupted(const char* whatToDoNext) {
  if (gSignal == 0) return;
  const std::string name = gSignal == SIGINT ? "SIGINT" : "SIGTERM";
  throw CommandExit(kExitInterrupted, "linkage: stopped by " + name + "; " + whatToDoNext);
}

std::string runAnsweringSignals(const std::function<std::string()>& work) {
  installInterruptHandlers();
  try {
    return work();
  } catch (const RunCancelled&) {
    stopIfInterrupted("nothing was written");
    throw;
  }
}

}  // namespace sl
