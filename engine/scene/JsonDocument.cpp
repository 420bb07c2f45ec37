#include "scene/JsonDocument.hpp"

#include "scene/JsonPath.hpp"
#include "scene/SceneLoader.hpp"

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

namespace dropscope {

namespace {

// Far deeper than any scene needs (the deepest value, shapes[i].matrix[r][c], is 4 levels down), yet
// shallow enough that a hostile file cannot make paths or nesting costly.
constexpr std::size_t kMaxDepth = 64;

// "line L, column C" of the character before byte `position`, counted as nlohmann's lexer counts.
std::string lineAndColumn(std::string_view text, std::size_t position) {
    const std::string_view read = text.substr(0, std::min(position, text.size()));
    const auto line = 1 + std::count(read.begin(), read.end(), '\n');
    const std::size_t lastNewline = read.rfind('\n');
    const std::size_t lineStart = lastNewline == std::string_view::npos ? 0 : lastNewline + 1;
    return "line " + std::to_string(line) + ", column " + std::to_string(position - lineStart);
}

// nlohmann's what() without the "[json.exception.parse_error.101] parse error at line 1, column 2: "
// prefix, whose position we print ourselves for every kind of parser error.
std::string parserMessage(const std::string& what) {
    std::string message = what;
    if (const auto bracket = message.find("] ");
        message.starts_with("[json.exception.") && bracket != std::string::npos) {
        message.erase(0, bracket + 2);
    }
    if (message.starts_with("parse error")) {
        if (const auto colon = message.find(": "); colon != std::string::npos) message.erase(0, colon + 2);
    }
    return message;
}

// Builds the document from SAX events, so that duplicate keys (which nlohmann would silently
// overwrite) and excessive nesting are reported with their JSON path, and parser errors with the
// line and column of every kind of error.
class DocumentBuilder final : public nlohmann::json_sax<Json> {
public:
    DocumentBuilder(Json& root, std::string_view text, const std::string& origin)
        : root_(root), text_(text), origin_(origin) {}

    bool null() override { return scalar(nullptr); }
    bool boolean(bool value) override { return scalar(value); }
    bool number_integer(number_integer_t value) override { return scalar(value); }
    bool number_unsigned(number_unsigned_t value) override { return scalar(value); }
    bool number_float(number_float_t value, const string_t& /*raw*/) override { return scalar(value); }
    bool string(string_t& value) override { return scalar(std::move(value)); }
    bool binary(binary_t& value) override { return scalar(Json::binary(std::move(value))); }

    bool start_object(std::size_t /*elements*/) override { return open(Json::object()); }
    bool start_array(std::size_t /*elements*/) override { return open(Json::array()); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& key) override {
        Container& object = open_.back();
        if (object.node->contains(key)) {
            throw SceneError(origin_, innermostPath(), "duplicate key " + jsonpath::quoted(key));
        }
        object.key = std::move(key);
        return true;
    }

    bool parse_error(std::size_t position, const std::string& /*lastToken*/,
                     const nlohmann::detail::exception& error) override {
        throw SceneError(origin_, "", lineAndColumn(text_, position) + ": " + parserMessage(error.what()));
    }

private:
    struct Container {
        Json* node;
        std::string key;  // the member being read, for objects
    };

    // Places a value in the innermost open container (or as the root); returns where it now lives.
    Json* add(Json value) {
        if (open_.empty()) {
            root_ = std::move(value);
            return &root_;
        }
        Container& parent = open_.back();
        if (parent.node->is_array()) {
            parent.node->push_back(std::move(value));
            return &parent.node->back();
        }
        Json& slot = (*parent.node)[parent.key];
        slot = std::move(value);
        return &slot;
    }

    // The path of the innermost open container; built only for messages. Each open container is the
    // last element, or the member `key`, of the one enclosing it.
    std::string innermostPath() const {
        std::string path;
        for (std::size_t depth = 1; depth < open_.size(); ++depth) {
            const Container& parent = open_[depth - 1];
            path = parent.node->is_array() ? jsonpath::element(path, parent.node->size() - 1)
                                           : jsonpath::member(path, parent.key);
        }
        return path;
    }

    bool scalar(Json value) {
        add(std::move(value));
        return true;
    }

    bool open(Json container) {
        if (open_.size() == kMaxDepth) {
            throw SceneError(origin_, innermostPath(),
                             "nested more than " + std::to_string(kMaxDepth) + " levels deep");
        }
        // A container's address is stable while it is open: its parent gains no other member meanwhile.
        open_.push_back({add(std::move(container)), {}});
        return true;
    }

    bool close() {
        open_.pop_back();
        return true;
    }

    Json& root_;
    std::string_view text_;
    const std::string& origin_;
    std::vector<Container> open_;
};

}  // namespace

Json parseJsonDocument(std::string_view text, const std::string& origin) {
    Json root;
    DocumentBuilder builder(root, text, origin);
    Json::sax_parse(text, &builder);
    return root;
}

std::string readJsonFileText(const std::filesystem::path& file) {
    const std::string origin = file.string();
    std::error_code status;
    if (!std::filesystem::exists(file, status)) throw SceneError(origin, "", "no such file");
    if (std::filesystem::is_directory(file, status)) throw SceneError(origin, "", "is a directory, not a scene file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SceneError(origin, "", "cannot open: " + std::generic_category().message(errno));
    // Read in blocks up to the limit: a device such as /dev/zero, or a runaway pipe, would otherwise be read
    // until memory runs out.
    std::string text;
    std::vector<char> block(std::size_t{1} << 20);
    while (in) {
        in.read(block.data(), static_cast<std::streamsize>(block.size()));
        if (text.size() + static_cast<std::size_t>(in.gcount()) > kMaxJsonFileBytes) {
            throw SceneError(origin, "",
                             "larger than " + std::to_string(kMaxJsonFileBytes >> 20) +
                                 " MiB, the most a scene or patches file may be (docs/limits.md)");
        }
        text.append(block.data(), static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) throw SceneError(origin, "", "cannot read: " + std::generic_category().message(errno));
    return text;
}

}  // namespace dropscope
