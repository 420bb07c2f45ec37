#version 330 core
// The exact surface of a sphere or ellipsoid under its proxy cube: the eye ray in the shape's unit-sphere
// frame, the nearest root in front of the eye (the far one when the eye is inside), its true depth.
in vec3 worldPosition;
flat in vec3 shapeCenter;
flat in mat3 toObject;
flat in mat3 toWorld;
flat in vec4 shapeColour;

uniform mat4 viewProjection;
uniform vec3 eye;
uniform float opacity;

out vec4 fragmentColour;

void main() {
    vec3 origin = toObject * (eye - shapeCenter);
    vec3 direction = toObject * (worldPosition - eye);
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
    vec3 world = shapeCenter + toWorld * surface;
    vec4 clip = viewProjection * vec4(world, 1.0);
    gl_FragDepth = 0.5 * clip.z / clip.w + 0.5;
    vec3 normal = normalize(transpose(toObject) * surface);
    float diffuse = abs(dot(normal, normalize(eye - world)));  // a headlight
    fragmentColour = vec4(shapeColour.rgb * (0.3 + 0.7 * diffuse), shapeColour.a * opacity);
}
