// Fuzz target: the COLLADA reader, then everything fuzz_common.h lists on what it read.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_common.h"
#include "meshedit/io/collada.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return meshedit::fuzz::read_and_exercise(
        data, size,
        [](std::string_view bytes, const std::string& name) {
            return meshedit::parse_collada(std::string(bytes), name);
        },
        "fuzz.dae");
}
