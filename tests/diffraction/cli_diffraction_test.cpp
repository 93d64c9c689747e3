// `facet eval diffraction` as scripts see it: the JSON-lines contract, CPU / GPU / exact agreement
// on a first-order peak (|S| = J_1(k w a), see diffraction_brdf_test.cpp), and errors.
#include <gtest/gtest.h>

#include <boost/math/special_functions/bessel.hpp>
#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "support/facet_paths.hpp"
#include "support/run_command.hpp"

namespace facet {
namespace {

using test::run_command;

const std::string kGrating = R"('{"type":"sinusoid","period_nm":1300,"amplitude_nm":80,"size_um":26,"samples":320}')";

std::vector<nlohmann::json> parse_lines(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

TEST(EvalDiffractionCli, AnswersGoodLinesAndReportsBadOnes) {
  const double x_r = 500.0 / 1300.0, z_r = std::sqrt(1 - x_r * x_r);
  std::ostringstream input;
  input << R"({"id": "peak", "wi": [0, 0, 1], "wr": [)" << x_r << ", 0, " << z_r << R"(], "lambda_nm": 500})"
        << "\n"
        << "not json\n"
        << R"({"id": 2, "wi": [0, 0, 1], "wr": [0, 0, 1]})"
        << "\n"
        << R"({"id": 3, "wi": [0, 0, -1], "wr": [0, 0, 1], "lambda_nm": 500})"
        << "\n"
        << R"({"id": 4, "wi": [0, 0, 2], "wr": [0, 0, 1], "lambda_nm": 500})"
        << "\n"
        << R"({"id": 5, "wi": [0, 0], "wr": [0, 0, 1], "lambda_nm": 500})"
        << "\n";
  const double w = -(1 + z_r), sigma = 26000.0;
  const double J1 = std::abs(boost::math::cyl_bessel_j(1, 2 * M_PI / 500 * w * 80));
  for (const char* device : {"cpu", "gpu", "cpu --exact"}) {
    auto r = run_command(kFacet + " eval diffraction --grating " + kGrating + " --device " + std::string(device),
                         input.str());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto lines = parse_lines(r.out);
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[0]["id"], "peak");
    const double S = std::sqrt(lines[0]["P2"].get<double>() / (4 * M_PI * sigma * sigma));
    EXPECT_NEAR(S, J1, 2e-4) << device;  // tolerance 1e-4 times the window weight bound (< 2)
    EXPECT_GT(lines[0]["brdf"].get<double>(), 0.0);
    EXPECT_TRUE(lines[1].contains("error"));
    for (int i = 2; i < 6; ++i) EXPECT_TRUE(lines[i].contains("error")) << device << " line " << i;
  }
}

// A wavelength the batch's shared tables cannot cover (the Taylor bound would need millions of
// terms) fails its own line only; the good line is still answered, on every device.
TEST(EvalDiffractionCli, AbsurdWavelengthFailsOnlyItsLine) {
  const std::string input = R"({"id": 1, "wi": [0, 0, 1], "wr": [0, 0, 1], "lambda_nm": 500})"
                            "\n"
                            R"({"id": 2, "wi": [0, 0, 1], "wr": [0, 0, 1], "lambda_nm": 1e-6})"
                            "\n";
  for (const char* device : {"cpu", "gpu"}) {
    auto r =
        run_command(kFacet + " eval diffraction --grating " + kGrating + " --device " + std::string(device), input);
    ASSERT_EQ(r.exit_code, 0) << device << ": " << r.err;
    const auto lines = parse_lines(r.out);
    ASSERT_EQ(lines.size(), 2u) << device;
    EXPECT_EQ(lines[0]["id"], 1);
    EXPECT_FALSE(lines[0].contains("error")) << lines[0];
    EXPECT_TRUE(std::isfinite(lines[0]["brdf"].get<double>()));
    EXPECT_EQ(lines[1]["id"], 2);
    EXPECT_TRUE(lines[1].contains("error")) << lines[1];
  }
}

TEST(EvalDiffractionCli, BadGratingAndExactOnGpuFailWithOneLine) {
  for (const std::string& args :
       {std::string(R"(--grating '{"type":"sinusoid"}')"), std::string("--grating /nonexistent.json"),
        "--grating " + kGrating + " --device gpu --exact"}) {
    auto r = run_command(kFacet + " eval diffraction " + args, R"({"wi":[0,0,1],"wr":[0,0,1],"lambda_nm":500})");
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

// A grating whose periods do not span whole samples (1200 nm on 96 samples over 12 um: 9.6 per
// period) is raised to 120 samples: one note line on stderr, and the answers are those of the grating
// asked for with 120 samples (bit for bit: the same field).
TEST(EvalDiffractionCli, SamplesRaisedToWholePeriodsSayItInOneNoteLine) {
  const std::string query = R"({"wi": [0, 0, 1], "wr": [0.4, 0.1, 0.9110433579144299], "lambda_nm": 480})"
                            "\n";
  auto with = [](int samples) {
    return std::string(R"('{"type":"crossed","period_nm":[1200,2000],"amplitude_nm":100,"size_um":12,"samples":)") +
           std::to_string(samples) + "}'";
  };
  const auto raised = run_command(kFacet + " eval diffraction --grating " + with(96), query);
  const auto whole = run_command(kFacet + " eval diffraction --grating " + with(120), query);
  ASSERT_EQ(raised.exit_code, 0) << raised.err;
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  EXPECT_EQ(raised.err,
            "facet: note: --grating: grating.samples 96 raised to 120, so every period spans a whole number of "
            "samples\n");
  EXPECT_EQ(whole.err, "");
  EXPECT_EQ(raised.out, whole.out);
  EXPECT_GT(parse_lines(raised.out).at(0)["brdf"].get<double>(), 0.0);
}

}  // namespace
}  // namespace facet
