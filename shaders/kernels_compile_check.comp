#version 450
#extension GL_GOOGLE_include_directive : require
// Compiles every shared kernel as GLSL: the same list the C++ twins are built from
// (lib/all_kernels.inc), so a kernel no shader uses yet still proves it is valid GLSL, and the
// build fails if it is not.
#include "lib/all_kernels.inc"

layout(local_size_x = 1) in;
void main() {}
