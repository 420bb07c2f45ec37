#include "cli/AtomicFile.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace dropscope {

void writeFileAtomically(const std::filesystem::path& target, const std::function<void(std::ostream&)>& write) {
    std::filesystem::path temporary = target;
    temporary += ".partial-" + std::to_string(::getpid());
    try {
        {
            std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
            if (!out) throw std::runtime_error(target.string() + ": cannot write (does the folder exist?)");
            write(out);
            out.flush();
            if (!out) throw std::runtime_error(target.string() + ": write failed (disk full?)");
        }
        std::error_code error;
        std::filesystem::rename(temporary, target, error);
        if (error) throw std::runtime_error(target.string() + ": cannot replace: " + error.message());
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

}  // namespace dropscope
