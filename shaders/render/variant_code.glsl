// The code this variant of the direct pass compiles in: FACET_VARIANT_CODE, a sum of FACET_CODE_*
// (layout/render_layout.glsl) that shaders/CMakeLists.txt defines per variant; undefined (other
// includers), everything. Lavapipe's pipeline set-up grows with every call it inlines, dead or not,
// so code a scene does not run is cut out by the preprocessor (docs/render_speed.md, "Pipeline set-up").
#ifndef FACET_RENDER_VARIANT_CODE_GLSL
#define FACET_RENDER_VARIANT_CODE_GLSL
#include "layout/render_layout.glsl"
#ifndef FACET_VARIANT_CODE
#define FACET_VARIANT_CODE FACET_CODE_ALL
#endif
#define FACET_VARIANT_HAS(code) ((FACET_VARIANT_CODE & (code)) != 0)
#endif
