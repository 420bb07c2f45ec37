// Frame time of the interactive app: the real App, headless through OSMesa (llvmpipe) at
// 1280x800, on a cloud of 1e4 water droplets with 1e3 recorded photon paths, every panel open and the
// cursor over the 3D view (so each frame also picks the shape under it through the octree for the
// tooltip). A frame is App::frame followed by glFinish. Measured, interleaved so that load drift reaches
// all alike:
//   steady   nothing changes: ImGui's panels, the pick, and the 3D view, in two frames: the second of its
//            view, which the app draws and keeps, and the next, which copies the kept picture;
//   orbit    the camera turns a degree about the target before each frame (what a drag does);
//   rebuild  every frame rebuilds the layers (what a change of a view option costs; here the axes are
//            switched on and off);
//   select   the selected droplet changes every frame (droplet 0, then none), which recolours two instances
//            in place;
//   reference ViewportScene::draw alone on the same state, drawn every frame (it keeps no picture): the 3D
//            view without ImGui and picking.
// Then, in blocks, the 3D view with only the shapes and with only the lines, and the shapes alone with the
// spheres' points drawn by the sphere programs and by the general ones (RenderOptions::sphereProgram), in
// alternate blocks; and the app orbiting and the 3D view alone with the hidden chords left out (as the app
// draws) and drawn (RenderOptions::skipHiddenChords), in alternate blocks; and the app orbiting, the 3D view
// alone and the shapes alone with the spheres apart drawn at their centre's depth (as the app draws) and not
// (RenderOptions::apartSpheres), in alternate blocks; and the app orbiting and copying its kept view with its panels
// drawn on the processor (as the app draws over a software OpenGL) and by OpenGL (UiState::panelsOnProcessor), frame by
// frame; likewise with the picture in the window's layout and in OpenGL's, and with the panels that stay kept in a
// layer (UiState::keepPanels) and all drawn every frame.
// docs/performance.md ("The app") has the figures.
//
// Run: build/bench/gui_frame_bench [--frames 40] [--droplets 1e4] [--paths 1e3] [--point-pixels 6] [--png FILE]
#include "gui/App.hpp"
#include "gui/Screenshot.hpp"
#include "gui/TraceActions.hpp"
#include "gui/ViewportScene.hpp"
#include "octree/CountArgument.hpp"
#include "octree/Measure.hpp"
#include "scene/SceneLoader.hpp"
#include "snapshot/OsmesaContext.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace dropscope::bench {

namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 800;
constexpr double kOrbitStep = 0.0174533;  // one degree, about what a slow drag turns a frame

struct Options {
    int frames = 40;
    std::uint64_t droplets = 10'000;
    std::uint64_t paths = 1'000;
    std::string png;
    float pointPixels = render::kInteractivePointPixels;
};

Options parse(int argc, char** argv) {
    Options options;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--frames")
            options.frames = static_cast<int>(parseCount(flag, argv[i + 1]));
        else if (flag == "--droplets")
            options.droplets = parseCount(flag, argv[i + 1]);
        else if (flag == "--paths")
            options.paths = parseCount(flag, argv[i + 1]);
        else if (flag == "--point-pixels")
            options.pointPixels = std::stof(argv[i + 1]);
        else if (flag == "--png")
            options.png = argv[i + 1];
        else
            throw std::invalid_argument("unknown option " + flag);
    }
    return options;
}

// Droplets of radius 0.01-0.03 at volume fraction about 0.06 (1e4 of them fill a 2-unit cube; the cube grows
// with the count, so the density stays), lit by a beam along +z.
std::string cloudScene(std::uint64_t droplets) {
    const double half = std::cbrt(static_cast<double>(droplets) / 1e4);
    const auto number = [](double x) {
        char text[32];
        std::snprintf(text, sizeof text, "%.6g", x);
        return std::string(text);
    };
    return R"({"dropscope": 1, "ambient": "air", "media": {"air": {"n": 1.000278}, "water": {"n": 1.3337}},
      "sources": [{"type": "beam", "origin": [0, 0, )" +
           number(-3 * half) + R"(], "direction": [0, 0, 1], "radius": )" + number(0.8 * half) + R"(}],
      "generators": [{"type": "droplet_cloud", "region": {"min": [)" +
           number(-half) + ", " + number(-half) + ", " + number(-half) + R"(], "max": [)" + number(half) + ", " +
           number(half) + ", " + number(half) + R"(]}, "count": )" + std::to_string(droplets) +
           R"(, "radius": {"distribution": "uniform", "min": 0.01, "max": 0.03},
      "medium": "water", "seed": 5}]})";
}

struct Series {
    std::vector<double> ms;
    double median() {
        std::sort(ms.begin(), ms.end());
        return ms[ms.size() / 2];
    }
    double minimum() const { return *std::min_element(ms.begin(), ms.end()); }
};

int run(const Options& options) {
    snapshot::OsmesaContext context(kWidth, kHeight);
    std::cout << "context: " << context.gl().describe() << "\n";
    Stopwatch loading;
    gui::App app(context.gl(), parseScene(cloudScene(options.droplets), "cloud"), {});
    std::printf("scene: %zu droplets, app ready in %.2f s\n", app.state().scene.document().shapeCount(),
                loading.seconds());

    gui::InputFrame input;
    input.windowWidth = input.framebufferWidth = kWidth;
    input.windowHeight = input.framebufferHeight = kHeight;
    input.mouseInside = true;
    input.mouseX = 700.0f;
    input.mouseY = 380.0f;
    Stopwatch firstFrame;
    app.frame(input);
    context.gl().Finish();
    std::printf("first frame (layers built and uploaded, shaders compiled): %.2f s\n", firstFrame.seconds());
    for (int k = 0; k < 2; ++k) app.frame(input);

    app.state().traces.fire.photons = options.paths;
    app.state().traces.fire.paths = options.paths;
    app.state().view.layers.render.pointPixels = options.pointPixels;
    app.state().view.layers.octree = true;
    app.state().view.layers.octreeFilter.level = 2;
    input.keysDown.set(gui::kKeySpace);
    app.frame(input);
    input.keysDown.reset(gui::kKeySpace);
    Stopwatch tracing;
    while (app.state().traces.job.running() || !app.state().traces.trace) {
        app.frame(input);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    std::printf(
        "traced %zu paths (%zu line vertices, and %zu of chords drawn only when they can show) in %.2f s "
        "of frames\n",
        app.state().traces.trace->outcome.result.paths.size(), app.viewport().layers().lines.vertices().size(),
        app.viewport().layers().chords.vertices().size(), tracing.seconds());

    gui::ViewportScene reference(context.gl(), false);  // draws its view in every frame
    reference.draw(app.state(), kWidth, kHeight);       // uploads the same layers once, then only draws
    Series steady, steadyCopied, orbit, rebuild, select, alone;
    // The axes on for one timed frame and off for the next, both rebuilding; droplet 0 selected for one and
    // nothing again for the next, both recolouring. The reference always draws the state it was built from
    // (no axes, nothing selected). The first steady frame is the second of its view (after the last
    // change), which the app draws and keeps; the next copies it.
    for (int k = 0; k < options.frames; ++k) {
        for (Series* series : {&steady, &steadyCopied}) {
            Stopwatch watch;
            app.frame(input);
            context.gl().Finish();
            series->ms.push_back(1e3 * watch.seconds());
        }
        {
            app.state().view.camera.orbit(kOrbitStep, 0.0);
            Stopwatch watch;
            app.frame(input);
            context.gl().Finish();
            orbit.ms.push_back(1e3 * watch.seconds());
        }
        for (const bool axes : {true, false}) {
            app.state().view.layers.axes = axes;
            Stopwatch watch;
            app.frame(input);
            context.gl().Finish();
            rebuild.ms.push_back(1e3 * watch.seconds());
        }
        for (const ShapeId selected : {ShapeId{0}, RayHit::kNone}) {
            app.state().scene.selectShape(selected);
            Stopwatch watch;
            app.frame(input);
            context.gl().Finish();
            select.ms.push_back(1e3 * watch.seconds());
        }
        {
            Stopwatch watch;
            reference.draw(app.state(), kWidth, kHeight);
            context.gl().Finish();
            alone.ms.push_back(1e3 * watch.seconds());
        }
    }
    // What the 3D view's time is made of: each layer alone (a block of frames each, after a rebuild).
    const auto layerAlone = [&](bool shapes, bool lines, bool sphereProgram = true, int frames = 0,
                                bool skipHiddenChords = true, bool apartSpheres = true) {
        gui::AppState& state = app.state();
        const render::RenderOptions kept = state.view.layers.render;
        state.view.layers.render.shapes = shapes;
        state.view.layers.render.lines = lines;
        state.view.layers.render.sphereProgram = sphereProgram;
        state.view.layers.render.skipHiddenChords = skipHiddenChords;
        state.view.layers.render.apartSpheres = apartSpheres;
        reference.draw(state, kWidth, kHeight);
        Series series;
        for (int k = 0; k < (frames > 0 ? frames : options.frames); ++k) {
            Stopwatch watch;
            reference.draw(state, kWidth, kHeight);
            context.gl().Finish();
            series.ms.push_back(1e3 * watch.seconds());
        }
        state.view.layers.render = kept;
        return series;
    };
    Series shapesAlone = layerAlone(true, false);
    Series linesAlone = layerAlone(false, true);
    // The peer of the sphere programs: the spheres' points drawn by the general ones, in four blocks.
    Series shapesSphereProgram, shapesGeneral;
    for (const bool sphereProgram : {true, false, false, true}) {  // each side first once
        const int frames = std::max(1, options.frames / 4);
        Series& into = sphereProgram ? shapesSphereProgram : shapesGeneral;
        const Series block = layerAlone(true, false, sphereProgram, frames);
        into.ms.insert(into.ms.end(), block.ms.begin(), block.ms.end());
    }
    // The peer of leaving the hidden chords out: drawing them, for the app orbiting and for the 3D view alone,
    // in alternate blocks (each after one untimed frame that rebuilds the layers).
    const auto orbitBlock = [&](bool skipHiddenChords, bool apartSpheres, int frames, Series& into) {
        gui::AppState& state = app.state();
        state.view.layers.render.skipHiddenChords = skipHiddenChords;
        state.view.layers.render.apartSpheres = apartSpheres;
        app.frame(input);
        for (int k = 0; k < frames; ++k) {
            state.view.camera.orbit(kOrbitStep, 0.0);
            Stopwatch watch;
            app.frame(input);
            context.gl().Finish();
            into.ms.push_back(1e3 * watch.seconds());
        }
        state.view.layers.render.skipHiddenChords = true;
        state.view.layers.render.apartSpheres = true;
    };
    Series orbitSkipping, orbitChords, viewSkipping, viewChords;
    for (const bool skip : {true, false, false, true}) {
        const int frames = std::max(1, options.frames / 4);
        orbitBlock(skip, true, frames, skip ? orbitSkipping : orbitChords);
        const Series block = layerAlone(true, true, true, frames, skip);
        Series& into = skip ? viewSkipping : viewChords;
        into.ms.insert(into.ms.end(), block.ms.begin(), block.ms.end());
    }
    // The peer of drawing the spheres apart at their centre's depth: not (RenderOptions::apartSpheres false),
    // for the app orbiting, the 3D view alone and the shapes alone, in alternate blocks.
    Series orbitApart, orbitNotApart, viewApart, viewNotApart, shapesApart, shapesNotApart;
    for (const bool apart : {true, false, false, true}) {
        const int frames = std::max(1, options.frames / 4);
        orbitBlock(true, apart, frames, apart ? orbitApart : orbitNotApart);
        const Series view = layerAlone(true, true, true, frames, true, apart);
        Series& viewInto = apart ? viewApart : viewNotApart;
        viewInto.ms.insert(viewInto.ms.end(), view.ms.begin(), view.ms.end());
        const Series shapes = layerAlone(true, false, true, frames, true, apart);
        Series& shapesInto = apart ? shapesApart : shapesNotApart;
        shapesInto.ms.insert(shapesInto.ms.end(), shapes.ms.begin(), shapes.ms.end());
    }
    // The peer of drawing a frame of spheres and lines on the processor (RenderOptions::processorRaster): OpenGL, for
    // the app orbiting and the 3D view alone, in alternate blocks.
    Series orbitProcessor, orbitOpenGL, viewProcessor, viewOpenGL;
    const bool processorAsIs = app.state().view.layers.render.processorRaster;
    for (const bool processor : {true, false, false, true}) {
        const int frames = std::max(1, options.frames / 4);
        app.state().view.layers.render.processorRaster = processor;
        orbitBlock(true, true, frames, processor ? orbitProcessor : orbitOpenGL);
        const Series view = layerAlone(true, true, true, frames);
        Series& viewInto = processor ? viewProcessor : viewOpenGL;
        viewInto.ms.insert(viewInto.ms.end(), view.ms.begin(), view.ms.end());
    }
    app.state().view.layers.render.processorRaster = processorAsIs;
    // A change and its peer alternated frame by frame (each side first in turn; `choose(true)` sets the change), for
    // the app orbiting and for a frame that copies the kept view (the third of its view, after the one drawing it and
    // the one keeping it).
    struct Sides {
        Series orbit;
        Series copied;
    };
    const auto alternateFrames = [&](const std::function<void(bool)>& choose, Sides& change, Sides& peer) {
        for (int k = 0; k < options.frames; ++k) {
            for (const bool changed : {k % 2 == 0, k % 2 != 0}) {
                choose(changed);
                app.state().view.camera.orbit(kOrbitStep, 0.0);
                Sides& sides = changed ? change : peer;
                for (Series* series : {&sides.orbit, (Series*)nullptr, &sides.copied}) {
                    Stopwatch watch;
                    app.frame(input);
                    context.gl().Finish();
                    if (series) series->ms.push_back(1e3 * watch.seconds());
                }
            }
        }
    };
    // The peer of drawing the panels on the processor (UiState::panelsOnProcessor): OpenGL's.
    Sides panelsProcessor, panelsOpenGL;
    alternateFrames([&](bool processor) { app.state().ui.panelsOnProcessor = processor; }, panelsProcessor,
                    panelsOpenGL);
    app.state().ui.panelsOnProcessor = true;
    // The peer of handing the processor's picture over in the window's own layout (GlFunctions::windowLayout,
    // OSMesa's: the top row first, RGBA), which makes the blit a copy of memory: OpenGL's layout (the bottom row
    // first).
    Sides windowLayoutSides, openGLLayoutSides;
    const render::PixelLayout windowLayout = context.gl().windowLayout;
    alternateFrames([&](bool window) { context.setWindowLayout(window ? windowLayout : render::PixelLayout{}); },
                    windowLayoutSides, openGLLayoutSides);
    context.setWindowLayout(windowLayout);
    // The peer of keeping the panels' lists that stay in a layer (UiState::keepPanels): every list drawn every frame.
    Sides keptSides, drawnSides;
    alternateFrames([&](bool kept) { app.state().ui.keepPanels = kept; }, keptSides, drawnSides);
    app.state().ui.keepPanels = true;
    const double reference3d = alone.median();
    std::printf("\n%-44s %10s %10s %12s\n", "frame (1280x800, llvmpipe)", "median ms", "min ms", "/ 3D alone");
    const auto row = [&](const char* name, Series& series) {
        std::printf("%-44s %10.1f %10.1f %12.2f\n", name, series.median(), series.minimum(),
                    series.median() / reference3d);
    };
    row("app, steady, view drawn and kept", steady);
    row("app, steady, kept view copied", steadyCopied);
    row("app, orbiting (1 degree a frame)", orbit);
    row("app, layers rebuilt every frame", rebuild);
    row("app, selection changed every frame", select);
    row("reference: 3D view alone (ViewportScene)", alone);
    row("  of which the shapes alone", shapesAlone);
    row("  of which the lines alone", linesAlone);
    row("  shapes alone, sphere programs (alternated)", shapesSphereProgram);
    row("  shapes alone, general programs (alternated)", shapesGeneral);
    row("app, orbiting, hidden chords left out (alt.)", orbitSkipping);
    row("app, orbiting, hidden chords drawn (alt.)", orbitChords);
    row("3D view alone, hidden chords left out (alt.)", viewSkipping);
    row("3D view alone, hidden chords drawn (alt.)", viewChords);
    row("app, orbiting, spheres apart at centre (alt.)", orbitApart);
    row("app, orbiting, spheres apart not (alt.)", orbitNotApart);
    row("3D view alone, spheres apart at centre (alt.)", viewApart);
    row("3D view alone, spheres apart not (alt.)", viewNotApart);
    row("shapes alone, spheres apart at centre (alt.)", shapesApart);
    row("shapes alone, spheres apart not (alt.)", shapesNotApart);
    row("app, orbiting, drawn on the processor (alt.)", orbitProcessor);
    row("app, orbiting, drawn by OpenGL (alt.)", orbitOpenGL);
    row("3D view alone, on the processor (alt.)", viewProcessor);
    row("3D view alone, by OpenGL (alt.)", viewOpenGL);
    row("app, orbiting, panels on the processor (alt.)", panelsProcessor.orbit);
    row("app, orbiting, panels by OpenGL (alt.)", panelsOpenGL.orbit);
    row("kept view copied, panels on processor (alt.)", panelsProcessor.copied);
    row("kept view copied, panels by OpenGL (alt.)", panelsOpenGL.copied);
    row("app, orbiting, window's layout (alt.)", windowLayoutSides.orbit);
    row("app, orbiting, OpenGL's layout (alt.)", openGLLayoutSides.orbit);
    row("kept view copied, window's layout (alt.)", windowLayoutSides.copied);
    row("kept view copied, OpenGL's layout (alt.)", openGLLayoutSides.copied);
    row("app, orbiting, panels kept (alt.)", keptSides.orbit);
    row("app, orbiting, panels drawn (alt.)", drawnSides.orbit);
    row("kept view copied, panels kept (alt.)", keptSides.copied);
    row("kept view copied, panels drawn (alt.)", drawnSides.copied);
    std::printf("steady (kept view copied): %.1f frames/s, orbiting: %.1f frames/s\n", 1e3 / steadyCopied.median(),
                1e3 / orbit.median());
    // The ray tree (R): first of the scene (its optical scene built from the document), then again from a source
    // moved a little (what a drag with "live" on does: the optical scene is kept). On the UI thread, as every tree
    // was before RayTreeJob and as a document of up to TraceState::rayTreeBackgroundShapes shapes still is; then
    // on the job, the app drawing orbiting frames until the tree arrives.
    gui::TraceState& traces = app.state().traces;
    const auto moveSource = [&] {
        std::vector<Source> sources = app.state().scene.document().sources();
        sources[app.state().scene.selectedSource()].origin += Point(1e-3, 0.0, 0.0);
        app.state().scene.document().setSources(sources);
    };
    const std::size_t background = traces.rayTreeBackgroundShapes;
    traces.rayTreeBackgroundShapes = std::numeric_limits<std::size_t>::max();
    for (const bool kept : {false, true}) {
        if (kept) moveSource();
        Stopwatch watch;
        gui::fireRayTree(app.state());
        std::printf("ray tree on the UI thread, %s: %.1f ms, %zu events\n",
                    kept ? "the source moved (optical scene kept)" : "optical scene built", 1e3 * watch.seconds(),
                    traces.rayTree ? traces.rayTree->nodes.size() : 0);
    }
    traces.rayTreeBackgroundShapes = 0;
    gui::forgetTraces(traces);
    for (const bool kept : {false, true}) {
        if (kept) moveSource();
        const std::uint64_t shownBefore = traces.shownId;
        Stopwatch shown;
        Stopwatch call;
        gui::fireRayTree(app.state());
        const double asked = 1e3 * call.seconds();
        Series frames;
        // Until the frame that takes the tree (and builds the view's layers for it) has been drawn.
        while (traces.shownId == shownBefore && app.state().ui.status.text().find("failed") == std::string::npos) {
            app.state().view.camera.orbit(kOrbitStep, 0.0);
            Stopwatch frame;
            app.frame(input);
            context.gl().Finish();
            frames.ms.push_back(1e3 * frame.seconds());
        }
        if (!traces.rayTree) throw std::runtime_error(app.state().ui.status.text());
        const double longest = *std::max_element(frames.ms.begin(), frames.ms.end());  // one frame at least
        std::printf(
            "ray tree on the job, %s: %.1f ms on the UI thread to ask, shown after %.1f ms and %zu "
            "orbiting frames (median %.1f ms, longest %.1f ms, the last one taking the tree and building the "
            "view's layers for it in %.1f ms), %zu events\n",
            kept ? "the source moved" : "optical scene built", asked, 1e3 * shown.seconds(), frames.ms.size(),
            frames.median(), longest, 1e3 * app.viewport().lastRebuildSeconds(), traces.rayTree->nodes.size());
    }
    traces.rayTreeBackgroundShapes = background;
    if (!options.png.empty()) {
        app.frame(input);
        gui::writePng(gui::readFramebuffer(context.gl(), kWidth, kHeight), options.png);
        std::printf("last frame written to %s\n", options.png.c_str());
    }
    return 0;
}

}  // namespace

}  // namespace dropscope::bench

int main(int argc, char** argv) {
    try {
        return dropscope::bench::run(dropscope::bench::parse(argc, argv));
    } catch (const std::exception& error) {
        std::cerr << "gui_frame_bench: " << error.what() << "\n";
        return 2;
    }
}
