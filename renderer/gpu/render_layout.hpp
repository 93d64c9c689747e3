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
static_assert(contiguous_ids(
    std::array<int, FACET_RENDER_BINDING_COUNT - FACET_RENDER_SCENE_BINDING_COUNT>{
        FACET_RENDER_BINDING_DIFFRACTION_COEFFICIENTS, FACET_RENDER_BINDING_DIFFRACTION_MATERIALS,
        FACET_RENDER_BINDING_DIFFRACTION_WAVELENGTHS, FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS,
        FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_SCALES, FACET_RENDER_BINDING_DIFFRACTION_OBSERVER,
        FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS_1, FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS_2,
        FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS_3, FACET_RENDER_BINDING_PIXEL_LIST,
        FACET_RENDER_BINDING_STATISTICS_QUEUE},
    FACET_RENDER_SCENE_BINDING_COUNT));
static_assert(contiguous_ids(std::array<int, FACET_RENDER_SPEC_COUNT>{FACET_RENDER_SPEC_HAS_MICROFLAKE,
                                                                      FACET_RENDER_SPEC_HAS_TEXTURE,
                                                                      FACET_RENDER_SPEC_TEXTURE_METHOD,
                                                                      FACET_RENDER_SPEC_HAS_DIFFRACTION,
                                                                      FACET_RENDER_SPEC_DIFFRACTION_METHOD,
                                                                      FACET_RENDER_SPEC_HAS_MICROSURFACE,
                                                                      FACET_RENDER_SPEC_HAS_SPHERES,
                                                                      FACET_RENDER_SPEC_HAS_TRIANGLES,
                                                                      FACET_RENDER_SPEC_PREINTEGRATED_SLICES,
                                                                      FACET_RENDER_SPEC_PREINTEGRATED_SLICE_WORDS,
                                                                      FACET_RENDER_SPEC_AOVS,
                                                                      FACET_RENDER_SPEC_COUNTS_WORK,
                                                                      FACET_RENDER_SPEC_HAS_LINEAR_COLORMAPS,
                                                                      FACET_RENDER_SPEC_HAS_STEP_COLORMAPS,
                                                                      FACET_RENDER_SPEC_WHOLE_MIP_TEXELS,
                                                                      FACET_RENDER_SPEC_ESTIMATES_ERROR,
                                                                      FACET_RENDER_SPEC_MICROSURFACE_HEIGHT_MAPS,
                                                                      FACET_RENDER_SPEC_MICROSURFACE_SLOPE_MAPS,
                                                                      FACET_RENDER_SPEC_MICROSURFACE_LOBES,
                                                                      FACET_RENDER_SPEC_STEP_COLORMAP_POINTS,
                                                                      FACET_RENDER_SPEC_LINEAR_COLORMAP_POINTS,
                                                                      FACET_RENDER_SPEC_COLORMAP_SEARCH_STEPS,
                                                                      FACET_RENDER_SPEC_COLORMAP_DIVIDES,
                                                                      FACET_RENDER_SPEC_PLANE_TRIPS,
                                                                      FACET_RENDER_SPEC_SPHERE_TRIPS,
                                                                      FACET_RENDER_SPEC_STATISTICS_PASS}));

}  // namespace facet::gpu
