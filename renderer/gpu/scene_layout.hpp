// C++ view of shaders/layout/scene_layout.glsl: the same structs, with GLM types.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace facet::gpu {
using glm::uvec4;
using glm::vec3;
using glm::vec4;
using uint = std::uint32_t;
#include "layout/scene_layout.glsl"

static_assert(sizeof(GpuGlobals) == 160);
static_assert(sizeof(GpuPlane) == 80);
static_assert(sizeof(GpuSphere) == 32);
static_assert(sizeof(GpuTriangle) == 144);
static_assert(sizeof(GpuBvhNode) == 32);
static_assert(sizeof(GpuMaterial) == 64);
static_assert(sizeof(GpuTextureLevel) == 16);
static_assert(sizeof(GpuColormap) == 64);
static_assert(sizeof(GpuTile) == 64);
}  // namespace facet::gpu
