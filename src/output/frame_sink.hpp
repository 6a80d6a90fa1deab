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
  // Where the sink gives each frame's buffer back once it is done with it (none: the buffer is freed). The
  // recycler must outlive the sink.
  void recycleInto(ImageRecycler& recycler) { recycler_ = &recycler; }

 protected:
  void giveBack(Image& image) {
    if (recycler_) recycler_->give(std::move(image));
  }

 private:
  ImageRecycler* recycler_ = nullptr;
};

}  // namespace sl
