#include "contracts/stop_reading.hpp"

#include <sstream>

namespace sl {
namespace {

std::string against(const char* what, double value, double limit) {
  std::ostringstream text;
  text.precision(3);
  text << what << " " << value << " > limit " << limit;
  return text.str();
}

}  // namespace

std::string stopReading(StopReason reason, double measured, double limit) {
  switch (reason) {  // every reason, no default
    case StopReason::EnergyBlowUp:
      return against("energy drift", measured, limit);
    case StopReason::RodLength:
      return against("rod-length error", measured, limit);
    case StopReason::NonFinite:
    case StopReason::PoleFoldBack:
    case StopReason::FieldBlowUp:
    case StopReason::StepSizeCollapse:
    case StopReason::MaxSteps:
    case StopReason::ConstraintRankLoss:
      return "";
  }
  return "";
}

}  // namespace sl
