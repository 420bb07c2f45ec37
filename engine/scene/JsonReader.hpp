#pragma once

#include "geometry/Vector.hpp"
#include "scene/JsonDocument.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace dropscope {

// A read-only view of one value of a scene document that knows its JSON path. Every accessor
// checks the type (and the shape of vectors and matrices) and throws SceneError at this value's path.
class JsonReader {
public:
    JsonReader(const Json& value, std::string path, const std::string& origin);

    const std::string& path() const { return path_; }
    // The file (or other source) the document came from.
    const std::string& origin() const { return origin_; }
    [[noreturn]] void fail(const std::string& message) const;
    // Runs a constructor or factory of the value read here; a std::invalid_argument it throws
    // becomes a SceneError at this path.
    template <class Make>
    auto construct(Make make) const -> decltype(make()) {
        try {
            return make();
        } catch (const std::invalid_argument& error) {
            fail(error.what());
        }
    }

    // Objects. expectKeys fails on the first key not in `allowed`, suggesting the nearest one.
    void expectObject() const;
    void expectKeys(std::initializer_list<std::string_view> allowed) const;
    JsonReader member(std::string_view key) const;  // fails when the key is missing
    std::optional<JsonReader> optionalMember(std::string_view key) const;
    std::vector<std::pair<std::string, JsonReader>> members() const;

    // Arrays. fixedArray fails unless the array has `size` elements, saying it expected `what`.
    std::vector<JsonReader> elements() const;
    std::vector<JsonReader> fixedArray(std::size_t size, std::string_view what) const;

    bool isNumber() const { return value_.is_number(); }
    bool isString() const { return value_.is_string(); }
    bool isObject() const { return value_.is_object(); }
    bool isArray() const { return value_.is_array(); }

    // Scalars. number() is finite; positive() is finite and > 0; nonNegative() finite and >= 0.
    double number() const;
    double positive() const;
    double nonNegative() const;
    std::int64_t integer() const;
    std::string string() const;
    bool boolean() const;  // true or false

    // [x, y, z] of finite numbers; positiveVector3 also requires each component > 0.
    Eigen::Vector3d vector3() const;
    Eigen::Vector3d positiveVector3() const;
    // [x, y, z] of finite numbers, not all zero, normalised.
    Direction direction() const;
    // [[a, b, c], [d, e, f], [g, h, i]], rows first.
    Eigen::Matrix3d matrix3() const;

private:
    const Json& value_;
    std::string path_;
    const std::string& origin_;
};

}  // namespace dropscope
