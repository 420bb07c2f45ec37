#include "scene/JsonReader.hpp"

#include "scene/JsonPath.hpp"
#include "scene/SceneLoader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dropscope {

namespace {

// "object", "array", "string", "number", "boolean" or "null".
std::string describeType(const Json& value) { return value.type_name(); }

// Levenshtein distance, for "did you mean" suggestions on misspelt keys.
std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
            diagonal = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
        }
    }
    return row[b.size()];
}

std::string unknownKeyMessage(const std::string& key, std::initializer_list<std::string_view> allowed) {
    std::string_view nearest;
    std::size_t nearestDistance = std::numeric_limits<std::size_t>::max();
    for (const std::string_view candidate : allowed) {
        const std::size_t distance = editDistance(key, candidate);
        if (distance < nearestDistance) {
            nearest = candidate;
            nearestDistance = distance;
        }
    }
    std::string message = "unknown key " + jsonpath::quoted(key);
    if (nearestDistance <= std::max<std::size_t>(2, key.size() / 3)) {
        return message + " (did you mean " + jsonpath::quoted(std::string(nearest)) + "?)";
    }
    message += " (valid keys: ";
    for (const std::string_view candidate : allowed) {
        if (candidate != *allowed.begin()) message += ", ";
        message += candidate;
    }
    return message + ")";
}

}  // namespace

JsonReader::JsonReader(const Json& value, std::string path, const std::string& origin)
    : value_(value), path_(std::move(path)), origin_(origin) {}

void JsonReader::fail(const std::string& message) const { throw SceneError(origin_, path_, message); }

void JsonReader::expectObject() const {
    if (!value_.is_object()) fail("expected an object, got " + describeType(value_));
}

void JsonReader::expectKeys(std::initializer_list<std::string_view> allowed) const {
    expectObject();
    for (const auto& [key, value] : value_.items()) {
        if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
            fail(unknownKeyMessage(key, allowed));
        }
    }
}

JsonReader JsonReader::member(std::string_view key) const {
    std::optional<JsonReader> found = optionalMember(key);
    if (!found) fail("missing required key " + jsonpath::quoted(std::string(key)));
    return *found;
}

std::optional<JsonReader> JsonReader::optionalMember(std::string_view key) const {
    expectObject();
    const auto found = value_.find(key);
    if (found == value_.end()) return std::nullopt;
    return JsonReader(*found, jsonpath::member(path_, std::string(key)), origin_);
}

std::vector<std::pair<std::string, JsonReader>> JsonReader::members() const {
    expectObject();
    std::vector<std::pair<std::string, JsonReader>> result;
    for (const auto& [key, value] : value_.items()) {
        result.emplace_back(key, JsonReader(value, jsonpath::member(path_, key), origin_));
    }
    return result;
}

std::vector<JsonReader> JsonReader::elements() const {
    if (!value_.is_array()) fail("expected an array, got " + describeType(value_));
    std::vector<JsonReader> result;
    result.reserve(value_.size());
    for (std::size_t i = 0; i < value_.size(); ++i) {
        result.emplace_back(value_[i], jsonpath::element(path_, i), origin_);
    }
    return result;
}

double JsonReader::number() const {
    if (!value_.is_number()) fail("expected a number, got " + describeType(value_));
    const double number = value_.get<double>();
    // The parser already rejects numbers beyond double range; this guards values made some other way.
    if (!std::isfinite(number)) fail("must be a finite number");
    return number;
}

double JsonReader::positive() const {
    const double value = number();
    if (!(value > 0.0)) fail("must be > 0");
    return value;
}

double JsonReader::nonNegative() const {
    const double value = number();
    if (!(value >= 0.0)) fail("must be >= 0");
    return value;
}

std::int64_t JsonReader::integer() const {
    if (!value_.is_number()) fail("expected an integer, got " + describeType(value_));
    if (!value_.is_number_integer()) fail("must be an integer, got " + value_.dump());
    if (value_.is_number_unsigned() &&
        value_.get<std::uint64_t>() > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        fail("integer out of range: " + value_.dump());
    }
    return value_.get<std::int64_t>();
}

bool JsonReader::boolean() const {
    if (!value_.is_boolean()) fail("expected true or false, got " + describeType(value_));
    return value_.get<bool>();
}

std::string JsonReader::string() const {
    if (!value_.is_string()) fail("expected a string, got " + describeType(value_));
    return value_.get<std::string>();
}

std::vector<JsonReader> JsonReader::fixedArray(std::size_t size, std::string_view what) const {
    if (!value_.is_array()) fail("expected " + std::string(what) + ", got " + describeType(value_));
    if (value_.size() != size) {
        fail("expected " + std::string(what) + ", got " + std::to_string(value_.size()) + " element" +
             (value_.size() == 1 ? "" : "s"));
    }
    return elements();
}

Eigen::Vector3d JsonReader::vector3() const {
    const std::vector<JsonReader> components = fixedArray(3, "an array of 3 numbers");
    return {components[0].number(), components[1].number(), components[2].number()};
}

Eigen::Vector3d JsonReader::positiveVector3() const {
    const std::vector<JsonReader> components = fixedArray(3, "an array of 3 numbers");
    return {components[0].positive(), components[1].positive(), components[2].positive()};
}

Direction JsonReader::direction() const {
    const Direction direction(vector3());
    if (!direction) fail("must be a non-zero vector");
    return direction;
}

Eigen::Matrix3d JsonReader::matrix3() const {
    const std::vector<JsonReader> rows = fixedArray(3, "a 3x3 matrix (an array of 3 rows of 3 numbers)");
    Eigen::Matrix3d m;
    for (Eigen::Index i = 0; i < 3; ++i) m.row(i) = rows[static_cast<std::size_t>(i)].vector3().transpose();
    return m;
}

}  // namespace dropscope
