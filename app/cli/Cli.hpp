#pragma once

#include <exception>
#include <iosfwd>

namespace dropscope {

// Exit status of the dropscope program.
inline constexpr int kExitSuccess = 0;
inline constexpr int kExitInternalError = 1;  // a bug: an exception no input should cause
inline constexpr int kExitBadInput = 2;       // bad arguments, missing or invalid scene file
inline constexpr int kExitTooManyLost = 4;    // trace --max-lost F: more photons lost than F; results written
inline constexpr int kExitInterrupted = 130;  // stopped by Ctrl-C (128 + SIGINT); partial results written

// The dropscope command line: parses argv (argv[0] is the program), runs the subcommand, and returns
// the exit status. Never throws. Results go to `out`; a failure prints exactly one line to `err`.
int runCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

// Says what `failure` (a std::exception) was on `err`, one line, and gives the exit status for it: kExitBadInput
// for bad input and memory, kExitInternalError otherwise.
int reportFailure(const std::exception_ptr& failure, std::ostream& err);

}  // namespace dropscope
