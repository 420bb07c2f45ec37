#pragma once

#include "render/Camera.hpp"
#include "render/DrawData.hpp"
#include "render/GlFunctions.hpp"
#include "render/MeshCache.hpp"
#include "render/ShaderProgram.hpp"

#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace dropscope::render {

// What to draw; every layer can be switched off.
struct RenderOptions {
    bool shapes = true;
    bool translucent = false;      // every shape blended at `opacity`, drawn after everything opaque
    bool translucentBoxes = true;  // boxes blended: usually cells around the droplets
    float opacity = 0.35f;
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
    // Where uploadScene keeps the mesh geometries between uploads (buildShapeInstances).
    MeshCache& meshCache() { return *meshCache_; }
    void setLines(const LineBatch& lines);
    // Opaque flat-coloured faces (detector images), drawn after the lines: a line lying on a face wins.
    void setSurfaces(const TriangleBatch& surfaces);
    // Small spheres (event markers): instances of the impostor, drawn with the shapes, always opaque.
    void setMarkers(const std::vector<ShapeInstance>& markers);

    void draw(const Camera& camera, const RenderOptions& options, int width, int height);

private:
    struct Mesh;
    struct FrameUniforms {
        glm::mat4 viewProjection;
        glm::mat4 inverseViewProjection;
        glm::vec3 eye;
        glm::vec3 up;
    };
    void drawShapes(const Mesh& mesh, const ShaderProgram& program, const FrameUniforms& frame, float opacity);
    void drawMeshes(const FrameUniforms& frame, float opacity);

    const GlFunctions& gl_;
    Anchor anchor_;
    std::unique_ptr<ShaderProgram> impostor_;
    std::unique_ptr<ShaderProgram> box_;
    std::unique_ptr<ShaderProgram> line_;
    std::unique_ptr<Mesh> rounded_;
    std::unique_ptr<Mesh> boxes_;
    std::unique_ptr<Mesh> markers_;
    std::unique_ptr<Mesh> lines_;
    std::unique_ptr<Mesh> surfaces_;
    std::unique_ptr<MeshCache> meshCache_;
    // One per geometry, in the order the shapes list them (a fixed drawing order, for determinism).
    std::vector<std::pair<std::shared_ptr<const MeshGeometry>, std::unique_ptr<Mesh>>> meshes_;
};

}  // namespace dropscope::render
