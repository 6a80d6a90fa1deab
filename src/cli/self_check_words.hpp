#pragma once
// A result's own check (inverse/self_check.hpp) in words, for tables, JSON and warnings: the one place that
// names the checks to a person.

#include <string>
#include <vector>

#include "inverse/self_check.hpp"

namespace sl {

// "confirmed", "not finite", "open", "missed target", "routes disagree", "radii disagree": a table cell or a
// JSON value.
std::string selfCheckName(SelfCheck check);
// Why a result is unconfirmed, as the end of a sentence ("it does not close within 1e-08").
std::string selfCheckReason(SelfCheck check);

// For a command's list of results (`noun`: "closed geodesic"): warns on stderr, unless quiet, of each one whose
// check failed ("linkage periodic: warning: closed geodesic 2 is unconfirmed: ..."), and ends the command with exit 3
// when the list has results and none is confirmed. Returns what a summary adds: "" or " (2 unconfirmed)".
std::string reportUnconfirmed(const std::string& command, const std::string& noun, const std::vector<SelfCheck>& checks,
                              bool quiet);

}  // namespace sl
