// The batch manifest (docs/batch.md): every finished output with the hash of the inputs it was made
// from and the hash of its bytes, so a rerun skips what is done and redoes what changed or is missing.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "batch/items.hpp"

namespace facet::batch {

struct ManifestEntry {
  std::string scene;  // the scene file, as the job names it
  std::string method;
  int frame = 0;
  std::string inputs_hash;
  std::map<std::string, std::string> files;  // output root-relative path -> content hash (EXR, PNG preview)
  double render_ms = 0.0;                    // wall time of the item, for the record
  std::vector<std::string> overrides;        // the --set applied to the scene ("set"; absent when none)
};

// Keyed by Item::output.
using Manifest = std::map<std::string, ManifestEntry>;

// An absent file is an empty manifest. Anything unreadable as a facet manifest is a one-line
// facet::Error: the user decides whether to delete it (and re-render everything).
Manifest read_manifest(const std::filesystem::path& path);

// Written atomically (temporary + rename): a kill at any moment leaves the old or the new manifest.
void write_manifest(const std::filesystem::path& path, const Manifest& manifest);

// Where shard I of N keeps its manifest: "<stem>.shard-I-of-N.json" beside `manifest`.
std::filesystem::path shard_manifest_path(const std::filesystem::path& manifest, const Shard& shard);

// The shard manifests of `manifest` present on disk, sorted.
std::vector<std::filesystem::path> find_shard_manifests(const std::filesystem::path& manifest);

// `into` with the entries of `from` added; where both have an entry for an output, `from` wins.
void merge_manifest(Manifest& into, const Manifest& from);

}  // namespace facet::batch
