#version 330 core
// Dear ImGui's triangles (ImDrawVert: position in ImGui's display coordinates, atlas coordinates, and a
// colour as four normalised bytes), projected by an orthographic matrix over the display rectangle.
layout(location = 0) in vec2 position;
layout(location = 1) in vec2 atlasCoordinate;
layout(location = 2) in vec4 colour;

uniform mat4 projection;

out vec2 textureCoordinate;
out vec4 vertexColour;

void main() {
    textureCoordinate = atlasCoordinate;
    vertexColour = colour;
    gl_Position = projection * vec4(position, 0.0, 1.0);
}
