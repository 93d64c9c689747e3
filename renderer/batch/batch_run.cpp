#include "batch/batch_run.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "batch/batch_summary.hpp"
#include "batch/input_hash.hpp"
#include "batch/items.hpp"
#include "batch/job.hpp"
#include "batch/manifest.hpp"
#include "common/counted.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "common/progress.hpp"
#include "frames/frame_file.hpp"
#include "frames/prepared_frames.hpp"
#include "scene/camera_path.hpp"
#include "scene/scene_loader.hpp"

namespace facet::batch {

namespace {

namespace fs = std::filesystem;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct LoadedScene {
  std::optional<Scene> scene;
  std::string error;       // why it failed to load or hash
  std::string files_hash;  // the scene file and every file it references
};

LoadedScene load(const fs::path& file, const std::vector<std::string>& overrides) {
  LoadedScene loaded;
  try {
    loaded.scene = load_scene(file, overrides);
    loaded.files_hash = scene_files_hash(file, overrides);
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
    if (file_hash(root / file) != hash) return nullptr;
  return &it->second;
}

int merge_shards(const fs::path& manifest_path) {
  const std::vector<fs::path> shards = find_shard_manifests(manifest_path);
  if (shards.empty())
    throw Error("--merge: no shard manifests " + manifest_path.stem().string() + ".shard-I-of-N.json beside " +
                manifest_path.string());
  Manifest merged = read_manifest(manifest_path);
  for (const fs::path& shard : shards) merge_manifest(merged, read_manifest(shard));
  write_manifest(manifest_path, merged);
  std::cerr << "facet: merged " << counted(std::ssize(shards), "shard manifest") << " into " << manifest_path.string()
            << " (" << counted(std::ssize(merged), "output") << ")\n";
  return 0;
}

// One Vulkan device for the whole batch, created on first use (a batch of reference frames, or one
// with nothing left to do, never touches Vulkan).
class SharedDevice {
 public:
  explicit SharedDevice(vk::ContextOptions options) : options_(std::move(options)) {}
  vk::Context& context() {
    if (!context_) context_ = std::make_unique<vk::Context>(options_);
    return *context_;
  }

 private:
  vk::ContextOptions options_;
  std::unique_ptr<vk::Context> context_;
};

// What this shard does: the job's items, its own manifest (up-to-date items carried over), the rest pending.
struct ShardPlan {
  std::vector<Item> items;
  std::vector<std::string> inputs_hashes;  // per item; empty where the scene did not load
  fs::path manifest_path;                  // this shard's
  Manifest manifest;
  std::vector<size_t> pending;  // indices into `items`; the items of one scene and method are consecutive
  std::vector<SummaryRow> rows;
  std::map<std::pair<size_t, std::string>, size_t> row_of;  // (scene, method) -> row
  SummaryRow& row(const Item& item) { return rows[row_of.at({item.scene, item.method})]; }
};

// An owned item is skipped if this shard's manifest, or the merged one, has it up to date.
ShardPlan plan_shard(const Job& job, const Shard& shard, const std::vector<LoadedScene>& scenes, const fs::path& root,
                     const fs::path& manifest_path, const std::string& facet_version) {
  ShardPlan plan;
  std::vector<int> frame_counts;
  for (const LoadedScene& scene : scenes) frame_counts.push_back(scene.scene ? frame_count(*scene.scene) : 1);
  plan.items = expand_items(job, frame_counts);
  plan.inputs_hashes.resize(plan.items.size());
  plan.manifest_path = shard.whole() ? manifest_path : shard_manifest_path(manifest_path, shard);
  plan.manifest = read_manifest(plan.manifest_path);
  const Manifest merged = shard.whole() ? Manifest{} : read_manifest(manifest_path);
  for (size_t i = 0; i < plan.items.size(); ++i) {
    if (!shard.owns(i)) continue;
    const Item& item = plan.items[i];
    const auto [row, fresh] = plan.row_of.emplace(std::pair(item.scene, item.method), plan.rows.size());
    if (fresh) plan.rows.push_back({job.scenes[item.scene].stem().string(), item.method});
    const LoadedScene& scene = scenes[item.scene];
    if (scene.scene) plan.inputs_hashes[i] = item_inputs_hash(scene.files_hash, job, item, facet_version);
    const ManifestEntry* done = up_to_date(plan.manifest, item, plan.inputs_hashes[i], root);
    if (!done) done = up_to_date(merged, item, plan.inputs_hashes[i], root);
    if (done) {
      plan.manifest[item.output] = *done;
      ++plan.rows[row->second].skipped;
    } else {
      plan.pending.push_back(i);
    }
  }
  return plan;
}

// `method` of the job ("reference" is the CPU reference with the job's grid and seed) prepared for
// `scene` with the job's AOVs (`error` only where the method estimates it: the `filtered` family);
// null with `error` set when that fails, so each of the group's items fails with it.
std::unique_ptr<frames::PreparedFrames> prepare_group(const LoadedScene& scene, const std::string& method,
                                                      const Job& job, SharedDevice& device, std::string& error) {
  error = scene.error;
  if (!scene.scene) return nullptr;
  try {
    AovSet aovs = job.aovs;
    if (method == "reference") {
      aovs.error = false;
      return std::make_unique<frames::PreparedFrames>(
          *scene.scene, frames::ReferenceMethod{job.grid, job.seed, 0, aovs}, nullptr);
    }
    gpu::RenderMethod parsed = gpu::RenderMethod::parse(method);  // before the device: a typo needs no Vulkan
    aovs.error = aovs.error && parsed.estimates_error();
    parsed.aovs = aovs;
    return std::make_unique<frames::PreparedFrames>(*scene.scene, parsed, &device.context());
  } catch (const std::exception& e) {
    error = e.what();
    return nullptr;
  }
}

// Renders and writes one item; its manifest entry lists the EXR and the preview with their hashes.
ManifestEntry render_item(frames::PreparedFrames& prepared, const Scene& scene, const Job& job, const Item& item,
                          const std::string& inputs_hash, const fs::path& root, const std::atomic<bool>& cancel) {
  const auto start = std::chrono::steady_clock::now();
  const Camera camera = camera_at(scene, item.frame);
  const auto [width, height] = frames::frame_size(camera, job.width, job.height);
  frames::FrameRequest request;
  request.frame = item.frame;
  request.timings = false;   // the manifest has them; the files stay reproducible
  request.cancel = &cancel;  // a reference frame is abandoned between tiles
  const frames::Frame frame = prepared.render(camera, width, height, request);
  const frames::FrameFile file{root / item.output, job.pixel_type, job.exposure, job.preview};
  frames::write_frame(file, frame.image, frame.metadata);
  ManifestEntry entry{job.scenes[item.scene].string(), item.method, item.frame, inputs_hash, {}, 0.0,
                      job.scene_overrides};
  entry.files[item.output] = file_hash(file.path);
  if (job.preview) {
    const std::string preview = fs::path(item.output).replace_extension(".png").string();
    entry.files[preview] = file_hash(root / preview);
  }
  entry.render_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return entry;
}

// Renders the pending items group by group (one scene and method: prepared once), writing the
// manifest after each; stops early when `stop_requested` is set.
void render_pending(const Job& job, const fs::path& root, const std::vector<LoadedScene>& scenes, ShardPlan& plan,
                    SharedDevice& device, const std::atomic<bool>& stop_requested) {
  const std::vector<size_t>& pending = plan.pending;
  ProgressBar progress("batch", static_cast<int64_t>(pending.size()));
  const bool interactive = ::isatty(STDERR_FILENO) != 0;
  const auto render_start = std::chrono::steady_clock::now();
  size_t next = 0;
  while (next < pending.size() && !stop_requested) {
    const Item& first = plan.items[pending[next]];
    size_t end = next;
    while (end < pending.size() && plan.items[pending[end]].scene == first.scene &&
           plan.items[pending[end]].method == first.method)
      ++end;
    SummaryRow& row = plan.row(first);
    const LoadedScene& scene = scenes[first.scene];
    const auto setup_start = std::chrono::steady_clock::now();  // the preparation counts for the group
    std::string group_error;
    const std::unique_ptr<frames::PreparedFrames> prepared =
        prepare_group(scene, first.method, job, device, group_error);
    row.seconds += seconds_since(setup_start);
    for (; next < end && !stop_requested; ++next) {
      const size_t i = pending[next];
      const Item& item = plan.items[i];
      const auto item_start = std::chrono::steady_clock::now();
      try {
        if (!prepared) throw Error(group_error);
        plan.manifest[item.output] =
            render_item(*prepared, *scene.scene, job, item, plan.inputs_hashes[i], root, stop_requested);
        write_manifest(plan.manifest_path, plan.manifest);
        ++row.rendered;
      } catch (const std::exception& e) {
        if (stop_requested) break;  // abandoned, not failed: the next run renders it
        plan.manifest.erase(item.output);
        write_manifest(plan.manifest_path, plan.manifest);
        ++row.failed;
        std::cerr << "\nfacet: batch: " << item.output << " (" << job.scenes[item.scene].string() << ", " << item.method
                  << ", frame " << item.frame << ") failed: " << e.what() << "\n";
      }
      row.seconds += seconds_since(item_start);
      progress.update(static_cast<int64_t>(next + 1));
      // Logs (Slurm, kubectl logs) get one line per item, as the bar does not draw there.
      if (!interactive)
        std::cerr << format_progress(item.output, static_cast<int64_t>(next + 1), static_cast<int64_t>(pending.size()),
                                     seconds_since(render_start))
                  << "\n";
    }
  }
  for (; next < pending.size(); ++next) ++plan.row(plan.items[pending[next]]).unfinished;
  if (!stop_requested && !pending.empty()) progress.finish();
}

}  // namespace

int run_batch(const BatchOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Job job = load_job(options.job, options.overrides);
  const fs::path root = options.out_dir.empty() ? job.file.parent_path() : options.out_dir;
  const fs::path manifest_path = root / job.manifest;
  if (options.merge) return merge_shards(manifest_path);
  const Shard shard = Shard::parse(options.shard);

  // Every shard loads every scene, so all derive the same item list.
  std::vector<LoadedScene> scenes;
  for (const fs::path& file : job.scenes) scenes.push_back(load(file, job.scene_overrides));
  ShardPlan plan = plan_shard(job, shard, scenes, root, manifest_path, options.facet_version);
  write_manifest(plan.manifest_path, plan.manifest);

  // Set by SIGINT/SIGTERM: the batch stops after the current GPU frame (or abandons the current
  // reference frame between tiles), with every finished output in the manifest.
  const std::atomic<bool>& stop_requested = stop_on_interrupt();
  SharedDevice device(options.device);
  render_pending(job, root, scenes, plan, device, stop_requested);

  std::cerr << "facet: batch " << job.file.string() << (shard.whole() ? "" : " shard " + options.shard) << ": "
            << counted(std::ssize(plan.items), "item") << " in the job\n";
  print_summary(plan.rows, seconds_since(start));
  int failed = 0, unfinished = 0;
  for (const SummaryRow& row : plan.rows) {
    failed += row.failed;
    unfinished += row.unfinished;
  }
  if (stop_requested)
    throw Error("interrupted: " + counted(unfinished, "item") + " unfinished, every finished one is in " +
                plan.manifest_path.string() + "; run again to continue");
  if (failed > 0) throw Error(counted(failed, "item") + " failed (listed above); the others are done");
  return 0;
}

}  // namespace facet::batch
