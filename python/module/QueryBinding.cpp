// dropscope.query: the first shape each ray meets, as `dropscope query` finds it.
#include "PythonScene.hpp"

#include "tree/RayHit.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace dropscope::python {

namespace {

using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string shapeText(const Rows& rows) {
    std::string text = "(";
    for (py::ssize_t axis = 0; axis < rows.ndim(); ++axis) {
        text += (axis ? ", " : "") + std::to_string(rows.shape(axis));
    }
    return text + (rows.ndim() == 1 ? ",)" : ")");
}

void checkRows(const Rows& rows, const char* name) {
    if (rows.ndim() != 2 || rows.shape(1) != 3) {
        throw py::value_error(std::string(name) + ": expected an (N, 3) array, got shape " + shapeText(rows));
    }
}

}  // namespace

void bindQuery(py::module_& module) {
    module.def(
        "query",
        [](const PythonScene& scene, const Rows& origins, const Rows& directions, bool brute) {
            checkRows(origins, "origins");
            checkRows(directions, "directions");
            if (origins.shape(0) != directions.shape(0)) {
                throw py::value_error("origins and directions: " + std::to_string(origins.shape(0)) + " and " +
                                      std::to_string(directions.shape(0)) + " rays");
            }
            const auto count = static_cast<std::size_t>(origins.shape(0));
            const double* o = origins.data();
            const double* d = directions.data();
            // The rays file's rules (cli/RayCsv.cpp): finite numbers, a direction that is not zero.
            std::vector<std::pair<Point, Direction>> rays;
            rays.reserve(count);
            for (std::size_t i = 0; i < count; ++i) {
                for (int k = 0; k < 3; ++k) {
                    if (!std::isfinite(o[3 * i + k]) || !std::isfinite(d[3 * i + k])) {
                        throw py::value_error((std::isfinite(o[3 * i + k]) ? "directions[" : "origins[") +
                                              std::to_string(i) + "]: not finite");
                    }
                }
                const Direction direction(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
                if (!direction) throw py::value_error("directions[" + std::to_string(i) + "]: is zero");
                rays.emplace_back(Point(o[3 * i], o[3 * i + 1], o[3 * i + 2]), direction);
            }
            const std::shared_ptr<const Octree> octree = brute ? nullptr : scene.octree();
            const std::shared_ptr<const Scene> kept = scene.shared();
            py::array_t<std::int64_t> ids(static_cast<py::ssize_t>(count));
            py::array_t<double> distances(static_cast<py::ssize_t>(count));
            std::int64_t* id = ids.mutable_data();
            double* distance = distances.mutable_data();
            {
                py::gil_scoped_release release;
                for (std::size_t i = 0; i < count; ++i) {
                    const RayHit hit = octree ? octree->firstHit(rays[i].first, rays[i].second)
                                              : bruteForceFirstHit(kept->shapes, rays[i].first, rays[i].second);
                    id[i] = hit ? static_cast<std::int64_t>(hit.shape) : -1;
                    distance[i] = hit ? hit.distance : std::numeric_limits<double>::quiet_NaN();
                }
            }
            return py::make_tuple(std::move(ids), std::move(distances));
        },
        py::arg("scene"), py::arg("origins"), py::arg("directions"), py::arg("brute") = false);
}

}  // namespace dropscope::python
