#include "pov/emit_layers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "pov/povray_path.h"
#include "util/check.h"
#include "util/format.h"
#include "util/text_escape.h"

namespace mirage {

namespace {

// 17 significant digits: every index and height reads back as the same double (the index
// steps of real air are near 1e-11).
std::string g17(double v) { return sig(v, 17); }

}  // namespace

std::string layers_include(const LayerStack& s, const LayerEmitSettings& st) {
    MIRAGE_CHECK(well_formed(s));
    const int k_cam = s.layer_at(st.camera_y);
    const double n_cam = s.index(k_cam);
    std::ostringstream out;
    for (const auto& line : st.header) out << "// " << line << "\n";
    if (st.many_origins) {
        out << "//\n// " << s.boundaries()
            << " boundaries; the camera's rays start at different heights: layer " << k_cam
            << " (y = " << g17(st.camera_y) << "), of the largest index " << g17(n_cam)
            << ", is POV-Ray's atmosphere, the index every ior below is relative to.\n";
    } else {
        out << "//\n// " << s.boundaries() << " boundaries; the camera at y = " << g17(st.camera_y)
            << " is in layer " << k_cam << " of index " << g17(n_cam)
            << ", the index every ior below is relative to.\n";
    }
    if (st.layout == LayerLayout::Gaps) {
        out << "// Gap layout: each layer a slab of its own, gaps of " << g17(st.gap)
            << " units between them hold the camera's index\n"
               "// (POV-Ray's atmosphere), so that every refraction is computed in double "
               "precision.\n\n";
    } else {
        out << "// Planes split at the camera's layer: below it plane { y, h } (inside is below),\n"
               "// above it plane { -y, -h } (inside is above); each clipped to a thin slab.\n\n";
    }
    if (st.ground_height != 0.0) {
        out << "// Heights above the ground at y = " << g17(st.ground_height)
            << " (Mirage_Ground_Height): every layer is moved up there.\n";
    }
    out << st.checks;
    out << "global_settings { max_trace_level 256 }\n\n";
    out << "#declare Mirage_Layer_Texture = texture {\n"
           "    pigment { rgbf 1 }\n"
           "    finish { ambient 0 diffuse 0 specular 0 phong 0 reflection 0 }\n"
           "}\n\n";
    const auto& h = s.heights;
    const int N = s.boundaries();
    // Layers below the camera's may reach farther than those above.
    const HorizontalBox& low = st.extent_below ? *st.extent_below : st.extent;
    auto corners = [&](double y0, double y1, bool below) {
        const HorizontalBox& e = below ? low : st.extent;
        std::ostringstream b;
        b << "<" << g17(e.x0) << ", " << g17(y0) << ", " << g17(e.z0) << ">, <" << g17(e.x1) << ", "
          << g17(y1) << ", " << g17(e.z1) << ">";
        return b.str();
    };
    auto box = [&](double y0, double y1, bool below) {
        return "box { " + corners(y0, y1, below) + " }";
    };
    auto tail = [&](int layer) {
        // POV-Ray keeps an ior in single precision: the float value is what it will use.
        return "    texture { Mirage_Layer_Texture }\n    interior { ior " +
               sig(pov_ior(s, k_cam, layer), 9) + " }\n    no_shadow\n" +
               (st.ground_height != 0.0 ? "    translate <0, " + g17(st.ground_height) + ", 0>\n"
                                        : std::string()) +
               "}\n";
    };
    if (st.layout == LayerLayout::Gaps) {
        // One object per layer but the camera's: slabs between the gaps, the lowest and the
        // highest layer as half-spaces (the top one must never be left towards the sky).
        const double g = st.gap;
        for (int k = 0; k <= N; ++k) {
            // The camera's layer is POV-Ray's atmosphere, and so is any layer whose ior is the
            // float 1: a slab of it would only cost POV-Ray free continued rays.
            if (k == k_cam || pov_ior(s, k_cam, k) == 1.0f) continue;
            const double bottom = k == 0 ? 0.0 : h[k - 1] + (k - 1 == k_cam ? 0.0 : 0.5 * g);
            const double top = k == N ? 0.0 : h[k] - (k == k_cam - 1 ? 0.0 : 0.5 * g);
            if (k == 0) {
                out << "plane { y, " << g17(top) << "\n    clipped_by { "
                    << box(std::min(-1.0 - std::fabs(top), st.lowest_y - 1.0 - std::fabs(top)),
                           top + 0.5 * g, k < k_cam)
                    << " }\n"
                    << tail(k);
            } else if (k == N) {
                out << "plane { -y, " << g17(-bottom) << "\n    clipped_by { "
                    << box(bottom - 0.5 * g, bottom + 1e6, k < k_cam) << " }\n"
                    << tail(k);
            } else {
                out << "box { " << corners(bottom, top, k < k_cam) << "\n" << tail(k);
            }
        }
        return out.str();
    }
    for (int j = 0; j < N; ++j) {
        // Half-thickness of the clipping slab: well inside the gap to the neighbours.
        const double below = j == 0 ? h[0] : h[j] - h[j - 1];
        const double above = j + 1 < N ? h[j + 1] - h[j] : below;
        double gap = std::min(below, above);
        if (h[j] < st.camera_y) gap = std::min(gap, st.camera_y - h[j]);
        if (h[j] > st.camera_y) gap = std::min(gap, h[j] - st.camera_y);
        const double half = std::max(0.4 * gap, 1e-7 * std::max(1.0, std::fabs(h[j])));
        const bool under = j < k_cam;  // boundary below the camera
        // The layer this plane's interior stands for: the one just below (under the camera)
        // or just above it.
        const int layer = under ? j : j + 1;
        out << "plane { " << (under ? "y, " : "-y, ") << (under ? g17(h[j]) : g17(-h[j]))
            << "\n    clipped_by { " << box(h[j] - half, h[j] + half, under) << " }\n"
            << tail(layer);
    }
    return out.str();
}

std::string layers_csv(const LayerStack& s, double camera_y) {
    const int k_cam = s.layer_at(camera_y);
    std::ostringstream out;
    out << "layer,bottom,top,index,eta2_minus_eta0_2,ior_as_emitted,object\n";
    const int N = s.boundaries();
    for (int k = 0; k <= N; ++k) {
        const double bottom = k == 0 ? 0.0 : s.heights[k - 1];
        const std::string top = k == N ? "inf" : g17(s.heights[k]);
        out << k << "," << g17(bottom) << "," << top << "," << g17(s.index(k)) << ","
            << g17(s.excess[k]) << ",";
        if (k == k_cam) {
            out << "1,camera layer (no object)\n";
        } else if (k < k_cam) {
            out << sig(pov_ior(s, k_cam, k), 9) << ",\"plane { y, " << g17(s.heights[k])
                << " }\"\n";
        } else {
            out << sig(pov_ior(s, k_cam, k), 9) << ",\"plane { -y, " << g17(-s.heights[k - 1])
                << " }\"\n";
        }
    }
    return out.str();
}

std::string render_ini(const IniSettings& st) {
    // The paths were checked by compile_settings (pov/povray_path.h): none holds a line end
    // or a '"'.  The comment is escaped all the same.
    auto quote = [](const std::string& p) { return povray_quoted(p); };
    std::ostringstream out;
    out << "; Renders " << escape_control(st.scene) << " with its compiled mirage atmosphere.\n"
        << "; Written by mirage compile; run: povray <this file>\n"
        << "Input_File_Name=" << quote(st.scene) << "\n"
        << "Output_File_Name=" << quote(st.output_image) << "\n"
        << "Output_File_Type=N\n"
        << "Width=" << st.width << "\n"
        << "Height=" << st.height << "\n"
        << "Display=Off\n"
        << "Bounding_Method=2\n";
    if (st.antialias) {
        out << "Antialias=On\nAntialias_Threshold=" << sig(st.antialias_threshold, 6) << "\n";
    } else {
        out << "Antialias=Off\n";
    }
    for (const auto& p : st.library_paths) out << "Library_Path=" << quote(p) << "\n";
    // The clock as the float POV-Ray holds (its nine digits give that float back); the
    // declared numbers in full.
    if (st.clock) out << "Clock=" << sig(static_cast<float>(*st.clock), 9) << "\n";
    for (const auto& [name, value] : st.declares)
        out << "Declare=" << name << "=" << g17(value) << "\n";
    out << "Declare=Mirage_Compiled=1\n";
    return out.str();
}

}  // namespace mirage
