// Fuzz target: the .bez reader, then the patches tessellated (at a density the input picks)
// and everything fuzz_common.h lists on the welded mesh.

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "fuzz_common.h"
#include "meshedit/core/budget.h"
#include "meshedit/io/io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace meshedit;
    static const bool ready = (fuzz::set_up(), true);
    (void)ready;
    std::vector<BezierPatch> patches;
    try {
        patches = parse_bez(std::string_view(reinterpret_cast<const char*>(data), size), "f.bez");
    } catch (const IoError&) {
        return 0;
    }
    const std::uint64_t seed = fuzz::hash(data, size);
    for (const BezierPatch& patch : patches) {
        fuzz::check(is_finite(patch.evaluate(0.25, 0.75)),
                    "finite control points evaluated to a non-finite point");
    }
    TessellationOptions options;
    options.density = 1 + static_cast<int>(seed % 6);
    Mesh mesh;
    try {
        mesh = tessellate(patches, options);
    } catch (const BudgetError&) {
        return 0;
    }
    fuzz::exercise(std::move(mesh), seed >> 3);
    return 0;
}
