#version 330 core
// Spheres and ellipsoids: one camera-facing quad per shape, covering the silhouette of its bounding
// sphere (radius R, the largest semi-axis); impostor.frag ray-casts the shape's unit sphere through it.
// At distance d from the eye the tangent cone cuts the plane through the centre in a circle of radius
// R d / sqrt(d^2 - R^2), so a quad of that half-size there covers the shape. With the eye inside (or
// nearly inside) the bounding sphere no such quad exists; the quad then covers the whole near plane.
layout(location = 0) in vec3 corner;  // (+-1, +-1, 0)
layout(location = 2) in vec3 center;
layout(location = 3) in mat3 linear;         // locations 3, 4, 5
layout(location = 6) in mat3 inverseLinear;  // locations 6, 7, 8
layout(location = 9) in vec4 colour;

uniform mat4 viewProjection;
uniform mat4 inverseViewProjection;
uniform vec3 eye;
uniform vec3 cameraUp;

out vec3 worldPosition;
flat out vec3 shapeCenter;
flat out mat3 toObject;
flat out mat3 toWorld;
flat out vec4 shapeColour;

void main() {
    shapeCenter = center;
    toObject = inverseLinear;
    toWorld = linear;
    shapeColour = colour;
    float radius = max(length(linear[0]), max(length(linear[1]), length(linear[2])));
    vec3 toEye = eye - center;
    float distance = length(toEye);
    if (distance > 1.01 * radius) {
        vec3 forward = toEye / distance;
        vec3 right = normalize(cross(cameraUp, forward));
        if (any(isnan(right))) right = normalize(cross(vec3(1.0, 0.0, 0.0), forward));
        vec3 up = cross(forward, right);
        float halfSize = radius * distance / sqrt(distance * distance - radius * radius);
        worldPosition = center + halfSize * (corner.x * right + corner.y * up);
        gl_Position = viewProjection * vec4(worldPosition, 1.0);
    } else {
        vec4 near = inverseViewProjection * vec4(corner.xy, -1.0, 1.0);
        worldPosition = near.xyz / near.w;
        gl_Position = vec4(corner.xy, -1.0, 1.0);
    }
}
