#include "scene/JsonPath.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>

namespace dropscope::jsonpath {

namespace {

bool isIdentifier(const std::string& key) {
    const auto identifierChar = [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    };
    return !key.empty() && std::all_of(key.begin(), key.end(), identifierChar);
}

}  // namespace

std::string member(const std::string& parent, const std::string& key) {
    if (!isIdentifier(key)) return parent + "[" + quoted(key) + "]";
    return parent.empty() ? key : parent + "." + key;
}

std::string element(const std::string& parent, std::size_t index) { return parent + "[" + std::to_string(index) + "]"; }

std::string quoted(const std::string& text) {
    return nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string number(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

}  // namespace dropscope::jsonpath
