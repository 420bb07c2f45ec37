#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <vector>

namespace dropscope {

struct FileToWrite {
    std::filesystem::path target;
    std::function<void(std::ostream&)> write;
};

// Writes a set of files all or none: each `write` fills a temporary file beside its target; only once
// every one was written and flushed are they renamed over their targets. Throws std::runtime_error
// naming the file on failure, leaving every target untouched. (A rename can in principle still fail
// after an earlier one succeeded; the targets are checked to be replaceable first, so that takes a
// race with another process.)
void writeFilesAtomically(const std::vector<FileToWrite>& files);

// One file, whole or not at all.
void writeFileAtomically(const std::filesystem::path& target, const std::function<void(std::ostream&)>& write);

}  // namespace dropscope
