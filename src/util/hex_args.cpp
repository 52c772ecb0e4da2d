#include "util/hex_args.h"

namespace mirage {

std::string args_to_hex(const std::vector<std::string>& args) {
    static const char digits[] = "0123456789abcdef";
    std::string hex;
    for (const std::string& a : args) {
        for (unsigned char c : a) {
            hex += digits[c >> 4];
            hex += digits[c & 15];
        }
        hex += "00";
    }
    return hex;
}

std::optional<std::vector<std::string>> args_from_hex(const std::string& hex) {
    auto value = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        return -1;
    };
    if (hex.size() % 2 != 0) return std::nullopt;
    std::vector<std::string> args;
    std::string current;
    for (std::size_t i = 0; i < hex.size(); i += 2) {
        const int hi = value(hex[i]), lo = value(hex[i + 1]);
        if (hi < 0 || lo < 0) return std::nullopt;
        const char c = static_cast<char>(hi * 16 + lo);
        if (c == '\0') {
            args.push_back(current);
            current.clear();
        } else {
            current += c;
        }
    }
    if (!current.empty()) return std::nullopt;  // an argument not ended
    return args;
}

}  // namespace mirage
