// Fuzz target: the PLY reader, then everything fuzz_common.h lists on what it read.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_common.h"
#include "meshedit/io/ply.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return meshedit::fuzz::read_and_exercise(data, size, meshedit::parse_ply, "fuzz.ply");
}
