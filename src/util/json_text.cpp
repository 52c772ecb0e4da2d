#include "util/json_text.h"

namespace mirage {

std::string json_text(const nlohmann::json& j, int indent) {
    // nlohmann's default handler throws type_error 316 at the first byte that is not UTF-8.
    return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace mirage
