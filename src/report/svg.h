// Minimal SVG plotting primitives shared by the ray diagrams and reports: a data-to-pixel
// frame with "nice" axis ticks, and escaping.
#pragma once

#include <string>
#include <vector>

namespace mirage {

/// Tick positions covering [lo, hi] with a 1-2-5 step, about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target = 6);

/// Text safe for SVG/XML content and attribute values.
std::string svg_escape(const std::string& text);

/// A rectangular plot: data coordinates (x right, y up) mapped onto a pixel box.
struct PlotFrame {
    double x0, x1, y0, y1;            // data range
    double left, top, width, height;  // pixel box of the plotting area

    double px(double x) const { return left + (x - x0) / (x1 - x0) * width; }
    double py(double y) const { return top + (1.0 - (y - y0) / (y1 - y0)) * height; }
    /// Axes with ticks, grid and labels, as SVG elements.
    std::string axes(const std::string& x_label, const std::string& y_label) const;
};

/// Formats a number for a tick label (no trailing zeros).
std::string tick_label(double v);

}  // namespace mirage
