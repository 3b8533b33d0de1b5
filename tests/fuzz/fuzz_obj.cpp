// Fuzz target: the OBJ reader, then everything fuzz_common.h lists on what it read.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_common.h"
#include "meshedit/core/budget.h"
#include "meshedit/io/obj.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace meshedit;
    static const bool ready = (fuzz::set_up(), true);
    (void)ready;
    MeshSoup soup;
    try {
        soup = parse_obj(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.obj");
    } catch (const IoError&) {
        return 0;  // a clean refusal is what bad input should get
    } catch (const BudgetError&) {
        return 0;
    }
    fuzz::exercise(soup, fuzz::hash(data, size));
    return 0;
}
