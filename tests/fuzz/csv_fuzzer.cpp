// The libFuzzer target of the batch CSV reader of `mirage path --batch` (table_fuzz_input.h):
// `make fuzz FUZZ_TARGET=csv` builds it with clang and runs it on its seeds.
#include <cstddef>
#include <cstdint>

#include "table_fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    mirage::fuzz::check_csv_input(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
