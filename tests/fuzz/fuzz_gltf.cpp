// Fuzz target: the glTF and GLB (the content decides which; no folder, so only embedded buffers)
// reader, then everything fuzz_common.h lists on what it read.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_common.h"
#include "meshedit/io/gltf.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // No folder: only buffers embedded in the file (data URIs, the GLB binary chunk).
    return meshedit::fuzz::read_and_exercise(
        data, size,
        [](std::string_view bytes, const std::string& name) {
            return meshedit::parse_gltf(bytes, name, std::nullopt);
        },
        "fuzz.gltf");
}
