#version 330 core
// Spheres and ellipsoids: an instanced unit cube [-1, 1]^3 around each shape, mapped by the shape's
// linear part (sphere: r I; ellipsoid: R diag(a, b, c)); impostor.frag ray-casts the unit sphere inside.
layout(location = 0) in vec3 corner;
layout(location = 2) in vec3 center;
layout(location = 3) in mat3 linear;         // locations 3, 4, 5
layout(location = 6) in mat3 inverseLinear;  // locations 6, 7, 8
layout(location = 9) in vec4 colour;

uniform mat4 viewProjection;

out vec3 worldPosition;
flat out vec3 shapeCenter;
flat out mat3 toObject;
flat out mat3 toWorld;
flat out vec4 shapeColour;

void main() {
    worldPosition = center + linear * corner;
    shapeCenter = center;
    toObject = inverseLinear;
    toWorld = linear;
    shapeColour = colour;
    gl_Position = viewProjection * vec4(worldPosition, 1.0);
}
