#version 330 core
// Every line drawing (octree cells, photon paths, source glyphs, axes, grid): coloured segments.
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour;

uniform mat4 viewProjection;

out vec4 lineColour;

void main() {
    lineColour = colour;
    gl_Position = viewProjection * vec4(position, 1.0);
}
