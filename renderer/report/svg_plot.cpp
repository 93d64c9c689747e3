#include "report/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "report/pareto.hpp"

namespace facet::report {

namespace {

constexpr double kWidth = 480, kHeight = 320;
constexpr double kLeft = 64, kRight = 16, kTop = 28, kBottom = 44;

bool plottable(const PlotPoint& p) { return p.x > 0.0 && p.y > 0.0 && std::isfinite(p.x) && std::isfinite(p.y); }

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", value);
  return buffer;
}

std::string decade_label(int decade) {
  if (decade >= 0 && decade <= 3) return std::to_string(static_cast<int>(std::lround(std::pow(10.0, decade))));
  return "1e" + std::to_string(decade);
}

}  // namespace

double LogAxis::to_pixel(double value) const {
  const double t = (std::log10(value) - lo_decade) / (hi_decade - lo_decade);
  return pixel_lo + t * (pixel_hi - pixel_lo);
}

LogAxis LogAxis::enclosing(const std::vector<double>& values, double pixel_lo, double pixel_hi) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (double v : values)
    if (v > 0.0 && std::isfinite(v)) {
      lo = std::min(lo, std::log10(v));
      hi = std::max(hi, std::log10(v));
    }
  if (lo > hi) lo = hi = 0.0;
  LogAxis axis{static_cast<int>(std::floor(lo)), static_cast<int>(std::ceil(hi)), pixel_lo, pixel_hi};
  if (axis.hi_decade <= axis.lo_decade) axis.hi_decade = axis.lo_decade + 1;
  return axis;
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string speed_error_svg(const std::vector<PlotPoint>& all_points, const PlotLabels& labels) {
  std::vector<PlotPoint> points;
  std::copy_if(all_points.begin(), all_points.end(), std::back_inserter(points), plottable);
  std::vector<double> xs, ys;
  std::vector<CostError> cost_error;
  for (const PlotPoint& p : points) {
    xs.push_back(p.x);
    ys.push_back(p.y);
    cost_error.push_back({p.x, p.y});
  }
  const LogAxis x_axis = LogAxis::enclosing(xs, kLeft, kWidth - kRight);
  const LogAxis y_axis = LogAxis::enclosing(ys, kHeight - kBottom, kTop);  // up is smaller pixel y
  const std::vector<std::size_t> front = pareto_front(cost_error);

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
      << "\" viewBox=\"0 0 " << kWidth << " " << kHeight << "\" font-family=\"sans-serif\" font-size=\"10\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"" << kWidth / 2 << "\" y=\"16\" text-anchor=\"middle\" font-size=\"12\">"
      << xml_escape(labels.title) << "</text>\n";
  // Decade grid lines and labels.
  for (int d = x_axis.lo_decade; d <= x_axis.hi_decade; ++d) {
    const std::string px = number(x_axis.to_pixel(std::pow(10.0, d)));
    svg << "<line class=\"grid\" x1=\"" << px << "\" y1=\"" << kTop << "\" x2=\"" << px << "\" y2=\""
        << kHeight - kBottom << "\" stroke=\"#ddd\"/>\n";
    svg << "<text x=\"" << px << "\" y=\"" << kHeight - kBottom + 14 << "\" text-anchor=\"middle\">" << decade_label(d)
        << "</text>\n";
  }
  for (int d = y_axis.lo_decade; d <= y_axis.hi_decade; ++d) {
    const std::string py = number(y_axis.to_pixel(std::pow(10.0, d)));
    svg << "<line class=\"grid\" x1=\"" << kLeft << "\" y1=\"" << py << "\" x2=\"" << kWidth - kRight << "\" y2=\""
        << py << "\" stroke=\"#ddd\"/>\n";
    svg << "<text x=\"" << kLeft - 4 << "\" y=\"" << py << "\" text-anchor=\"end\" dominant-baseline=\"middle\">"
        << decade_label(d) << "</text>\n";
  }
  svg << "<text x=\"" << (kLeft + kWidth - kRight) / 2 << "\" y=\"" << kHeight - 8 << "\" text-anchor=\"middle\">"
      << xml_escape(labels.x_axis) << "</text>\n";
  svg << "<text transform=\"translate(14 " << (kTop + kHeight - kBottom) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << xml_escape(labels.y_axis) << "</text>\n";
  // The front as a staircase: from each member, right at its error until the next member's time.
  if (!front.empty()) {
    svg << "<path class=\"front\" fill=\"none\" stroke=\"#c33\" stroke-width=\"1.5\" d=\"M"
        << number(x_axis.to_pixel(points[front[0]].x)) << " " << number(y_axis.to_pixel(points[front[0]].y));
    for (std::size_t k = 1; k < front.size(); ++k)
      svg << " H" << number(x_axis.to_pixel(points[front[k]].x)) << " V" << number(y_axis.to_pixel(points[front[k]].y));
    svg << "\"/>\n";
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
    const std::string cx = number(x_axis.to_pixel(points[i].x)), cy = number(y_axis.to_pixel(points[i].y));
    svg << "<circle class=\"point" << (on_front ? " front" : "") << "\" cx=\"" << cx << "\" cy=\"" << cy
        << "\" r=\"3.5\" fill=\"" << (on_front ? "#c33" : "#369") << "\"><title>" << xml_escape(points[i].label)
        << "</title></circle>\n";
    svg << "<text x=\"" << cx << "\" y=\"" << cy << "\" dx=\"5\" dy=\"-5\">" << xml_escape(points[i].label)
        << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace facet::report
