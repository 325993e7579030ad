// Shared by the GLU sources: the visibility of the exported glu* entry points (the library is
// built with hidden visibility, so only what carries FFC_GLU_EXPORT leaves it).
#pragma once

#include <GL/gl.h>
#include <GL/glu.h>

#define FFC_GLU_EXPORT extern "C" __attribute__((visibility("default")))
