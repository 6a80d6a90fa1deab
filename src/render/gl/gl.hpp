#pragma once
// The one place that includes OpenGL: glad's 3.3 core loader, generated at build time (src/render/CMakeLists.txt)
// and filled from the process's backend (gl_backend.cpp), so that EGL and OSMesa can live in one binary.
#include <glad/gl.h>
