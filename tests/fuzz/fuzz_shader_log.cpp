// Fuzz target: the shader compile log parser (render/shader_log.h). Any bytes: the result is
// bounded by the cap plus its note, and the parse is linear (no backtracking).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "meshedit/overlay/shader_log.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view log(reinterpret_cast<const char*>(data), size);
    const std::string line = meshedit::readable_shader_log(log, 256);
    // The cap plus one rewritten location ("line N, column M: " is longer than "0:N(M): ") and
    // the "… (N more characters)" note.
    if (line.size() > 256 + 2 * size + 64 && line.size() > 4096) {
        std::abort();
    }
    if (line.find('\n') != std::string::npos || line.find('\r') != std::string::npos) {
        std::abort();
    }
    return 0;
}
