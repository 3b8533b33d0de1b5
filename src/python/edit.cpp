// Running the edit language on a Python mesh: all steps or none, errors as Python exceptions.
#include <utility>

#include "meshedit/ops/ops.h"
#include "py_mesh.h"

namespace meshedit::python {

std::vector<std::string> apply_text(PyMesh& target, const std::string& text, bool session,
                                    ElementRef* last) {
    const std::vector<ops::Step> steps = session ? ops::parse_session(text) : ops::parse(text);
    release_views(target);
    std::vector<std::string> notices;
    ops::ApplyOptions options;
    options.notice = [&notices](const std::string& line) { notices.push_back(line); };
    // One step checks before it changes anything; a longer list runs on a copy, so that a
    // refusal half-way leaves the mesh as it was (the CLI writes nothing instead).
    try {
        ElementRef selected;
        if (steps.size() <= 1) {
            selected = ops::apply_steps(target.mesh, steps, options);
        } else {
            Mesh copy = target.mesh;
            selected = ops::apply_steps(copy, steps, options);
            target.mesh = std::move(copy);
        }
        if (last != nullptr) {
            *last = selected;
        }
    } catch (const ops::OpError& e) {
        if (e.refused()) {
            throw Refused(e.what());
        }
        throw BadStep(e.what());
    }
    ++target.version;
    return notices;
}

}  // namespace meshedit::python
