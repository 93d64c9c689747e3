#include "report/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <utility>

#include "report/pareto.hpp"

namespace facet::report {

namespace {

constexpr double kWidth = 480, kHeight = 320;
constexpr double kLeft = 64, kRight = 16, kTop = 28, kBottom = 44;
constexpr double kPointRadius = 3.5;
constexpr double kLegendLine = 14;  // px between legend lines under the plot
constexpr double kLabelGap = 1;     // px kept clear around a label, more than the 0.005 px of rounding its position

struct Box {
  double left, top, right, bottom;
  bool intersects(const Box& o) const { return left < o.right && o.left < right && top < o.bottom && o.top < bottom; }
  bool inside(const Box& o) const { return left >= o.left && right <= o.right && top >= o.top && bottom <= o.bottom; }
};

// UTF-8 code points: a label's glyph count.
std::size_t glyphs(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

double label_width(const std::string& text) { return kLabelCharWidth * static_cast<double>(glyphs(text)); }

struct PlacedLabel {
  Box box;
  bool leader = false;  // placed away from its point: a line joins them
};

// Greedy placement: for each point in turn, the first candidate box (8 directions around it, at
// growing distances) inside the plot area that meets no placed label and no point. None: legend.
std::vector<std::optional<PlacedLabel>> place_labels(const std::vector<PlotPoint>& points,
                                                     const std::vector<std::pair<double, double>>& at) {
  const Box area{kLeft, kTop, kWidth - kRight, kHeight - kBottom};
  std::vector<Box> obstacles;
  for (const auto& [x, y] : at)
    obstacles.push_back({x - kPointRadius, y - kPointRadius, x + kPointRadius, y + kPointRadius});
  const double height = kLabelAscent + kLabelDescent;
  std::vector<std::optional<PlacedLabel>> placed(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double width = label_width(points[i].label), gap = kPointRadius + 1.5;
    const auto [x, y] = at[i];
    for (double distance : {0.0, 8.0, 16.0, 26.0, 38.0, 52.0, 70.0, 92.0}) {
      for (auto [dx, dy] : {std::pair{1, -1}, {1, 1}, {-1, -1}, {-1, 1}, {1, 0}, {-1, 0}, {0, -1}, {0, 1}}) {
        const double offset = gap + distance;
        const double left = dx > 0 ? x + offset : dx < 0 ? x - offset - width : x - width / 2;
        const double top = dy > 0 ? y + offset : dy < 0 ? y - offset - height : y - height / 2;
        const Box box{left, top, left + width, top + height};
        const Box clearance{left - kLabelGap, top - kLabelGap, left + width + kLabelGap, top + height + kLabelGap};
        if (!box.inside(area) ||
            std::any_of(obstacles.begin(), obstacles.end(), [&](const Box& o) { return clearance.intersects(o); }))
          continue;
        placed[i] = PlacedLabel{box, distance > 0.0};
        obstacles.push_back(box);
        break;
      }
      if (placed[i]) break;
    }
  }
  return placed;
}

// The names without a place, "also: a, b, ...", in lines of at most the picture's width.
std::vector<std::string> legend_lines(const std::vector<PlotPoint>& points,
                                      const std::vector<std::optional<PlacedLabel>>& placed) {
  std::vector<std::string> lines;
  std::string line;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (placed[i]) continue;
    const std::string item = (lines.empty() && line.empty() ? "also: " : line.empty() ? "" : ", ") + points[i].label;
    if (!line.empty() && label_width(line + item + ",") > kWidth - 16) {
      lines.push_back(line + ",");
      line = points[i].label;
    } else {
      line += item;
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

bool plottable(const PlotPoint& p) { return p.x > 0.0 && p.y > 0.0 && std::isfinite(p.x) && std::isfinite(p.y); }

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

std::string svg_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", value);
  return buffer;
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

  std::vector<std::pair<double, double>> at;
  for (const PlotPoint& p : points) at.emplace_back(x_axis.to_pixel(p.x), y_axis.to_pixel(p.y));
  const std::vector<std::optional<PlacedLabel>> placed = place_labels(points, at);
  const std::vector<std::string> legend = legend_lines(points, placed);
  const double height = kHeight + kLegendLine * static_cast<double>(legend.size());

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << kWidth << " " << height << "\" font-family=\"sans-serif\" font-size=\""
      << kLabelFontSize << "\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"" << kWidth / 2 << "\" y=\"16\" text-anchor=\"middle\" font-size=\"12\">"
      << xml_escape(labels.title) << "</text>\n";
  // Decade grid lines and labels.
  for (int d = x_axis.lo_decade; d <= x_axis.hi_decade; ++d) {
    const std::string px = svg_number(x_axis.to_pixel(std::pow(10.0, d)));
    svg << "<line class=\"grid\" x1=\"" << px << "\" y1=\"" << kTop << "\" x2=\"" << px << "\" y2=\""
        << kHeight - kBottom << "\" stroke=\"#ddd\"/>\n";
    svg << "<text x=\"" << px << "\" y=\"" << kHeight - kBottom + 14 << "\" text-anchor=\"middle\">" << decade_label(d)
        << "</text>\n";
  }
  for (int d = y_axis.lo_decade; d <= y_axis.hi_decade; ++d) {
    const std::string py = svg_number(y_axis.to_pixel(std::pow(10.0, d)));
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
        << svg_number(x_axis.to_pixel(points[front[0]].x)) << " " << svg_number(y_axis.to_pixel(points[front[0]].y));
    for (std::size_t k = 1; k < front.size(); ++k)
      svg << " H" << svg_number(x_axis.to_pixel(points[front[k]].x)) << " V" << svg_number(y_axis.to_pixel(points[front[k]].y));
    svg << "\"/>\n";
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
    const auto [x, y] = at[i];
    svg << "<circle class=\"point" << (on_front ? " front" : "") << "\" cx=\"" << svg_number(x) << "\" cy=\"" << svg_number(y)
        << "\" r=\"" << kPointRadius << "\" fill=\"" << (on_front ? "#c33" : "#369") << "\"><title>"
        << xml_escape(points[i].label) << "</title></circle>\n";
    if (!placed[i]) continue;
    const Box& box = placed[i]->box;
    if (placed[i]->leader) {  // to the box's nearest point
      svg << "<line class=\"leader\" x1=\"" << svg_number(x) << "\" y1=\"" << svg_number(y) << "\" x2=\""
          << svg_number(std::clamp(x, box.left, box.right)) << "\" y2=\"" << svg_number(std::clamp(y, box.top, box.bottom))
          << "\" stroke=\"#999\" stroke-width=\"0.75\"/>\n";
    }
    svg << "<text class=\"label\" x=\"" << svg_number(box.left) << "\" y=\"" << svg_number(box.top + kLabelAscent) << "\">"
        << xml_escape(points[i].label) << "</text>\n";
  }
  for (std::size_t k = 0; k < legend.size(); ++k)
    svg << "<text class=\"legend\" x=\"8\" y=\"" << svg_number(kHeight + kLegendLine * static_cast<double>(k) + 4) << "\">"
        << xml_escape(legend[k]) << "</text>\n";
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace facet::report
