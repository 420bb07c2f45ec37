#include "PythonScene.hpp"

#include "cli/BadInput.hpp"
#include "cli/InspectReport.hpp"
#include "cli/OutputDirectory.hpp"
#include "cli/SceneSummary.hpp"
#include "scene/JsonDocument.hpp"
#include "scene/SceneLoader.hpp"
#include "scene/SceneWriter.hpp"

#include <pybind11/stl.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace dropscope::python {

PythonScene::PythonScene(std::string text, std::string origin, std::string base)
    : text_(std::move(text)),
      origin_(std::move(origin)),
      base_(std::move(base)),
      scene_(std::make_shared<const Scene>(parseScene(text_, origin_))) {}

void PythonScene::replace(std::string text) {
    auto scene = std::make_shared<const Scene>(parseScene(text, base_.empty() ? origin_ : base_));
    text_ = std::move(text);
    scene_ = std::move(scene);
    octree_.reset();
}

std::shared_ptr<const Octree> PythonScene::octree() const {
    if (!octree_) {
        std::vector<std::unique_ptr<Shape>> shapes;
        shapes.reserve(scene_->shapes.size());
        for (const auto& shape : scene_->shapes) shapes.push_back(shape->clone());
        octree_ = std::make_shared<const Octree>(std::move(shapes), scene_->octree);
    }
    return octree_;
}

void saveRunFiles(const std::string& directory, const std::vector<std::string>& fileNames,
                  const std::function<void()>& write) {
    checkOutputDirectory(directory, fileNames);
    createOutputDirectory(directory);
    try {
        write();
    } catch (const std::runtime_error& error) {
        throw BadInputError(error.what());
    }
}

void bindScene(py::module_& module) {
    py::class_<PythonScene>(module, "SceneCore")
        .def(py::init<std::string, std::string>(), py::arg("text"), py::arg("origin"))
        .def_static(
            "read",
            [](const std::string& path) {
                return PythonScene(readJsonFileText(path), path, std::filesystem::absolute(path).string());
            },
            py::arg("path"))
        .def_property_readonly("text", &PythonScene::text)
        .def_property_readonly("origin", &PythonScene::origin)
        .def("replace", &PythonScene::replace, py::arg("text"))
        .def_property_readonly("shape_count", [](const PythonScene& self) { return self.scene().shapes.size(); })
        .def_property_readonly("explicit_shape_count",
                               [](const PythonScene& self) { return self.scene().explicitShapeCount; })
        .def_property_readonly("shape_names", [](const PythonScene& self) { return self.scene().shapeNames; })
        .def("inspect_json",
             [](const PythonScene& self) {
                 std::ostringstream out;
                 writeInspectJson(self.scene(), summarise(self.scene()), out);
                 return out.str();
             })
        .def("explicit_json", [](const PythonScene& self) { return sceneToJson(self.scene()); });
}

}  // namespace dropscope::python
