// The diffraction BRDF on the GPU: shaders/eval_diffraction.comp over a batch of queries, with
// the spectral tables uploaded as float (docs/diffraction.md).
#pragma once

#include <span>
#include <vector>

#include "diffraction/diffraction_eval.hpp"
#include "diffraction/spectral_tables.hpp"
#include "gpu/batch_eval.hpp"
#include "vk/context.hpp"

namespace facet::gpu {

// One result per query, in order. Throws facet::Error if the tables exceed the device's storage
// buffer range.
std::vector<diffraction::DiffractionResult> evaluate_diffraction(vk::Context& context,
                                                                 const diffraction::SpectralTables& tables,
                                                                 std::span<const diffraction::DiffractionQuery> queries,
                                                                 BatchTiming* timing = nullptr);

}  // namespace facet::gpu
