// facet eval visible-slope: the visible slope Gaussian of N(s̄, Σ) seen from (θ, φ)
// (shaders/lib/visible_slope.glsl; derivation in docs/visible_slope.md).
//   in:  {"sx", "sy", "vx", "vy", "cxy", "theta", "phi", "id"?}
//   out: {"id", "N", "log_N", "mean": [sx, sy], "cov": [vx, vy, cxy]}
#include <cmath>
#include <iostream>
#include <memory>

#include "cli/eval_command.hpp"
#include "cli/json_lines.hpp"
#include "eval_visible_slope.spv.h"
#include "kernels/shared.hpp"

namespace facet::cli {

namespace {

struct SlopeQuery {
  glm::dvec2 mean;
  glm::dvec3 cov;  // var_x, var_y, c_xy
  double theta, phi;
};

SlopeQuery parse_slope_query(const nlohmann::json& line) {
  SlopeQuery q;
  q.mean = {require_number(line, "sx"), require_number(line, "sy")};
  q.cov = {require_number(line, "vx"), require_number(line, "vy"), require_number(line, "cxy")};
  q.theta = require_number(line, "theta");
  q.phi = require_number(line, "phi");
  for (double v : {q.mean.x, q.mean.y, q.cov.x, q.cov.y, q.cov.z, q.theta, q.phi})
    if (!std::isfinite(v)) throw Error("every value must be finite");
  if (!(q.cov.x > 0.0 && q.cov.y > 0.0 && q.cov.x * q.cov.y - q.cov.z * q.cov.z > 0.0))
    throw Error("the covariance [[vx, cxy], [cxy, vy]] must be positive definite");
  if (!(q.theta >= 0.0 && q.theta < M_PI / 2)) throw Error("theta must lie in [0, pi/2)");
  return q;
}

nlohmann::json slope_answer(double N, double log_N, glm::dvec2 mean, glm::dvec3 cov) {
  return {{"N", N}, {"log_N", log_N}, {"mean", {mean.x, mean.y}}, {"cov", {cov.x, cov.y, cov.z}}};
}

std::vector<nlohmann::json> evaluate_cpu(const std::vector<SlopeQuery>& queries) {
  std::vector<nlohmann::json> answers;
  for (const auto& q : queries) {
    auto v = kernels::f64::visible_slope(q.mean, q.cov, q.theta, q.phi);
    answers.push_back(slope_answer(v.N, v.log_N, v.mean, v.cov));
  }
  return answers;
}

std::vector<nlohmann::json> evaluate_gpu(const EvalOptions& options, const std::vector<SlopeQuery>& queries) {
  std::vector<gpu::EvalRecord> records;
  for (const auto& q : queries)
    records.push_back({glm::vec4(q.mean.x, q.mean.y, q.cov.x, q.cov.y), glm::vec4(q.cov.z, q.theta, q.phi, 0.0)});
  auto results = run_gpu_eval(options, "eval_visible_slope", eval_visible_slope_spv, records);
  std::vector<nlohmann::json> answers;
  for (const auto& r : results) answers.push_back(slope_answer(r.a.x, r.a.y, {r.a.z, r.a.w}, {r.b.x, r.b.y, r.b.z}));
  return answers;
}

}  // namespace

void add_eval_visible_slope(CLI::App& eval, Action& action) {
  auto* command = eval.add_subcommand(
      "visible-slope", "Visible slope Gaussian: lines {sx, sy, vx, vy, cxy, theta, phi[, id]} -> {id, N, mean, cov}");
  auto options = std::make_shared<EvalOptions>();
  add_eval_options(*command, *options);
  command->callback([&action, options] {
    action = [options] {
      run_json_lines<SlopeQuery>(std::cin, std::cout, parse_slope_query, [&](const std::vector<SlopeQuery>& q) {
        return options->device == "gpu" ? evaluate_gpu(*options, q) : evaluate_cpu(q);
      });
      return 0;
    };
  });
}

}  // namespace facet::cli
