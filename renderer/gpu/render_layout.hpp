// C++ view of shaders/layout/render_layout.glsl: the direct pass's binding slots, specialization ids
// and workgroup size under the names the shaders use, checked to form the ranges vk::Kernel binds.
#pragma once

#include <array>

#include "gpu/contiguous_ids.hpp"
#include "layout/render_layout.glsl"

namespace facet::gpu {

// Every name of the layout file once: a name left out here (a 0 in its place) or repeated breaks the range.
static_assert(contiguous_ids(std::array<int, FACET_RENDER_SCENE_BINDING_COUNT>{
    FACET_RENDER_BINDING_GLOBALS, FACET_RENDER_BINDING_PLANES, FACET_RENDER_BINDING_SPHERES,
    FACET_RENDER_BINDING_BVH_NODES, FACET_RENDER_BINDING_TRIANGLES, FACET_RENDER_BINDING_MATERIALS,
    FACET_RENDER_BINDING_PIXELS, FACET_RENDER_BINDING_TEXTURE_LEVELS, FACET_RENDER_BINDING_TEXELS,
    FACET_RENDER_BINDING_COLORMAPS, FACET_RENDER_BINDING_COLORMAP_POINTS}));
static_assert(contiguous_ids(std::array<int, FACET_RENDER_BINDING_COUNT - FACET_RENDER_SCENE_BINDING_COUNT>{
                                 FACET_RENDER_BINDING_DIFFRACTION_COEFFICIENTS,
                                 FACET_RENDER_BINDING_DIFFRACTION_MATERIALS,
                                 FACET_RENDER_BINDING_DIFFRACTION_WAVELENGTHS,
                                 FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS,
                                 FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_SCALES,
                                 FACET_RENDER_BINDING_DIFFRACTION_OBSERVER},
                             FACET_RENDER_SCENE_BINDING_COUNT));
static_assert(contiguous_ids(std::array<int, FACET_RENDER_SPEC_COUNT>{
    FACET_RENDER_SPEC_HAS_MICROFLAKE, FACET_RENDER_SPEC_HAS_TEXTURE, FACET_RENDER_SPEC_TEXTURE_METHOD,
    FACET_RENDER_SPEC_HAS_DIFFRACTION, FACET_RENDER_SPEC_DIFFRACTION_METHOD,
    FACET_RENDER_SPEC_HAS_MICROSURFACE, FACET_RENDER_SPEC_HAS_SPHERES, FACET_RENDER_SPEC_HAS_TRIANGLES}));

}  // namespace facet::gpu
