// Stage "emit" of mirage compile (compile/stages.h).
#include <algorithm>
#include <filesystem>

#include "compile/stages.h"
#include "pov/emit_layers.h"
#include "pov/emit_stamp.h"

namespace mirage {

EmittedFiles emit_files(const CompileContext& ctx, const LayerStack& stack, double reach,
                        std::optional<double> reach_below, const std::string& out_dir,
                        const std::string& image, const std::vector<std::string>& header,
                        bool corrected) {
    const glm::dvec3& eye = ctx.camera.location;
    LayerEmitSettings es;
    es.camera_y = ctx.reference_y(stack);
    es.many_origins = ctx.many_origins;
    for (const glm::dvec3& corner :
         {camera_ray(ctx.camera, 0, 0, ctx.options.width, ctx.options.height).origin,
          camera_ray(ctx.camera, ctx.options.width, 0, ctx.options.width, ctx.options.height)
              .origin,
          camera_ray(ctx.camera, 0, ctx.options.height, ctx.options.width, ctx.options.height)
              .origin,
          camera_ray(ctx.camera, ctx.options.width, ctx.options.height, ctx.options.width,
                     ctx.options.height)
              .origin})
        if (ctx.many_origins) es.lowest_y = std::min(es.lowest_y, corner.y);
    es.ground_height = ctx.settings.ground_height;
    es.extent = {eye.x - reach, eye.x + reach, eye.z - reach, eye.z + reach};
    if (reach_below) {
        const double r = *reach_below;
        es.extent_below = HorizontalBox{eye.x - r, eye.x + r, eye.z - r, eye.z + r};
    }
    es.layout = ctx.gaps ? LayerLayout::Gaps : LayerLayout::Nested;
    es.gap = ctx.gap;
    es.header = header;
    // A render the layers were not compiled for stops at parse time: through the template's
    // own camera when they were solved for the corrected one (whose render scene checks the
    // size and the settings), or at another size.
    es.checks = corrected ? corrected_camera_check(ctx.name + ".ini")
                          : size_check(ctx.options.width, ctx.options.height);
    IniSettings ini;
    ini.scene = std::filesystem::absolute(ctx.options.scene).string();
    ini.output_image = image;
    ini.width = ctx.options.width;
    ini.height = ctx.options.height;
    ini.library_paths.push_back(out_dir);
    for (const auto& p : ctx.library_paths) ini.library_paths.push_back(p);
    ini.antialias = ctx.options.antialias;
    ini.clock = ctx.options.clock;
    ini.declares = ctx.options.declares;
    EmittedFiles f;
    f.include = layers_include(stack, es);
    f.csv = layers_csv(stack, es.camera_y);
    f.ini = render_ini(ini);
    return f;
}

}  // namespace mirage
