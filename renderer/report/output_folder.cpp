#include "report/output_folder.hpp"

#include <algorithm>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "report/report_files.hpp"

namespace facet::report {

namespace fs = std::filesystem;

namespace {

const std::set<std::string> kReportFiles = {"results.json", "run.json", "report.md", "index.html"};

// The scene folders a previous report's run.json names; refuses a run.json no report of a known
// schema wrote (one without `schema` predates it and has the layout of schema 1).
std::set<std::string> previous_scenes(const fs::path& run_json) {
  std::set<std::string> scenes;
  if (!fs::exists(run_json)) return scenes;
  nlohmann::json run;
  try {
    run = nlohmann::json::parse(std::ifstream(run_json));
  } catch (const nlohmann::json::exception&) {
    throw Error("--out: " + run_json.string() + " is not a facet bench run.json; choose an empty or new folder");
  }
  const int schema =
      run.is_object() && run.contains("schema") && run["schema"].is_number_integer() ? run["schema"].get<int>() : 0;
  if (schema > kReportSchema || !run.is_object() || !run.contains("scenes") || !run["scenes"].is_array())
    throw Error("--out: " + run_json.string() + " is a report of schema " + std::to_string(schema) +
                ", which this facet (schema " + std::to_string(kReportSchema) +
                ") does not read; choose an empty or new folder");
  for (const nlohmann::json& scene : run["scenes"])
    if (scene.is_object() && scene.contains("scene") && scene["scene"].is_string())
      scenes.insert(scene["scene"].get<std::string>());
  return scenes;
}

bool only_pictures(const fs::path& folder) {
  return std::all_of(fs::directory_iterator(folder), fs::directory_iterator(), [](const fs::directory_entry& e) {
    return e.is_regular_file() && (e.path().extension() == ".png" || e.path().extension() == ".svg");
  });
}

}  // namespace

void prepare_output_folder(const fs::path& out, const std::vector<std::string>& scenes) {
  std::error_code error;
  if (!fs::exists(out, error)) return;
  if (!fs::is_directory(out)) throw Error("--out: " + out.string() + " is not a folder");
  std::set<std::string> scene_folders = previous_scenes(out / "run.json");
  scene_folders.insert(scenes.begin(), scenes.end());
  std::vector<fs::path> to_remove;
  for (const fs::directory_entry& entry : fs::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    if (name == "cache" && entry.is_directory()) continue;
    const bool report_file = kReportFiles.count(name) && entry.is_regular_file();
    const bool scene_folder = scene_folders.count(name) && entry.is_directory() && only_pictures(entry.path());
    if (!report_file && !scene_folder)
      throw Error("--out: " + entry.path().string() +
                  " was not written by facet bench; choose an empty or new folder, or remove it");
    to_remove.push_back(entry.path());
  }
  for (const fs::path& path : to_remove) fs::remove_all(path);
}

}  // namespace facet::report
