// Fixture: the GUI including its sibling, the command line.
#pragma once

#include "cli/Cli.hpp"
