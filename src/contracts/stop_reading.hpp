#pragma once
// A watchdog's reading against its limit in a few digits, e.g. "energy drift 2.13 > limit 1", the one home of
// these words: run reports (simulation's StopInfo::reading) and the frames' text panel (render/frame_words.hpp)
// both say it so. Empty for a stop without a reading.

#include <string>

#include "contracts/registry.hpp"

namespace sl {

std::string stopReading(StopReason reason, double measured, double limit);

}  // namespace sl
