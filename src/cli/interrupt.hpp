#pragma once
// SIGINT and SIGTERM as a request to stop: long commands poll it between frames (or chunks of
// samples), finish what they are writing, leave no partial file and exit with kExitInterrupted.

namespace sl {

void installInterruptHandlers();
bool interruptRequested();
// Throws CommandExit(kExitInterrupted) with a message naming the signal and what to do next.
void stopIfInterrupted(const char* whatToDoNext);

}  // namespace sl
