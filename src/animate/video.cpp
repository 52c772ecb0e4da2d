#include "animate/video.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "util/atomic_file.h"
#include "util/format.h"
#include "util/process.h"

namespace mirage {

namespace fs = std::filesystem;

namespace {

std::string tail(const std::string& path, int lines) {
    std::ifstream in(path);
    std::vector<std::string> all;
    std::string line;
    while (std::getline(in, line)) all.push_back(line);
    std::string s;
    for (std::size_t i = all.size() > static_cast<std::size_t>(lines) ? all.size() - lines : 0;
         i < all.size(); ++i)
        s += "\n  " + all[i];
    return s;
}

Status run_ffmpeg(const VideoSettings& st, const std::vector<std::string>& args,
                  const std::string& target, const std::string& format) {
    const std::string tmp = temporary_name_for(target);
    std::vector<std::string> argv = {st.ffmpeg,
                                     "-nostdin",
                                     "-y",
                                     "-hide_banner",
                                     "-loglevel",
                                     "error",
                                     "-framerate",
                                     sig(st.fps, 6),
                                     "-start_number",
                                     std::to_string(st.first_number),
                                     "-i",
                                     st.pattern,
                                     "-frames:v",
                                     std::to_string(st.frame_count)};
    argv.insert(argv.end(), args.begin(), args.end());
    argv.insert(argv.end(), {"-f", format, tmp});
    std::ofstream(st.log, std::ios::app) << "$ ffmpeg ... " << target << "\n";
    auto run = run_process(argv, "", st.log);
    if (!run) return run.error();
    std::error_code ec;
    if (run->exit_code != 0 || !fs::exists(tmp, ec)) {
        fs::remove(tmp, ec);
        return make_error(target + ": ffmpeg failed (exit " + std::to_string(run->exit_code) +
                          ", " + st.log + "):" + tail(st.log, 5));
    }
    return commit_file(tmp, target);
}

}  // namespace

Status assemble_video(const VideoSettings& st) {
    if (st.frame_count < 1) return make_error(st.video + ": no frames to assemble");
    std::error_code ec;
    fs::remove(st.log, ec);
    // Even sizes for yuv420p; one thread, so that the same frames give the same bytes.
    if (auto s = run_ffmpeg(st,
                            {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-threads",
                             "1", "-pix_fmt", "yuv420p", "-crf", "18", "-movflags", "+faststart"},
                            st.video, "mp4");
        !s)
        return s;
    if (st.preview.empty()) return Ok{};
    const std::string filter = "scale=" + std::to_string(st.preview_width) +
                               ":-1:flags=lanczos,split[a][b];[a]palettegen[p];[b][p]paletteuse";
    return run_ffmpeg(st, {"-vf", filter, "-loop", "0"}, st.preview, "gif");
}

Result<int> count_video_frames(const std::string& path, const std::string& ffprobe) {
    const std::string log = temporary_name_for(path + ".ffprobe");
    auto run = run_process({ffprobe, "-v", "error", "-count_frames", "-select_streams", "v:0",
                            "-show_entries", "stream=nb_read_frames", "-of", "csv=p=0", path},
                           "", log);
    if (!run) return run.error();
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::error_code ec;
    fs::remove(log, ec);
    if (run->exit_code != 0) return make_error(path + ": ffprobe failed: " + text);
    try {
        return std::stoi(text);
    } catch (...) {
        return make_error(path + ": ffprobe said '" + text + "', not a frame count");
    }
}

}  // namespace mirage
