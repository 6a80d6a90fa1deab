#pragma once
// Everything the program reads from its environment, in one place: read here, at the command line's edge, and
// passed down to the stages as plain values (the stages read no environment variable themselves).

#include <string>

namespace sl {

struct Environment {
  // LINKAGE_LOCK_WAIT: seconds a render waits for a lock another process holds on its folder (a cluster whose
  // shared file system is slow may want more); limits::kMaxLockWaitSeconds if unset.
  double lockWaitSeconds;
  // LINKAGE_ENCODER_WAIT: seconds the video encoder may read nothing before the render gives up on it;
  // limits::kMaxEncoderStallSeconds if unset.
  double encoderWaitSeconds;
  // SL_SHADER_DIR: a folder to read the shaders from instead of the ones built into the program (work on the
  // shaders without rebuilding); empty if unset.
  std::string shaderFolder;
  // LINKAGE_GL: the GL backend of commands that draw when --gl does not say (cli/gl_choice.hpp); empty if unset.
  std::string glBackend;
  // The switches of Mesa's llvmpipe that change the code it generates, and so the pixels, as "NAME=value" joined by
  // spaces (GALLIUM_OVERRIDE_CPU_CAPS, GALLIUM_NOSSE, LP_NATIVE_VECTOR_WIDTH); empty if none is set. Recorded with
  // the renderer.
  std::string llvmpipeSwitches;
  // LINKAGE_PROGRESS=json: progress as one JSON object per line on stderr, for a script or a job scheduler to read
  // (cli/progress.hpp); unset or "text": the lines for people.
  bool progressJson = false;
};

// The variables read, and what each does, in words (the man page's ENVIRONMENT).
struct EnvironmentWords {
  const char* name;
  const char* meaning;
};
inline constexpr EnvironmentWords kEnvironmentWords[] = {
    {"LINKAGE_GL", "the GL backend of commands that draw when --gl does not say (a name --gl takes)"},
    {"LINKAGE_LOCK_WAIT", "seconds a render waits for a lock another process holds on its folder (unset: a minute)"},
    {"LINKAGE_ENCODER_WAIT", "seconds the video encoder may read nothing before the render gives up (unset: a minute)"},
    {"LINKAGE_PROGRESS",
     "json: progress as one JSON object per line on stderr ({\"command\", \"unit\", \"done\", "
     "\"total\", \"rate\", \"eta_seconds\"}), for scripts; text (unset): lines for people"},
    {"SL_SHADER_DIR", "a folder to read the shaders from instead of the built-in ones"},
    {"GALLIUM_OVERRIDE_CPU_CAPS, GALLIUM_NOSSE, LP_NATIVE_VECTOR_WIDTH",
     "llvmpipe's switches that change its code and so the pixels; recorded with the renderer in every manifest"},
};

// Read once, at the first call. Throws CommandExit (exit 2) naming the variable when a value is unusable.
const Environment& environment();

}  // namespace sl
