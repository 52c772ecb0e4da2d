#include "animate/animate_report.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "animate/frame_plan.h"
#include "util/atomic_file.h"
#include "util/format.h"
#include "util/json_text.h"
#include "util/process.h"
#include "report/gnuplot_run.h"

namespace mirage {

namespace fs = std::filesystem;

namespace {

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string gp_quote(const std::string& s) {
    std::string q = "\"";
    for (char c : s) q += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
    return q + "\"";
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string plot_script(const AnimationSummary& s, const std::vector<VanishingRow>& rows,
                        const std::vector<std::string>& names) {
    std::ostringstream gp;
    gp << "# " << s.name << ": the mirrored images of the marked objects against the eye's\n"
       << "# distance, from the exact paths.  Written by mirage animate; run it in this\n"
       << "# directory: gnuplot -e \"png_out='vanishing.png'; svg_out='vanishing.svg'\" "
          "vanishing.gp\n";
    for (std::size_t k = 0; k < names.size(); ++k) {
        gp << "$m" << k << " << EOD\n";
        for (const auto& r : rows)
            if (r.view.name == names[k])
                gp << shortest(r.view.eye_distance) << " " << shortest(r.view.angular_size_deg)
                   << "\n";
        gp << "EOD\n";
    }
    gp << "set title "
       << gp_quote(s.name + ": the mirrored image of each marked object (" +
                   std::to_string(s.width) + "x" + std::to_string(s.height) + ")")
       << " noenhanced\n"
       << "set xlabel \"horizontal distance from the eye to the object's centre, m\"\n"
       << "set ylabel \"vertical angular size of the mirrored image, degrees\"\n"
       << "set grid lc rgb \"#dddddd\"\n"
       << "set key top left box opaque noenhanced\n"
       << "set yrange [0:*]\n"
       << "set offsets graph 0.02, graph 0.02, graph 0.1, 0\n";
    const char* colours[] = {"#c0392b", "#2e5cb8", "#2e8b57", "#8e44ad", "#d35400"};
    std::ostringstream plot;
    plot << "plot ";
    for (std::size_t k = 0; k < names.size(); ++k) {
        double vanish = 0.0;
        for (const auto& r : rows)
            if (r.view.name == names[k]) vanish = r.view.vanishing_distance;
        const std::string colour = colours[k % 5];
        if (k > 0) plot << ", \\\n     ";
        // The vanishing distance: a dashed line in the object's colour.
        gp << "set arrow from " << shortest(vanish) << ", graph 0 to " << shortest(vanish)
           << ", graph 1 nohead dt 2 lw 1.5 lc rgb " << gp_quote(colour) << "\n";
        plot << "$m" << k << " using 1:2 with linespoints lw 2 pt 7 ps 0.8 lc rgb "
             << gp_quote(colour) << " title "
             << gp_quote(names[k] + " (no mirrored image nearer than " + sig(vanish, 4) + " m)");
    }
    gp << "if (strstrt(GPVAL_TERMINALS, \"pngcairo\") > 0) {\n"
       << "    set terminal pngcairo size 900,560 font \"DejaVu Sans,11\"\n"
       << "} else {\n"
       << "    set terminal png size 900,560\n"
       << "}\n"
       << "set output png_out\n"
       << plot.str() << "\n"
       << "set terminal svg size 900,560 dynamic font \"DejaVu Sans,11\"\n"
       << "set output svg_out\n"
       << "replot\n"
       << "set output\n";
    return gp.str();
}

}  // namespace

Result<ReportFiles> write_animation_report(const AnimationSummary& s,
                                           const std::vector<VanishingRow>& rows) {
    ReportFiles f;
    const fs::path dir = s.out_dir;
    f.csv = (dir / "vanishing.csv").string();
    f.script = (dir / "vanishing.gp").string();
    f.summary = (dir / "summary.md").string();
    f.json = (dir / "report.json").string();

    std::ostringstream csv;
    csv << "frame,clock,object,eye_distance_m,vanishing_distance_m,mirrored,angular_size_deg,"
           "angular_size_px,elevation_low_deg,elevation_high_deg\n";
    std::vector<std::string> names;
    for (const auto& r : rows) {
        if (std::find(names.begin(), names.end(), r.view.name) == names.end())
            names.push_back(r.view.name);
        const MarkedView& v = r.view;
        csv << r.frame << "," << clock_text(r.clock) << "," << csv_field(v.name) << ","
            << sig(v.eye_distance, 9) << "," << sig(v.vanishing_distance, 9) << ","
            << (v.mirrored ? 1 : 0) << "," << sig(v.angular_size_deg, 6) << ","
            << sig(v.angular_size_px, 6) << "," << sig(v.elevation_low_deg, 6) << ","
            << sig(v.elevation_high_deg, 6) << "\n";
    }
    if (auto w = write_file_atomic(f.csv, csv.str()); !w) return w.error();

    if (!names.empty()) {
        if (auto w = write_file_atomic(f.script, plot_script(s, rows, names)); !w) return w.error();
        if (!find_program(s.gnuplot)) {
            f.notes.push_back(s.gnuplot + " is not on PATH: no plot drawn (run vanishing.gp)");
        } else {
            const std::string png = (dir / "vanishing.png").string(),
                              svg = (dir / "vanishing.svg").string();
            const std::string png_tmp = (dir / ".vanishing.tmp.png").string(),
                              svg_tmp = (dir / ".vanishing.tmp.svg").string();
            const std::string log = (dir / "gnuplot.log").string();
            std::error_code ec;
            fs::remove(log, ec);
            auto run = run_process(
                {s.gnuplot, "-e",
                 "png_out=" + gnuplot_quoted(png_tmp) + "; svg_out=" + gnuplot_quoted(svg_tmp),
                 f.script},
                dir.string(), log);
            if (!run) return run.error();
            if (run->exit_code != 0 || !fs::exists(png_tmp, ec) || !fs::exists(svg_tmp, ec)) {
                fs::remove(png_tmp, ec);
                fs::remove(svg_tmp, ec);
                f.notes.push_back("gnuplot failed (" + log + "): no plot drawn");
            } else {
                if (auto c = commit_file(png_tmp, png); !c) return c.error();
                if (auto c = commit_file(svg_tmp, svg); !c) return c.error();
                f.png = png;
                f.svg = svg;
            }
        }
    }

    std::vector<double> times;
    for (const auto& fr : s.frames)
        if (fr.rendered_now && fr.seconds > 0.0) times.push_back(fr.seconds);
    std::ostringstream md;
    md << "# " << s.name << ": animation\n\n"
       << "- scene: `" << s.scene << "`\n"
       << "- " << s.frames.size() << " frames at " << s.width << "x" << s.height << ", " << s.model
       << " model, " << s.threads << " thread(s) per frame, " << s.runner << "\n"
       << "- every frame's task: `" << s.frame_command << "` (N the frame)\n"
       << "- machine: " << s.machine << "\n"
       << "- frames rendered in this run: " << times.size() << ", wall time "
       << sig(s.frames_seconds, 4) << " s";
    if (!times.empty())
        md << ", median " << sig(median(times), 4) << " s per frame (its task's wall time)";
    md << "; video and preview " << sig(s.assemble_seconds, 3) << " s\n\n";
    md << "| frame | clock | seconds |\n|---|---|---|\n";
    for (const auto& fr : s.frames)
        md << "| " << fr.number << " | " << clock_text(fr.clock) << " | "
           << (fr.rendered_now ? sig(fr.seconds, 4) : std::string("done before")) << " |\n";
    if (!names.empty()) {
        md << "\n## The mirrored images of the marked objects\n\n"
           << "From the exact paths of the scene's atmosphere, in the vertical plane through the "
              "eye and each object's centre; `vanishing.csv`, plotted in `vanishing.png`.\n\n"
           << "| object | vanishes nearer than (m) | frames with a mirrored image "
              "|\n|---|---|---|\n";
        for (const auto& n : names) {
            int with = 0, all = 0;
            double vanish = 0.0;
            for (const auto& r : rows)
                if (r.view.name == n) {
                    ++all;
                    with += r.view.mirrored ? 1 : 0;
                    vanish = r.view.vanishing_distance;
                }
            md << "| " << n << " | " << sig(vanish, 5) << " | " << with << " of " << all << " |\n";
        }
        md << "\n![mirrored image against distance](vanishing.png)\n";
    }
    if (auto w = write_file_atomic(f.summary, md.str()); !w) return w.error();

    nlohmann::json j;
    j["scene"] = s.scene;
    j["model"] = s.model;
    j["width"] = s.width;
    j["height"] = s.height;
    j["runner"] = s.runner;
    j["threads_per_frame"] = s.threads;
    j["frames_seconds"] = s.frames_seconds;
    j["assemble_seconds"] = s.assemble_seconds;
    j["median_frame_seconds"] = median(times);
    j["machine"] = s.machine;
    nlohmann::json frames = nlohmann::json::array();
    for (const auto& fr : s.frames)
        frames.push_back({{"frame", fr.number},
                          {"clock", fr.clock},
                          {"seconds", fr.seconds},
                          {"rendered_now", fr.rendered_now}});
    j["frames"] = frames;
    nlohmann::json marked = nlohmann::json::array();
    for (const auto& r : rows)
        marked.push_back({{"frame", r.frame},
                          {"object", r.view.name},
                          {"eye_distance_m", r.view.eye_distance},
                          {"vanishing_distance_m", r.view.vanishing_distance},
                          {"mirrored", r.view.mirrored},
                          {"angular_size_deg", r.view.angular_size_deg}});
    j["marked"] = marked;
    if (auto w = write_file_atomic(f.json, json_text(j) + "\n"); !w) return w.error();
    return f;
}

}  // namespace mirage
