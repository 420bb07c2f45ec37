#pragma once

#include <stdexcept>

namespace dropscope {

// Bad input a command finds after the arguments were parsed (an output path that cannot be used,
// say): what() is its one line, "PATH: message". runCli reports it with exit status kExitBadInput.
class BadInputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace dropscope
