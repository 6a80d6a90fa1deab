#pragma once
// SIGINT and SIGTERM as a request to stop: long commands poll it between frames (or chunks of
// samples), finish what they are writing, leave no partial file and exit with kExitInterrupted.

#include <functional>
#include <string>

namespace sl {

void installInterruptHandlers();
bool interruptRequested();
// Throws CommandExit(kExitInterrupted) with a message naming the signal and what to do next.
void stopIfInterrupted(const char* whatToDoNext);
// A command whose work answers a signal by RunCancelled (a search, a run): the handlers installed first, and a
// cancellation after a signal ends the command with exit 130, "nothing was written". Returns what `work` returns.
std::string runAnsweringSignals(const std::function<std::string()>& work);

}  // namespace sl
