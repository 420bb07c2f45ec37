#include "cli/OutputDirectory.hpp"

#include "cli/BadInput.hpp"

#include <system_error>

namespace dropscope {

namespace fs = std::filesystem;

void checkOutputDirectory(const fs::path& directory, const std::vector<std::string>& fileNames) {
    std::error_code error;
    const fs::file_status status = fs::status(directory, error);
    if (fs::exists(status) && !fs::is_directory(status)) {
        throw BadInputError(directory.string() + ": exists and is not a directory");
    }
    for (const std::string& name : fileNames) {
        const fs::file_status file = fs::symlink_status(directory / name, error);
        if (fs::exists(file) && !fs::is_regular_file(file)) {
            throw BadInputError((directory / name).string() + ": exists and is not a regular file");
        }
    }
}

void createOutputDirectory(const fs::path& directory) {
    std::error_code error;
    fs::create_directories(directory, error);
    if (error) throw BadInputError(directory.string() + ": cannot create the output directory: " + error.message());
}

}  // namespace dropscope
