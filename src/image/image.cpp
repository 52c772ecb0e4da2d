#include "image/image.h"

#include "util/check.h"

namespace mirage {

Image::Image(int width_, int height_) : width(width_), height(height_) {
    MIRAGE_CHECK(width_ >= 0 && height_ >= 0);
    pixels.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 3, 0.0f);
}

glm::vec3 Image::at(int x, int y) const {
    MIRAGE_CHECK(x >= 0 && x < width && y >= 0 && y < height);
    const std::size_t i = index(x, y);
    return glm::vec3(pixels[i], pixels[i + 1], pixels[i + 2]);
}

void Image::set(int x, int y, const glm::vec3& rgb) {
    MIRAGE_CHECK(x >= 0 && x < width && y >= 0 && y < height);
    const std::size_t i = index(x, y);
    pixels[i] = rgb.x;
    pixels[i + 1] = rgb.y;
    pixels[i + 2] = rgb.z;
}

}  // namespace mirage
