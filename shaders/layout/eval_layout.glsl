// Records of the batched `facet eval` kernels, shared by GLSL and C++
// (renderer/gpu/batch_eval.hpp). vec4-only, so std430 equals the C++ layout.
#ifndef FACET_EVAL_LAYOUT_GLSL
#define FACET_EVAL_LAYOUT_GLSL

// Every eval kernel reads In records and writes Out records, one invocation per record.
struct EvalRecord {
  vec4 a;
  vec4 b;
};

// Push constants: the first record of this dispatch and how many records there are in all.
struct EvalRange {
  uvec4 offset_count;  // offset, count
};

#define FACET_EVAL_WORKGROUP 64

// Storage-buffer slots of every eval kernel (gpu/batch_eval.cpp binds them by these names);
// eval_diffraction.comp reads its spectral tables at the next two (diffraction/diffraction_gpu.cpp).
#define FACET_EVAL_BINDING_IN 0
#define FACET_EVAL_BINDING_OUT 1
#define FACET_EVAL_BINDING_COUNT 2
#define FACET_EVAL_BINDING_DIFFRACTION_TABLE 2
#define FACET_EVAL_BINDING_DIFFRACTION_INFO 3
#define FACET_EVAL_DIFFRACTION_BINDING_COUNT 4

#endif
