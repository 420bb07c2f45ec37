// Fixture: the engine including an OpenGL loader.
#pragma once

#include <epoxy/gl.h>
