#pragma once
// The one place that includes OpenGL: core-profile prototypes straight from OSMesa (no loader).
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES
#endif
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
