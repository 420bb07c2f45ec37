#version 330 core
// The exact surface of a sphere or ellipsoid under its proxy quad: the eye ray in the shape's unit-sphere
// frame, the nearest root in front of the eye (the far one when the eye is inside), its true depth. The
// POINT_SPRITE variants (impostor.vert) find the eye ray from the pixel; without EXACT_DEPTH they leave the
// depth to the point.
#extension GL_ARB_conservative_depth : enable
#if !defined(POINT_SPRITE) || defined(EXACT_DEPTH)
#define WRITES_DEPTH
#endif
#if defined(GL_ARB_conservative_depth) && defined(WRITES_DEPTH)
// The quad or point lies in front of the shape (impostor.vert), so the depth written is never nearer than
// its own: a driver may then test that depth before running this shader.
layout(depth_greater) out float gl_FragDepth;
#endif
#ifdef POINT_SPRITE
// The eye ray through a pixel is affine in its window coordinates: rayAtOrigin + x rayPerPixelX + y rayPerPixelY
// (the near plane's point minus the eye, Renderer::draw).
uniform vec3 rayAtOrigin;
uniform vec3 rayPerPixelX;
uniform vec3 rayPerPixelY;
#else
in vec3 worldPosition;
#endif
flat in vec3 objectEye;  // the eye in the shape's unit-sphere frame (impostor.vert)
#ifdef SPHERE
flat in float inverseRadius;  // toObject is I / r: the same products, without the matrix
#else
flat in mat3 toObject;
#endif
flat in vec4 shapeColour;

uniform vec3 eye;
// The clip z and w of eye + t ray: eyeClip + t (dot(clipZ, ray), dot(clipW, ray)) (the view-projection's rows).
uniform vec2 eyeClip;
uniform vec3 clipZ;
uniform vec3 clipW;
uniform float opacity;

out vec4 fragmentColour;

void main() {
#ifdef POINT_SPRITE
    vec3 ray = rayAtOrigin + gl_FragCoord.x * rayPerPixelX + gl_FragCoord.y * rayPerPixelY;
#else
    vec3 ray = worldPosition - eye;
#endif
    vec3 origin = objectEye;
#ifdef SPHERE
    vec3 direction = inverseRadius * ray;
#else
    vec3 direction = toObject * ray;
#endif
    float a = dot(direction, direction);
    float b = dot(origin, direction);
    float c = dot(origin, origin) - 1.0;
    float discriminant = b * b - a * c;
    if (discriminant < 0.0) discard;
    float root = sqrt(discriminant);
    float t = (-b - root) / a;
    if (t < 0.0) t = (-b + root) / a;
    if (t < 0.0) discard;
    vec3 surface = origin + t * direction;
#ifdef WRITES_DEPTH
    vec2 clip = eyeClip + t * vec2(dot(clipZ, ray), dot(clipW, ray));  // the same t along the ray in world space
    gl_FragDepth = 0.5 * clip.x / clip.y + 0.5;
#endif
#ifdef SPHERE
    vec3 normal = normalize(inverseRadius * surface);
#else
    vec3 normal = normalize(transpose(toObject) * surface);
#endif
    float diffuse = abs(dot(normal, normalize(-ray)));  // a headlight
    fragmentColour = vec4(shapeColour.rgb * (0.3 + 0.7 * diffuse), shapeColour.a * opacity);
}
