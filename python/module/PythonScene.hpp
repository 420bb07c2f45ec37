#pragma once

#include "scene/Scene.hpp"
#include "tree/Octree.hpp"

#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace dropscope::python {

// The scene behind a Python `dropscope.Scene`: the JSON text it was read from (a file's, or the dict's as
// json.dumps wrote it), the origin that names it in messages and results ("scene.json", "<dict>"), and the
// parsed Scene. An edit replaces the text and parses it again, all or nothing: the loader's rules, overlaps
// included, hold for every state a Python scene can be in. Traces keep the Scene they started with.
class PythonScene {
public:
    // Throws SceneError as the loader does. `base`, when not empty, is the file's absolute path: edits parse
    // the scene again under it, so files the scene refers to (Bezier patches) are found after a chdir.
    PythonScene(std::string text, std::string origin, std::string base = {});

    const std::string& text() const { return text_; }
    const std::string& origin() const { return origin_; }
    const Scene& scene() const { return *scene_; }
    std::shared_ptr<const Scene> shared() const { return scene_; }

    // Parses `text` as the scene's new state (same origin); on SceneError nothing changes.
    void replace(std::string text);

    // The octree of `dropscope query`: the shapes with the scene's octree settings, built at the first query
    // after each change (the caller holds the GIL).
    std::shared_ptr<const Octree> octree() const;

private:
    std::string text_;
    std::string origin_;
    std::string base_;
    std::shared_ptr<const Scene> scene_;
    mutable std::shared_ptr<const Octree> octree_;
};

// Set in a process forked from one that had loaded the module: it traces on one thread (Module.cpp).
inline bool forkedChild = false;

// A run's save(dir): `directory` checked for `fileNames` and created, then `write` writes them into it (all or
// none); an unusable folder is BadInputError, as in the CLI.
void saveRunFiles(const std::string& directory, const std::vector<std::string>& fileNames,
                  const std::function<void()>& write);

void bindScene(pybind11::module_& module);
void bindQuery(pybind11::module_& module);
void bindTrace(pybind11::module_& module);
void bindMie(pybind11::module_& module);
void bindSnapshot(pybind11::module_& module);

}  // namespace dropscope::python
