#include "batch/items.hpp"

#include <cstdio>
#include <cstdlib>
#include <map>

#include "common/error.hpp"

namespace facet::batch {

namespace {

std::string file_safe(const std::string& text) {
  std::string safe = text;
  for (char& c : safe) {
    const bool keep =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
    if (!keep) c = '_';
  }
  return safe;
}

std::string padded(int value, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%0*d", digits, value);
  return text;
}

}  // namespace

std::string expand_output(const std::string& pattern, const std::string& scene, const std::string& method, int frame) {
  std::string out;
  for (size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '{') {
      out += pattern[i];
      continue;
    }
    const size_t close = pattern.find('}', i);
    if (close == std::string::npos) throw Error("output \"" + pattern + "\": unclosed '{'");
    const std::string name = pattern.substr(i + 1, close - i - 1);
    if (name == "scene") {
      out += scene;
    } else if (name == "method") {
      out += file_safe(method);
    } else if (name == "frame") {
      out += std::to_string(frame);
    } else if (name.size() == 8 && name.rfind("frame:0", 0) == 0 && name[7] >= '1' && name[7] <= '9') {
      out += padded(frame, name[7] - '0');
    } else {
      throw Error("output \"" + pattern + "\": unknown field {" + name +
                  "} (known: {scene}, {method}, {frame}, {frame:0N})");
    }
    i = close;
  }
  return out;
}

std::vector<Item> expand_items(const Job& job, const std::vector<int>& frame_counts) {
  std::vector<Item> items;
  std::map<std::string, size_t> writer;  // output -> item position
  for (size_t s = 0; s < job.scenes.size(); ++s) {
    std::vector<int> frames = job.frames.value_or(std::vector<int>{});
    if (!job.frames)
      for (int f = 0; f < frame_counts.at(s); ++f) frames.push_back(f);
    for (const std::string& method : job.methods) {
      for (int frame : frames) {
        Item item{s, method, frame, expand_output(job.output, job.scenes[s].stem().string(), method, frame)};
        const auto [it, fresh] = writer.emplace(item.output, items.size());
        if (!fresh) {
          const Item& other = items[it->second];
          throw Error(job.file.string() + ": output \"" + job.output + "\" gives " + item.output + " for both " +
                      job.scenes[other.scene].string() + " " + other.method + " frame " + std::to_string(other.frame) +
                      " and " + job.scenes[s].string() + " " + method + " frame " + std::to_string(frame) +
                      (job.output.find("{frame") == std::string::npos ? " (add {frame})" : ""));
        }
        items.push_back(std::move(item));
      }
    }
  }
  return items;
}

Shard Shard::parse(const std::string& text) {
  const size_t slash = text.find('/');
  const char* what = ": must be I/N with integers 0 <= I < N";
  if (slash == std::string::npos) throw Error("--shard " + text + what);
  const std::string i_text = text.substr(0, slash), n_text = text.substr(slash + 1);
  char* end_i = nullptr;
  char* end_n = nullptr;
  const long i = std::strtol(i_text.c_str(), &end_i, 10);
  const long n = std::strtol(n_text.c_str(), &end_n, 10);
  if (i_text.empty() || n_text.empty() || *end_i != '\0' || *end_n != '\0' || n < 1 || n > 100000 || i < 0 || i >= n)
    throw Error("--shard " + text + what);
  return {static_cast<int>(i), static_cast<int>(n)};
}

}  // namespace facet::batch
