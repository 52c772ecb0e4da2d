// The libFuzzer target of the TrueType font reader (table_fuzz_input.h):
// `make fuzz FUZZ_TARGET=truetype` builds it with clang and runs it on its seeds.
#include <cstddef>
#include <cstdint>

#include "table_fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    mirage::fuzz::check_truetype_input(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
