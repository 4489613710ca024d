#version 330 core
// A student's shader that tries to read a file outside the shader folders: it must be refused
// before the file is read, so no line of it can appear in an error message.
#include "/etc/os-release"
out vec4 o_color;
void main() { o_color = vec4(1.0); }
