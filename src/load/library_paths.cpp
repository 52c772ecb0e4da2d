#include "load/library_paths.h"

#include <filesystem>

namespace mirage {

std::vector<std::string> default_library_paths(const std::string& scene) {
    namespace fs = std::filesystem;
    std::vector<std::string> paths;
    paths.push_back(fs::absolute(fs::path(scene)).parent_path().string());
#ifdef MIRAGE_POV_INCLUDES
    paths.push_back(MIRAGE_POV_INCLUDES);
#endif
    paths.push_back("/usr/share/povray-3.7/include");
    return paths;
}

}  // namespace mirage
