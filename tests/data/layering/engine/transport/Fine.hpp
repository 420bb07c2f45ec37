// Fixture: an include that keeps to the rules.
#pragma once

#include "geometry/Vector.hpp"

#include <vector>
