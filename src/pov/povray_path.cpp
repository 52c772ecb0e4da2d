#include "pov/povray_path.h"

#include "util/text_escape.h"

namespace mirage {

std::string povray_path_problem(const std::string& path) {
    for (unsigned char c : path) {
        if (c == '\n' || c == '\r')
            return "a line end, and POV-Ray's .ini cannot hold one in a value (the rest of the "
                   "name would be read as options of its own)";
        if (c < 0x20 || c == 0x7F)
            return "a control character, which POV-Ray's .ini cannot hold in a value";
        if (c == '"') return "a '\"', which ends a quoted value in POV-Ray's .ini";
        if (c == '\\') return "a '\\', which POV-Ray 3.7 reads as an escape in a file name";
        if (c >= 0x80)
            return "a byte outside ASCII, which POV-Ray 3.7 loses on the way to the file system "
                   "(it cannot open such a file)";
    }
    return "";
}

Status check_povray_path(const std::string& path, const std::string& what) {
    const std::string why = povray_path_problem(path);
    if (why.empty()) return Ok{};
    return make_error(escape_control(path) + ": " + what +
                      " is read by POV-Ray, and its path holds " + why + "; rename it");
}

std::string povray_quoted(const std::string& path) { return "\"" + path + "\""; }

}  // namespace mirage
