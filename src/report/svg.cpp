#include "report/svg.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace mirage {

std::vector<double> nice_ticks(double lo, double hi, int target) {
    std::vector<double> ticks;
    if (!(hi > lo)) return {lo};
    const double raw = (hi - lo) / std::max(1, target);
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        step = m * mag;
        if (step >= raw) break;
    }
    for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step)
        ticks.push_back(std::fabs(t) < 1e-12 * step ? 0.0 : t);
    return ticks;
}

std::string svg_escape(const std::string& text) {
    std::string out;
    for (char ch : text) {
        switch (ch) {
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
                out += ch;
        }
    }
    return out;
}

std::string tick_label(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string PlotFrame::axes(const std::string& x_label, const std::string& y_label) const {
    std::ostringstream s;
    s << "<g font-family=\"sans-serif\" font-size=\"12\" fill=\"#333\">\n";
    for (double t : nice_ticks(x0, x1)) {
        s << "<line x1=\"" << px(t) << "\" y1=\"" << top << "\" x2=\"" << px(t) << "\" y2=\""
          << top + height << "\" stroke=\"#e4e4e4\"/>\n";
        s << "<text x=\"" << px(t) << "\" y=\"" << top + height + 16 << "\" text-anchor=\"middle\">"
          << tick_label(t) << "</text>\n";
    }
    for (double t : nice_ticks(y0, y1)) {
        s << "<line x1=\"" << left << "\" y1=\"" << py(t) << "\" x2=\"" << left + width
          << "\" y2=\"" << py(t) << "\" stroke=\"#e4e4e4\"/>\n";
        s << "<text x=\"" << left - 6 << "\" y=\"" << py(t) + 4 << "\" text-anchor=\"end\">"
          << tick_label(t) << "</text>\n";
    }
    s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << width << "\" height=\""
      << height << "\" fill=\"none\" stroke=\"#555\"/>\n";
    s << "<text x=\"" << left + width / 2 << "\" y=\"" << top + height + 36
      << "\" text-anchor=\"middle\">" << svg_escape(x_label) << "</text>\n";
    s << "<text transform=\"translate(" << left - 46 << "," << top + height / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << svg_escape(y_label) << "</text>\n";
    s << "</g>\n";
    return s.str();
}

}  // namespace mirage
