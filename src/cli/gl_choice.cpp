#include "cli/gl_choice.hpp"

#include "cli/environment.hpp"
#include "cli/exit_codes.hpp"
#include "contracts/registry.hpp"
#include "render/gl_backend.hpp"

namespace sl {
namespace {

std::string backendList() {
  std::string list;
  for (const auto& b : kGlBackends) list += (list.empty() ? "" : ", ") + std::string(b.name);
  return list;
}

}  // namespace

void addGlOption(CLI::App& command, std::string& value) {
  std::string help = "the OpenGL backend (default: LINKAGE_GL, else auto):";
  for (const auto& b : kGlBackends) help += "\n  " + std::string(b.name) + ": " + std::string(b.description);
  command.add_option("--gl", value, help)->check(CLI::IsMember(namesOf(kGlBackends)));
}

void chooseGlBackend(const std::string& optionValue) {
  const bool fromOption = !optionValue.empty();
  const std::string name = fromOption ? optionValue : environment().glBackend;
  if (name.empty()) return;  // auto, the renderer's default
  const std::string where = fromOption ? "--gl" : "LINKAGE_GL";
  const auto backend = parseKind(kGlBackends, name);
  if (!backend) throw CommandExit(kExitBadInput, where + ": found \"" + name + "\"; expected one of " + backendList());
  try {
    requestGlBackend(*backend);
  } catch (const GlUnavailable& error) {
    throw CommandExit(kExitBadInput, where + " " + name + ": " + error.what());
  }
}

std::string rendererIdentity(const std::string& glRenderer, const std::string& glVersion) {
  std::string identity = glRenderer + " | " + glVersion;
  if (glRenderer.rfind("llvmpipe", 0) == 0) {
    identity += " | cpu " + llvmpipeCpuFeatures();
    if (!environment().llvmpipeSwitches.empty()) identity += " " + environment().llvmpipeSwitches;
  }
  return identity;
}

std::string glBackendWords() {
  const auto backend = glBackendInUse();
  if (!backend) return "no GL backend";
  const std::string fallback = glFallbackReason();
  return nameOf(*backend) + (fallback.empty() ? "" : " (" + fallback + ")");
}

}  // namespace sl
