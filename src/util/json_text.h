// JSON as text from any bytes: every JSON file and every JSON printed goes through here, so
// that a name that is not UTF-8 (a scene, a folder, a Marked_Name) cannot stop a command.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace mirage {

/// `j` as text (`indent` < 0: on one line); bytes that are not UTF-8 become U+FFFD.
std::string json_text(const nlohmann::json& j, int indent = 2);

}  // namespace mirage
