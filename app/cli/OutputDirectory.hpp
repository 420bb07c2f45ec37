#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace dropscope {

// Refuses (BadInputError) an --out that names something other than a folder, or that holds one of `fileNames`
// as something other than a regular file, before any work is done.
void checkOutputDirectory(const std::filesystem::path& directory, const std::vector<std::string>& fileNames);

// Creates `directory` and its parents; BadInputError naming it when that fails.
void createOutputDirectory(const std::filesystem::path& directory);

}  // namespace dropscope
