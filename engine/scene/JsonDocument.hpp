#pragma once

#include <nlohmann/json.hpp>

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

// The whole text of a file. Throws SceneError ("FILE: no such file", "is a directory, not a scene file",
// "cannot open: ...", "cannot read: ...").
std::string readJsonFileText(const std::filesystem::path& file);

}  // namespace dropscope
