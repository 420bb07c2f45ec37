#include "results/SummaryJson.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace dropscope {

namespace {

using Json = nlohmann::ordered_json;

Json valueJson(const SummaryValue& value) {
    return std::visit(
        [](const auto& v) -> Json {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, double>) {
                return std::isfinite(v) ? Json(v) : Json(nullptr);
            } else {
                return Json(v);
            }
        },
        value);
}

// Where a top-level key goes: its place in keyOrder, or after all of them.
std::size_t rank(const std::string& key, const std::vector<std::string_view>& keyOrder) {
    return static_cast<std::size_t>(std::find(keyOrder.begin(), keyOrder.end(), key) - keyOrder.begin());
}

}  // namespace

void writeSummaryJson(const ResultReport& report, const std::vector<std::string_view>& keyOrder, std::ostream& out) {
    std::vector<const SummaryEntry*> entries;
    for (const SummaryEntry& entry : report.summary()) entries.push_back(&entry);
    std::stable_sort(entries.begin(), entries.end(), [&](const SummaryEntry* a, const SummaryEntry* b) {
        return rank(a->path.front(), keyOrder) < rank(b->path.front(), keyOrder);
    });
    Json summary = Json::object();
    for (const SummaryEntry* entry : entries) {
        Json* node = &summary;
        for (const std::string& key : entry->path) node = &(*node)[key];
        *node = valueJson(entry->value);
    }
    out << summary.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
}

}  // namespace dropscope
