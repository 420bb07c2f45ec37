#version 330 core
in vec3 worldPosition;
in vec3 worldNormal;
flat in vec4 shapeColour;

uniform vec3 eye;
uniform float opacity;

out vec4 fragmentColour;

void main() {
    float diffuse = abs(dot(normalize(worldNormal), normalize(eye - worldPosition)));  // a headlight
    fragmentColour = vec4(shapeColour.rgb * (0.3 + 0.7 * diffuse), shapeColour.a * opacity);
}
