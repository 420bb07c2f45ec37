#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>

namespace dropscope {

// Writes a file whole or not at all: `write` fills a temporary file beside `target`, which is renamed
// over `target` only once everything was written and flushed. Throws std::runtime_error naming the
// file on failure, leaving `target` untouched.
void writeFileAtomically(const std::filesystem::path& target, const std::function<void(std::ostream&)>& write);

}  // namespace dropscope
