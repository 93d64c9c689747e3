// facet eval cross-section: sigma(u) = integral of D(m) max(0, m.w) dm of a normal distribution
// (shaders/lib/cross_section.glsl, renderer/kernels/cross_section_exact.hpp, docs/cross_sections.md).
//   in:  {"ndf": "beckmann"|"ggx"|"kk"|"sg", "param": alpha or b, "u": cos theta_i in [-1, 1], "id"?}
//   out: {"id", "sigma"}
// --method exact (CPU only): closed forms in double, quadrature for the spherical Gaussian;
// --method fast: the float kernels the GPU runs (on the CPU twin or, with --device gpu, the GPU).
#include <cmath>
#include <iostream>
#include <memory>

#include "cli/eval_command.hpp"
#include "cli/json_lines.hpp"
#include "eval_cross_section.spv.h"
#include "kernels/cross_section_exact.hpp"

namespace facet::cli {

namespace {

struct CrossSectionQuery {
  int ndf;
  double param;
  double u;
};

// Parameter ranges: alpha of Beckmann, GGX and the spherical Gaussian in [1e-3, 1e3] (the
// validated domain of docs/cross_sections.md); b of Kagiwada-Kalaba in (0, 1).
CrossSectionQuery parse_query(const nlohmann::json& line) {
  auto it = line.find("ndf");
  if (it == line.end()) throw Error("missing key 'ndf'");
  if (!it->is_string()) throw Error("'ndf' must be one of beckmann, ggx, kk, sg");
  const std::string name = it->get<std::string>();
  const char* names[] = {"beckmann", "ggx", "kk", "sg"};
  CrossSectionQuery q{-1, require_number(line, "param"), require_number(line, "u")};
  for (int i = 0; i < 4; ++i)
    if (name == names[i]) q.ndf = i;
  if (q.ndf < 0) throw Error("'ndf' must be one of beckmann, ggx, kk, sg, got '" + name + "'");
  if (!(q.u >= -1.0 && q.u <= 1.0)) throw Error("'u' must lie in [-1, 1]");
  if (q.ndf == 2) {
    if (!(q.param > 0.0 && q.param < 1.0)) throw Error("'param' (b) of kk must lie in (0, 1)");
  } else if (!(q.param >= 1e-3 && q.param <= 1e3)) {
    throw Error("'param' (alpha) must lie in [1e-3, 1e3]");
  }
  return q;
}

}  // namespace

void add_eval_cross_section(CLI::App& eval, Action& action) {
  auto* command = eval.add_subcommand("cross-section",
                                      "Cross-section sigma(u) of an NDF: lines {ndf, param, u[, id]} -> {id, sigma}");
  auto options = std::make_shared<EvalOptions>();
  auto method = std::make_shared<std::string>("exact");
  add_eval_options(*command, *options);
  command->add_option("--method", *method, "exact: double closed forms / quadrature (CPU); fast: the GPU kernels")
      ->check(CLI::IsMember({"exact", "fast"}))
      ->capture_default_str();
  command->callback([&action, options, method] {
    action = [options, method] {
      if (options->device == "gpu" && *method == "exact")
        throw Error("--method exact runs on the CPU only; use --device cpu, or --method fast on the GPU");
      run_json_lines<CrossSectionQuery>(
          std::cin, std::cout, parse_query, [&](const std::vector<CrossSectionQuery>& queries) {
            std::vector<nlohmann::json> answers;
            if (options->device == "gpu") {
              std::vector<gpu::EvalRecord> records;
              for (const auto& q : queries) records.push_back({glm::vec4(q.ndf, q.param, q.u, 0), glm::vec4(0)});
              for (const auto& r : run_gpu_eval(*options, "eval_cross_section", eval_cross_section_spv, records))
                answers.push_back({{"sigma", r.a.x}});
            } else {
              for (const auto& q : queries)
                answers.push_back({{"sigma", kernels::cross_section(q.ndf, q.param, q.u, *method == "exact")}});
            }
            return answers;
          });
      return 0;
    };
  });
}

}  // namespace facet::cli
