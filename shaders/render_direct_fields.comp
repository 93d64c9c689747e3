#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// The direct pass for scenes whose microsurfaces' height fields are traced (render/direct_pass.glsl).
#define FACET_HEIGHT_FIELDS
#include "render/direct_pass.glsl"
