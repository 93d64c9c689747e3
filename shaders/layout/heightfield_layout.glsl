// Where the levels of a height field's min-max chains lie in the texel buffer, declared once for GLSL
// and C++ (renderer/gpu/microsurface_upload.hpp builds the chains; render/heightfield_trace.glsl reads
// them): level l starts span - (span >> l) texels after level 0, span = the texels of one chain
// (heightfield_bound_span), so the tracer finds a level's bounds by arithmetic instead of loading the
// level's record at every step.
#ifndef FACET_HEIGHTFIELD_LAYOUT_GLSL
#define FACET_HEIGHTFIELD_LAYOUT_GLSL

#define FACET_HEIGHTFIELD_BOUND_LEVEL(span, l) ((span) - ((span) >> (l)))

#endif
