// The diffraction BRDF on the GPU: shaders/eval_diffraction.comp over a batch of queries, with
// the spectral tables uploaded as float (docs/diffraction.md).
#pragma once

#include <span>
#include <vector>

#include "diffraction/diffraction_eval.hpp"
#include "diffraction/spectral_tables.hpp"
#include "gpu/batch_eval.hpp"
#include "vk/context.hpp"

namespace facet::diffraction {

// One result per query, in order. Throws facet::Error if the tables exceed the device's storage
// buffer range.
std::vector<DiffractionResult> evaluate_gpu(vk::Context& context, const SpectralTables& tables,
                                            std::span<const DiffractionQuery> queries,
                                            gpu::BatchTiming* timing = nullptr);

}  // namespace facet::diffraction
