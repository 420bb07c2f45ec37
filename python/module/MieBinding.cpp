// dropscope.mie: `dropscope mie` in-process (computeMie), its table and summary for Python.
#include "PythonScene.hpp"

#include "cli/MieCommand.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

namespace py = pybind11;

namespace dropscope::python {

namespace {

// Text for sys.stderr written from code that runs without the GIL: each flush takes it and writes.
class PythonStderr : public std::stringbuf {
protected:
    int sync() override {
        const std::string text = str();
        str({});
        if (!text.empty()) {
            py::gil_scoped_acquire acquire;
            py::module_::import("sys").attr("stderr").attr("write")(text);
        }
        return 0;
    }
};

}  // namespace

void bindMie(py::module_& module) {
    py::class_<MieRun, std::shared_ptr<MieRun>>(module, "MieRunCore")
        .def("summary_json",
             [](const MieRun& self) {
                 std::ostringstream out;
                 writeMieSummary(self.summary, out);
                 return out.str();
             })
        .def("columns",
             [](const MieRun& self) {
                 py::dict columns;
                 for (const ResultColumn& column : self.table.columns) {
                     const auto& values = std::get<std::vector<double>>(column.values);
                     columns[column.name.c_str()] =
                         py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
                 }
                 return columns;
             })
        .def(
            "save",
            [](const MieRun& self, const std::string& directory) {
                saveRunFiles(directory, {"mie.csv", "summary.json"}, [&] { writeMieFiles(directory, self); });
            },
            py::arg("directory"));
    module.def(
        "mie",
        [](std::optional<double> index, std::optional<double> kappa, std::optional<double> x,
           std::vector<double> xRange, std::optional<std::uint64_t> xCount, const PythonScene* scene,
           std::optional<std::uint64_t> shape, std::optional<std::uint64_t> generator, std::uint64_t bins) {
            MieOptions options;
            options.index = index;
            options.kappa = kappa;
            options.x = x;
            options.xRange = std::move(xRange);
            options.xCount = xCount;
            options.shape = shape;
            options.generator = generator;
            options.bins = bins;
            std::shared_ptr<const Scene> kept;
            if (scene) {
                options.scenePath = scene->origin();
                kept = scene->shared();
            }
            PythonStderr buffer;
            std::ostream err(&buffer);
            py::gil_scoped_release release;
            return std::make_shared<MieRun>(computeMie(options, err, kept.get()));
        },
        py::arg("index"), py::arg("kappa"), py::arg("x"), py::arg("x_range"), py::arg("x_count"), py::arg("scene"),
        py::arg("shape"), py::arg("generator"), py::arg("bins"));
}

}  // namespace dropscope::python
