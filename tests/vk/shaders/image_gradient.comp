#version 450
// Test kernel: reads texel (x, y) of `source`, writes it scaled by 2 plus (x, y, 0, 1) into
// `target`; buffer binding 0 carries the image size.
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, binding = 0) readonly buffer Size { uvec2 size; };
layout(binding = 1, rgba32f) uniform readonly image2D source;
layout(binding = 2, rgba32f) uniform writeonly image2D target;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(size.x) || p.y >= int(size.y)) return;
  imageStore(target, p, 2.0 * imageLoad(source, p) + vec4(p, 0.0, 1.0));
}
