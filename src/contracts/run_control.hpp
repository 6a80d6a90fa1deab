#pragma once
// How a caller stops long work and hears how far it got: runs (Trajectory::setCancellation) and searches
// (connect, closed geodesics) answer SIGINT and SIGTERM through these, without knowing of signals.
#include <functional>
#include <stdexcept>

namespace sl {

// Thrown by Trajectory::sampleAt when the run's cancellation check (setCancellation) answers true; the run is
// left as it was after its last step.
struct RunCancelled : std::runtime_error {
  RunCancelled() : std::runtime_error("the run was cancelled") {}
};
// The check long searches (connect, closed geodesics) ask between their rays and shots: RunCancelled when
// `cancelled` is given and answers true.
inline void stopIfCancelled(bool (*cancelled)()) {
  if (cancelled && cancelled()) throw RunCancelled();
}
// Where the same searches say how far they got: after each ray and shot, the count done of those planned in the
// current pass (a search may make several passes, each counted from 0; the total may grow as seeds are found).
using SearchProgress = std::function<void(long done, long total)>;

}  // namespace sl
