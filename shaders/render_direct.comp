#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// The direct pass for scenes without traced height fields (render/direct_pass.glsl).
#include "render/direct_pass.glsl"
