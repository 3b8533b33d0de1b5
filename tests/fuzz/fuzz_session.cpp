// Fuzz target: session files (`--ops @FILE`, the viewer's Ctrl+Shift+E): header lines, line
// ends of every kind (LF, CRLF, a lone CR) and comma lists on a line. When the file parses,
// its steps run on a small closed mesh and a small open one as fuzz_ops runs a list, and the
// result must validate; its header is read as convert reads it.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_common.h"
#include "fuzz_steps.h"
#include "meshedit/core/budget.h"
#include "meshedit/ops/ops.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace meshedit;
    static const bool ready = (fuzz::set_up(), true);
    (void)ready;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    (void)ops::session_header_value(text, "input-fnv1a64");
    std::vector<ops::Step> steps;
    try {
        steps = ops::parse_session(text);
    } catch (const ops::SyntaxError&) {
        return 0;
    } catch (const BudgetError&) {
        return 0;
    }
    fuzz::run_steps_on_two_meshes(steps, "a session left an invalid mesh");
    return 0;
}
