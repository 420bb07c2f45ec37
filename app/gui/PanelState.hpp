#pragma once

#include "geometry/Shape.hpp"
#include "gui/plot/PlotWindowState.hpp"
#include "tree/OctreeTypes.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace dropscope::gui {

// The file-name prompt open, if any (File menu, Ctrl+O).
enum class FilePrompt { None, Open, SaveAs, ExportPaths, Screenshot };

// The screenshot prompt's own choices: panels or the 3D view alone, the window's size or another.
struct ScreenshotChoice {
    bool panels = false;
    bool windowSize = true;
    int width = 1920;
    int height = 1080;
};

// The file prompt's field and choices (FilePrompts.cpp).
struct FilePromptFields {
    FilePrompt filledFor = FilePrompt::None;  // the prompt the field was last filled in for
    std::string path;
    ScreenshotChoice screenshot;
};

// The droplet cloud generator's fields (ScenePanel.cpp).
struct CloudFields {
    Eigen::Vector3d lower{-1.0, -1.0, -1.0};
    Eigen::Vector3d upper{1.0, 1.0, 1.0};
    int count = 100;
    double radiusMin = 0.02;
    double radiusMax = 0.06;
    int seed = 1;
};

// The Scene panel's (ScenePanel.cpp).
struct ScenePanelFields {
    std::string filter;             // the shape list's filter text
    std::uint32_t editingItem = 0;  // the ImGui item whose edits merge into one undo step (0: none)
    CloudFields cloud;
};

// The Media panel's Dispersion window (DispersionWindow.cpp): open or not, and for which medium.
struct MediaPanelFields {
    bool dispersionOpen = false;
    MediumId dispersionOf = 0;
};

// The Fire panel's source editor (FirePanel.cpp).
struct FirePanelFields {
    std::uint32_t editingItem = 0;  // the ImGui item whose edits merge into one undo step (0: none)
};

// The Detectors panel's editor (DetectorsPanel.cpp).
struct DetectorsPanelFields {
    std::uint32_t editingItem = 0;  // the ImGui item whose edits merge into one undo step (0: none)
};

// The octree's per-level statistics, which walk every cell: computed again only for another document or
// revision (OctreePanel.cpp).
struct OctreeStatistics {
    std::uint64_t generation = 0;
    std::uint64_t revision = 0;
    std::vector<LevelStatistics> levels;  // empty until computed
};

// What the panels keep from one frame to the next besides the state they show: the fields of a form
// being filled in, a cache. Opening a scene starts them afresh.
struct PanelState {
    FilePromptFields filePrompt;
    ScenePanelFields scenePanel;
    MediaPanelFields mediaPanel;
    FirePanelFields firePanel;
    DetectorsPanelFields detectorsPanel;
    OctreeStatistics octreeStatistics;
    bool octreeCellsShown = false;  // in the last frame: the Octree panel opens when the cells are switched on
    plot::PlotWindowState angularPlot{.exportPath = "angular-plot.csv"};  // the Results panel's
};

}  // namespace dropscope::gui
