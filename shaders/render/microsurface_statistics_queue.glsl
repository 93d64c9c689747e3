// filtered's statistics of traced microsurfaces in a dispatch of their own (docs/render_speed.md, "The
// statistics in a pass of their own"). lavapipe runs every branch of a program for every group of 8 lanes,
// masked, so in the pass that traces, the statistics' code cost every pixel its time, although only samples
// whose footprint is wider than a texel (w < 1 of (T1)) use it. That pass queues those samples here instead;
// a second dispatch of the same program (kStatisticsPass) shades the queue alone, each entry from its sample's
// camera ray and hit, as the tracing pass would have.
#ifndef FACET_RENDER_MICROSURFACE_STATISTICS_QUEUE_GLSL
#define FACET_RENDER_MICROSURFACE_STATISTICS_QUEUE_GLSL
#include "layout/render_layout.glsl"

layout(std430, binding = FACET_RENDER_BINDING_STATISTICS_QUEUE) buffer StatisticsQueue {
  uvec4 statistics_count;       // x: the entries the tracing dispatch appended
  uvec4 statistics_entries[];   // (slot, the hit's t, its plane, the statistics' light visibility), floats as bits
};

// A queued sample: its slot in the pixel buffer, where its camera ray met a field (t, on `plane`), and whether
// the statistics' shadow ray from a footprint out reached the light.
struct QueuedStatistics {
  uint slot;
  float t;
  uint plane;
  float visibility;
};

// Whether this invocation's sample left the statistics' part of its radiance to the queue, and what it left
// (set by microsurface_field_radiance; main() appends it with the sample's slot).
bool statistics_pending = false;
QueuedStatistics pending_statistics;

void queue_statistics(QueuedStatistics s) {
  statistics_entries[atomicAdd(statistics_count.x, 1u)] =
      uvec4(s.slot, floatBitsToUint(s.t), s.plane, floatBitsToUint(s.visibility));
}

QueuedStatistics queued_statistics(uint entry) {
  uvec4 e = statistics_entries[entry];
  return QueuedStatistics(e.x, uintBitsToFloat(e.y), e.z, uintBitsToFloat(e.w));
}

#endif
