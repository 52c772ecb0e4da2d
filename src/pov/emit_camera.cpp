#include "pov/emit_camera.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

#include "image/image_io.h"
#include "layers/band_aim.h"
#include "pov/povray_path.h"
#include "util/check.h"
#include "util/format.h"

namespace mirage {

namespace {

// 2^-40: the mesh's scale (exact in decimal to 17 digits: the nearest double is 2^-40).
constexpr const char* kMeshScale = "9.0949470177292824e-13";

void append_float(std::string& out, float v) {
    char buf[32];
    if (v == 0.0f) v = 0.0f;  // no "-0"
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

void append_int(std::string& out, long v) {
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

// A vertex by its bits (float32 components; -0 is written as 0 and keyed as 0).
struct VertexKey {
    uint32_t x, y, z;
    explicit VertexKey(const glm::vec3& p) : x(bits(p.x)), y(bits(p.y)), z(bits(p.z)) {}
    static uint32_t bits(float v) {
        if (v == 0.0f) v = 0.0f;
        uint32_t b;
        std::memcpy(&b, &v, sizeof b);
        return b;
    }
    bool operator==(const VertexKey&) const = default;
};

struct VertexKeyHash {
    size_t operator()(const VertexKey& k) const {
        uint64_t h = k.x;
        h = h * 0x9E3779B97F4A7C15ull ^ k.y;
        h = h * 0x9E3779B97F4A7C15ull ^ k.z;
        return static_cast<size_t>(h ^ (h >> 29));
    }
};

void append_vertex(std::string& out, const glm::vec3& p) {
    out += '<';
    append_float(out, p.x);
    out += ',';
    append_float(out, p.y);
    out += ',';
    append_float(out, p.z);
    out += '>';
}

}  // namespace

std::string mesh_camera_include(const MeshCameraSettings& st) {
    MIRAGE_CHECK(st.width > 0 && st.height > 0 && !st.samples.empty());
    const size_t faces = static_cast<size_t>(st.width) * st.height;
    std::string out;
    out.reserve(st.samples.size() * faces * 64 + 4096);
    for (const auto& line : st.header) out += "// " + line + "\n";
    out += "//\n// One mesh per sample of a pixel; face y * " + std::to_string(st.width) +
           " + x is pixel (x, y)'s ray, along its flat normal from the eye.\n\n";
    for (size_t m = 0; m < st.samples.size(); ++m) {
        const std::vector<glm::dvec3>& dirs = st.samples[m];
        MIRAGE_CHECK(dirs.size() == faces);
        out += "#declare Mirage_Camera_Mesh_" + std::to_string(m) + " = mesh2 {\n";
        // Faces share their vertices where they are equal (a level camera's rows share one,
        // its columns the other), which leaves POV-Ray far fewer numbers to parse.
        std::vector<glm::vec3> vertices{glm::vec3(0.0f)};
        std::unordered_map<VertexKey, long, VertexKeyHash> index_of;
        std::vector<std::array<long, 2>> face_vertices(faces);
        const auto vertex_index = [&](const glm::vec3& p) {
            const auto [it, added] =
                index_of.try_emplace(VertexKey{p}, static_cast<long>(vertices.size()));
            if (added) vertices.push_back(p);
            return it->second;
        };
        for (size_t f = 0; f < faces; ++f) {
            const MeshFace face = mesh_face(mesh_direction(dirs[f]));
            face_vertices[f] = {vertex_index(face.p2), vertex_index(face.p3)};
        }
        out += "    vertex_vectors { ";
        append_int(out, static_cast<long>(vertices.size()));
        out += ",\n";
        for (size_t k = 0; k < vertices.size(); ++k) {
            if (k > 0) out += ',';
            append_vertex(out, vertices[k]);
            if (k % 4 == 3) out += '\n';
        }
        out += "\n    }\n    face_indices { ";
        append_int(out, static_cast<long>(faces));
        out += ",\n";
        for (size_t f = 0; f < faces; ++f) {
            out += "<0,";
            append_int(out, face_vertices[f][0]);
            out += ',';
            append_int(out, face_vertices[f][1]);
            out += f + 1 < faces ? ">," : ">";
            if (f % 8 == 7) out += '\n';
        }
        out += "\n    }\n}\n\n";
    }
    out += "#declare Mirage_Camera = camera {\n    mesh_camera {\n        ";
    out += std::to_string(st.samples.size()) + " 0\n";
    const std::string eye =
        "<" + sig(st.eye.x, 17) + ", " + sig(st.eye.y, 17) + ", " + sig(st.eye.z, 17) + ">";
    for (size_t m = 0; m < st.samples.size(); ++m)
        out += "        mesh { Mirage_Camera_Mesh_" + std::to_string(m) + " scale " + kMeshScale +
               " translate " + eye + " }\n";
    out += "    }\n    location <0, 0, 0>\n    direction <0, 0, 1>\n}\n";
    return out;
}

std::string render_scene(const RenderSceneSettings& st) {
    // Paths POV-Ray can take (check_povray_path): quoted, they are SDL strings too.
    const std::string scene = povray_quoted(st.scene);
    const std::string camera = povray_quoted(st.camera_include);
    std::string out;
    for (const auto& line : st.header) out += "// " + line + "\n";
    out += "#version 3.7;\n\n";
    out += "#if (image_width != " + std::to_string(st.width) +
           " | image_height != " + std::to_string(st.height + 1) + ")\n";
    out += "    #error concat(\"mirage: this camera was solved for " + std::to_string(st.width) +
           "x" + std::to_string(st.height) + " (rendered " + std::to_string(st.width) + "x" +
           std::to_string(st.height + 1) +
           ", the top row dropped after), not \", str(image_width, 0, 0), \"x\", "
           "str(image_height, 0, 0), \": run mirage compile again for that size\")\n";
    out += "#end\n\n";
    out += "#declare Mirage_Corrected_Camera = 1;\n";
    out += "#include " + scene + "\n\n";
    out += "#ifndef (Mirage_Inc_Temp)\n";
    out += "    #error concat(\"mirage: \", " + scene +
           ", \" never includes mirage.inc: the atmosphere is missing (add #include "
           "\\\"mirage.inc\\\" after its #version)\")\n";
    out += "#end\n\n";
    if (!st.settings_check.empty()) {
        out += "// The template's Mirage_ settings as they were compiled.\n";
        out += st.settings_check + "\n";
    }
    out += "// The scene's camera replaced by the corrected one.\n";
    out += "#include " + camera + "\n";
    out += "camera { Mirage_Camera }\n";
    return out;
}

Status crop_mesh_camera_render(const std::string& png) {
    auto im = read_image(png);
    if (!im) return im.error();
    if (im->height < 2) return make_error(png + ": not a mesh camera's render (one row)");
    Image cropped(im->width, im->height - 1);
    std::copy(im->pixels.begin() + static_cast<std::ptrdiff_t>(im->index(0, 1)), im->pixels.end(),
              cropped.pixels.begin());
    return write_png_codes(cropped, png);
}

}  // namespace mirage
