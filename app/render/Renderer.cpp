#include "render/Renderer.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstddef>

namespace dropscope::render {

namespace {

// The unit cube [-1, 1]^3 as 12 triangles with outward face normals: position, normal.
std::vector<float> cubeTriangles() {
    std::vector<float> out;
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = -1; side <= 1; side += 2) {
            const int u = (axis + 1) % 3;
            const int v = (axis + 2) % 3;
            const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            for (int k : {0, 1, 2, 0, 2, 3}) {
                float p[3];
                p[axis] = static_cast<float>(side);
                p[u] = corners[k][0];
                p[v] = corners[k][1];
                float n[3] = {0, 0, 0};
                n[axis] = static_cast<float>(side);
                out.insert(out.end(), {p[0], p[1], p[2], n[0], n[1], n[2]});
            }
        }
    }
    return out;
}

// Two triangles over the square (+-1, +-1, 0): the impostors' camera-facing quad (shaders/impostor.vert).
std::vector<float> quadTriangles() {
    std::vector<float> out;
    const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k : {0, 1, 2, 0, 2, 3}) out.insert(out.end(), {corners[k][0], corners[k][1], 0.0f, 0.0f, 0.0f, 1.0f});
    return out;
}

}  // namespace

// A vertex array with a static mesh (optional) and a per-instance or per-vertex buffer.
struct Renderer::Mesh {
    const GlFunctions& gl;
    GLuint vertexArray = 0;
    GLuint meshBuffer = 0;
    GLuint dataBuffer = 0;
    GLuint indexBuffer = 0;  // made by makeIndexed only
    GLsizei meshVertices = 0;
    GLsizei meshIndices = 0;  // > 0: drawn by its indices
    GLsizei count = 0;        // instances, or vertices for lines

    explicit Mesh(const GlFunctions& functions) : gl(functions) {
        gl.GenVertexArrays(1, &vertexArray);
        gl.GenBuffers(1, &meshBuffer);
        gl.GenBuffers(1, &dataBuffer);
    }
    ~Mesh() {
        if (indexBuffer != 0) gl.DeleteBuffers(1, &indexBuffer);
        gl.DeleteBuffers(1, &dataBuffer);
        gl.DeleteBuffers(1, &meshBuffer);
        gl.DeleteVertexArrays(1, &vertexArray);
    }
    Mesh(const Mesh&) = delete;
    Mesh& operator=(const Mesh&) = delete;

    void attribute(GLuint location, GLint size, GLsizei stride, std::size_t offset, GLuint divisor) const {
        gl.EnableVertexAttribArray(location);
        gl.VertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
        gl.VertexAttribDivisor(location, divisor);
    }

    // A mesh (position, normal) in locations 0 and 1, ShapeInstance in 2..9 (one per instance).
    void makeInstanced(const std::vector<float>& mesh) {
        meshVertices = static_cast<GLsizei>(mesh.size() / 6);
        gl.BindVertexArray(vertexArray);
        gl.BindBuffer(GL_ARRAY_BUFFER, meshBuffer);
        gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.size() * sizeof(float)), mesh.data(),
                      GL_STATIC_DRAW);
        instanceAttributes();
    }

    // makeInstanced for an indexed mesh (MeshVertex has the same layout: position, normal).
    void makeIndexed(const MeshGeometry& geometry) {
        static_assert(sizeof(MeshVertex) == 6 * sizeof(float));
        meshVertices = static_cast<GLsizei>(geometry.vertices.size());
        meshIndices = static_cast<GLsizei>(geometry.indices.size());
        gl.BindVertexArray(vertexArray);
        gl.BindBuffer(GL_ARRAY_BUFFER, meshBuffer);
        gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(geometry.vertices.size() * sizeof(MeshVertex)),
                      geometry.vertices.data(), GL_STATIC_DRAW);
        gl.GenBuffers(1, &indexBuffer);
        gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer);  // part of the vertex array's state
        gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(geometry.indices.size() * sizeof(std::uint32_t)),
                      geometry.indices.data(), GL_STATIC_DRAW);
        instanceAttributes();
    }

    // Locations 0 and 1 from the bound vertex array's mesh buffer, 2..9 from the instances.
    void instanceAttributes() {
        attribute(0, 3, 6 * sizeof(float), 0, 0);
        attribute(1, 3, 6 * sizeof(float), 3 * sizeof(float), 0);
        gl.BindBuffer(GL_ARRAY_BUFFER, dataBuffer);
        constexpr auto stride = static_cast<GLsizei>(sizeof(ShapeInstance));
        attribute(2, 3, stride, offsetof(ShapeInstance, center), 1);
        for (GLuint column = 0; column < 3; ++column) {
            attribute(3 + column, 3, stride, offsetof(ShapeInstance, linear) + column * 3 * sizeof(float), 1);
            attribute(6 + column, 3, stride, offsetof(ShapeInstance, inverseLinear) + column * 3 * sizeof(float), 1);
        }
        attribute(9, 4, stride, offsetof(ShapeInstance, colour), 1);
        gl.BindVertexArray(0);
    }

    void makeLines() {
        gl.BindVertexArray(vertexArray);
        gl.BindBuffer(GL_ARRAY_BUFFER, dataBuffer);
        constexpr auto stride = static_cast<GLsizei>(sizeof(LineVertex));
        attribute(0, 3, stride, offsetof(LineVertex, position), 0);
        attribute(1, 4, stride, offsetof(LineVertex, colour), 0);
        gl.BindVertexArray(0);
    }

    template <class T>
    void upload(const std::vector<T>& data) {
        gl.BindBuffer(GL_ARRAY_BUFFER, dataBuffer);
        gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
        count = static_cast<GLsizei>(data.size());
    }
};

Renderer::Renderer(const GlFunctions& gl)
    : gl_(gl),
      impostor_(std::make_unique<ShaderProgram>(gl, "impostor.vert", "impostor.frag")),
      box_(std::make_unique<ShaderProgram>(gl, "box.vert", "box.frag")),
      line_(std::make_unique<ShaderProgram>(gl, "line.vert", "line.frag")),
      rounded_(std::make_unique<Mesh>(gl)),
      boxes_(std::make_unique<Mesh>(gl)),
      markers_(std::make_unique<Mesh>(gl)),
      lines_(std::make_unique<Mesh>(gl)),
      surfaces_(std::make_unique<Mesh>(gl)),
      meshCache_(std::make_unique<MeshCache>()) {
    rounded_->makeInstanced(quadTriangles());
    boxes_->makeInstanced(cubeTriangles());
    markers_->makeInstanced(quadTriangles());
    lines_->makeLines();
    surfaces_->makeLines();
}

Renderer::~Renderer() = default;

void Renderer::setShapes(const ShapeInstances& instances) {
    rounded_->upload(instances.rounded);
    boxes_->upload(instances.boxes);
    // The instances of each geometry, in the order of their first shape.
    std::vector<std::pair<std::shared_ptr<const MeshGeometry>, std::vector<ShapeInstance>>> groups;
    for (const MeshInstance& mesh : instances.meshes) {
        const auto group =
            std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == mesh.geometry; });
        if (group != groups.end()) {
            group->second.push_back(mesh.instance);
        } else {
            groups.push_back({mesh.geometry, {mesh.instance}});
        }
    }
    decltype(meshes_) kept;
    for (auto& [geometry, shapeInstances] : groups) {
        const auto old =
            std::find_if(meshes_.begin(), meshes_.end(), [&](const auto& m) { return m.first == geometry; });
        std::unique_ptr<Mesh> mesh;
        if (old != meshes_.end()) {
            mesh = std::move(old->second);
        } else {
            mesh = std::make_unique<Mesh>(gl_);
            mesh->makeIndexed(*geometry);
        }
        mesh->upload(shapeInstances);
        kept.emplace_back(geometry, std::move(mesh));
    }
    meshes_ = std::move(kept);  // the buffers of geometries no longer drawn are deleted here
}

void Renderer::setLines(const LineBatch& lines) { lines_->upload(lines.vertices()); }

void Renderer::setSurfaces(const TriangleBatch& surfaces) { surfaces_->upload(surfaces.vertices()); }

void Renderer::setMarkers(const std::vector<ShapeInstance>& markers) { markers_->upload(markers); }

void Renderer::drawShapes(const Mesh& mesh, const ShaderProgram& program, const FrameUniforms& frame, float opacity) {
    if (mesh.count == 0) return;
    program.use();
    gl_.UniformMatrix4fv(program.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
    // Only the impostor program has these two; a location of -1 is ignored.
    gl_.UniformMatrix4fv(program.uniform("inverseViewProjection"), 1, GL_FALSE,
                         glm::value_ptr(frame.inverseViewProjection));
    gl_.Uniform3fv(program.uniform("cameraUp"), 1, glm::value_ptr(frame.up));
    gl_.Uniform3fv(program.uniform("eye"), 1, glm::value_ptr(frame.eye));
    gl_.Uniform1f(program.uniform("opacity"), opacity);
    gl_.BindVertexArray(mesh.vertexArray);
    if (mesh.meshIndices > 0) {
        gl_.DrawElementsInstanced(GL_TRIANGLES, mesh.meshIndices, GL_UNSIGNED_INT, nullptr, mesh.count);
    } else {
        gl_.DrawArraysInstanced(GL_TRIANGLES, 0, mesh.meshVertices, mesh.count);
    }
}

void Renderer::drawMeshes(const FrameUniforms& frame, float opacity) {
    for (const auto& mesh : meshes_) drawShapes(*mesh.second, *box_, frame, opacity);
}

void Renderer::draw(const Camera& camera, const RenderOptions& options, int width, int height) {
    Camera local = camera;  // the same camera, in anchor-relative coordinates
    const glm::dvec3 origin(anchor_.origin.x(), anchor_.origin.y(), anchor_.origin.z());
    local.eye -= origin;
    local.target -= origin;
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    const glm::mat4 viewProjection = local.projectionMatrix(aspect) * local.viewMatrix();
    const FrameUniforms frame{viewProjection, glm::inverse(viewProjection), glm::vec3(local.eye), glm::vec3(local.up)};

    gl_.Viewport(0, 0, width, height);
    gl_.ClearColor(options.background[0], options.background[1], options.background[2], options.background[3]);
    gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(GL_LESS);
    gl_.Disable(GL_BLEND);
    gl_.DepthMask(GL_TRUE);

    drawShapes(*markers_, *impostor_, frame, 1.0f);
    const bool boxesBlended = options.translucent || options.translucentBoxes;
    if (options.shapes && !options.translucent) drawShapes(*rounded_, *impostor_, frame, 1.0f);
    if (options.shapes && !boxesBlended) drawShapes(*boxes_, *box_, frame, 1.0f);
    if (options.shapes && !options.translucent) drawMeshes(frame, 1.0f);
    if (options.lines && lines_->count > 0) {
        line_->use();
        gl_.UniformMatrix4fv(line_->uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
        gl_.BindVertexArray(lines_->vertexArray);
        gl_.DrawArrays(GL_LINES, 0, lines_->count);
    }
    if (options.lines && surfaces_->count > 0) {
        line_->use();
        gl_.UniformMatrix4fv(line_->uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
        gl_.BindVertexArray(surfaces_->vertexArray);
        // Pushed back a little in depth: a line drawn on a detector (its outline, axes, hatching) would otherwise
        // tie with it, rasterised at slightly other depths, and show dashed.
        gl_.Enable(GL_POLYGON_OFFSET_FILL);
        gl_.PolygonOffset(1.0f, 1.0f);
        gl_.DrawArrays(GL_TRIANGLES, 0, surfaces_->count);
        gl_.Disable(GL_POLYGON_OFFSET_FILL);
    }
    if (options.shapes && boxesBlended) {
        gl_.Enable(GL_BLEND);
        gl_.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        gl_.DepthMask(GL_FALSE);
        drawShapes(*boxes_, *box_, frame, options.opacity);
        if (options.translucent) {
            drawShapes(*rounded_, *impostor_, frame, options.opacity);
            // Only the faces towards the eye, as the impostors draw only the nearest surface: a mesh's back
            // faces blended too would make it look twice as opaque as a droplet.
            gl_.Enable(GL_CULL_FACE);
            drawMeshes(frame, options.opacity);
            gl_.Disable(GL_CULL_FACE);
        }
        gl_.DepthMask(GL_TRUE);
        gl_.Disable(GL_BLEND);
    }
    gl_.BindVertexArray(0);
}

}  // namespace dropscope::render
