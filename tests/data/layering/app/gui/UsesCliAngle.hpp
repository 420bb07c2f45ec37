// Fixture: the GUI including its sibling through angle brackets.
#pragma once

#include <cli/Cli.hpp>
