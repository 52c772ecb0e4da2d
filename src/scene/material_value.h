// The material items a scene may #declare besides pigments, finishes and textures: normals,
// interiors, materials, fogs and the maps (pigment_map, normal_map, texture_map,
// slope_map), held by one alternative of the parser's Value.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace mirage {

/// POV-Ray's material { texture interior }.
struct Material {
    std::optional<Texture> texture;
    std::optional<Interior> interior;
    std::optional<Texture> interior_texture;
};

struct MaterialValue {
    enum class Kind {
        Normal,
        Interior,
        Material,
        Fog,
        PigmentMap,
        NormalMap,
        TextureMap,
        SlopeMap
    };
    Kind kind = Kind::Normal;
    Normal normal;
    Interior interior;
    Material material;
    Fog fog;
    std::vector<PigmentMapEntry> pigment_map;
    std::vector<NormalMapEntry> normal_map;
    std::vector<TextureMapEntry> texture_map;
    std::vector<SlopeMapEntry> slope_map;

    /// "normal", "interior", "pigment_map"... for messages.
    std::string type_name() const {
        switch (kind) {
            case Kind::Normal:
                return "normal";
            case Kind::Interior:
                return "interior";
            case Kind::Material:
                return "material";
            case Kind::Fog:
                return "fog";
            case Kind::PigmentMap:
                return "pigment_map";
            case Kind::NormalMap:
                return "normal_map";
            case Kind::TextureMap:
                return "texture_map";
            case Kind::SlopeMap:
                return "slope_map";
        }
        return "material item";
    }
};

}  // namespace mirage
