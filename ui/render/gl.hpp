// The one place that includes OpenGL: core profile 3.3 entry points called directly (glvnd).
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES
#endif
#include <GL/glcorearb.h>
