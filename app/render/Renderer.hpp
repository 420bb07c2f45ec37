#pragma once

#include "render/ApartSpheres.hpp"
#include "render/Camera.hpp"
#include "render/CpuRasteriser.hpp"
#include "render/DrawData.hpp"
#include "render/GlFunctions.hpp"
#include "render/MeshCache.hpp"
#include "render/ShaderProgram.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace dropscope::render {

// The app's pointPixels: droplets up to 6 pixels across are points. A line passing a point droplet within
// its radius in depth may be hidden by it over those few pixels.
inline constexpr float kInteractivePointPixels = 6.0f;

// Spheres and ellipsoids up to this many pixels across are drawn as points rather than quads (one vertex,
// not four), with exact depth: the picture is the same. Lowered to what the driver's points allow.
inline constexpr float kExactPointPixels = 32.0f;

// Above this many spheres and ellipsoids no frame draws spheres apart at their centre's depth
// (RenderOptions::apartSpheres): working out which are apart takes 0.16 s at 1e6 droplets, and such clouds are
// drawn mostly as points of a few pixels, whose depth is the front's either way (docs/rendering.md, "Spheres apart").
inline constexpr int kApartMostSpheres = 300000;

// Frames of more pixels than this (a 3840 x 2160 screen) are drawn by OpenGL even with
// RenderOptions::processorRaster: the processor's picture costs 8 bytes a pixel, kept between frames (12 with a
// picture held for the kept view), and a screenshot of up to 8192 x 8192 pixels would keep half a gigabyte.
inline constexpr long kProcessorMostPixels = 3840L * 2160L;

// What to draw; every layer can be switched off.
struct RenderOptions {
    bool shapes = true;
    bool translucent = false;      // every shape blended at `opacity`, drawn after everything opaque
    bool translucentBoxes = true;  // boxes blended: usually cells around the droplets
    float opacity = 0.35f;
    // Spheres and ellipsoids at most this many pixels across are drawn as points with the depth of the
    // shape's front for all their pixels (shaders/impostor.vert): the same silhouette and shading, but
    // hidden pixels are skipped before shading. 0 draws every shape with its exact depth (snapshots,
    // tests). Larger ones up to kExactPointPixels are points too, with exact depth.
    float pointPixels = 0.0f;
    // Runs of spheres drawn as points by the program that passes a radius, not two matrices (the same
    // picture, less vertex work: docs/rendering.md, "Spheres' points"); false draws them as ellipsoids are,
    // for comparison.
    bool sphereProgram = true;
    // Spheres that nothing else drawn reaches into (render/ApartSpheres.hpp) are drawn, when pointPixels is
    // above 0, as points at their centre's depth up to kExactPointPixels: the same picture but at their rims,
    // and hidden pixels skipped before shading (docs/rendering.md, "Spheres apart"). Not while chords are drawn
    // (they lie inside). false keeps them to pointPixels and the front's depth, for comparison.
    bool apartSpheres = true;
    // The chords handed to setLines are left out while they cannot show: shapes drawn opaque, no sphere's
    // or ellipsoid's chunk reaching the eye or the near plane (the same picture, fewer segments for the
    // driver: docs/rendering.md, "Chords"). false draws them always, for comparison.
    bool skipHiddenChords = true;
    // A frame holding only opaque spheres (markers among them) and lines is drawn on the processor
    // (render/CpuRasteriser) and handed to the driver as one picture: for a software OpenGL (llvmpipe), whose
    // cost per point and per segment is what limits such a frame. The same picture, but every sphere at its exact
    // depth and a line's ends within a pixel of OpenGL's (docs/rendering.md, "Drawn on the processor"). A frame
    // holding anything else is drawn by OpenGL whatever this says.
    bool processorRaster = false;
    bool lines = true;  // the line layers handed to setLines (octree, paths, glyphs, axes, grid) and the surfaces
    Colour background{0.08f, 0.09f, 0.11f, 1.0f};

    bool operator==(const RenderOptions&) const = default;
};

// Draws a scene with OpenGL 3.3 core through a GlFunctions table; the same code for the GUI's window and
// the headless snapshot. Shapes are instanced (two draw calls for any number of spheres, ellipsoids and
// boxes, one for each mesh geometry of the parametric and implicit shapes); every line layer is one draw
// call.
class Renderer {
public:
    explicit Renderer(const GlFunctions& gl);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    void setAnchor(const Anchor& anchor) { anchor_ = anchor; }
    const Anchor& anchor() const { return anchor_; }
    // Keeps the buffers of the mesh geometries still in use and uploads the new ones.
    void setShapes(const ShapeInstances& instances);
    // The colour of shape `id`'s instance, as setShapes last gave it, written in place: a new selection
    // without uploading every shape again. False when it has no instance.
    bool recolourShape(ShapeId id, const Colour& colour);
    // Where uploadScene keeps the mesh geometries between uploads (buildShapeInstances).
    MeshCache& meshCache() { return *meshCache_; }
    void setLines(const LineBatch& lines);
    // `chords` (SceneLayers::chords) after `lines`, in one buffer: a frame draws them only when they can
    // show (RenderOptions::skipHiddenChords).
    void setLines(const LineBatch& lines, const LineBatch& chords);
    // Opaque flat-coloured faces (detector images), drawn after the lines: a line lying on a face wins.
    void setSurfaces(const TriangleBatch& surfaces);
    // Small spheres (event markers): instances of the impostor, drawn with the shapes, always opaque.
    void setMarkers(const std::vector<ShapeInstance>& markers);

    // What a frame drawn on the processor gets drawn over it before it is handed over (the app's panels:
    // gui/platform/ImGuiRasteriser), in the picture's own pixels.
    using RasterOverlay = std::function<void(RasterImage&)>;
    // Draws the frame into the framebuffer bound for drawing. Drawn on the processor, `overlay` (when there is one)
    // is drawn over it before the hand-over, with `hold` the picture without the overlay is held for showHeld, and
    // the framebuffer's depth is left as it was. Returns whether the overlay was drawn.
    bool draw(const Camera& camera, const RenderOptions& options, int width, int height,
              const RasterOverlay& overlay = {}, bool hold = false);
    // The last picture held by draw (0: none yet). showHeld hands it over again, with `overlay` drawn over it, into
    // the framebuffer bound for drawing (the whole picture, whatever the scissor box), while `picture` is still
    // heldPicture() and its size width x height; false, drawing nothing, otherwise.
    std::uint64_t heldPicture() const { return heldPicture_; }
    bool showHeld(std::uint64_t picture, int width, int height, const RasterOverlay& overlay);
    // Whether a frame of these options and size is drawn on the processor (when OpenGL can take its picture).
    bool drawsOnProcessor(const RenderOptions& options, int width, int height) const;
    // How many spheres apart (RenderOptions::apartSpheres) the last frame offered to the points at their
    // centre's depth: those of its chunks in view (each sphere's width and place then decide).
    std::size_t apartInLastFrame() const { return apartInLastFrame_; }
    // Whether the last frame was drawn on the processor (RenderOptions::processorRaster).
    bool lastFrameOnProcessor() const { return lastFrameOnProcessor_; }

private:
    struct Mesh;
    struct FrameUniforms {
        glm::mat4 viewProjection;
        glm::mat4 inverseViewProjection;
        glm::vec3 eye;
        glm::vec3 up;
        float pixelsPerUnit;
        float maxStretch;
        float width;
        float height;
        // The eye ray through window coordinates (x, y): rayAtOrigin + x rayPerPixelX + y rayPerPixelY.
        glm::vec3 rayAtOrigin;
        glm::vec3 rayPerPixelX;
        glm::vec3 rayPerPixelY;
        // The clip z and w of a point eye + t ray: eyeClip + t (dot(clipZ, ray), dot(clipW, ray)).
        glm::vec2 eyeClip;
        glm::vec3 clipZ;
        glm::vec3 clipW;
    };
    // A run of spheres and ellipsoids next to each other in space and in the instance buffer: the frame
    // skips it outside the view, and draws it as quads, points or both by the sizes it can have on screen.
    struct RoundedChunk {
        GLint first = 0;
        GLsizei count = 0;
        glm::dvec3 centre{0.0};  // a sphere around every shape of the run
        double radius = 0.0;
        double smallest = 0.0;  // the shapes' bounding radii
        double largest = 0.0;
        bool spheres = false;  // every shape's matrices are r I and I / r
        GLsizei apart = 0;     // how many of its spheres are apart (apart_), as last uploaded
    };
    // pointPixels and exactPointPixels 0: the quad program draws every instance.
    void setShapeUniforms(const ShaderProgram& program, const FrameUniforms& frame, float opacity, float pointPixels,
                          float exactPointPixels, float apartPixels = 0.0f) const;
    void drawShapes(const Mesh& mesh, const ShaderProgram& program, const FrameUniforms& frame, float opacity);
    // apartPixels > 0: spheres apart up to that width are points at their centre's depth.
    void drawRounded(const FrameUniforms& frame, float opacity, float pointPixels, bool sphereProgram,
                     float apartPixels = 0.0f);
    // apart_'s flags uploaded, and the chunks' counts of them, when they have changed.
    void refreshApart();
    void drawMeshes(const FrameUniforms& frame, float opacity);
    // Whether a run of spheres and ellipsoids comes within `reach` of the eye: the eye may be inside one of
    // them, or the near plane cut one open.
    bool roundedWithin(const glm::dvec3& eye, double reach) const;
    // Whether this frame's layers are all the processor draws: opaque spheres, markers that are spheres, lines.
    bool processorCanDraw(const RenderOptions& options, int width, int height) const;
    // The layout of the framebuffer bound for drawing: the window's (GlFunctions::windowLayout) or OpenGL's own.
    PixelLayout targetLayout() const;
    // Whether the processor's picture can be blitted into the framebuffer bound for drawing (not multisampled) and
    // its texture made for width x height in the channel order of `layout`.
    bool readyToHandOver(int width, int height, PixelLayout layout);
    // The frame drawn by rasterise into rasterImage_ in `layout` (held first with `hold`), then handed over.
    void drawOnProcessor(const RasterView& view, const RenderOptions& options, GLsizei lineVertices, PixelLayout layout,
                         const RasterOverlay& overlay, bool hold);
    // rasterImage_, with `overlay` drawn over it, uploaded and copied into the framebuffer bound for drawing: in the
    // framebuffer's own layout, a copy of memory.
    void handOver(const RasterOverlay& overlay);

    const GlFunctions& gl_;
    Anchor anchor_;
    std::unique_ptr<ShaderProgram> impostor_;
    std::unique_ptr<ShaderProgram> impostorPoints_;       // points with the front's depth
    std::unique_ptr<ShaderProgram> impostorExactPoints_;  // points with exact depth
    std::unique_ptr<ShaderProgram> spherePoints_;         // the two for runs of spheres only
    std::unique_ptr<ShaderProgram> sphereExactPoints_;
    float exactPointPixels_ = kExactPointPixels;
    std::unique_ptr<ShaderProgram> box_;
    std::unique_ptr<ShaderProgram> line_;
    std::unique_ptr<Mesh> rounded_;
    std::unique_ptr<Mesh> roundedPoints_;  // rounded_'s instances, one vertex each
    ApartSpheres apart_;                   // their flags are roundedPoints_'s own data (location 10)
    std::size_t apartInLastFrame_ = 0;
    std::vector<RoundedChunk> chunks_;
    static constexpr std::uint32_t kNoInstance = 0xFFFFFFFFu;
    std::vector<std::uint32_t> roundedAt_;       // by shape id: its place in rounded_'s (ordered) instances
    std::vector<ShapeId> boxIds_;                // the shape of each of boxes_'s instances
    std::vector<std::vector<ShapeId>> meshIds_;  // the shapes of each of meshes_'s instances
    std::unique_ptr<Mesh> boxes_;
    std::unique_ptr<Mesh> markers_;
    std::unique_ptr<Mesh> lines_;
    GLsizei chordsFrom_ = 0;  // lines_'s vertices from here on are chords
    std::unique_ptr<Mesh> surfaces_;
    std::unique_ptr<MeshCache> meshCache_;
    // What the processor draws, kept beside the buffers (32 bytes a sphere, whether or not a frame asks for it):
    // rounded_'s instances in its order when they are all spheres (else none, and roundedAllSpheres_ false), the
    // markers alike, the lines and chords as lines_ holds them.
    std::vector<RasterSphere> rasterSpheres_;
    bool roundedAllSpheres_ = true;
    std::vector<RasterSphere> rasterMarkers_;
    bool markersAllSpheres_ = true;
    std::vector<LineVertex> rasterLines_;
    RasterImage rasterImage_;
    std::vector<std::uint32_t> heldColour_;  // rasterImage_'s colour as drawn with `hold`, before its overlay
    PixelLayout heldLayout_;
    int heldWidth_ = 0;
    int heldHeight_ = 0;
    std::uint64_t heldPicture_ = 0;
    std::uint64_t pictures_ = 0;  // pictures drawn on the processor
    GLuint rasterTexture_ = 0;    // rasterImage_ uploaded, read through rasterFramebuffer_
    GLuint rasterFramebuffer_ = 0;
    int rasterTextureWidth_ = 0;
    int rasterTextureHeight_ = 0;
    bool rasterTextureBgra_ = false;  // the order Mesa stores its pixels in
    bool lastFrameOnProcessor_ = false;
    // One per geometry, in the order the shapes list them (a fixed drawing order, for determinism).
    std::vector<std::pair<std::shared_ptr<const MeshGeometry>, std::unique_ptr<Mesh>>> meshes_;
};

}  // namespace dropscope::render
