// What every command is given to read a scene: the scene file, the image size and the
// include folders.  Each command's options embed it (CompileOptions, TraceOptions,
// CompareOptions, StudyOptions, FrameOptions), so that one command hands it to another whole.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace mirage {

struct SceneInput {
    std::string scene;                       // the .pov file
    int width = 320, height = 240;           // the image's size, pixels
    std::vector<std::string> library_paths;  // extra include directories, searched first
    // Replaces the air's wavelength (Mirage_Wavelength), nm: one channel of a colour render
    // (docs/colour.md).  Unset: the scene's.
    std::optional<double> wavelength_nm;

    /// This part of a command's options, to hand to another command's options whole:
    /// `compile_options.input() = study_options.input();`.
    SceneInput& input() { return *this; }
    const SceneInput& input() const { return *this; }
};

}  // namespace mirage
