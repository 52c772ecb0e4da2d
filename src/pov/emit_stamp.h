// What a compiled atmosphere was compiled for, checked by POV-Ray at parse time: the
// scene's Mirage_... settings as they were declared.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace mirage {

/// One setting: its name, and its value when the scene declared it.
struct StampedSetting {
    std::string name;
    std::optional<Declared> declared;
};

/// The settings among `names` as `scene` declares them.
std::vector<StampedSetting> stamped_settings(const Scene& scene,
                                             const std::vector<std::string>& names);

/// SDL that stops POV-Ray with an #error naming the setting, its value now and the value
/// compiled, when a setting differs from `settings` (declared now and not then, or the
/// other way, or another value).  Numbers are
/// compared to a part in 1e12 of their size; a string holding a byte outside printable
/// ASCII is checked for being declared only.
std::string settings_check(const std::vector<StampedSetting>& settings);

/// SDL that stops POV-Ray with an #error naming both sizes when the render is not
/// `width` x `height`.
std::string size_check(int width, int height);

/// SDL that stops POV-Ray unless the scene being parsed declared Mirage_Corrected_Camera (the
/// render scene written with the corrected camera does): layers solved for that camera render
/// wrong through the template's own.  `ini` names what to render instead (the .ini's file
/// name: a long path would be cut from POV-Ray's message).
std::string corrected_camera_check(const std::string& ini);

}  // namespace mirage
