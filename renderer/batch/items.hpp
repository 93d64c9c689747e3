// The items of a job (one output each: scene × method × frame), their output names, and the
// deterministic split of the items into shards for schedulers (docs/batch.md).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "batch/job.hpp"

namespace facet::batch {

struct Item {
  size_t scene = 0;  // index into Job::scenes
  std::string method;
  int frame = 0;
  std::string output;  // the expanded output pattern, relative to the output root; the manifest key
};

// `pattern` with {scene} (the scene file's stem), {method} (characters other than letters, digits,
// '.', '_' and '-' become '_', so "ss:4" gives "ss_4"), {frame} and {frame:0N} (zero-padded to N
// digits, N in 1..9) substituted. Throws facet::Error for any other {...} or an unclosed brace.
std::string expand_output(const std::string& pattern, const std::string& scene, const std::string& method, int frame);

// Every item in a fixed order: scenes in job order, methods in job order, frames ascending (the
// job's `frames`, or 0..frame_counts[scene]-1). Throws facet::Error if two items would write the
// same output.
std::vector<Item> expand_items(const Job& job, const std::vector<int>& frame_counts);

// Shard `index` of `count` (`--shard I/N`, 0 <= I < N) owns the items whose position in the
// expanded list is I modulo N: every shard derives the same list, so N shards with no coordination
// render each item exactly once, and neighbouring frames spread evenly over the shards.
struct Shard {
  int index = 0;
  int count = 1;
  static Shard parse(const std::string& text);  // "I/N"; throws facet::Error
  bool owns(size_t item_position) const {
    return static_cast<int>(item_position % static_cast<size_t>(count)) == index;
  }
  bool whole() const { return count == 1; }
};

}  // namespace facet::batch
