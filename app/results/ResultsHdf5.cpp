#include "results/ResultsHdf5.hpp"

#include "results/Hdf5Writer.hpp"

#include <algorithm>
#include <map>
#include <ostream>

namespace dropscope {

namespace {

// What a reader checks before anything else: this layout, and its version (docs/results-format.md).
constexpr const char* kFormatName = "dropscope results";
constexpr std::uint64_t kFormatVersion = 1;

// A summary key or a table, column or image name as an HDF5 name: '%' and '/' percent-encoded, and so is a
// name that is only ".", so that a medium named "salt/water" stays one group ("salt%2Fwater"); Python's
// urllib.parse.unquote gives the name back. Every other name is written as it is.
std::string hdf5Name(const std::string& name) {
    if (name == ".") return "%2E";
    std::string encoded;
    for (char c : name) encoded += c == '%' ? "%25" : c == '/' ? "%2F" : std::string(1, c);
    return encoded;
}

bool isOmitted(const std::vector<std::string>& path, const std::vector<std::vector<std::string>>& omitted) {
    return std::any_of(omitted.begin(), omitted.end(), [&](const std::vector<std::string>& prefix) {
        return prefix.size() <= path.size() && std::equal(prefix.begin(), prefix.end(), path.begin());
    });
}

// The root's attributes: the format, the version, and the run's seed and photon count when the summary has them.
void writeRootAttributes(Hdf5MemoryFile& file, const ResultReport& report, const ResultsFileInfo& info) {
    file.setAttribute(file.root(), "format", std::string(kFormatName));
    file.setAttribute(file.root(), "format_version", kFormatVersion);
    file.setAttribute(file.root(), "dropscope_version", info.version);
    for (const char* key : {"seed", "photons"}) {
        if (const SummaryValue* value = report.find({key}); value && std::holds_alternative<std::uint64_t>(*value)) {
            file.setAttribute(file.root(), key, std::get<std::uint64_t>(*value));
        }
    }
}

void setSummaryAttribute(Hdf5MemoryFile& file, hid_t group, const std::string& name, const SummaryValue& value) {
    std::visit(
        [&](const auto& v) {
            if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::nullptr_t>) {
                file.setNullAttribute(group, name);
            } else {
                file.setAttribute(group, name, v);
            }
        },
        value);
}

// /summary: each key path a chain of groups, its value an attribute of the innermost one.
void writeSummary(Hdf5MemoryFile& file, const ResultReport& report, const ResultsFileInfo& info) {
    std::map<std::vector<std::string>, Hdf5Handle> groups;
    groups.emplace(std::vector<std::string>{}, file.createGroup(file.root(), "summary"));
    for (const SummaryEntry& entry : report.summary()) {
        if (isOmitted(entry.path, info.omittedSummaryKeys)) continue;
        std::vector<std::string> prefix;
        hid_t group = groups.at(prefix).id();
        for (std::size_t k = 0; k + 1 < entry.path.size(); ++k) {
            prefix.push_back(entry.path[k]);
            auto found = groups.find(prefix);
            if (found == groups.end()) {
                found = groups.emplace(prefix, file.createGroup(group, hdf5Name(entry.path[k]))).first;
            }
            group = found->second.id();
        }
        setSummaryAttribute(file, group, hdf5Name(entry.path.back()), entry.value);
    }
}

// /tables/NAME: one dataset per column, of shape grid (ny, nx) when the rows are an image's pixels.
void writeTable(Hdf5MemoryFile& file, hid_t tables, const ResultTable& table) {
    const Hdf5Handle group = file.createGroup(tables, hdf5Name(table.name));
    std::vector<std::string> names;
    for (const ResultColumn& column : table.columns) names.push_back(hdf5Name(column.name));
    file.setAttribute(group.id(), "columns", names);
    file.setAttribute(group.id(), "rows", static_cast<std::uint64_t>(table.rows()));
    std::vector<hsize_t> shape{table.rows()};
    if (!table.grid.empty()) {
        shape.assign(table.grid.begin(), table.grid.end());
        file.setAttribute(group.id(), "grid", std::vector<std::uint64_t>(table.grid.begin(), table.grid.end()));
    }
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
        const Hdf5Handle dataset =
            std::visit([&](const auto& values) { return file.writeDataset(group.id(), names[c], shape, values); },
                       table.columns[c].values);
        file.setAttribute(dataset.id(), "unit", table.columns[c].unit);
    }
}

// /images/NAME: height x width x 3 sRGB bytes, with the attributes of the HDF5 image specification (1.2)
// that viewers such as HDFView look for.
void writeImage(Hdf5MemoryFile& file, hid_t images, const ResultImage& image) {
    const std::vector<hsize_t> shape{static_cast<hsize_t>(image.height), static_cast<hsize_t>(image.width), 3};
    const Hdf5Handle dataset = file.writeDataset(images, hdf5Name(image.name), shape, image.rgb);
    file.setAsciiAttribute(dataset.id(), "CLASS", "IMAGE");
    file.setAsciiAttribute(dataset.id(), "IMAGE_VERSION", "1.2");
    file.setAsciiAttribute(dataset.id(), "IMAGE_SUBCLASS", "IMAGE_TRUECOLOR");
    file.setAsciiAttribute(dataset.id(), "INTERLACE_MODE", "INTERLACE_PIXEL");
}

}  // namespace

std::vector<std::byte> resultsHdf5Bytes(const ResultReport& report, const ResultsFileInfo& info) {
    Hdf5MemoryFile file;
    writeRootAttributes(file, report, info);
    file.writeDataset(file.root(), "scene_json", {}, std::vector<std::string>{info.sceneJson});
    writeSummary(file, report, info);
    const Hdf5Handle tables = file.createGroup(file.root(), "tables");
    for (const ResultTable& table : report.tables()) writeTable(file, tables.id(), table);
    const Hdf5Handle images = file.createGroup(file.root(), "images");
    for (const ResultImage& image : report.images()) writeImage(file, images.id(), image);
    return file.bytes();
}

void writeResultsHdf5(const ResultReport& report, const ResultsFileInfo& info, std::ostream& out) {
    const std::vector<std::byte> bytes = resultsHdf5Bytes(report, info);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace dropscope
