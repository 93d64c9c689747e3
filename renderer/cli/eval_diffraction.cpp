// facet eval diffraction: Stam's diffraction BRDF of a grating (renderer/diffraction,
// shaders/lib/diffraction_brdf.glsl; derivation in docs/diffraction.md).
//   --grating JSON_OR_FILE   the grating (renderer/scene/grating/grating.hpp lists the keys)
//   in:  {"wi": [x, y, z], "wr": [x, y, z], "lambda_nm", "id"?}   (unit vectors, surface frame, z up)
//   out: {"id", "brdf", "P2"}
// The tables are built for the smallest wavelength and largest |w| among the input lines; a line
// that makes them impossible gets its own error and the others are answered.
// --exact (CPU only) evaluates the DFT of exp(i k w h) itself instead of the Taylor sum.
#include <algorithm>
#include <iostream>
#include <memory>

#include "cli/eval_command.hpp"
#include "cli/json_lines.hpp"
#include "common/counted.hpp"
#include "diffraction/exact_transform.hpp"
#include "gpu/diffraction_eval.hpp"
#include "scene/grating/grating.hpp"

namespace facet::cli {

namespace {

using diffraction::DiffractionQuery;
using diffraction::DiffractionResult;

glm::dvec3 require_direction(const nlohmann::json& line, const std::string& key) {
  auto it = line.find(key);
  if (it == line.end()) throw Error("missing key '" + key + "'");
  if (!it->is_array() || it->size() != 3 || !(*it)[0].is_number() || !(*it)[1].is_number() || !(*it)[2].is_number())
    throw Error("'" + key + "' must be an array of 3 numbers");
  return {(*it)[0].get<double>(), (*it)[1].get<double>(), (*it)[2].get<double>()};
}

DiffractionQuery parse_diffraction_query(const nlohmann::json& line) {
  DiffractionQuery q{require_direction(line, "wi"), require_direction(line, "wr"), require_number(line, "lambda_nm")};
  diffraction::validate_query(q);
  return q;
}

// Tables covering exactly the wavelengths and directions asked for.
diffraction::SpectralTables tables_for(const diffraction::Grating& grating, const std::vector<DiffractionQuery>& qs) {
  diffraction::TableRange range;
  range.lambda_min_nm = range.lambda_max_nm = qs.front().lambda_nm;
  range.w_max = 0.0;
  for (const auto& q : qs) {
    range.lambda_min_nm = std::min(range.lambda_min_nm, q.lambda_nm);
    range.lambda_max_nm = std::max(range.lambda_max_nm, q.lambda_nm);
    range.w_max = std::max(range.w_max, q.wi.z + q.wr.z);
  }
  range.w_max = std::clamp(range.w_max, 1e-9, 2.0);
  return diffraction::build_spectral_tables(grating, range);
}

std::vector<nlohmann::json> answers(const std::vector<DiffractionResult>& results) {
  std::vector<nlohmann::json> out;
  for (const auto& r : results) out.push_back({{"brdf", r.brdf}, {"P2", r.P2}});
  return out;
}

struct DiffractionOptions {
  EvalOptions eval;
  std::string grating;
  bool exact = false;
};

std::vector<nlohmann::json> evaluate(const DiffractionOptions& options, const diffraction::Grating& grating,
                                     const std::vector<DiffractionQuery>& qs) {
  const diffraction::SpectralTables tables = tables_for(grating, qs);
  std::vector<DiffractionResult> results;
  if (options.eval.device == "gpu") {
    vk::Context context({options.eval.vulkan.device, options.eval.vulkan.validation});
    results = gpu::evaluate_diffraction(context, tables, qs);
    if (context.validation_message_count() > 0)
      throw Error("Vulkan validation reported " + counted(context.validation_message_count(), "message"));
  } else if (options.exact) {
    const diffraction::ExactTransform exact(grating, tables);
    for (const auto& q : qs) results.push_back(exact.evaluate(q));
  } else {
    for (const auto& q : qs) results.push_back(diffraction::evaluate_taylor(tables, q));
  }
  return answers(results);
}

// One batch shares one table set; when the batch's extremes make it impossible (an absurd
// wavelength or a grating too high for the Taylor bound), each line is answered on its own, so
// only the offending lines get {"error": ...}.
std::vector<nlohmann::json> evaluate_lines(const DiffractionOptions& options, const diffraction::Grating& grating,
                                           const std::vector<DiffractionQuery>& qs) {
  try {
    return evaluate(options, grating, qs);
  } catch (const Error&) {
    if (qs.size() == 1) throw;
  }
  std::vector<nlohmann::json> out;
  for (const DiffractionQuery& q : qs) {
    try {
      out.push_back(evaluate(options, grating, {q}).front());
    } catch (const Error& e) {
      out.push_back({{"error", e.what()}});
    }
  }
  return out;
}

}  // namespace

void add_eval_diffraction(CLI::App& eval, Action& action) {
  auto* command =
      eval.add_subcommand("diffraction", "Stam's diffraction BRDF: lines {wi, wr, lambda_nm[, id]} -> {id, brdf, P2}");
  auto options = std::make_shared<DiffractionOptions>();
  add_eval_options(*command, options->eval);
  command->add_option("--grating", options->grating, "The grating: inline JSON or a JSON file")->required();
  command->add_flag("--exact", options->exact, "CPU only: the exact transform instead of the Taylor tables");
  command->callback([&action, options] {
    action = [options] {
      if (options->exact && options->eval.device == "gpu") throw Error("--exact runs on the CPU only");
      // A bad grating fails before any line is read.
      const diffraction::Grating grating = diffraction::parse_grating(options->grating);
      run_json_lines<DiffractionQuery>(
          std::cin, std::cout, parse_diffraction_query,
          [&](const std::vector<DiffractionQuery>& qs) { return evaluate_lines(*options, grating, qs); });
      return 0;
    };
  });
}

}  // namespace facet::cli
