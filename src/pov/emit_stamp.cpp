#include "pov/emit_stamp.h"

#include <cmath>

#include "util/format.h"

namespace mirage {

namespace {

// An SDL string literal, or nothing when a byte cannot be written plainly.
std::optional<std::string> sdl_string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u > 0x7e) return std::nullopt;
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string vector_text(const glm::dvec3& v) {
    return "<" + shortest(v.x) + ", " + shortest(v.y) + ", " + shortest(v.z) + ">";
}

// The value as the message shows it (an SDL string expression).
std::string shown(const Declared& d) {
    if (const double* v = std::get_if<double>(&d.value)) return "\"" + shortest(*v) + "\"";
    if (const glm::dvec3* v = std::get_if<glm::dvec3>(&d.value))
        return "\"" + vector_text(*v) + "\"";
    const auto s = sdl_string(std::get<std::string>(d.value));
    return s ? "concat(\"\\\"\", " + *s + ", \"\\\"\")" : "\"a string\"";
}

// The value `name` has now (an SDL string expression), as `d`'s type.
std::string now(const std::string& name, const Declared& d) {
    if (std::holds_alternative<double>(d.value)) return "str(" + name + ", 0, -1)";
    if (std::holds_alternative<glm::dvec3>(d.value))
        return "concat(\"<\", vstr(3, " + name + ", \", \", 0, -1), \">\")";
    return "concat(\"\\\"\", " + name + ", \"\\\"\")";
}

// The SDL condition under which `name` differs from the declared value (it is declared).
std::optional<std::string> differs(const std::string& name, const Declared& d) {
    if (const double* v = std::get_if<double>(&d.value)) {
        const double scale = std::max(std::fabs(*v), 1e-300);
        return "abs(" + name + " - (" + shortest(*v) + ")) > " + shortest(1e-12 * scale);
    }
    if (const glm::dvec3* v = std::get_if<glm::dvec3>(&d.value)) {
        const double scale = std::max(std::fabs(v->x) + std::fabs(v->y) + std::fabs(v->z), 1e-300);
        return "vlength(" + name + " - " + vector_text(*v) + ") > " + shortest(1e-12 * scale);
    }
    const auto s = sdl_string(std::get<std::string>(d.value));
    if (!s) return std::nullopt;
    return "strcmp(" + name + ", " + *s + ") != 0";
}

}  // namespace

std::vector<StampedSetting> stamped_settings(const Scene& scene,
                                             const std::vector<std::string>& names) {
    std::vector<StampedSetting> out;
    for (const auto& n : names) {
        StampedSetting s{n, std::nullopt};
        if (const auto it = scene.symbols.find(n); it != scene.symbols.end())
            s.declared = it->second;
        out.push_back(std::move(s));
    }
    return out;
}

std::string settings_check(const std::vector<StampedSetting>& settings) {
    // Short: POV-Ray cuts an #error message past about 150 characters.
    const std::string again = ": run mirage compile again\")";
    std::string out;
    for (const auto& s : settings) {
        const std::string said = "    #error concat(\"mirage: " + s.name;
        if (!s.declared) {
            out += "#ifdef (" + s.name + ")\n" + said + " is declared now, compiled without it" +
                   again + "\n#end\n";
            continue;
        }
        out += "#ifndef (" + s.name + ")\n" + said + " is not declared now, compiled with \", " +
               shown(*s.declared) + ", \"" + again + "\n";
        // A value of another type than compiled (a string for a number) fails to parse in
        // the comparison: POV-Ray's own message names the line.
        if (const auto cond = differs(s.name, *s.declared))
            out += "#elseif (" + *cond + ")\n" + said + " = \", " + now(s.name, *s.declared) +
                   ", \" now, compiled with \", " + shown(*s.declared) + ", \"" + again + "\n";
        out += "#end\n";
    }
    return out;
}

std::string size_check(int width, int height) {
    const std::string w = std::to_string(width), h = std::to_string(height);
    return "#if (image_width != " + w + " | image_height != " + h + ")\n" +
           "    #error concat(\"mirage: this atmosphere was compiled for " + w + "x" + h +
           ", not \", str(image_width, 0, 0), \"x\", str(image_height, 0, 0), \": run mirage "
           "compile again for that size\")\n#end\n";
}

std::string corrected_camera_check(const std::string& ini) {
    const auto name = sdl_string(ini);
    return "#ifndef (Mirage_Corrected_Camera)\n    #error concat(\"mirage: these layers are for "
           "the corrected camera: render \", " +
           (name ? *name : std::string("\"the compiled .ini\"")) + ", \" beside them\")\n#end\n";
}

}  // namespace mirage
