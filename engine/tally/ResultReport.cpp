#include "tally/ResultReport.hpp"

#include <algorithm>
#include <stdexcept>

namespace dropscope {

std::size_t ResultColumn::size() const {
    return std::visit([](const auto& column) { return column.size(); }, values);
}

namespace {

bool isPrefix(const std::vector<std::string>& prefix, const std::vector<std::string>& path) {
    return prefix.size() <= path.size() && std::equal(prefix.begin(), prefix.end(), path.begin());
}

std::string joined(const std::vector<std::string>& path) {
    std::string text;
    for (const std::string& key : path) text += (text.empty() ? "" : ".") + key;
    return text;
}

}  // namespace

void ResultReport::set(std::vector<std::string> path, SummaryValue value) {
    if (path.empty()) throw std::invalid_argument("a summary value needs a key");
    for (const SummaryEntry& entry : summary_) {
        // Each key is set once (two tallies reporting one key would hide one of them), and a key is a
        // value or a group of values, never both.
        if (entry.path == path) throw std::invalid_argument("summary key " + joined(path) + " is set twice");
        if (isPrefix(entry.path, path) || isPrefix(path, entry.path)) {
            throw std::invalid_argument("summary keys " + joined(entry.path) + " and " + joined(path) + " clash");
        }
    }
    summary_.push_back({std::move(path), std::move(value)});
}

void ResultReport::addTable(ResultTable table) {
    if (this->table(table.name)) throw std::invalid_argument("two result tables named " + table.name);
    for (const ResultColumn& column : table.columns) {
        if (column.size() != table.rows()) {
            throw std::invalid_argument("result table " + table.name + ": column " + column.name + " has " +
                                        std::to_string(column.size()) + " rows, not " + std::to_string(table.rows()));
        }
    }
    if (!table.grid.empty() && (table.grid.size() != 2 || table.grid[0] * table.grid[1] != table.rows())) {
        throw std::invalid_argument("result table " + table.name + ": its grid does not match its rows");
    }
    tables_.push_back(std::move(table));
}

void ResultReport::addImage(ResultImage image) {
    for (const ResultImage& other : images_) {
        if (other.name == image.name) throw std::invalid_argument("two result images named " + image.name);
    }
    if (image.width < 1 || image.height < 1 ||
        image.rgb.size() != 3 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height)) {
        throw std::invalid_argument("result image " + image.name + ": its size does not match its pixels");
    }
    images_.push_back(std::move(image));
}

const ResultColumn* ResultTable::column(std::string_view columnName) const {
    const auto found =
        std::find_if(columns.begin(), columns.end(), [&](const ResultColumn& c) { return c.name == columnName; });
    return found == columns.end() ? nullptr : &*found;
}

const SummaryValue* ResultReport::find(const std::vector<std::string>& path) const {
    const auto entry =
        std::find_if(summary_.begin(), summary_.end(), [&](const SummaryEntry& e) { return e.path == path; });
    return entry == summary_.end() ? nullptr : &entry->value;
}

const ResultTable* ResultReport::table(std::string_view name) const {
    const auto found =
        std::find_if(tables_.begin(), tables_.end(), [&](const ResultTable& t) { return t.name == name; });
    return found == tables_.end() ? nullptr : &*found;
}

}  // namespace dropscope
