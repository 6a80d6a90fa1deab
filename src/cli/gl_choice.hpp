#pragma once
// The GL backend of the commands that draw (render, still, --version): `--gl NAME`, else LINKAGE_GL, else auto
// (docs/rendering.md, "GL backends"). Parsed here, at the edge, and handed to the renderer as a GlBackend.

#include <string>

#include <CLI/CLI.hpp>

namespace sl {

// Adds `--gl auto|egl|egl-gpu|osmesa` to a command that draws.
void addGlOption(CLI::App& command, std::string& value);

// Tells the renderer which backend this process draws through: `optionValue` if not empty, else LINKAGE_GL, else
// auto. Before the command's first Renderer. Throws CommandExit (exit 2) for a backend this binary lacks, naming
// where the choice came from.
void chooseGlBackend(const std::string& optionValue);

// The renderer as a manifest records it (ManifestContents::renderers): "GL_RENDERER | GL_VERSION", and for
// llvmpipe " | cpu FEATURES" with the llvmpipe switches set in the environment: what the frames' bytes depend on.
std::string rendererIdentity(const std::string& glRenderer, const std::string& glVersion);

// The backend in use for a summary line: "egl", or "osmesa (egl: <why it did not start>)" where auto fell back.
std::string glBackendWords();

}  // namespace sl
