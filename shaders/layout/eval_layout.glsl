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

#endif
