// A numbered sequence of frames made into an H.264 video and a small looping GIF with
// Debian's ffmpeg, each written under a temporary name and renamed.
#pragma once

#include <string>

#include "util/result.h"

namespace mirage {

struct VideoSettings {
    std::string ffmpeg = "ffmpeg";
    std::string pattern;   // printf pattern of the frames, e.g. frames/frame_%04d.png
    int first_number = 1;  // of the first frame
    int frame_count = 0;
    double fps = 12.0;
    int preview_width = 160;  // pixels; the height keeps the aspect ratio
    std::string video;        // .mp4 (H.264, yuv420p)
    std::string preview;      // .gif, looping; empty: none
    std::string log;          // ffmpeg's output
};

/// Makes the video, then the preview.  An error names what failed with the end of ffmpeg's log.
Status assemble_video(const VideoSettings& settings);

/// The number of video frames of a file, as ffprobe counts them (-count_frames); an error
/// when ffprobe cannot read it.
Result<int> count_video_frames(const std::string& path, const std::string& ffprobe = "ffprobe");

}  // namespace mirage
