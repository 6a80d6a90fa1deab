#include "cli/self_check_words.hpp"

#include <iostream>

#include "cli/exit_codes.hpp"
#include "contracts/csv_format.hpp"

namespace sl {

std::string selfCheckName(SelfCheck check) {
  switch (check) {
    case SelfCheck::confirmed: return "confirmed";
    case SelfCheck::notFinite: return "not finite";
    case SelfCheck::openClosure: return "open";
    case SelfCheck::missedTarget: return "missed target";
    case SelfCheck::routesDisagree: return "routes disagree";
    case SelfCheck::radiiDisagree: return "radii disagree";
    case SelfCheck::turningDisagrees: return "routes disagree";
    case SelfCheck::gaussBonnetFails: return "Gauss-Bonnet fails";
  }
  return "unknown";
}

std::string selfCheckReason(SelfCheck check) {
  switch (check) {
    case SelfCheck::confirmed: return "it passes its own check";
    case SelfCheck::notFinite: return "a length or an error is not a finite number";
    case SelfCheck::openClosure: return "it does not close within " + shortest(kClosureBound);
    case SelfCheck::missedTarget: return "it ends farther than " + shortest(kEndErrorBound) + " from its target";
    case SelfCheck::routesDisagree:
      return "its independent route's length differs by more than " + shortest(kRouteAgreement) + " (relative)";
    case SelfCheck::radiiDisagree:
      return "the nearest cut point and Klingenberg's lemma differ by more than " + shortest(kInjectivityAgreementCells) +
             " grid cells";
    case SelfCheck::turningDisagrees:
      return "its two transport routes turn the vector differently by more than " + shortest(kHolonomyRouteBound) +
             " rad";
    case SelfCheck::gaussBonnetFails:
      return "its turning differs from the enclosed curvature or the angle excess by more than " +
             shortest(kGaussBonnetBound) + " rad";
  }
  return "unknown check";
}

std::string reportUnconfirmed(const std::string& command, const std::string& noun, const std::vector<SelfCheck>& checks,
                              bool quiet) {
  std::size_t unconfirmed = 0;
  for (std::size_t i = 0; i < checks.size(); ++i) {
    if (checks[i] == SelfCheck::confirmed) continue;
    ++unconfirmed;
    if (!quiet)
      std::cerr << "linkage " << command << ": warning: " << noun << " " << i << " is unconfirmed: "
                << selfCheckReason(checks[i]) << "; a scene cannot start on it\n";
  }
  if (!checks.empty() && unconfirmed == checks.size())
    throw CommandExit(kExitFailure, "linkage " + command + ": no " + noun + " passed its own check (" +
                                        std::to_string(unconfirmed) + " found, all unconfirmed)");
  return unconfirmed ? " (" + std::to_string(unconfirmed) + " unconfirmed)" : "";
}

}  // namespace sl
