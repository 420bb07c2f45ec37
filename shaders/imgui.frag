#version 330 core
// The vertex colour times the texture (the font atlas, whose white pixel fills shapes, or a user image).
uniform sampler2D atlas;

in vec2 textureCoordinate;
in vec4 vertexColour;
out vec4 fragmentColour;

void main() { fragmentColour = vertexColour * texture(atlas, textureCoordinate); }
