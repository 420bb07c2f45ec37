#version 330 core
// Spheres and ellipsoids: one camera-facing quad per shape, covering the silhouette of its bounding
// sphere (radius R, the largest semi-axis); impostor.frag ray-casts the shape's unit sphere through it.
// At distance d from the eye the tangent cone cuts the plane touching the bounding sphere's front in a
// circle of radius R (d - R) / sqrt(d^2 - R^2), so a quad of that half-size there covers the shape, and the
// shape lies behind the quad along every eye ray through it (impostor.frag relies on this). With the eye
// inside (or nearly inside) the bounding sphere no such quad exists, and with the sphere's front before the
// near plane it would be clipped; the quad then covers the whole near plane.
//
// Shapes whose silhouette is at most `exactPointPixels` across are drawn by the POINT_SPRITE variants
// instead: one point, a square covering the silhouette, on the eye ray through the centre at the depth of
// the bounding sphere's nearest point. With EXACT_DEPTH (up to exactPointPixels, above pointPixels) the fragments write their true
// depth as a quad's do; without (up to pointPixels) the point's depth is the fragments', so the depth test
// can run before the fragment shader. The three variants size a shape with the same expression, so each
// shape is drawn by exactly one of them.
//
// A sphere apart (nothing else drawn reaches into it: render/ApartSpheres.hpp) up to `apartPixels` is such a
// point without EXACT_DEPTH too, at its centre's depth: along each eye ray through it everything else lies before
// its entry or beyond its exit, and the centre's depth lies between the two but at the rim (docs/rendering.md,
// "Spheres apart").
//
// SPHERE (with POINT_SPRITE) draws runs of shapes that are all spheres, whose matrices are r I and I / r: it
// reads one column of each and hands impostor.frag 1/r instead of a matrix, 13 floats a shape read instead
// of 25 and 8 passed on instead of 16, for the same numbers (docs/rendering.md, "Spheres' points").
layout(location = 0) in vec3 corner;  // (+-1, +-1, 0)
layout(location = 2) in vec3 center;
#ifdef SPHERE
layout(location = 3) in vec3 linearX;         // the first column of r I
layout(location = 6) in vec3 inverseLinearX;  // the first column of I / r
#else
layout(location = 3) in mat3 linear;         // locations 3, 4, 5
layout(location = 6) in mat3 inverseLinear;  // locations 6, 7, 8
#endif
layout(location = 9) in vec4 colour;
#ifdef POINT_SPRITE
layout(location = 10) in float apart;  // 1 for a sphere apart, else 0
#endif

uniform mat4 viewProjection;
uniform mat4 inverseViewProjection;
uniform vec3 eye;
uniform vec3 cameraUp;
uniform float pointPixels;       // points with the front's depth up to this width (0: none)
uniform float exactPointPixels;  // points with exact depth above pointPixels, up to this width
uniform float apartPixels;       // spheres apart up to this width: points at their centre's depth (0: none)
uniform float pixelsPerUnit;   // framebuffer pixels a unit length spans at unit depth on the axis
uniform float maxStretch;      // how much wider than on the axis a shape is drawn in the corners
uniform vec2 viewportSize;

#ifndef POINT_SPRITE
out vec3 worldPosition;
#endif
flat out vec3 objectEye;  // the eye in the shape's unit-sphere frame
#ifdef SPHERE
flat out float inverseRadius;
#else
flat out mat3 toObject;
#endif
flat out vec4 shapeColour;

const vec4 kDropped = vec4(0.0, 0.0, 2.0, 1.0);  // beyond the far plane: clipped

void main() {
    shapeColour = colour;
#ifdef SPHERE
    inverseRadius = inverseLinearX.x;
    objectEye = inverseRadius * (eye - center);
    float radius = length(linearX);  // as the largest column's length below: the three are equal
#else
    toObject = inverseLinear;
    objectEye = inverseLinear * (eye - center);
    float radius = max(length(linear[0]), max(length(linear[1]), length(linear[2])));
#endif
    vec3 toEye = eye - center;
    float distance = length(toEye);
    // The silhouette's width in pixels: the tangent cone's on the axis, widened off the axis by
    // (distance / depth)^2 (depth = the centre's clip w).
    vec4 clipCentre = viewProjection * vec4(center, 1.0);
    float depth = clipCentre.w;
    float stretch = depth > 0.0 ? min(distance * distance / (depth * depth), maxStretch) : maxStretch;
    float pixels = distance > 1.01 * radius
                       ? 2.0 * radius * pixelsPerUnit / sqrt(distance * distance - radius * radius) * stretch
                       : 1e30;
    // A point is a square centred on the centre's image. At angle theta off the axis the silhouette (angular
    // radius alpha) reaches f tan(alpha) s / (1 - tan(theta) tan(alpha)) from there, s = 1 / cos^2(theta);
    // the square covers that, with a quarter pixel to spare. A point is clipped whole when its centre leaves
    // the view, so one that reaches within a pixel of the image's edge, or is not wholly beyond the near
    // plane, is drawn as a quad.
    float tanAlpha = distance > 1.01 * radius ? radius / sqrt(distance * distance - radius * radius) : 1e30;
    float spread = 1.0 - sqrt(max(stretch - 1.0, 0.0)) * tanAlpha;
    float pointSize = spread > 0.1 ? 2.0 * pixelsPerUnit * tanAlpha * stretch / spread + 0.5 : 1e30;
    vec2 pixel = (clipCentre.xy / clipCentre.w * 0.5 + 0.5) * viewportSize;
    vec3 forward = toEye / distance;
    // On the eye ray through the centre, at the view depth of the bounding sphere's nearest point: the
    // point's depth is never farther than any point of the shape.
    vec3 nearest = eye - toEye * (1.0 - radius / max(depth, 1e-30));
    vec4 nearestClip = viewProjection * vec4(nearest, 1.0);
    bool inside = depth > 1.01 * radius && nearestClip.z >= -nearestClip.w &&
                  all(greaterThanEqual(pixel - 0.5 * pointSize - 1.0, vec2(0.0))) &&
                  all(lessThanEqual(pixel + 0.5 * pointSize + 1.0, viewportSize));
    // 0: a quad; 1: a point with exact depth; 2: a point with the front's depth.
    int tier = !inside || pixels > exactPointPixels ? 0 : (pixels <= pointPixels ? 2 : 1);
#ifdef POINT_SPRITE
    // Off the view's axis, at angle phi, the centre's depth leaves the sphere's span along the outer
    // R (1 - cos phi) of the silhouette (docs/rendering.md, "Spheres apart"): at most a pixel there. depth /
    // distance is cos phi at the centre. A centre beyond the far plane would clip the point whole.
    bool centreDepth = apart > 0.5 && pixels <= apartPixels && pixels * (1.0 - depth / distance) < 2.0 &&
                       clipCentre.z <= clipCentre.w;
    if (tier == 1 && centreDepth) tier = 2;
#ifdef EXACT_DEPTH
    const int kTier = 1;
#else
    const int kTier = 2;
#endif
    if (tier != kTier) {
        gl_Position = kDropped;
        gl_PointSize = 1.0;
        return;
    }
    gl_Position = centreDepth ? clipCentre : nearestClip;
    gl_PointSize = pointSize;
#else
    if (tier != 0) {
        gl_Position = kDropped;
        return;
    }
    vec3 right = normalize(cross(cameraUp, forward));
    if (any(isnan(right))) right = normalize(cross(vec3(1.0, 0.0, 0.0), forward));
    vec3 up = cross(forward, right);
    // In the plane touching the bounding sphere's front, the cone is narrower by (d - R) / d; every point of
    // the shape lies behind the quad along the eye ray through it.
    float halfSize = distance > 1.01 * radius
                         ? radius * (distance - radius) / sqrt(distance * distance - radius * radius)
                         : 0.0;
    // The quad is used only when all four corners lie beyond the near plane (the same test for each).
    bool beyondNear = distance > 1.01 * radius;
    for (int k = 0; k < 4; ++k) {
        vec2 c = vec2(k == 1 || k == 3 ? 1.0 : -1.0, k >= 2 ? 1.0 : -1.0);
        vec4 clip = viewProjection * vec4(center + radius * forward + halfSize * (c.x * right + c.y * up), 1.0);
        beyondNear = beyondNear && clip.z >= -clip.w;
    }
    if (beyondNear) {
        worldPosition = center + radius * forward + halfSize * (corner.x * right + corner.y * up);
        gl_Position = viewProjection * vec4(worldPosition, 1.0);
    } else {
        vec4 near = inverseViewProjection * vec4(corner.xy, -1.0, 1.0);
        worldPosition = near.xyz / near.w;
        gl_Position = vec4(corner.xy, -1.0, 1.0);
    }
#endif
}
