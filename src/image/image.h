// An RGB image in memory: float samples, row-major from the top row, three per pixel.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

namespace mirage {

/// RGB float pixels.  What the values mean (linear radiance or encoded code values / 255)
/// is the producer's to say; the tracer writes linear values.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> pixels;  // width * height * 3 floats, top row first

    Image() = default;
    /// A black image of the given size (both >= 0).
    Image(int width, int height);

    bool empty() const { return width == 0 || height == 0; }
    std::size_t index(int x, int y) const {
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x)) *
               3;
    }
    glm::vec3 at(int x, int y) const;
    void set(int x, int y, const glm::vec3& rgb);
};

}  // namespace mirage
