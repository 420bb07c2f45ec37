// Fixture: reaching up into the tree by a relative path, from a .h file.
#pragma once

#include "../tree/Octree.hpp"
