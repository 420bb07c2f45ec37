// dropscope.snapshot: `dropscope snapshot`'s picture (renderSnapshotImage) as an (H, W, 4) array.
#include "PythonScene.hpp"

#include "cli/SnapshotCommand.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <string>

namespace py = pybind11;

namespace dropscope::python {

namespace {

// The CLI's options from the keyword arguments dropscope.snapshot checked and spelled as the CLI's values.
SnapshotCommandOptions snapshotOptions(int width, int height, const py::dict& given) {
    SnapshotCommandOptions options;
    options.render.width = width;
    options.render.height = height;
    render::LayerOptions& layers = options.render.layers;
    for (const auto& [key, value] : given) {
        const std::string name = py::cast<std::string>(key);
        if (name == "eye")
            options.eye = py::cast<std::string>(value);
        else if (name == "target")
            options.target = py::cast<std::string>(value);
        else if (name == "fov_deg")
            options.fovDeg = py::cast<double>(value);
        else if (name == "octree_level")
            options.octreeLevel = py::cast<int>(value);
        else if (name == "octree_filter")
            options.octreeFilter = py::cast<std::string>(value);
        else if (name == "octree_colour")
            options.octreeColour = py::cast<std::string>(value);
        else if (name == "colour_by")
            options.colourBy = py::cast<std::string>(value);
        else if (name == "polarisation")
            options.polarisation = py::cast<std::string>(value);
        else if (name == "paths")
            options.render.paths = py::cast<std::uint64_t>(value);
        else if (name == "photons")
            options.render.photons = py::cast<std::uint64_t>(value);
        else if (name == "seed")
            options.render.seed = py::cast<std::uint64_t>(value);
        else if (name == "select")
            options.select = py::cast<std::int64_t>(value);
        else if (name == "markers")
            layers.markers = py::cast<bool>(value);
        else if (name == "ray_tree")
            layers.rayTree = py::cast<bool>(value);
        else if (name == "traversal")
            layers.traversal = py::cast<bool>(value);
        else if (name == "sources")
            layers.sources = py::cast<bool>(value);
        else if (name == "detectors")
            layers.detectors = py::cast<bool>(value);
        else if (name == "axes")
            layers.axes = py::cast<bool>(value);
        else if (name == "grid")
            layers.grid = py::cast<bool>(value);
        else if (name == "no_shapes")
            options.noShapes = py::cast<bool>(value);
        else if (name == "translucent")
            layers.render.translucent = py::cast<bool>(value);
        else
            throw py::type_error("snapshot() got an unexpected keyword argument '" + name + "'");
    }
    return options;
}

}  // namespace

void bindSnapshot(py::module_& module) {
    module.def(
        "snapshot",
        [](const PythonScene& scene, int width, int height, const py::dict& options) {
            const SnapshotCommandOptions resolved = snapshotOptions(width, height, options);
            const std::shared_ptr<const Scene> kept = scene.shared();
            snapshot::Image image;
            {
                py::gil_scoped_release release;
                image = renderSnapshotImage(resolved, *kept);
            }
            py::array_t<std::uint8_t> pixels({image.height, image.width, 4});
            std::copy(image.rgba.begin(), image.rgba.end(), pixels.mutable_data());
            return pixels;
        },
        py::arg("scene"), py::arg("width"), py::arg("height"), py::arg("options"));
}

}  // namespace dropscope::python
