// Fixture: the engine including OpenGL.
#pragma once

#include <GL/gl.h>
