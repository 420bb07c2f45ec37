#version 330 core
// Boxes: an instanced unit cube [-1, 1]^3 with face normals, scaled to the box's half extents. Also the
// meshes of parametric and implicit shapes (render/MeshCache.hpp): vertex normals, positions relative
// to the shape's translation, which is `center`; `linear` is the identity for them.
layout(location = 0) in vec3 corner;
layout(location = 1) in vec3 faceNormal;
layout(location = 2) in vec3 center;
layout(location = 3) in mat3 linear;
layout(location = 6) in mat3 inverseLinear;
layout(location = 9) in vec4 colour;

uniform mat4 viewProjection;

out vec3 worldPosition;
out vec3 worldNormal;
flat out vec4 shapeColour;

void main() {
    worldPosition = center + linear * corner;
    worldNormal = transpose(inverseLinear) * faceNormal;
    shapeColour = colour;
    gl_Position = viewProjection * vec4(worldPosition, 1.0);
}
