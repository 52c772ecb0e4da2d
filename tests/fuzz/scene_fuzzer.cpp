// The libFuzzer target of the scene parser and the Mirage_ settings reader: `make fuzz`
// builds it with clang (AddressSanitizer, UndefinedBehaviorSanitizer) and runs it, seeded
// from scenes/, pov_includes/, the test snippets and tests/fuzz/crashes/ with a dictionary
// of the scene language's words (tools/fuzz_corpus.py).
#include <cstddef>
#include <cstdint>

#include "scene_fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    mirage::fuzz::check_scene_input(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
