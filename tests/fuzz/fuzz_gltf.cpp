// Fuzz target: the glTF and GLB (the content decides which; no folder, so only embedded buffers)
// reader, then everything fuzz_common.h lists on what it read.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_common.h"
#include "meshedit/core/budget.h"
#include "meshedit/io/gltf.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace meshedit;
    static const bool ready = (fuzz::set_up(), true);
    (void)ready;
    MeshSoup soup;
    try {
        soup = parse_gltf(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.gltf");
    } catch (const IoError&) {
        return 0;  // a clean refusal is what bad input should get
    } catch (const BudgetError&) {
        return 0;
    }
    fuzz::exercise(soup, fuzz::hash(data, size));
    return 0;
}
