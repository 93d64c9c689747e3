// facet batch JOB.json: every scene × method × frame of a job, precomputing once per scene and
// method, resumable through a manifest and split into shards for schedulers (docs/batch.md).
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include "batch/input_hash.hpp"
#include "batch/items.hpp"
#include "batch/job.hpp"
#include "batch/manifest.hpp"
#include "cli/batch_renderer.hpp"
#include "cli/commands.hpp"
#include "cli/frame_output.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "common/progress.hpp"
#include "scene/camera_path.hpp"
#include "scene/scene_loader.hpp"

namespace facet::cli {

namespace {

namespace fs = std::filesystem;
using batch::Item;
using batch::Manifest;
using batch::ManifestEntry;

struct BatchCommandOptions {
  fs::path job;
  std::string shard = "0/1";
  bool merge = false;
  fs::path out_dir;
  DeviceOptions device;
};

struct LoadedScene {
  std::optional<Scene> scene;
  std::string error;        // why it failed to load or hash
  std::string files_hash;   // the scene file and every file it references
};

LoadedScene load(const fs::path& file) {
  LoadedScene loaded;
  try {
    loaded.scene = load_scene(file);
    loaded.files_hash = batch::scene_files_hash(file);
  } catch (const Error& e) {
    loaded.scene.reset();
    loaded.error = e.what();
  }
  return loaded;
}

// The entry for `item` if its inputs are unchanged and every file it lists still has its bytes.
const ManifestEntry* up_to_date(const Manifest& manifest, const Item& item, const std::string& inputs_hash,
                                const fs::path& root) {
  const auto it = manifest.find(item.output);
  if (it == manifest.end() || inputs_hash.empty() || it->second.inputs_hash != inputs_hash ||
      it->second.files.count(item.output) == 0)
    return nullptr;
  for (const auto& [file, hash] : it->second.files)
    if (batch::file_hash(root / file) != hash) return nullptr;
  return &it->second;
}

// One row of the summary: the items of one scene and method in this shard.
struct SummaryRow {
  std::string scene, method;
  int rendered = 0, skipped = 0, failed = 0, unfinished = 0;
  double seconds = 0.0;
};

void print_summary(const std::vector<SummaryRow>& rows, double total_seconds) {
  SummaryRow total{"total", ""};
  std::fprintf(stderr, "%-28s %-16s %8s %8s %8s %10s %9s\n", "scene", "method", "rendered", "skipped", "failed",
               "unfinished", "time (s)");
  for (const SummaryRow& row : rows) {
    std::fprintf(stderr, "%-28s %-16s %8d %8d %8d %10d %9.2f\n", row.scene.c_str(), row.method.c_str(), row.rendered,
                 row.skipped, row.failed, row.unfinished, row.seconds);
    total.rendered += row.rendered;
    total.skipped += row.skipped;
    total.failed += row.failed;
    total.unfinished += row.unfinished;
  }
  std::fprintf(stderr, "%-28s %-16s %8d %8d %8d %10d %9.2f\n", "total", "", total.rendered, total.skipped, total.failed,
               total.unfinished, total_seconds);
}

int merge_shards(const fs::path& manifest_path) {
  const std::vector<fs::path> shards = batch::find_shard_manifests(manifest_path);
  if (shards.empty())
    throw Error("--merge: no shard manifests " + manifest_path.stem().string() + ".shard-I-of-N.json beside " +
                manifest_path.string());
  Manifest merged = batch::read_manifest(manifest_path);
  for (const fs::path& shard : shards) batch::merge_manifest(merged, batch::read_manifest(shard));
  batch::write_manifest(manifest_path, merged);
  std::cerr << "facet: merged " << shards.size() << " shard manifests into " << manifest_path.string() << " ("
            << merged.size() << " outputs)\n";
  return 0;
}

int run_batch(const BatchCommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const batch::Job job = batch::load_job(options.job);
  const fs::path root = options.out_dir.empty() ? job.file.parent_path() : options.out_dir;
  const fs::path manifest_path = root / job.manifest;
  if (options.merge) return merge_shards(manifest_path);
  const batch::Shard shard = batch::Shard::parse(options.shard);

  // Every shard loads every scene, so all derive the same item list.
  std::vector<LoadedScene> scenes;
  std::vector<int> frame_counts;
  for (const fs::path& file : job.scenes) {
    scenes.push_back(load(file));
    frame_counts.push_back(scenes.back().scene ? frame_count(*scenes.back().scene) : 1);
  }
  const std::vector<Item> items = batch::expand_items(job, frame_counts);

  // Plan: an owned item is skipped if this shard's manifest, or the merged one, has it up to date.
  const fs::path own_path = shard.whole() ? manifest_path : batch::shard_manifest_path(manifest_path, shard);
  Manifest own = batch::read_manifest(own_path);
  const Manifest merged = shard.whole() ? Manifest{} : batch::read_manifest(manifest_path);
  std::vector<SummaryRow> rows;
  std::map<std::pair<size_t, std::string>, size_t> row_of;  // (scene, method) -> row
  std::vector<size_t> pending;
  std::vector<std::string> inputs_hashes(items.size());
  for (size_t i = 0; i < items.size(); ++i) {
    if (!shard.owns(i)) continue;
    const Item& item = items[i];
    const auto [row, fresh] = row_of.emplace(std::pair(item.scene, item.method), rows.size());
    if (fresh) rows.push_back({job.scenes[item.scene].stem().string(), item.method});
    const LoadedScene& scene = scenes[item.scene];
    if (scene.scene) inputs_hashes[i] = batch::item_inputs_hash(scene.files_hash, job, item, FACET_VERSION);
    const ManifestEntry* done = up_to_date(own, item, inputs_hashes[i], root);
    if (!done) done = up_to_date(merged, item, inputs_hashes[i], root);
    if (done) {
      own[item.output] = *done;
      ++rows[row->second].skipped;
    } else {
      pending.push_back(i);
    }
  }
  batch::write_manifest(own_path, own);

  // Set by SIGINT/SIGTERM: the batch stops after the current GPU frame (or abandons the current
  // reference frame between tiles), with every finished output in the manifest.
  const std::atomic<bool>& stop_requested = stop_on_interrupt();
  SharedDevice device(options.device);
  ProgressBar progress("batch", static_cast<int64_t>(pending.size()));
  const bool interactive = ::isatty(STDERR_FILENO) != 0;
  const auto render_start = std::chrono::steady_clock::now();
  size_t next = 0;
  while (next < pending.size() && !stop_requested) {
    // The pending items of one scene and method are consecutive: one renderer serves them all.
    const Item& first = items[pending[next]];
    size_t end = next;
    while (end < pending.size() && items[pending[end]].scene == first.scene && items[pending[end]].method == first.method)
      ++end;
    SummaryRow& row = rows[row_of.at({first.scene, first.method})];
    const LoadedScene& scene = scenes[first.scene];
    const auto setup_start = std::chrono::steady_clock::now();  // the precomputation counts for the group
    std::unique_ptr<BatchRenderer> renderer;
    std::string group_error = scene.error;
    if (scene.scene) {
      try {
        renderer = std::make_unique<BatchRenderer>(*scene.scene, first.method, job, device, &stop_requested);
      } catch (const std::exception& e) {
        group_error = e.what();
      }
    }
    row.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_start).count();
    for (; next < end && !stop_requested; ++next) {
      const size_t i = pending[next];
      const Item& item = items[i];
      const auto item_start = std::chrono::steady_clock::now();
      try {
        if (!renderer) throw Error(group_error);
        const RenderedFrame frame = renderer->render(item.frame);
        const OutputOptions output{root / item.output, job.pixel_type, job.exposure, job.preview};
        write_frame(output, frame.image, frame.metadata);
        ManifestEntry entry{job.scenes[item.scene].string(), item.method, item.frame, inputs_hashes[i], {}, 0.0};
        entry.files[item.output] = batch::file_hash(output.path);
        if (job.preview) {
          const std::string preview = fs::path(item.output).replace_extension(".png").string();
          entry.files[preview] = batch::file_hash(root / preview);
        }
        entry.render_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - item_start).count();
        own[item.output] = entry;
        batch::write_manifest(own_path, own);
        ++row.rendered;
      } catch (const std::exception& e) {
        if (stop_requested) break;  // abandoned, not failed: the next run renders it
        own.erase(item.output);
        batch::write_manifest(own_path, own);
        ++row.failed;
        std::cerr << "\nfacet: batch: " << item.output << " (" << job.scenes[item.scene].string() << ", "
                  << item.method << ", frame " << item.frame << ") failed: " << e.what() << "\n";
      }
      row.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - item_start).count();
      progress.update(static_cast<int64_t>(next + 1));
      // Logs (Slurm, kubectl logs) get one line per item, as the bar does not draw there.
      if (!interactive)
        std::cerr << format_progress(item.output, static_cast<int64_t>(next + 1), static_cast<int64_t>(pending.size()),
                                     std::chrono::duration<double>(std::chrono::steady_clock::now() - render_start).count())
                  << "\n";
    }
  }
  for (; next < pending.size(); ++next) ++rows[row_of.at({items[pending[next]].scene, items[pending[next]].method})].unfinished;
  if (!stop_requested && !pending.empty()) progress.finish();

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << "facet: batch " << job.file.string() << (shard.whole() ? "" : " shard " + options.shard) << ": "
            << items.size() << " items in the job\n";
  print_summary(rows, seconds);
  int failed = 0, unfinished = 0;
  for (const SummaryRow& row : rows) {
    failed += row.failed;
    unfinished += row.unfinished;
  }
  if (stop_requested)
    throw Error("interrupted: " + std::to_string(unfinished) + " items unfinished, every finished one is in " +
                own_path.string() + "; run again to continue");
  if (failed > 0) throw Error(std::to_string(failed) + " items failed (listed above); the others are done");
  return 0;
}

}  // namespace

void add_batch_command(CLI::App& app, Action& action) {
  auto* command = app.add_subcommand("batch", "Render every scene x method x frame of a job file, resumably");
  auto options = std::make_shared<BatchCommandOptions>();
  command->add_option("job", options->job, "Job file (JSON, see docs/batch.md)")->required();
  command->add_option("--shard", options->shard, "I/N: render only shard I (0-based) of N (Slurm arrays, k8s Indexed Jobs)")
      ->capture_default_str();
  command->add_flag("--merge", options->merge, "Merge the shard manifests into the job's manifest, then exit");
  command->add_option("--out-dir", options->out_dir,
                      "Root of the job's relative output and manifest paths (default: the job file's directory)");
  add_device_options(*command, options->device);
  command->callback([&action, options] { action = [options] { return run_batch(*options); }; });
}

}  // namespace facet::cli
