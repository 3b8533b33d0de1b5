// The session: every mesh edit is recorded in the document as steps of the edit language
// (Document::session, kept in step with undo and redo because it is part of what they
// restore), and exported as a file `meshedit convert IN OUT --ops @FILE` replays to the same
// mesh, bit for bit: a teacher's demo, a student's steps for a grader.

#include <string>
#include <vector>

#include "meshedit/files/files.h"
#include "meshedit/ops/ops.h"
#include "meshedit/viewer/editor.h"

namespace meshedit::viewer {

Outcome Editor::export_session(const std::filesystem::path& path) {
    if (std::optional<Outcome> busy = refuse_if_busy()) {
        return *busy;
    }
    if (doc_.mode != Mode::Mesh) {
        return refused(std::string("sessions record the edits of mesh files, not of a ") +
                       kind_name(doc_.mode));
    }
    end_drag();
    if (Outcome confirmed = confirm_modal(); confirmed.refused) {
        return confirmed;
    }
    const std::string input = session_source_.empty() ? "(none)" : session_source_.string();
    std::vector<std::string> header = {
        "MeshEdit session: " + std::to_string(doc_.session.size()) + " steps",
        "replay: meshedit convert " + input + " OUT --ops @" + path.filename().string(),
        "input: " + input};
    if (!session_source_hash_.empty()) {
        header.push_back("input-fnv1a64: " + session_source_hash_);
    }
    try {
        const std::string text = ops::session_text(header, doc_.session);
        write_atomically(path, [&](const std::filesystem::path& tmp) { write_file(tmp, text); });
    } catch (const IoError& e) {
        return refused(e.what());
    }
    return {kNothing, "exported " + std::to_string(doc_.session.size()) + " steps to " +
                          path.filename().string() + " (meshedit convert IN OUT --ops @" +
                          path.filename().string() + " replays them)"};
}

}  // namespace meshedit::viewer
