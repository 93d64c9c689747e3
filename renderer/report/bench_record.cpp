#include "report/bench_record.hpp"

#include <algorithm>

namespace facet::report {

namespace {

// The ms of a frame's `per_pixel` operations at `per_second`, if both are measured.
std::optional<double> frame_ms_at(int width, int height, const std::optional<double>& per_pixel,
                                  const std::optional<double>& per_second) {
  if (!per_pixel || !per_second || !(*per_second > 0.0)) return std::nullopt;
  return 1e3 * static_cast<double>(width) * height * *per_pixel / *per_second;
}

}  // namespace

std::optional<double> BenchRecord::roofline_fma_ms() const {
  return frame_ms_at(width, height, work_fma_per_pixel, probe_fma_per_second);
}

std::optional<double> BenchRecord::roofline_reads_ms() const {
  return frame_ms_at(width, height, reads_per_pixel, probe_texel_reads_per_second);
}

std::optional<double> BenchRecord::roofline_ms() const {
  const std::optional<double> fma = roofline_fma_ms(), reads = roofline_reads_ms();
  if (fma && reads) return std::max(*fma, *reads);
  return fma ? fma : reads;
}

std::optional<double> BenchRecord::device_vs_roofline() const {
  const std::optional<double> limit = roofline_ms();
  if (!limit || !timing.has_gpu_time || !(*limit > 0.0)) return std::nullopt;
  return timing.gpu_ms.median / *limit;
}

nlohmann::json number_or_null(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json to_json(const BenchRecord& r) {
  nlohmann::json json = {{"scene", r.scene},   {"scene_file", r.scene_file}, {"set", r.overrides},
                         {"method", r.method}, {"width", r.width},           {"height", r.height},
                         {"device", r.device}, {"machine", r.machine},       {"facet_version", r.facet_version}};
  if (r.error) {
    json["error"] = *r.error;
    return json;
  }
  const Spread& headline = r.timing.headline();
  json["time_ms"] = headline.median;
  json["time_ms_min"] = headline.min;
  json["time_ms_max"] = headline.max;
  json["time_source"] = r.timing.has_gpu_time ? "gpu" : "wall";
  json["wall_ms"] = r.timing.wall_ms.median;
  json["wall_ms_min"] = r.timing.wall_ms.min;
  json["wall_ms_max"] = r.timing.wall_ms.max;
  json["gpu_ms"] = r.timing.has_gpu_time ? nlohmann::json(r.timing.gpu_ms.median) : nlohmann::json(nullptr);
  json["repeats"] = r.timing.repeats;
  json["prepare_ms"] = r.prepare_ms;
  json["phases"] = nlohmann::json::object();
  for (const Phase& phase : r.phases.phases()) json["phases"][phase.name] = phase.ms;
  json.update(facet::to_json(r.comparison));
  json["image"] = r.image;
  json["heatmap"] = r.heatmap;
  json["probe_fma_per_second"] = number_or_null(r.probe_fma_per_second);
  json["probe_texel_reads_per_second"] = number_or_null(r.probe_texel_reads_per_second);
  json["work_fma_per_pixel"] = number_or_null(r.work_fma_per_pixel);
  json["reads_per_pixel"] = number_or_null(r.reads_per_pixel);
  json["roofline_fma_ms"] = number_or_null(r.roofline_fma_ms());
  json["roofline_reads_ms"] = number_or_null(r.roofline_reads_ms());
  json["roofline_ms"] = number_or_null(r.roofline_ms());
  json["device_vs_roofline"] = number_or_null(r.device_vs_roofline());
  if (r.error_estimate) json.update(to_json(*r.error_estimate));
  if (r.path)
    json["path"] = {{"frames", r.path->frames},
                    {"rmse", r.path->rmse},
                    {"flip", r.path->flip},
                    {"rmse_jump_ratio", error_smoothness(r.path->rmse).jump_ratio()},
                    {"flip_jump_ratio", error_smoothness(r.path->flip).jump_ratio()}};
  return json;
}

}  // namespace facet::report
