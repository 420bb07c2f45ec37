#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace dropscope {

// Object members keep their order in the file, so media ids follow the file.
using Json = nlohmann::ordered_json;

// Parses strict JSON (RFC 8259: no comments, no trailing text). Throws SceneError:
//   "ORIGIN: line L, column C: <parser message>"   for malformed JSON or a number out of double range;
//   "ORIGIN: PATH: duplicate key \"k\""           for a key given twice in one object.
Json parseJsonDocument(std::string_view text, const std::string& origin);

}  // namespace dropscope
