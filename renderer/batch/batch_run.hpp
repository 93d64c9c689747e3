// `facet batch`: every scene × method × frame of a job, each scene's method prepared once for all
// its frames, resumable through a manifest and split into shards for schedulers (docs/batch.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "vk/context.hpp"

namespace facet::batch {

struct BatchOptions {
  std::filesystem::path job;
  std::vector<std::string> overrides;  // --set: of the job's keys, or else of every scene's (load_job)
  std::string shard = "0/1";      // I/N: this process renders shard I of N
  bool merge = false;             // merge the shard manifests into the job's manifest instead of rendering
  std::filesystem::path out_dir;  // root of the outputs and the manifest; empty: the job file's directory
  vk::ContextOptions device;      // created only when a GPU item is to be rendered
  std::string facet_version;      // part of every item's inputs hash
};

// Renders the items of the shard that are not up to date, keeping the manifest current after each,
// and prints a summary on stderr; or, with `merge`, merges the shard manifests. A failing item does not
// stop the others. Returns 0; throws facet::Error when items failed or SIGINT/SIGTERM stopped the run
// (every finished item is in the manifest then).
int run_batch(const BatchOptions& options);

}  // namespace facet::batch
