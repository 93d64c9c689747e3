// The binding contract of the direct pass (render_direct.comp, render_direct_fields.comp), by name:
// its storage-buffer slots, specialization constant ids and workgroup size. Plain #defines, so the
// same lines serve GLSL and C++ (renderer/gpu/render_layout.hpp includes this file and checks that
// the slots and the ids each run 0..count-1 without gaps or repeats; vk::Kernel binds slots 0..B-1).
#ifndef FACET_RENDER_LAYOUT_GLSL
#define FACET_RENDER_LAYOUT_GLSL

// The scene's buffers (render/scene_bindings.glsl; C++: SceneBuffers, gpu/scene_upload.hpp).
#define FACET_RENDER_BINDING_GLOBALS 0
#define FACET_RENDER_BINDING_PLANES 1
#define FACET_RENDER_BINDING_SPHERES 2
#define FACET_RENDER_BINDING_BVH_NODES 3
#define FACET_RENDER_BINDING_TRIANGLES 4
#define FACET_RENDER_BINDING_MATERIALS 5
#define FACET_RENDER_BINDING_PIXELS 6  // the tile's pixels, owned by the pass (gpu/direct_pass.hpp)
#define FACET_RENDER_BINDING_TEXTURE_LEVELS 7
#define FACET_RENDER_BINDING_TEXELS 8
#define FACET_RENDER_BINDING_COLORMAPS 9
#define FACET_RENDER_BINDING_COLORMAP_POINTS 10
#define FACET_RENDER_SCENE_BINDING_COUNT 11

// The diffraction materials' buffers (render/diffraction_shading.glsl; C++: DiffractionBuffers,
// gpu/diffraction_upload.hpp).
#define FACET_RENDER_BINDING_DIFFRACTION_COEFFICIENTS 11
#define FACET_RENDER_BINDING_DIFFRACTION_MATERIALS 12
#define FACET_RENDER_BINDING_DIFFRACTION_WAVELENGTHS 13
#define FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS 14
#define FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_SCALES 15
#define FACET_RENDER_BINDING_DIFFRACTION_OBSERVER 16
// Further slices of the preintegrated words, when one texel binding cannot hold them (slice 0 is
// PREINTEGRATED_WORDS; renderer/gpu/preintegrated_slices.hpp).
#define FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS_1 17
#define FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS_2 18
#define FACET_RENDER_BINDING_DIFFRACTION_PREINTEGRATED_WORDS_3 19
// filtered:adaptive's refinement: the strata a listed dispatch renders, one RG32UI texel each, a pixel's
// frame position and the stratum's index as (x | stratum << 16, y) (render/direct_pass.glsl;
// renderer/gpu/direct_pass.cpp).
#define FACET_RENDER_BINDING_PIXEL_LIST 20
// filtered on traced microsurfaces: the queue of samples whose statistics a dispatch of their own shades
// (render/microsurface_statistics_queue.glsl): a uvec4 count, then a uvec4 an entry.
#define FACET_RENDER_BINDING_STATISTICS_QUEUE 21
#define FACET_RENDER_BINDING_COUNT 22
#define FACET_RENDER_PREINTEGRATED_SLICES 4  // the word bindings above

// Specialization constants (what each selects: render/direct_pass.glsl).
#define FACET_RENDER_SPEC_HAS_MICROFLAKE 0
#define FACET_RENDER_SPEC_HAS_TEXTURE 1
#define FACET_RENDER_SPEC_TEXTURE_METHOD 2
#define FACET_RENDER_SPEC_HAS_DIFFRACTION 3
#define FACET_RENDER_SPEC_DIFFRACTION_METHOD 4
#define FACET_RENDER_SPEC_HAS_MICROSURFACE 5
#define FACET_RENDER_SPEC_HAS_SPHERES 6
#define FACET_RENDER_SPEC_HAS_TRIANGLES 7
#define FACET_RENDER_SPEC_PREINTEGRATED_SLICES 8
#define FACET_RENDER_SPEC_PREINTEGRATED_SLICE_WORDS 9
#define FACET_RENDER_SPEC_AOVS 10
#define FACET_RENDER_SPEC_COUNTS_WORK 11
#define FACET_RENDER_SPEC_HAS_LINEAR_COLORMAPS 12
#define FACET_RENDER_SPEC_HAS_STEP_COLORMAPS 13
#define FACET_RENDER_SPEC_WHOLE_MIP_TEXELS 14
#define FACET_RENDER_SPEC_ESTIMATES_ERROR 15
#define FACET_RENDER_SPEC_MICROSURFACE_HEIGHT_MAPS 16
#define FACET_RENDER_SPEC_MICROSURFACE_SLOPE_MAPS 17
#define FACET_RENDER_SPEC_MICROSURFACE_LOBES 18
#define FACET_RENDER_SPEC_STEP_COLORMAP_POINTS 19
#define FACET_RENDER_SPEC_LINEAR_COLORMAP_POINTS 20
#define FACET_RENDER_SPEC_COLORMAP_SEARCH_STEPS 21
#define FACET_RENDER_SPEC_PLANE_TRIPS 22
#define FACET_RENDER_SPEC_SPHERE_TRIPS 23
#define FACET_RENDER_SPEC_COLORMAP_DIVIDES 24
#define FACET_RENDER_SPEC_STATISTICS_PASS 25
#define FACET_RENDER_SPEC_COUNT 26
// The value of FACET_RENDER_SPEC_PLANE_TRIPS and _SPHERE_TRIPS for a loop over the scene's count (render/trace.glsl).
#define FACET_RENDER_LOOPED_TRIPS 0xffffffffu
// Colour maps of up to this many points are walked whole (not searched); where every map of a kind in a
// scene is, its walks are unrolled to the longest's points (render/texture_sampling.glsl).
#define FACET_RENDER_WALKED_COLORMAP_POINTS 16

// The code a variant of the program compiles in: its FACET_VARIANT_CODE is a sum of these
// (render/direct_pass.glsl; shaders/CMakeLists.txt lists the variants, renderer/gpu/direct_pass_variant.hpp
// picks the smallest that covers a scene and method). Material families, primitive kinds, the
// filtered methods' code (filtered, filtered:table: colour-map integrals, microsurface statistics)
// and the diffraction methods (kDiffractionMethod): spectral (also orders' fallback), preintegrated, orders.
#define FACET_CODE_TEXTURE 1
#define FACET_CODE_DIFFRACTION 2
#define FACET_CODE_MICROFLAKE 4
#define FACET_CODE_MICROSURFACE 8
#define FACET_CODE_SPHERES 16
#define FACET_CODE_TRIANGLES 32
#define FACET_CODE_FILTERED 64
#define FACET_CODE_DIFFRACTION_PREINTEGRATED 128
#define FACET_CODE_DIFFRACTION_ORDERS 256
#define FACET_CODE_DIFFRACTION_SPECTRAL 512
#define FACET_CODE_ALL 1023

// Workgroups are FACET_RENDER_WORKGROUP x FACET_RENDER_WORKGROUP pixels of a tile.
#define FACET_RENDER_WORKGROUP 8

// `filtered` tiles a textured pixel with FACET_RENDER_FILTERED_SPLIT^2 sub-footprints per axis pair
// (render/texture_sampling.glsl, kFilteredSplit); filtered:adaptive prices its refinement with it
// (renderer/gpu/adaptive_refinement.cpp).
#define FACET_RENDER_FILTERED_SPLIT 2

#endif
