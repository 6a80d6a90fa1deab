#pragma once
// Where rendered frames go. consume() may return before the frame is written (sinks encode on their
// own threads, overlapping with rendering); finish() waits for everything, flushes the manifest, and
// rethrows the first error a worker met. Errors also surface from the next consume().

#include "contracts/image.hpp"

namespace sl {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void consume(int frameIndex, Image image) = 0;
  virtual void finish() = 0;
};

}  // namespace sl
