#include "render/Renderer.hpp"

#include "render/OffscreenImage.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>

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

// The square (+-1, +-1, 0) as a strip of two triangles: the impostors' camera-facing quad
// (shaders/impostor.vert).
std::vector<float> quadStrip() {
    std::vector<float> out;
    const float corners[4][2] = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
    for (const auto& corner : corners) out.insert(out.end(), {corner[0], corner[1], 0.0f, 0.0f, 0.0f, 1.0f});
    return out;
}

// Spheres and ellipsoids per chunk: enough that a frame's draw calls stay few, few enough that culling
// by chunk is fine-grained. Scenes up to this size keep the order they were given in.
constexpr std::size_t kChunkShapes = 256;
constexpr std::size_t kMostChunks = 1024;

// 10 bits of each coordinate, interleaved: neighbours along this curve are neighbours in space.
std::uint32_t mortonCode(const std::array<float, 3>& p, const glm::dvec3& low, const glm::dvec3& scale) {
    std::uint32_t code = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const double unit = (static_cast<double>(p[static_cast<std::size_t>(axis)]) - low[axis]) * scale[axis];
        const auto cell = static_cast<std::uint32_t>(std::clamp(unit, 0.0, 1023.0));
        for (int bit = 0; bit < 10; ++bit) code |= ((cell >> bit) & 1u) << (3 * bit + axis);
    }
    return code;
}

// The shapes in space-filling-curve order (unchanged when they fit in one chunk).
std::vector<std::uint32_t> spatialOrder(const std::vector<ShapeInstance>& shapes) {
    std::vector<std::uint32_t> order(shapes.size());
    std::iota(order.begin(), order.end(), 0u);
    if (shapes.size() <= kChunkShapes) return order;
    glm::dvec3 low(std::numeric_limits<double>::max());
    glm::dvec3 high(std::numeric_limits<double>::lowest());
    for (const ShapeInstance& shape : shapes) {
        const glm::dvec3 c(shape.center[0], shape.center[1], shape.center[2]);
        low = glm::min(low, c);
        high = glm::max(high, c);
    }
    const glm::dvec3 extent = high - low;
    glm::dvec3 scale;
    for (int axis = 0; axis < 3; ++axis) scale[axis] = extent[axis] > 0.0 ? 1024.0 / extent[axis] : 0.0;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> keys(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        keys[i] = {mortonCode(shapes[i].center, low, scale), static_cast<std::uint32_t>(i)};
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < keys.size(); ++i) order[i] = keys[i].second;
    return order;
}

// The planes bounding what viewProjection sees, as (n, d) with n.x + d >= 0 inside, |n| = 1.
std::array<glm::dvec4, 6> frustumPlanes(const glm::mat4& viewProjection) {
    const glm::dmat4 m(viewProjection);
    std::array<glm::dvec4, 6> planes;
    for (int k = 0; k < 3; ++k) {
        for (int side = 0; side < 2; ++side) {
            glm::dvec4 plane;
            for (int column = 0; column < 4; ++column) {
                plane[column] = m[column][3] + (side == 0 ? 1.0 : -1.0) * m[column][k];
            }
            planes[static_cast<std::size_t>(2 * k + side)] = plane / glm::length(glm::dvec3(plane));
        }
    }
    return planes;
}

// `instances` as the processor draws them, into `spheres`, when every one is a sphere (else `spheres` is left empty
// and the answer is false).
bool rasterSpheres(const std::vector<ShapeInstance>& instances, std::vector<RasterSphere>& spheres) {
    spheres.clear();
    if (!std::all_of(instances.begin(), instances.end(), isSphereInstance)) return false;
    spheres.reserve(instances.size());
    for (const ShapeInstance& sphere : instances) spheres.push_back(rasterSphere(sphere));
    return true;
}

}  // namespace

// A vertex array with a static mesh (optional) and a per-instance or per-vertex buffer.
struct Renderer::Mesh {
    const GlFunctions& gl;
    GLuint vertexArray = 0;
    GLuint meshBuffer = 0;
    GLuint dataBuffer = 0;
    GLuint indexBuffer = 0;  // made by makeIndexed only
    GLenum mode = GL_TRIANGLES;
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
    void makeInstanced(const std::vector<float>& mesh, GLenum primitives = GL_TRIANGLES) {
        mode = primitives;
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
        shapeAttributes(1, 0);
        gl.BindVertexArray(0);
    }

    // ShapeInstance in locations 2..9 from the bound buffer, from instance `first` on; a divisor of 1
    // reads one per instance, 0 one per vertex.
    void shapeAttributes(GLuint divisor, GLint first) const {
        constexpr auto stride = static_cast<GLsizei>(sizeof(ShapeInstance));
        const std::size_t base = static_cast<std::size_t>(first) * sizeof(ShapeInstance);
        attribute(2, 3, stride, base + offsetof(ShapeInstance, center), divisor);
        for (GLuint column = 0; column < 3; ++column) {
            attribute(3 + column, 3, stride, base + offsetof(ShapeInstance, linear) + column * 3 * sizeof(float),
                      divisor);
            attribute(6 + column, 3, stride, base + offsetof(ShapeInstance, inverseLinear) + column * 3 * sizeof(float),
                      divisor);
        }
        attribute(9, 4, stride, base + offsetof(ShapeInstance, colour), divisor);
    }

    // The instances of `shapes` as points, one vertex each (its data buffer, not this mesh's).
    void makePointsOf(const Mesh& shapes) {
        mode = GL_POINTS;
        gl.BindVertexArray(vertexArray);
        gl.BindBuffer(GL_ARRAY_BUFFER, shapes.dataBuffer);
        shapeAttributes(0, 0);
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
      impostorPoints_(std::make_unique<ShaderProgram>(gl, "impostor.vert", "impostor.frag", "#define POINT_SPRITE\n")),
      impostorExactPoints_(std::make_unique<ShaderProgram>(gl, "impostor.vert", "impostor.frag",
                                                           "#define POINT_SPRITE\n#define EXACT_DEPTH\n")),
      spherePoints_(std::make_unique<ShaderProgram>(gl, "impostor.vert", "impostor.frag",
                                                    "#define POINT_SPRITE\n#define SPHERE\n")),
      sphereExactPoints_(std::make_unique<ShaderProgram>(
          gl, "impostor.vert", "impostor.frag", "#define POINT_SPRITE\n#define EXACT_DEPTH\n#define SPHERE\n")),
      box_(std::make_unique<ShaderProgram>(gl, "box.vert", "box.frag")),
      line_(std::make_unique<ShaderProgram>(gl, "line.vert", "line.frag")),
      rounded_(std::make_unique<Mesh>(gl)),
      roundedPoints_(std::make_unique<Mesh>(gl)),
      boxes_(std::make_unique<Mesh>(gl)),
      markers_(std::make_unique<Mesh>(gl)),
      lines_(std::make_unique<Mesh>(gl)),
      surfaces_(std::make_unique<Mesh>(gl)),
      meshCache_(std::make_unique<MeshCache>()) {
    GLint pointSizes[2] = {1, 1};
    gl_.GetIntegerv(GL_POINT_SIZE_RANGE, pointSizes);
    // A point's side is 1.05 w + 0.5 and must stay a pixel inside the driver's largest (impostor.vert).
    exactPointPixels_ = std::min(kExactPointPixels, static_cast<float>(pointSizes[1] - 2) / 1.05f);
    rounded_->makeInstanced(quadStrip(), GL_TRIANGLE_STRIP);
    roundedPoints_->makePointsOf(*rounded_);
    // The points' own buffer holds the spheres' apart flags (impostor.vert's `apart`), a float each: llvmpipe
    // read a byte attribute there as 0.
    gl_.BindVertexArray(roundedPoints_->vertexArray);
    gl_.BindBuffer(GL_ARRAY_BUFFER, roundedPoints_->dataBuffer);
    roundedPoints_->attribute(10, 1, sizeof(float), 0, 0);
    gl_.BindVertexArray(0);
    boxes_->makeInstanced(cubeTriangles());
    markers_->makeInstanced(quadStrip(), GL_TRIANGLE_STRIP);
    lines_->makeLines();
    surfaces_->makeLines();
}

Renderer::~Renderer() {
    if (rasterFramebuffer_ != 0) gl_.DeleteFramebuffers(1, &rasterFramebuffer_);
    if (rasterTexture_ != 0) gl_.DeleteTextures(1, &rasterTexture_);
}

void Renderer::setShapes(const ShapeInstances& instances) {
    const std::vector<std::uint32_t> order = spatialOrder(instances.rounded);
    std::vector<ShapeInstance> rounded;
    rounded.reserve(order.size());
    for (const std::uint32_t k : order) rounded.push_back(instances.rounded[k]);
    rounded_->upload(rounded);
    roundedAllSpheres_ = rasterSpheres(rounded, rasterSpheres_);
    roundedAt_.clear();
    for (std::size_t place = 0; place < order.size(); ++place) {
        const ShapeId id = instances.roundedIds[order[place]];
        if (id >= roundedAt_.size()) roundedAt_.resize(id + std::size_t{1}, kNoInstance);
        roundedAt_[id] = static_cast<std::uint32_t>(place);
    }
    boxIds_ = instances.boxIds;
    std::vector<ApartSpheres::Ball> otherShapes;
    for (const ShapeInstance& box : instances.boxes) {
        // box.vert's cube [-1, 1]^3 through `linear`: no corner farther than the columns' lengths added.
        float reach = 0.0f;
        for (std::size_t column = 0; column < 3; ++column) {
            const float* v = &box.linear[3 * column];
            reach += std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        }
        otherShapes.push_back({glm::vec3(box.center[0], box.center[1], box.center[2]), reach});
    }
    std::vector<std::pair<const MeshGeometry*, float>> reaches;  // by geometry: its positions are relative to
    for (const MeshInstance& mesh : instances.meshes) {          // the instance's centre (DrawData.hpp)
        auto known =
            std::find_if(reaches.begin(), reaches.end(), [&](const auto& r) { return r.first == mesh.geometry.get(); });
        if (known == reaches.end()) {
            float reach = 0.0f;
            for (const MeshVertex& v : mesh.geometry->vertices) {
                reach = std::max(reach, glm::length(glm::vec3(v.position[0], v.position[1], v.position[2])));
            }
            known = reaches.insert(reaches.end(), {mesh.geometry.get(), reach});
        }
        const std::array<float, 3>& c = mesh.instance.center;
        otherShapes.push_back({glm::vec3(c[0], c[1], c[2]), known->second});
    }
    apart_.setShapes(rounded, otherShapes);
    const std::vector<float> noneApart(rounded.size(), 0.0f);  // until a frame asks (refreshApart)
    gl_.BindBuffer(GL_ARRAY_BUFFER, roundedPoints_->dataBuffer);
    gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(noneApart.size() * sizeof(float)), noneApart.data(),
                   GL_STATIC_DRAW);
    chunks_.clear();
    const std::size_t perChunk = std::max(kChunkShapes, (rounded.size() + kMostChunks - 1) / kMostChunks);
    for (std::size_t first = 0; first < rounded.size(); first += perChunk) {
        const std::size_t end = std::min(rounded.size(), first + perChunk);
        glm::dvec3 low(std::numeric_limits<double>::max());
        glm::dvec3 high(std::numeric_limits<double>::lowest());
        RoundedChunk chunk{static_cast<GLint>(first), static_cast<GLsizei>(end - first)};
        chunk.smallest = std::numeric_limits<double>::max();
        chunk.spheres = true;
        for (std::size_t i = first; i < end; ++i) {
            chunk.spheres = chunk.spheres && isSphereInstance(rounded[i]);
            const double radius = ApartSpheres::boundingBall(rounded[i]).radius;
            const glm::dvec3 c(rounded[i].center[0], rounded[i].center[1], rounded[i].center[2]);
            low = glm::min(low, c - radius);
            high = glm::max(high, c + radius);
            chunk.smallest = std::min(chunk.smallest, radius);
            chunk.largest = std::max(chunk.largest, radius);
        }
        chunk.centre = 0.5 * (low + high);
        chunk.radius = 0.5 * glm::length(high - low);
        chunks_.push_back(chunk);
    }
    boxes_->upload(instances.boxes);
    // The instances of each geometry, in the order of their first shape, and their shapes' ids.
    std::vector<std::pair<std::shared_ptr<const MeshGeometry>, std::vector<ShapeInstance>>> groups;
    meshIds_.clear();
    for (std::size_t k = 0; k < instances.meshes.size(); ++k) {
        const MeshInstance& mesh = instances.meshes[k];
        const auto group =
            std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == mesh.geometry; });
        const auto at = static_cast<std::size_t>(group - groups.begin());
        if (group != groups.end()) {
            group->second.push_back(mesh.instance);
        } else {
            groups.push_back({mesh.geometry, {mesh.instance}});
            meshIds_.emplace_back();
        }
        meshIds_[at].push_back(instances.meshIds[k]);
    }
    decltype(meshes_) kept;
    for (auto& group : groups) {
        const std::shared_ptr<const MeshGeometry>& geometry = group.first;  // named, not bound: a lambda captures it
        const auto old =
            std::find_if(meshes_.begin(), meshes_.end(), [&](const auto& m) { return m.first == geometry; });
        std::unique_ptr<Mesh> mesh;
        if (old != meshes_.end()) {
            mesh = std::move(old->second);
        } else {
            mesh = std::make_unique<Mesh>(gl_);
            mesh->makeIndexed(*geometry);
        }
        mesh->upload(group.second);
        kept.emplace_back(geometry, std::move(mesh));
    }
    meshes_ = std::move(kept);  // the buffers of geometries no longer drawn are deleted here
}

bool Renderer::recolourShape(ShapeId id, const Colour& colour) {
    const auto write = [&](const Mesh& mesh, std::size_t place) {
        gl_.BindBuffer(GL_ARRAY_BUFFER, mesh.dataBuffer);
        gl_.BufferSubData(GL_ARRAY_BUFFER,
                          static_cast<GLintptr>(place * sizeof(ShapeInstance) + offsetof(ShapeInstance, colour)),
                          sizeof(Colour), colour.data());
        return true;
    };
    if (id < roundedAt_.size() && roundedAt_[id] != kNoInstance) {
        if (roundedAt_[id] < rasterSpheres_.size()) rasterSpheres_[roundedAt_[id]].colour = colour;
        return write(*rounded_, roundedAt_[id]);
    }
    if (const auto box = std::find(boxIds_.begin(), boxIds_.end(), id); box != boxIds_.end())
        return write(*boxes_, static_cast<std::size_t>(box - boxIds_.begin()));
    for (std::size_t group = 0; group < meshIds_.size(); ++group) {
        const std::vector<ShapeId>& ids = meshIds_[group];
        if (const auto mesh = std::find(ids.begin(), ids.end(), id); mesh != ids.end())
            return write(*meshes_[group].second, static_cast<std::size_t>(mesh - ids.begin()));
    }
    return false;
}

void Renderer::setLines(const LineBatch& lines) {
    lines_->upload(lines.vertices());
    rasterLines_ = lines.vertices();
    chordsFrom_ = lines_->count;
    apart_.setSegments(lines.vertices());
}

void Renderer::setLines(const LineBatch& lines, const LineBatch& chords) {
    if (chords.empty()) {
        setLines(lines);
        return;
    }
    std::vector<LineVertex> vertices;
    vertices.reserve(lines.vertices().size() + chords.vertices().size());
    vertices.insert(vertices.end(), lines.vertices().begin(), lines.vertices().end());
    vertices.insert(vertices.end(), chords.vertices().begin(), chords.vertices().end());
    lines_->upload(vertices);
    rasterLines_ = std::move(vertices);
    chordsFrom_ = static_cast<GLsizei>(lines.vertices().size());
    apart_.setSegments(lines.vertices());  // not the chords: a frame that draws them draws no sphere at its centre
}

void Renderer::setSurfaces(const TriangleBatch& surfaces) {
    surfaces_->upload(surfaces.vertices());
    apart_.setTriangles(surfaces.vertices());
}

void Renderer::setMarkers(const std::vector<ShapeInstance>& markers) {
    markers_->upload(markers);
    markersAllSpheres_ = rasterSpheres(markers, rasterMarkers_);
    apart_.setMarkers(markers);
}

void Renderer::refreshApart() {
    if (!apart_.takeUpdated()) return;
    const std::vector<std::uint8_t>& apart = apart_.apart();
    gl_.BindBuffer(GL_ARRAY_BUFFER, roundedPoints_->dataBuffer);
    const std::vector<float> flags(apart.begin(), apart.end());
    gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(flags.size() * sizeof(float)), flags.data(),
                   GL_STATIC_DRAW);
    for (RoundedChunk& chunk : chunks_) {
        const auto first = apart.begin() + chunk.first;
        chunk.apart = static_cast<GLsizei>(std::count(first, first + chunk.count, std::uint8_t{1}));
    }
}

void Renderer::setShapeUniforms(const ShaderProgram& program, const FrameUniforms& frame, float opacity,
                                float pointPixels, float exactPointPixels, float apartPixels) const {
    program.use();
    gl_.UniformMatrix4fv(program.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
    // Only the impostor programs have these; a location of -1 is ignored.
    gl_.UniformMatrix4fv(program.uniform("inverseViewProjection"), 1, GL_FALSE,
                         glm::value_ptr(frame.inverseViewProjection));
    gl_.Uniform3fv(program.uniform("cameraUp"), 1, glm::value_ptr(frame.up));
    gl_.Uniform1f(program.uniform("pointPixels"), pointPixels);
    gl_.Uniform1f(program.uniform("exactPointPixels"), exactPointPixels);
    gl_.Uniform1f(program.uniform("apartPixels"), apartPixels);
    gl_.Uniform1f(program.uniform("pixelsPerUnit"), frame.pixelsPerUnit);
    gl_.Uniform1f(program.uniform("maxStretch"), frame.maxStretch);
    gl_.Uniform2f(program.uniform("viewportSize"), frame.width, frame.height);
    gl_.Uniform3fv(program.uniform("rayAtOrigin"), 1, glm::value_ptr(frame.rayAtOrigin));
    gl_.Uniform3fv(program.uniform("rayPerPixelX"), 1, glm::value_ptr(frame.rayPerPixelX));
    gl_.Uniform3fv(program.uniform("rayPerPixelY"), 1, glm::value_ptr(frame.rayPerPixelY));
    gl_.Uniform2f(program.uniform("eyeClip"), frame.eyeClip.x, frame.eyeClip.y);
    gl_.Uniform3fv(program.uniform("clipZ"), 1, glm::value_ptr(frame.clipZ));
    gl_.Uniform3fv(program.uniform("clipW"), 1, glm::value_ptr(frame.clipW));
    gl_.Uniform3fv(program.uniform("eye"), 1, glm::value_ptr(frame.eye));
    gl_.Uniform1f(program.uniform("opacity"), opacity);
}

void Renderer::drawShapes(const Mesh& mesh, const ShaderProgram& program, const FrameUniforms& frame, float opacity) {
    if (mesh.count == 0) return;
    setShapeUniforms(program, frame, opacity, 0.0f, 0.0f);  // every instance drawn by this one call
    gl_.BindVertexArray(mesh.vertexArray);
    if (mesh.meshIndices > 0) {
        gl_.DrawElementsInstanced(mesh.mode, mesh.meshIndices, GL_UNSIGNED_INT, nullptr, mesh.count);
    } else {
        gl_.DrawArraysInstanced(mesh.mode, 0, mesh.meshVertices, mesh.count);
    }
}

// The chunks in view, nearest first, each drawn by the variants its shapes' widths on screen call for:
// quads (wider than exactPointPixels_, or at the image's edge), points with exact depth (wider than
// pointPixels), points with the front's depth (the rest). Nearest first lets a driver that tests depth
// before shading (the last kind always, the others where it honours impostor.frag's depth_greater) drop most
// hidden fragments unshaded; the last kind goes last, behind all the exact depth. The bounds on a chunk's
// widths are loose by a percent, so float rounding in the shader cannot leave a shape undrawn.
void Renderer::drawRounded(const FrameUniforms& frame, float opacity, float pointPixels, bool sphereProgram,
                           float apartPixels) {
    if (rounded_->count == 0) return;
    const std::array<glm::dvec4, 6> planes = frustumPlanes(frame.viewProjection);
    const glm::dvec3 eye(frame.eye);
    const glm::dvec3 forward = glm::normalize(glm::dvec3(frame.clipW));  // a point's clip w grows along the view axis
    const double pixelsPerUnit = frame.pixelsPerUnit;
    pointPixels = std::min(pointPixels, exactPointPixels_);  // no point wider than the driver's points allow
    const double exactPoints = exactPointPixels_;
    using Drawn = std::vector<std::pair<double, const RoundedChunk*>>;
    Drawn quadChunks, exactPointChunks, pointChunks;
    for (const RoundedChunk& chunk : chunks_) {
        const double distance = glm::length(chunk.centre - eye);
        const double nearest = distance - chunk.radius;
        // A point reaching within a pixel of the image's edge is a quad (impostor.vert): the half-width of
        // the largest point this chunk can have, plus 2 pixels, as a length at the chunk's far side (a
        // length there spans fewer pixels than anywhere nearer), widens the band in which a chunk counts
        // as over an edge of the view.
        const double tanAlpha = nearest > 1.01 * chunk.largest
                                    ? chunk.largest / std::sqrt(nearest * nearest - chunk.largest * chunk.largest)
                                    : std::numeric_limits<double>::infinity();
        const double spread = 1.0 - std::sqrt(frame.maxStretch - 1.0) * tanAlpha;
        const double halfPoint = spread > 0.1 ? pixelsPerUnit * tanAlpha * frame.maxStretch / spread + 0.25
                                              : std::numeric_limits<double>::infinity();
        const double pointHalf = std::min(halfPoint, 0.5 * exactPoints / std::max(spread, 0.1) + 0.25);
        const double margin = (pointHalf + 2.0) * (distance + chunk.radius) / pixelsPerUnit;
        bool straddles = false;  // over an edge of the view: its shapes there are quads
        bool outside = false;
        for (const glm::dvec4& plane : planes) {
            const double signedDistance = glm::dot(glm::dvec3(plane), chunk.centre) + plane.w;
            outside = outside || signedDistance < -chunk.radius;
            straddles = straddles || signedDistance < chunk.radius + margin;
        }
        if (outside) continue;
        const double widest = nearest > 1.01 * chunk.largest
                                  ? 1.01 * 2.0 * chunk.largest * pixelsPerUnit /
                                        std::sqrt(nearest * nearest - chunk.largest * chunk.largest) * frame.maxStretch
                                  : std::numeric_limits<double>::infinity();
        const double narrowest = 0.99 * 2.0 * chunk.smallest * pixelsPerUnit / (distance + chunk.radius);
        // Spheres apart may take the front's-depth points' program up to apartPixels: impostor.vert decides,
        // shape by shape, which of the two point programs draws each. A chunk of spheres all apart, clear of
        // the view's planes (the far one among them) and near enough the axis that even its widest has its band
        // at the rim under a pixel (impostor.vert: w (1 - cos phi) < 2, here with a margin for float rounding)
        // needs no exact points.
        const bool someApart = apartPixels > 0.0f && chunk.apart > 0;
        bool noExactPoints = false;
        if (someApart && chunk.apart == chunk.count && !straddles) {
            const double cosCentre = glm::dot(forward, (chunk.centre - eye) / distance);
            const double offAxis =
                std::acos(std::clamp(cosCentre, -1.0, 1.0)) + std::asin(std::min(1.0, chunk.radius / distance));
            noExactPoints = widest * (1.0 - std::cos(std::min(offAxis, 0.5 * std::numbers::pi))) < 1.9;
        }
        if (straddles || widest > exactPoints) quadChunks.emplace_back(distance, &chunk);
        if (widest > pointPixels && narrowest <= exactPoints && !noExactPoints) {
            exactPointChunks.emplace_back(distance, &chunk);
        }
        if (narrowest <= (someApart ? static_cast<double>(apartPixels) : pointPixels)) {
            pointChunks.emplace_back(distance, &chunk);
            if (someApart) apartInLastFrame_ += static_cast<std::size_t>(chunk.apart);
        }
    }
    for (Drawn* drawn : {&quadChunks, &exactPointChunks, &pointChunks}) {
        std::sort(drawn->begin(), drawn->end());
        if (opacity < 1.0f) std::reverse(drawn->begin(), drawn->end());  // blended: farthest first
    }
    if (!quadChunks.empty()) {
        setShapeUniforms(*impostor_, frame, opacity, pointPixels, exactPointPixels_, apartPixels);
        gl_.BindVertexArray(rounded_->vertexArray);
        gl_.BindBuffer(GL_ARRAY_BUFFER, rounded_->dataBuffer);
        for (const auto& [distance, chunk] : quadChunks) {
            rounded_->shapeAttributes(1, chunk->first);
            gl_.DrawArraysInstanced(rounded_->mode, 0, rounded_->meshVertices, chunk->count);
        }
        rounded_->shapeAttributes(1, 0);
    }
    gl_.Enable(GL_PROGRAM_POINT_SIZE);
    gl_.BindVertexArray(roundedPoints_->vertexArray);
    const ShaderProgram* current = nullptr;
    for (const auto& [programs, drawn] :
         {std::pair{std::pair{impostorExactPoints_.get(), sphereExactPoints_.get()}, &exactPointChunks},
          std::pair{std::pair{impostorPoints_.get(), spherePoints_.get()}, &pointChunks}}) {
        for (const auto& [distance, chunk] : *drawn) {
            const ShaderProgram* program = sphereProgram && chunk->spheres ? programs.second : programs.first;
            if (program != current) {
                setShapeUniforms(*program, frame, opacity, pointPixels, exactPointPixels_, apartPixels);
                current = program;
            }
            gl_.DrawArrays(GL_POINTS, chunk->first, chunk->count);
        }
    }
    gl_.Disable(GL_PROGRAM_POINT_SIZE);
}

bool Renderer::roundedWithin(const glm::dvec3& eye, double reach) const {
    return std::any_of(chunks_.begin(), chunks_.end(), [&](const RoundedChunk& chunk) {
        return glm::length(chunk.centre - eye) - chunk.radius <= reach;
    });
}

bool Renderer::drawsOnProcessor(const RenderOptions& options, int width, int height) const {
    return options.processorRaster && processorCanDraw(options, width, height);
}

bool Renderer::processorCanDraw(const RenderOptions& options, int width, int height) const {
    const bool shapesDrawable =
        !options.shapes || (!options.translucent && roundedAllSpheres_ && boxes_->count == 0 && meshes_.empty());
    return markersAllSpheres_ && shapesDrawable && (!options.lines || surfaces_->count == 0) &&
           static_cast<long>(width) * static_cast<long>(height) <= kProcessorMostPixels;
}

PixelLayout Renderer::targetLayout() const {
    GLint draw = 0;
    gl_.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    return draw == 0 ? gl_.windowLayout : PixelLayout{};
}

bool Renderer::readyToHandOver(int width, int height, PixelLayout layout) {
    GLint samples = 0;  // a blit into a multisampled framebuffer from a single-sampled one is an error
    gl_.GetIntegerv(GL_SAMPLE_BUFFERS, &samples);
    if (samples > 0 || width < 1 || height < 1) return false;
    if (rasterTexture_ != 0 && rasterTextureWidth_ == width && rasterTextureHeight_ == height &&
        rasterTextureBgra_ == layout.bgra) {
        return true;
    }
    const FramebufferBindings caller(gl_);
    GLint texture = 0;
    GLint unpackBuffer = 0;  // unbound while the texture is made: with one bound, its null pixels would be an offset
    gl_.GetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    gl_.GetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpackBuffer);
    gl_.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    if (rasterTexture_ == 0) {
        gl_.GenTextures(1, &rasterTexture_);
        gl_.GenFramebuffers(1, &rasterFramebuffer_);
    }
    gl_.BindTexture(GL_TEXTURE_2D, rasterTexture_);
    // Mesa stores an unsized GL_RGBA texture in the order of the pixels first given to it: BGRA here, as the window.
    if (layout.bgra) {
        gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, width, height, 0, GL_BGRA, GL_UNSIGNED_BYTE, nullptr);
    } else {
        gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    }
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture));
    gl_.BindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpackBuffer));
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, rasterFramebuffer_);
    gl_.FramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, rasterTexture_, 0);
    const bool complete = gl_.CheckFramebufferStatus(GL_READ_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    caller.restore(gl_);
    rasterTextureWidth_ = complete ? width : 0;
    rasterTextureHeight_ = complete ? height : 0;
    rasterTextureBgra_ = layout.bgra;
    return complete;
}

void Renderer::drawOnProcessor(const RasterView& view, const RenderOptions& options, GLsizei lineVertices,
                               PixelLayout layout, const RasterOverlay& overlay, bool hold) {
    RasterContent content;
    if (options.shapes) content.spheres = rasterSpheres_;
    content.markers = rasterMarkers_;
    content.lines = std::span<const LineVertex>(rasterLines_).first(static_cast<std::size_t>(lineVertices));
    rasterImage_.setLayout(layout);
    rasterise(content, view, options.background, rasterImage_, rasterThreads());
    ++pictures_;
    if (hold) {
        heldColour_ = rasterImage_.colour();
        heldLayout_ = layout;
        heldWidth_ = rasterImage_.width();
        heldHeight_ = rasterImage_.height();
        heldPicture_ = pictures_;
    }
    handOver(overlay);
}

void Renderer::handOver(const RasterOverlay& overlay) {
    if (overlay) overlay(rasterImage_);
    const int width = rasterImage_.width();
    const int height = rasterImage_.height();
    // The upload with the pixel store and bindings it needs, the caller's put back after.
    GLint texture = 0;
    GLint unpackBuffer = 0;
    GLint alignment = 4;
    GLint rowLength = 0;
    gl_.GetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    gl_.GetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpackBuffer);
    gl_.GetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    gl_.GetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
    gl_.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl_.PixelStorei(GL_UNPACK_ROW_LENGTH, rasterImage_.stride());
    gl_.BindTexture(GL_TEXTURE_2D, rasterTexture_);
    gl_.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, rasterImage_.layout().bgra ? GL_BGRA : GL_RGBA,
                      GL_UNSIGNED_BYTE, rasterImage_.colour().data());
    gl_.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture));
    gl_.PixelStorei(GL_UNPACK_ROW_LENGTH, rowLength);
    gl_.PixelStorei(GL_UNPACK_ALIGNMENT, alignment);
    gl_.BindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpackBuffer));
    // The caller's framebuffer gets the picture, its depth left as it was (as OffscreenImage's copy leaves it): nothing
    // drawn after the renderer tests depth (ImGui draws over the view without it), and a clear would cost llvmpipe a
    // pass over the whole depth buffer. The blit obeys a scissor box as the drawing would.
    const FramebufferBindings caller(gl_);
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, rasterFramebuffer_);
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(caller.draw));
    // With the top row first, the texture's row 0 holds the picture's top, so the blit turns it over: in the
    // window's own layout, a copy of memory.
    const bool turned = rasterImage_.layout().topRowFirst;
    gl_.BlitFramebuffer(0, 0, width, height, 0, turned ? height : 0, width, turned ? 0 : height, GL_COLOR_BUFFER_BIT,
                        GL_NEAREST);
    caller.restore(gl_);
}

bool Renderer::showHeld(std::uint64_t picture, int width, int height, const RasterOverlay& overlay) {
    if (picture == 0 || picture != heldPicture_ || heldWidth_ != width || heldHeight_ != height ||
        heldLayout_ != targetLayout() || !readyToHandOver(width, height, heldLayout_)) {
        return false;
    }
    rasterImage_.setLayout(heldLayout_);
    rasterImage_.resize(width, height);  // the same stride: the held rows are copied as they lie
    std::copy(heldColour_.begin(), heldColour_.end(), rasterImage_.colourData());
    const bool scissor = gl_.IsEnabled(GL_SCISSOR_TEST) == GL_TRUE;  // the whole picture, as OffscreenImage's copy
    if (scissor) gl_.Disable(GL_SCISSOR_TEST);
    handOver(overlay);
    if (scissor) gl_.Enable(GL_SCISSOR_TEST);
    return true;
}

void Renderer::drawMeshes(const FrameUniforms& frame, float opacity) {
    for (const auto& mesh : meshes_) drawShapes(*mesh.second, *box_, frame, opacity);
}

bool Renderer::draw(const Camera& camera, const RenderOptions& options, int width, int height,
                    const RasterOverlay& overlay, bool hold) {
    Camera local = camera;  // the same camera, in anchor-relative coordinates
    const glm::dvec3 origin(anchor_.origin.x(), anchor_.origin.y(), anchor_.origin.z());
    local.eye -= origin;
    local.target -= origin;
    const RasterView view = rasterView(local, width, height);
    const glm::mat4 projection = local.projectionMatrix(static_cast<double>(width) / static_cast<double>(height));
    // The widening of a shape in the image's corners, 1 / cos^2 of the angle off the axis (impostor.vert).
    const double cornerTan2 = 1.0 / (projection[0][0] * projection[0][0]) + 1.0 / (projection[1][1] * projection[1][1]);
    const glm::mat4& viewProjection = view.viewProjection;
    const FrameUniforms frame{viewProjection,
                              glm::inverse(viewProjection),
                              view.eye,
                              glm::vec3(local.up),
                              view.pixelsPerUnit,
                              static_cast<float>(1.0 + cornerTan2),
                              static_cast<float>(width),
                              static_cast<float>(height),
                              view.rayAtOrigin,
                              view.rayPerPixelX,
                              view.rayPerPixelY,
                              view.eyeClip,
                              view.clipZ,
                              view.clipW};

    gl_.Viewport(0, 0, width, height);
    gl_.ClearColor(options.background[0], options.background[1], options.background[2], options.background[3]);
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(GL_LESS);
    gl_.Disable(GL_BLEND);
    gl_.DepthMask(GL_TRUE);

    const bool boxesBlended = options.translucent || options.translucentBoxes;
    const bool roundedOpaque = options.shapes && !options.translucent;
    // The near plane's corners are the farthest of its points from the eye: 1 / cos of the angle off the axis.
    const double nearReach = 1.01 * local.nearPlane * std::sqrt(1.0 + cornerTan2);
    const bool chordsHidden = options.skipHiddenChords && roundedOpaque && chordsFrom_ < lines_->count &&
                              !roundedWithin(local.eye, nearReach);
    const bool chordsDrawn = options.lines && chordsFrom_ < lines_->count && !chordsHidden;
    apartInLastFrame_ = 0;
    const PixelLayout layout = targetLayout();
    lastFrameOnProcessor_ = drawsOnProcessor(options, width, height) && readyToHandOver(width, height, layout);
    if (lastFrameOnProcessor_) {
        drawOnProcessor(view, options, options.lines ? (chordsHidden ? chordsFrom_ : lines_->count) : 0, layout,
                        overlay, hold);
        return overlay != nullptr;
    }
    gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    drawShapes(*markers_, *impostor_, frame, 1.0f);
    float apartPixels = 0.0f;
    if (roundedOpaque && options.apartSpheres && options.pointPixels > 0.0f && !chordsDrawn &&
        rounded_->count <= kApartMostSpheres) {
        refreshApart();
        apartPixels = exactPointPixels_;
    }
    if (roundedOpaque) drawRounded(frame, 1.0f, options.pointPixels, options.sphereProgram, apartPixels);
    if (options.shapes && !boxesBlended) drawShapes(*boxes_, *box_, frame, 1.0f);
    if (options.shapes && !options.translucent) drawMeshes(frame, 1.0f);
    if (const GLsizei lineVertices = chordsHidden ? chordsFrom_ : lines_->count; options.lines && lineVertices > 0) {
        line_->use();
        gl_.UniformMatrix4fv(line_->uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
        gl_.BindVertexArray(lines_->vertexArray);
        gl_.DrawArrays(GL_LINES, 0, lineVertices);
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
            drawRounded(frame, options.opacity, options.pointPixels, options.sphereProgram);
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
    return false;
}

}  // namespace dropscope::render
