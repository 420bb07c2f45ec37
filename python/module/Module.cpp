// The compiled half of the Python package `dropscope` (docs/python.md); dropscope/__init__.py is the API.
#include "PythonScene.hpp"

#include "cli/BadInput.hpp"
#include "cli/MieCommand.hpp"
#include "cli/SnapshotCommand.hpp"
#include "cli/TraceCommand.hpp"
#include "results/Version.hpp"
#include "scene/SceneLoader.hpp"
#include "tree/RayHit.hpp"

#include <omp.h>
#include <pybind11/pybind11.h>

namespace py = pybind11;

PYBIND11_MODULE(_dropscope, module) {
    using namespace dropscope;
    module.doc() = "dropscope's engine (the API is the package dropscope, docs/python.md)";
    module.attr("__version__") = std::string(dropscopeVersion());
    // A bad scene is a ValueError whose text is the CLI's "FILE: JSON.PATH: message"; other bad input (an
    // option out of range, an output folder that cannot be used) a plain ValueError with the CLI's text.
    py::register_exception<SceneError>(module, "SceneError", PyExc_ValueError);
    py::register_exception<BadInputError>(module, "BadInputError", PyExc_ValueError);

    py::dict limits;
    limits["trace_bins"] = kMaxTraceBins;
    limits["trace_threads"] = kMaxTraceThreads;
    limits["trace_paths"] = kMaxTracePaths;
    limits["wavelength_bins"] = kMaxWavelengthBins;
    limits["mie_sizes"] = kMaxSizeCount;
    limits["snapshot_pixels_min"] = kMinSnapshotPixels;
    limits["snapshot_pixels_max"] = kMaxSnapshotPixels;
    limits["snapshot_paths"] = kMaxDrawnPaths;
    limits["snapshot_photons"] = kMaxSnapshotPhotons;
    limits["snapshot_select"] = std::uint64_t{RayHit::kNone} - 1;
    module.attr("limits") = limits;

    // GNU OpenMP cannot start threads in a child forked after the parent ran them (multiprocessing's default
    // start method on Linux): its first parallel region would wait forever. dropscope/__init__.py calls this
    // after every fork (os.register_at_fork); the child then runs everything on one thread.
    module.def("_after_fork_in_child", [] {
        python::forkedChild = true;
        omp_set_num_threads(1);
    });

    python::bindScene(module);
    python::bindQuery(module);
    python::bindTrace(module);
    python::bindMie(module);
    python::bindSnapshot(module);
}
