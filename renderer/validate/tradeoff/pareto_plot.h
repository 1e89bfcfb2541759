// The trade-off's Pareto plot: error against median frame time, log axes,
// drawn by gnuplot (Debian package gnuplot-nox) as DIR/pareto.png, with
// its script pareto.gp, data pareto.dat and gnuplot's output pareto.log.
//
// Every configuration but "converged" is a point: the Pareto front in red,
// joined by time and labelled in bold; the others grey, labelled small.
// An error of 0 has no place on a log axis: it is drawn at half the
// smallest error shown. The converged reference's residual (the
// tolerance, when > 0) is a dashed blue line with its caption.
//
// Axes (PlotAxes, from the points): time from tmin / 1.6 to tmax * 4
// (room for labels on the right), error from emin / 1.6 to emax * 1.6,
// emin the smallest error > 0 and at most the tolerance.
//
// Labels are placed here, not by gnuplot (which lets them overlap): the
// plot area is fixed in screen fractions (kPlotArea: a 1000 x 700 canvas,
// margins 0.09 / 0.97 / 0.09 / 0.93), so a point's pixel position is known.
// Each point, a 10 x 10 pixel box, the key (175 x 42 at the top right) and
// the tolerance's caption are taken first; then each label, the front's
// first (in front order) and then the others by decreasing error, takes
// the first free slot (inside the plot area, overlapping nothing taken):
// rows base, base + h, base - h, base + 2h, ... (17 rows; y grows
// upwards), base = -h for the front (below the point) and 0 for the
// others, h the line height (14 / 12 pixels); in each row first its preferred side (the front's to the
// left, the others' to the right, 9 pixels from the point) then the other.
// Text width: 7.5 / 6 pixels per character. A label more than 0.6 h away
// from its base row gets a thin leader line to its point. A label with no
// free slot stays at its base row (it may overlap).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace xval {

struct PlotItem {
  std::string id;
  double seconds = 0.0, error = 0.0;  // error as drawn (> 0)
  bool front = false;
};

struct PlotAxes {
  double xlo = 1, xhi = 10, ylo = 1, yhi = 10;  // log axes: all > 0
};

struct PlotArea {
  double width = 1000, height = 700;               // canvas, pixels
  double left = 0.09, right = 0.97, bottom = 0.09, top = 0.93;  // screen fractions
};
inline constexpr PlotArea kPlotArea{};

struct PlacedLabel {
  std::string id;
  double x = 0, y = 0;  // the text's anchor, as graph fractions
  bool left = false;    // text to the left of the anchor (right-aligned)
  bool front = false;
  bool leader = false;  // draw a line from the anchor to the point
  double seconds = 0, error = 0;  // the point
};

// Labels for `items` in the order given (front first, as documented).
std::vector<PlacedLabel> placeLabels(const std::vector<PlotItem>& items, const PlotAxes& axes,
                                     double tolerance, const PlotArea& area = kPlotArea);

// Writes pareto.dat, pareto.gp and pareto.png into dir from a tradeoff.json
// document; metric_label names the error axis. Throws std::runtime_error
// when gnuplot is missing or fails (naming pareto.log) or its PNG is not
// whole.
void writeParetoPlot(const nlohmann::ordered_json& tradeoff, const std::string& metric_label,
                     const std::filesystem::path& dir);

}  // namespace xval
