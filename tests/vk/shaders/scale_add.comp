#version 450
// Test kernel: out[i] = in[i] * scale + offset, with `scale` a specialization constant and
// `offset` a push constant, so one dispatch exercises every binding path of vk::Kernel.
layout(local_size_x = 64) in;
layout(constant_id = 0) const float scale = 1.0;
layout(std430, binding = 0) readonly buffer In { float values_in[]; };
layout(std430, binding = 1) writeonly buffer Out { float values_out[]; };
layout(push_constant) uniform Push { float offset; uint count; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < count) values_out[i] = values_in[i] * scale + offset;
}
