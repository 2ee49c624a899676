#pragma once
// The only way render/ reaches OpenGL. libOSMesa exports every gl* entry point, so with
// GL_GLEXT_PROTOTYPES the calls link straight against it: no loader, and no libGL in the link
// (docs/DEPENDENCIES.md section 5: with libGL first, calls would go to GLVND and do nothing).
// Private to render/: never include it from a public header.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
