// Frame time of the OpenGL renderer on llvmpipe: a cloud of 1e5 water droplets drawn as
// instanced impostors, about 1e4 photon path segments and the octree's cells at one level, headless
// through OSMesa at 1280x800. A frame is Renderer::draw followed by glFinish; median and minimum over
// many frames after a warm-up, for the whole scene, the shapes alone, the lines alone and a cleared frame
// (the reference of the same run), with the camera fitted to the cloud and zoomed in until a few droplets
// fill the screen. Frames of all the configurations are interleaved, so drift in the machine's load
// reaches them alike. Draw calls are counted by wrapping the draw functions of the GL table the renderer
// is given. docs/performance.md ("Rendering") has the figures and how to read them.
//
// Run: build/bench/render_bench [--frames 40] [--warm-up 3] [--segments 1e4] [--octree-level 2]
//                               [--droplets 1e5] [--width 1280] [--height 800] [--seed 1] [--png PREFIX]
#include "CloudScene.hpp"
#include "octree/CountArgument.hpp"
#include "octree/Measure.hpp"
#include "render/OctreeLayer.hpp"
#include "render/PathLayer.hpp"
#include "render/Renderer.hpp"
#include "rendering/DrawCount.hpp"
#include "run/TraceRun.hpp"
#include "scene/SceneLoader.hpp"
#include "snapshot/Image.hpp"
#include "snapshot/OsmesaContext.hpp"
#include "transport/OpticalScene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

using namespace dropscope;
using dropscope::bench::countingDraws;
using dropscope::bench::DrawCount;
using dropscope::bench::drawCount;
using dropscope::bench::fixed;
using dropscope::bench::median;
using dropscope::bench::parseCount;
using dropscope::bench::Stopwatch;

struct Options {
    int frames = 40;  // measured per configuration, after the warm-up
    int warmUp = 3;
    std::uint64_t segments = 10000;  // photon path segments, at least
    int octreeLevel = 2;
    std::uint64_t droplets = 100000;  // the cube grows with the count, so the density stays
    int width = 1280;
    int height = 800;
    std::uint64_t seed = 1;
    std::optional<std::string> png;  // PREFIX-fitted.png and PREFIX-zoomed.png of the whole scene
};

Options parseOptions(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            std::cout
                << "render_bench [--frames 40] [--warm-up 3] [--segments 1e4] [--octree-level 2] [--droplets 1e5]\n"
                   "             [--width 1280] [--height 800] [--seed 1] [--png PREFIX]\n";
            std::exit(0);
        }
        if (i + 1 >= argc) throw std::invalid_argument(flag + ": missing value");
        const char* value = argv[++i];
        const auto count = [&] { return parseCount(flag, value); };
        const auto small = [&] { return static_cast<int>(std::min<std::uint64_t>(count(), 100000)); };
        if (flag == "--frames")
            options.frames = std::max(1, small());
        else if (flag == "--warm-up")
            options.warmUp = small();
        else if (flag == "--segments")
            options.segments = count();
        else if (flag == "--octree-level")
            options.octreeLevel = small();
        else if (flag == "--droplets")
            options.droplets = std::max<std::uint64_t>(1, count());
        else if (flag == "--width")
            options.width = std::max(1, small());
        else if (flag == "--height")
            options.height = std::max(1, small());
        else if (flag == "--seed")
            options.seed = count();
        else if (flag == "--png")
            options.png = value;
        else
            throw std::invalid_argument("unknown option " + flag);
    }
    return options;
}

template <class T>
std::string megabytes(const std::vector<T>& data) {
    return fixed(static_cast<double>(data.size() * sizeof(T)) / 1e6, 2);
}

std::string loadAverage() {
    std::ifstream file("/proc/loadavg");
    std::string one;
    file >> one;
    return file ? one : "?";
}

// ---- The scene ---------------------------------------------------------------------------------------

Eigen::AlignedBox3d shapeBounds(const Octree& octree) {
    Eigen::AlignedBox3d bounds;
    for (const auto& shape : octree.shapes()) {
        if (shape) bounds.extend(shape->bounds());
    }
    return bounds;
}

// The first photons of a traced run whose paths make at least `segments` line segments (as drawn).
std::vector<PhotonPath> pathsOfSegments(const OpticalScene& optical, const std::vector<Source>& sources,
                                        const render::Anchor& anchor, double escapeLength, const Options& options) {
    for (std::uint64_t photons = std::max<std::uint64_t>(options.segments / 8, 16);; photons *= 2) {
        TraceSettings settings;
        settings.photons = photons;
        settings.paths = photons;
        settings.seed = options.seed;
        settings.threads = 1;
        TraceResult traced = runTrace(optical, sources, settings, TallySet{});
        std::uint64_t total = 0;
        for (std::size_t k = 0; k < traced.paths.size(); ++k) {
            render::LineBatch one(anchor);
            render::addPhotonPaths(one, {traced.paths[k]}, escapeLength);
            total += one.vertices().size() / 2;
            if (total >= options.segments) {
                traced.paths.resize(k + 1);
                return std::move(traced.paths);
            }
        }
    }
}

// Zoomed in on the first droplet the fitted view's central ray meets: the eye backs off along that ray
// (clear of droplets up to the hit) until the droplet's radius is kZoomHalfHeight of the half-height.
constexpr double kZoomHalfHeight = 0.4;

render::Camera zoomedCamera(const render::Camera& fitted, const Octree& octree, const Eigen::AlignedBox3d& bounds) {
    const Point eye(fitted.eye.x, fitted.eye.y, fitted.eye.z);
    const Direction towards(Point(fitted.target.x, fitted.target.y, fitted.target.z) - eye);
    const RayHit hit = octree.firstHit(eye, towards);
    if (!hit) throw std::runtime_error("the fitted view's central ray meets no droplet");
    const double radius = 0.5 * octree.shape(hit.shape)->bounds().sizes().maxCoeff();
    const Point surface = eye + hit.distance * towards.vector();
    const double distance = radius / kZoomHalfHeight / std::tan(0.5 * fitted.fovDeg * std::numbers::pi / 180.0);
    const Point zoomedEye = surface - distance * towards.vector();
    render::Camera camera = fitted;
    camera.target = {surface.x(), surface.y(), surface.z()};
    camera.eye = {zoomedEye.x(), zoomedEye.y(), zoomedEye.z()};
    camera.clipTo(bounds);
    return camera;
}

// ---- Frames --------------------------------------------------------------------------------------------

// One configuration: which layers, which camera, which viewport; its frame times.
struct Frame {
    std::string layers;
    std::string view;
    render::RenderOptions options;
    render::Camera camera;
    int width = 0;
    int height = 0;
    bool markers = false;         // with the event markers (the renderer draws whatever markers it holds)
    std::vector<double> seconds;  // draw + glFinish
    std::vector<double> submit;   // until draw returned
    DrawCount count;
};

// Times frames of one renderer: the wall clock of draw, then of draw + glFinish, and the draw calls.
// The event markers are set for the frames that want them and cleared after, outside the clock.
struct Bench {
    const render::GlFunctions& gl;
    render::Renderer& renderer;
    const std::vector<render::ShapeInstance>& markers;

    void run(Frame& frame, bool keep) {
        if (frame.markers) renderer.setMarkers(markers);
        drawCount() = {};
        const Stopwatch watch;
        renderer.draw(frame.camera, frame.options, frame.width, frame.height);
        const double submit = watch.seconds();
        gl.Finish();
        const double seconds = watch.seconds();
        frame.count = drawCount();
        if (frame.markers) renderer.setMarkers({});
        if (keep) {
            frame.seconds.push_back(seconds);
            frame.submit.push_back(submit);
        }
    }

    // Round robin over the frames: warm-up rounds first, then `rounds` measured.
    void measure(std::vector<Frame>& frames, int warmUp, int rounds) {
        for (int r = 0; r < warmUp + rounds; ++r) {
            for (Frame& frame : frames) run(frame, r >= warmUp);
        }
    }
};

Frame frame(std::string layers, std::string view, bool shapes, bool lines, const render::Camera& camera, int width,
            int height, bool markers = false) {
    Frame f;
    f.layers = std::move(layers);
    f.view = std::move(view);
    f.options.shapes = shapes;
    f.options.lines = lines;
    f.camera = camera;
    f.width = width;
    f.height = height;
    f.markers = markers;
    return f;
}

void printFrames(const std::vector<Frame>& frames, const std::string& title) {
    std::cout << "\n### " << title
              << "\n\n| layers | view | viewport | draw calls | instances | vertices submitted | median ms | min ms | "
                 "frames/s (median) | draw() returns after (median ms) | glFinish waits (median ms) |\n"
                 "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Frame& f : frames) {
        const double total = median(f.seconds);
        const double submit = median(f.submit);
        std::cout << "| " << f.layers << " | " << f.view << " | " << f.width << "x" << f.height << " | "
                  << f.count.calls << " | " << f.count.instances << " | " << f.count.vertices << " | "
                  << fixed(1e3 * total, 1) << " | "
                  << fixed(1e3 * *std::min_element(f.seconds.begin(), f.seconds.end()), 1) << " | "
                  << fixed(1.0 / total, 1) << " | " << fixed(1e3 * submit, 1) << " | "
                  << fixed(1e3 * (total - submit), 1) << " |\n";
    }
}

// Milliseconds of the first upload (the driver allocates the buffer's pages) and the median of five more.
template <class Upload>
std::string uploadMilliseconds(const render::GlFunctions& gl, Upload&& upload) {
    std::vector<double> seconds;
    for (int r = 0; r < 6; ++r) {
        const Stopwatch watch;
        upload();
        gl.Finish();
        seconds.push_back(watch.seconds());
    }
    const double first = seconds.front();
    seconds.erase(seconds.begin());
    return fixed(1e3 * first, 2) + " / " + fixed(1e3 * median(seconds), 2);
}

void writePng(snapshot::OsmesaContext& context, const std::string& file) {
    std::ofstream(file, std::ios::binary) << snapshot::encodePng(context.read());
    std::cerr << "wrote " << file << '\n';
}

// The cloud, its paths, one level of octree cells and the event markers, ready to upload.
struct BenchScene {
    Scene scene;
    std::unique_ptr<OpticalScene> optical;
    Eigen::AlignedBox3d bounds;
    render::Anchor anchor;
    std::vector<PhotonPath> paths;
    render::LineBatch lines{render::Anchor{}};
    std::size_t pathSegments = 0;
    std::size_t cellSegments = 0;
    std::vector<render::ShapeInstance> markers;
};

constexpr double kMarkerRadius = 0.02;  // mm: a fifth of the median droplet radius

BenchScene makeScene(const Options& options) {
    BenchScene s;
    const double halfSide = 15.0 * std::cbrt(static_cast<double>(options.droplets) / 1e5);
    std::cerr << "scene: " << options.droplets << " droplets\n";
    s.scene = parseScene(bench::cloudSceneText(options.droplets, halfSide), "render_bench cloud");
    s.optical = std::make_unique<OpticalScene>(s.scene);
    s.bounds = shapeBounds(s.optical->octree());
    s.anchor = render::Anchor{s.bounds.center()};
    const double escapeLength = 0.5 * s.bounds.diagonal().norm();
    std::cerr << "paths: about " << options.segments << " segments\n";
    s.paths = pathsOfSegments(*s.optical, s.scene.sources, s.anchor, escapeLength, options);
    s.lines = render::LineBatch(s.anchor);
    render::addPhotonPaths(s.lines, s.paths, escapeLength);
    s.pathSegments = s.lines.vertices().size() / 2;
    render::addOctreeCells(s.lines, s.optical->octree(), {render::OctreeFilter::Mode::OnlyLevel, options.octreeLevel});
    s.cellSegments = s.lines.vertices().size() / 2 - s.pathSegments;
    render::addEventMarkers(s.markers, s.paths, kMarkerRadius, s.anchor);
    return s;
}

// Building the instances on the CPU (median of 3), then each buffer to the driver; leaves the renderer
// holding the shapes and the lines, no markers.
std::string timeUploads(const render::GlFunctions& gl, render::Renderer& renderer, const BenchScene& s,
                        render::ShapeInstances& instances) {
    std::vector<double> build;
    for (int r = 0; r < 3; ++r) {
        const Stopwatch watch;
        instances = render::buildShapeInstances(s.optical->octree().shapes(), s.anchor);
        build.push_back(watch.seconds());
    }
    std::string row = fixed(1e3 * median(build), 1);
    row += " | " + uploadMilliseconds(gl, [&] { renderer.setShapes(instances); });
    row += " | " + uploadMilliseconds(gl, [&] { renderer.setLines(s.lines); });
    row += " | " + uploadMilliseconds(gl, [&] { renderer.setMarkers(s.markers); });
    renderer.setMarkers({});
    return row;
}

void printScene(const Options& options, const BenchScene& s, const render::ShapeInstances& instances,
                const std::string& uploads) {
    std::cout << "\n### Scene and upload\n\n| droplets (impostor instances) | photons | path segments | octree level "
              << options.octreeLevel
              << " cell segments | line vertices | event markers | build instances ms | upload instances ms | "
                 "upload lines ms | upload markers ms |\n|---|---|---|---|---|---|---|---|---|---|\n| "
              << instances.rounded.size() << " (" << megabytes(instances.rounded) << " MB) | " << s.paths.size()
              << " | " << s.pathSegments << " | " << s.cellSegments << " | " << s.lines.vertices().size() << " ("
              << megabytes(s.lines.vertices()) << " MB) | " << s.markers.size() << " | " << uploads << " |\n"
              << "\nUploads: the first, then the median of five more (each followed by glFinish).\n";
}

using Views = std::vector<std::pair<std::string, render::Camera>>;

// Every layer set under both cameras, interleaved.
std::vector<Frame> measureLayers(Bench& bench, const Views& views, const Options& options) {
    std::vector<Frame> frames;
    const int w = options.width;
    const int h = options.height;
    for (const auto& [view, camera] : views) {
        frames.push_back(frame("whole scene", view, true, true, camera, w, h));
        frames.push_back(frame("shapes", view, true, false, camera, w, h));
        frames.push_back(frame("lines", view, false, true, camera, w, h));
        frames.push_back(frame("clear only", view, false, false, camera, w, h));
        frames.push_back(frame("whole scene + event markers", view, true, true, camera, w, h, true));
    }
    std::cerr << "frames: " << frames.size() << " configurations x " << options.frames << '\n';
    bench.measure(frames, options.warmUp, options.frames);
    return frames;
}

// Where the time goes: the shapes alone with every instance and with the first tenth of them (spread
// through the whole cloud, as the generator placed them), at the full viewport and at a quarter of its
// pixels. Leaves the renderer holding the first tenth.
std::vector<Frame> measureScaling(Bench& bench, const Views& views, const Options& options,
                                  const render::ShapeInstances& instances) {
    std::vector<Frame> all;
    for (const auto& [view, camera] : views) {
        all.push_back(frame("shapes", view, true, false, camera, options.width, options.height));
        all.push_back(frame("shapes", view, true, false, camera, options.width / 2, options.height / 2));
    }
    std::vector<Frame> tenth = all;
    for (Frame& f : tenth) f.layers = "shapes, first tenth of the droplets";
    std::cerr << "scaling: every instance, then a tenth\n";
    bench.measure(all, options.warmUp, options.frames);
    render::ShapeInstances fewer;
    const auto count = static_cast<std::ptrdiff_t>(instances.rounded.size() / 10);
    fewer.rounded.assign(instances.rounded.begin(), instances.rounded.begin() + count);
    bench.renderer.setShapes(fewer);
    bench.measure(tenth, options.warmUp, options.frames);
    all.insert(all.end(), tenth.begin(), tenth.end());
    return all;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const Options options = parseOptions(argc, argv);
        const std::string loadBefore = loadAverage();
        const BenchScene s = makeScene(options);

        snapshot::OsmesaContext context(options.width, options.height);
        const render::GlFunctions& gl = context.gl();
        const render::GlFunctions counted = countingDraws(gl);
        render::Renderer renderer(counted);
        renderer.setAnchor(s.anchor);
        render::ShapeInstances instances;
        const std::string uploads = timeUploads(gl, renderer, s, instances);

        render::Camera fitted;
        fitted.fitTo(s.bounds, static_cast<double>(options.width) / static_cast<double>(options.height));
        const Views views{{"fitted", fitted}, {"zoomed", zoomedCamera(fitted, s.optical->octree(), s.bounds)}};

        // The first frame of each view: llvmpipe compiles the shaders' variants for it.
        Bench bench{gl, renderer, s.markers};
        std::string firstFrames;
        for (const auto& [view, camera] : views) {
            Frame first = frame("whole scene", view, true, true, camera, options.width, options.height);
            bench.run(first, true);
            firstFrames +=
                (firstFrames.empty() ? "" : ", ") + view + " " + fixed(1e3 * first.seconds.front(), 1) + " ms";
            if (options.png) writePng(context, *options.png + "-" + view + ".png");
        }
        const std::vector<Frame> layers = measureLayers(bench, views, options);
        const std::vector<Frame> scaling = measureScaling(bench, views, options, instances);

        const char* threads = std::getenv("LP_NUM_THREADS");
        std::cout << "render_bench: " << options.width << "x" << options.height << ", " << gl.describe()
                  << "; LP_NUM_THREADS " << (threads ? threads : "unset")
                  << " (CPUs: " << std::thread::hardware_concurrency() << "); " << options.frames
                  << " frames per configuration after " << options.warmUp << " warm-up, interleaved; load average "
                  << loadBefore << " -> " << loadAverage() << '\n';
        printScene(options, s, instances, uploads);
        std::cout << "\nFirst frame of the whole scene (llvmpipe compiles the shader variants): " << firstFrames
                  << ".\n";
        printFrames(layers, "Frame time (draw + glFinish)");
        printFrames(scaling, "Where the time goes: the shapes alone, by instances and pixels");
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "render_bench: " << error.what() << '\n';
        return 2;
    }
}
