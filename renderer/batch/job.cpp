#include "batch/job.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <set>

#include <nlohmann/json.hpp>

#include "batch/glob.hpp"
#include "batch/items.hpp"
#include "common/error.hpp"
#include "common/json_object_reader.hpp"
#include "common/json_overrides.hpp"
#include "scene/scene_loader.hpp"

namespace facet::batch {

namespace {

using Json = nlohmann::json;

std::vector<std::string> read_strings(JsonObjectReader& r, const std::string& key) {
  const Json& array = r.value(key);
  if (!array.is_array() || array.empty()) r.fail(key, "must be a non-empty array of strings");
  std::vector<std::string> strings;
  for (const Json& item : array) {
    if (!item.is_string() || item.get_ref<const std::string&>().empty())
      r.fail(key, "must be a non-empty array of strings");
    strings.push_back(item.get<std::string>());
  }
  return strings;
}

std::vector<int> read_frames(JsonObjectReader& r) {
  const Json& array = r.value("frames");
  const char* what = "must be a non-empty array of distinct integers >= 0";
  if (!array.is_array() || array.empty()) r.fail("frames", what);
  std::vector<int> frames;
  for (const Json& item : array) {
    if (!item.is_number_integer() || item.get<std::int64_t>() < 0 || item.get<std::int64_t>() > 1000000)
      r.fail("frames", what);
    frames.push_back(item.get<int>());
  }
  std::sort(frames.begin(), frames.end());
  if (std::adjacent_find(frames.begin(), frames.end()) != frames.end()) r.fail("frames", what);
  return frames;
}

// The top-level keys load_job reads; no scene has any of them.
bool is_job_key(const std::string& key) {
  static const std::set<std::string> keys{"scenes",     "methods",  "frames",   "output",    "width",   "height",
                                          "pixel_type", "preview", "exposure", "aov",       "reference", "manifest"};
  return keys.count(key) > 0;
}

void read_reference(JsonObjectReader r, Job& job) {
  job.grid = r.integer_in("grid", 1, 4096, job.grid);
  job.seed = r.integer_in("seed", 0, 2147483647, static_cast<int>(job.seed));
  r.finish();
}

}  // namespace

Job load_job(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::ifstream in(file, std::ios::binary);
  std::error_code error;
  if (!in || std::filesystem::is_directory(file, error)) throw Error(file.string() + ": cannot open for reading");
  Json document = Json::parse(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>(), nullptr, false);
  if (document.is_discarded()) throw Error(file.string() + ": invalid JSON");

  Job job;
  job.file = file;
  for (const std::string& assignment : overrides) {
    if (is_job_key(assignment.substr(0, assignment.find_first_of(".="))))
      apply_override(document, assignment, file.string());
    else
      job.scene_overrides.push_back(assignment);
  }
  JsonObjectReader r(document, file.string(), "");
  const std::filesystem::path base = file.parent_path();
  for (const std::string& pattern : read_strings(r, "scenes")) {
    try {
      for (const auto& scene : expand_glob(pattern, base))
        if (std::find(job.scenes.begin(), job.scenes.end(), scene) == job.scenes.end()) job.scenes.push_back(scene);
    } catch (const Error& e) {
      throw Error(file.string() + ": scenes: " + e.what());
    }
  }
  job.methods = read_strings(r, "methods");
  if (r.has("frames")) job.frames = read_frames(r);
  job.output = r.string("output");
  if (std::filesystem::path(job.output).extension() != ".exr")
    r.fail("output", "must be a path pattern ending in .exr");
  try {
    expand_output(job.output, "scene", "method", 0);
  } catch (const Error& e) {
    throw Error(file.string() + ": " + e.what());
  }
  job.width = r.integer_in("width", 1, kMaxImageSide, 0);
  job.height = r.integer_in("height", 1, kMaxImageSide, 0);
  job.pixel_type = r.string("pixel_type", job.pixel_type);
  if (job.pixel_type != "half" && job.pixel_type != "float") r.fail("pixel_type", "must be half or float");
  if (r.has("preview")) {
    if (!r.value("preview").is_boolean()) r.fail("preview", "must be true or false");
    job.preview = r.value("preview").get<bool>();
  }
  job.exposure = r.number("exposure", job.exposure);
  job.aov = r.string("aov", job.aov);
  try {
    job.aovs = parse_aovs(job.aov);
  } catch (const Error& e) {
    r.fail("aov", e.what());
  }
  if (r.has("reference")) read_reference(JsonObjectReader(r.value("reference"), file.string(), "reference"), job);
  job.manifest = r.string("manifest", file.stem().string() + ".manifest.json");
  if (job.manifest.empty() || job.manifest.extension() != ".json") r.fail("manifest", "must be a path ending in .json");
  r.finish();
  return job;
}

}  // namespace facet::batch
