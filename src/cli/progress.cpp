#include "cli/progress.hpp"

#include <unistd.h>
#include <cstdio>

namespace sl {

Progress::Progress(long total, bool quiet)
    : total_(total), enabled_(!quiet && ::isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
  if (drawn_) std::fputc('\n', stderr);
}

void Progress::update(long done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && done < total_ && now - lastDraw_ < std::chrono::milliseconds(200)) return;
  lastDraw_ = now;
  drawn_ = true;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  const double rate = seconds > 0 ? done / seconds : 0;
  const long eta = rate > 0 ? static_cast<long>((total_ - done) / rate) : 0;
  std::fprintf(stderr, "\rframe %ld/%ld  %.1f fps  ETA %ld:%02ld   ", done, total_, rate, eta / 60, eta % 60);
  std::fflush(stderr);
}

}  // namespace sl
