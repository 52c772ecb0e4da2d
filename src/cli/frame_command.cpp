// `mirage frame SCENE.pov`: where the mirage lies in the scene's frame and what would show it
// better (frame/frame.h), as text or JSON, with a teaching overlay.
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "frame/frame.h"
#include "frame/frame_output.h"
#include "image/image_io.h"
#include "util/json_text.h"
#include "util/output_set.h"
#include "util/text_escape.h"

namespace mirage {

namespace {

struct FrameCliOptions {
    FrameOptions frame;
    std::string overlay;
    bool json = false;
    bool plain = false;
};

[[noreturn]] void fail(const std::string& message) {
    std::cerr << "mirage frame: " << escape_terminal(message) << "\n";
    throw CommandFailed{1};
}

}  // namespace

void setup_frame_command(CLI::App& app) {
    auto o = std::make_shared<FrameCliOptions>();
    auto* sub = app.add_subcommand(
        "frame",
        "Where the mirage lies in the scene's frame, and which lens, camera height, distance "
        "or exaggeration would show it better");
    sub->add_option("scene", o->frame.scene, "the .pov scene")->required();
    sub->add_option("-W,--width", o->frame.width, "image width, pixels")->capture_default_str();
    sub->add_option("-H,--height", o->frame.height, "image height, pixels")->capture_default_str();
    sub->add_option("-o,--overlay", o->overlay,
                    "a PNG of the frame with the horizons, the mirage band and the vanishing "
                    "marks drawn over the tracer's render")
        ->check(non_empty_name());
    sub->add_flag("--plain", o->plain, "draw the overlay on a plain background (no render)");
    sub->add_flag("--json", o->json, "print the reading as JSON");
    sub->add_option("-L,--library-path", o->frame.library_paths,
                    "extra include directory (searched first)");
    sub->callback([o] {
        if (!o->overlay.empty())
            if (auto s = check_image_name(o->overlay); !s) fail(s.message());
        auto reading = frame_scene(o->frame);
        if (!reading) fail(reading.message());
        OutputSet outputs(reading->files);
        if (!o->overlay.empty()) {
            if (auto s = outputs.check(o->overlay); !s) fail(s.message());
            Image background;
            if (!o->plain) {
                auto traced = frame_background(o->frame);
                if (!traced) fail(traced.message());
                background = std::move(*traced);
            }
            if (auto s = write_image(frame_overlay(*reading, background), o->overlay, &outputs); !s)
                fail(s.message());
            if (auto s = outputs.commit(); !s) fail(s.message());
        }
        if (o->json) {
            nlohmann::json j = frame_json(*reading);
            if (!o->overlay.empty()) {
                j["overlay"] = o->overlay;
                j["overlay_legend"] = overlay_legend();
            }
            std::cout << json_text(j) << "\n";
            return;
        }
        std::cout << frame_text(*reading);
        if (!o->overlay.empty()) std::cout << "\nwrote " << o->overlay << "\n" << overlay_legend();
    });
}

}  // namespace mirage
