#include "results/AtomicFile.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace dropscope {

namespace {

namespace fs = std::filesystem;

fs::path temporaryFor(const fs::path& target) {
    fs::path temporary = target;
    temporary += ".partial-" + std::to_string(::getpid());
    return temporary;
}

void writeTemporary(const FileToWrite& file) {
    std::error_code error;
    const fs::file_status status = fs::symlink_status(file.target, error);
    if (fs::exists(status) && !fs::is_regular_file(status)) {
        throw std::runtime_error(file.target.string() + ": exists and is not a regular file");
    }
    std::ofstream out(temporaryFor(file.target), std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(file.target.string() + ": cannot write (does the folder exist?)");
    errno = 0;
    file.write(out);
    out.close();  // a full disk or quota may show only when the last block is written, at close
    if (!out) {
        // errno is the failed write's when the stream's last call set it: ENOSPC, EFBIG (ulimit -f), EDQUOT.
        const std::string reason = errno != 0 ? std::strerror(errno) : "disk full?";
        throw std::runtime_error(file.target.string() + ": write failed (" + reason + "); no file of this run written");
    }
}

}  // namespace

void writeFilesAtomically(const std::vector<FileToWrite>& files) {
    try {
        for (const FileToWrite& file : files) writeTemporary(file);
        for (const FileToWrite& file : files) {
            std::error_code error;
            fs::rename(temporaryFor(file.target), file.target, error);
            if (error) throw std::runtime_error(file.target.string() + ": cannot replace: " + error.message());
        }
    } catch (...) {
        for (const FileToWrite& file : files) {
            std::error_code ignored;
            fs::remove(temporaryFor(file.target), ignored);
        }
        throw;
    }
}

void writeFileAtomically(const fs::path& target, const std::function<void(std::ostream&)>& write) {
    writeFilesAtomically({{target, write}});
}

}  // namespace dropscope
