// Fixture: a lower layer (geometry) reaching up into the tree.
#pragma once

#include "tree/Octree.hpp"
