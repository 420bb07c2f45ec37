#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>

#include <string>
#include <string_view>

namespace dropscope {

// Object members keep their order in the file, so media ids follow the file.
using Json = nlohmann::ordered_json;

// Parses strict JSON (RFC 8259: no comments, no trailing text). Throws SceneError:
//   "ORIGIN: line L, column C: <parser message>"   for malformed JSON or a number out of double range;
//   "ORIGIN: PATH: duplicate key \"k\""           for a key given twice in one object.
Json parseJsonDocument(std::string_view text, const std::string& origin);

// The largest scene or patches file read: 1 GiB, some 8 million explicit shapes (a droplet cloud is a
// generator of a few lines).
inline constexpr std::size_t kMaxJsonFileBytes = std::size_t{1} << 30;

// The whole text of a file. Throws SceneError ("FILE: no such file", "is a directory, not a scene file",
// "cannot open: ...", "cannot read: ...", "larger than 1024 MiB, ...").
std::string readJsonFileText(const std::filesystem::path& file);

}  // namespace dropscope
