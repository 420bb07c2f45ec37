// dropscope.trace: `dropscope trace` in-process, its results as Python objects (TraceRunCore, wrapped by
// dropscope.TraceResult) and, on request, as the CLI's files.
#include "PythonScene.hpp"

#include "cli/TraceCommand.hpp"
#include "results/PathsJsonl.hpp"
#include "results/TraceFiles.hpp"
#include "run/TraceRun.hpp"
#include "scene/SceneLimits.hpp"
#include "tally/FateTally.hpp"
#include "transport/OpticalScene.hpp"

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <atomic>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace dropscope::python {

namespace {

// A finished (or stopped) run and what its files describe.
struct TraceRunCore {
    TraceResult result;
    TraceRunInfo info;
    std::vector<Medium> media;
    ResultReport report;
};

// A column as a numpy array (counts as int64), texts as a list; a detector's pixels shaped {ny, nx}.
py::object columnObject(const ResultColumn& column, const std::vector<std::size_t>& grid) {
    py::object values = std::visit(
        [](const auto& data) -> py::object {
            using Value = typename std::decay_t<decltype(data)>::value_type;
            if constexpr (std::is_same_v<Value, std::string>) {
                return py::cast(data);
            } else if constexpr (std::is_same_v<Value, double>) {
                return py::array_t<double>(static_cast<py::ssize_t>(data.size()), data.data());
            } else {
                py::array_t<std::int64_t> array(static_cast<py::ssize_t>(data.size()));
                std::int64_t* out = array.mutable_data();
                for (std::size_t i = 0; i < data.size(); ++i) out[i] = static_cast<std::int64_t>(data[i]);
                return array;
            }
        },
        column.values);
    if (grid.size() == 2 && py::isinstance<py::array>(values)) {
        values = values.attr("reshape")(py::make_tuple(grid[0], grid[1]));
    }
    return values;
}

py::dict tablesOf(const ResultReport& report) {
    py::dict tables;
    for (const ResultTable& table : report.tables()) {
        py::dict columns;
        for (const ResultColumn& column : table.columns)
            columns[column.name.c_str()] = columnObject(column, table.grid);
        tables[table.name.c_str()] = std::move(columns);
    }
    return tables;
}

py::dict imagesOf(const ResultReport& report) {
    py::dict images;
    for (const ResultImage& image : report.images()) {
        py::array_t<std::uint8_t> pixels({image.height, image.width, 3});
        std::copy(image.rgb.begin(), image.rgb.end(), pixels.mutable_data());
        images[image.name.c_str()] = std::move(pixels);
    }
    return images;
}

TraceOptions traceOptions(const PythonScene& scene, std::uint64_t photons, std::uint64_t seed, int threads, int bins,
                          const std::string& polarisation, const std::string& diffraction, int wavelengthBins,
                          bool orders, std::uint64_t paths, const std::string& fresnel, std::uint32_t maxEvents) {
    TraceOptions options;
    options.scenePath = scene.origin();
    options.photons = photons;
    options.seed = seed;
    options.threads = forkedChild ? 1 : threads;  // see forkedChild
    options.bins = bins;
    options.polarisation = polarisation;
    options.diffraction = diffraction;
    options.wavelengthBins = wavelengthBins;
    options.orders = orders;
    options.paths = paths;
    options.fresnel = fresnel;
    options.maxEvents = maxEvents;
    return options;
}

std::shared_ptr<TraceRunCore> trace(const PythonScene& pythonScene, std::uint64_t photons, std::uint64_t seed,
                                    int threads, int bins, const std::string& polarisation,
                                    const std::string& diffraction, int wavelengthBins, bool orders,
                                    std::uint64_t paths, const py::object& progress, const std::string& fresnel,
                                    std::uint32_t maxEvents) {
    const TraceOptions options = traceOptions(pythonScene, photons, seed, threads, bins, polarisation, diffraction,
                                              wavelengthBins, orders, paths, fresnel, maxEvents);
    const std::shared_ptr<const Scene> scene = pythonScene.shared();
    PreparedTrace prepared = prepareTrace(options, *scene);
    auto run = std::make_shared<TraceRunCore>();
    run->info = {options.scenePath, scene->sources.size(), prepared.settings, scene->wavelengthNm, scene->sources};
    run->info.sceneJson = pythonScene.text();

    // Ctrl-C and the progress callback are Python's: every interval the tracing thread that is the caller's
    // takes the GIL, lets Python run its signal handlers and calls `progress`. An exception from either stops
    // the run cleanly (no new photons) and is raised once the run has ended.
    std::atomic<bool> stop{false};
    std::optional<py::error_already_set> raised;
    TraceControl control;
    control.stop = &stop;
    control.onProgress = [&](const TraceProgress& now) {
        // A daemon thread still tracing when the interpreter exits: taking the GIL would end the thread inside
        // the OpenMP region. Stop instead; the interpreter is going away.
        if (_Py_IsFinalizing()) {
            stop = true;
            return;
        }
        py::gil_scoped_acquire acquire;
        if (raised) return;
        try {
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            if (!progress.is_none()) progress(now.done, now.total);
        } catch (py::error_already_set& error) {
            raised.emplace(std::move(error));
            stop = true;
        }
    };
    {
        py::gil_scoped_release release;
        const OpticalScene optical(*scene, prepared.settings.transport.diffraction != DiffractionModel::None);
        run->media = optical.media();
        run->result = runTrace(optical, scene->sources, prepared.settings, prepared.tallies, control);
    }
    if (raised) throw std::move(*raised);
    run->result.tallies.get<FateTally>().nameShapes([scene](ShapeId id) { return shapeLabel(*scene, id); });
    if (!progress.is_none()) progress(run->result.photons, run->result.requested);
    run->report = traceReport(run->result, run->info);
    return run;
}

}  // namespace

void bindTrace(py::module_& module) {
    py::class_<TraceRunCore, std::shared_ptr<TraceRunCore>>(module, "TraceRunCore")
        .def("summary_json",
             [](const TraceRunCore& self) {
                 std::ostringstream out;
                 writeTraceSummary(self.report, out);
                 return out.str();
             })
        .def("tables", [](const TraceRunCore& self) { return tablesOf(self.report); })
        .def("images", [](const TraceRunCore& self) { return imagesOf(self.report); })
        .def("paths_jsonl",
             [](const TraceRunCore& self) {
                 std::ostringstream out;
                 writePathsJsonl(self.result.paths, self.media, out);
                 return out.str();
             })
        .def(
            "save",
            [](const TraceRunCore& self, const std::string& directory) {
                saveRunFiles(directory, traceFileNames(self.result.tallies),
                             [&] { writeTraceFiles(directory, self.result, self.info, self.media); });
            },
            py::arg("directory"));
    module.def("trace", &trace, py::arg("scene"), py::arg("photons"), py::arg("seed"), py::arg("threads"),
               py::arg("bins"), py::arg("polarisation"), py::arg("diffraction"), py::arg("wavelength_bins"),
               py::arg("orders"), py::arg("paths"), py::arg("progress"), py::arg("fresnel"), py::arg("max_events"));
}

}  // namespace dropscope::python
