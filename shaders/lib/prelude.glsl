// The common subset of GLSL and C++ that every shared kernel under shaders/lib is written in.
//
// A kernel file includes this prelude and uses only: the scalar/vector aliases below
// (real, real2, real3, real4, real2x2), int/uint/bool, structs returned by value (no
// out/inout parameters), GLSL built-ins that GLM also provides (exp, sqrt, abs, min, max,
// clamp, mix, dot, ...) and literals written as real(0.5). Every function is declared
// `inline` (a no-op macro in GLSL), since C++ sees each definition in many translation units. On the GPU `real` is float; C++
// compiles the same file twice, into facet::kernels::f32 and facet::kernels::f64
// (renderer/kernels/shared.hpp), so the CPU reference runs a double twin of the GPU code.
#ifndef FACET_PRELUDE_GLSL
#define FACET_PRELUDE_GLSL

#ifndef __cplusplus
#define real float
#define real2 vec2
#define real3 vec3
#define real4 vec4
#define real2x2 mat2
#define REAL_IS_DOUBLE 0
#define inline
#endif


// Constants are macros so that each pass rounds them to its own precision.
#define FACET_PI real(3.14159265358979323846)
#define FACET_INV_PI real(0.31830988618379067154)
#define FACET_SQRT2 real(1.41421356237309504880)
#define FACET_INV_SQRT2PI real(0.39894228040143267794)

#endif
