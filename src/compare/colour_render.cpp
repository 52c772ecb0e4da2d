#include "compare/colour_render.h"

#include <filesystem>
#include <sstream>

#include "image/image_io.h"
#include "load/mirage_scene.h"
#include "trace/object_query.h"
#include "util/format.h"

namespace mirage {

namespace fs = std::filesystem;

Result<std::optional<ChannelWavelengths>> compile_colour_wavelengths(
    const CompileOptions& options, const std::vector<double>& asked, const std::string& option) {
    if (!asked.empty()) {
        auto nm = check_channel_wavelengths(asked, option);
        if (!nm) return nm.error();
        return std::optional<ChannelWavelengths>(*nm);
    }
    // The scene's own: read as the compile reads it (its camera, atmosphere and extent).
    SceneLoadOptions lo = scene_load_options(options);
    lo.strict = false;
    lo.object_queries = tracer_object_queries();
    lo.clock = options.clock;
    lo.declares = options.declares;
    auto loaded = load_mirage_scene(lo);
    // A scene that does not load is compiled as one design, whose own checks (the names POV-Ray
    // reads among them) come first and say what is wrong.
    if (!loaded) return std::optional<ChannelWavelengths>();
    return loaded->settings.channel_wavelengths_nm;
}

Result<Image> combine_channels(const Image& red, const Image& green, const Image& blue) {
    if (red.width != green.width || red.width != blue.width || red.height != green.height ||
        red.height != blue.height)
        return make_error("the channels' images differ in size: " + std::to_string(red.width) +
                          "x" + std::to_string(red.height) + ", " + std::to_string(green.width) +
                          "x" + std::to_string(green.height) + ", " + std::to_string(blue.width) +
                          "x" + std::to_string(blue.height));
    Image out(red.width, red.height);
    const Image* from[3] = {&red, &green, &blue};
    for (std::size_t k = 0; k < out.pixels.size(); ++k) out.pixels[k] = from[k % 3]->pixels[k];
    return out;
}

Result<ColourCompileReport> compile_colour(const CompileOptions& options,
                                           const ChannelWavelengths& nm, bool render) {
    const std::string name = fs::path(options.scene).stem().string();
    const fs::path out =
        options.out_dir.empty() ? fs::path("build/render") / name : fs::path(options.out_dir);
    ColourCompileReport rep;
    for (int c = 0; c < 3; ++c) {
        ColourChannel ch;
        ch.wavelength_nm = nm[c];
        CompileOptions o = options;
        o.wavelength_nm = nm[c];
        o.out_dir = (out / (name + "-" + shortest(nm[c]) + "nm")).string();
        o.image.clear();
        auto report = compile_scene(o);
        if (!report) return report.error();
        ch.report = std::move(*report);
        if (render) {
            const std::string dir = fs::path(ch.report.ini_path).parent_path().string();
            PovrayRenderSettings rs;
            rs.ini = ch.report.ini_path;
            rs.work_dir = dir;
            rs.log = (fs::path(dir) / "povray.log").string();
            if (ch.report.camera == "corrected") rs.crop_top_row = ch.report.image_path;
            auto r = render_povray(rs);
            if (!r) return r.error();
            if (r->exit_code != 0)
                return make_error("POV-Ray failed (exit " + std::to_string(r->exit_code) + ") on " +
                                  ch.report.ini_path + ":\n" + log_tail(rs.log, 20));
            ch.render = *r;
            ch.log = rs.log;
        }
        rep.channels.push_back(std::move(ch));
    }
    if (!render) return rep;
    Image images[3];
    for (int c = 0; c < 3; ++c) {
        auto img = read_image(rep.channels[c].report.image_path);
        if (!img) return img.error();
        images[c] = std::move(*img);
    }
    auto combined = combine_channels(images[0], images[1], images[2]);
    if (!combined) return combined.error();
    rep.image = options.image.empty() ? (out / (name + ".png")).string() : options.image;
    // POV-Ray's code values, channel by channel: no encoding added or undone.
    if (auto s = write_png_codes(*combined, rep.image); !s) return s.error();
    return rep;
}

std::string colour_compile_summary(const ColourCompileReport& r) {
    std::ostringstream o;
    const char* names[3] = {"red", "green", "blue"};
    for (std::size_t c = 0; c < r.channels.size(); ++c) {
        const ColourChannel& ch = r.channels[c];
        o << (c < 3 ? names[c] : "") << " " << shortest(ch.wavelength_nm)
          << " nm: " << ch.report.layers << " layers, max error " << sig(ch.report.max_error_px, 3)
          << " px, " << ch.report.ini_path;
        if (ch.render)
            o << ", POV-Ray " << sig(ch.render->seconds, 3) << " s"
              << (ch.render->log.cpu_seconds
                      ? " (" + sig(*ch.render->log.cpu_seconds, 3) + " CPU-seconds)"
                      : std::string());
        o << "\n";
    }
    if (!r.image.empty()) o << "  rendered    " << r.image << " (the three channels)\n";
    return o.str();
}

}  // namespace mirage
