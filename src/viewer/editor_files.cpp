// The editor's files: open, save, save as, and the window title.

#include <memory>
#include <stdexcept>
#include <utility>

#include "meshedit/files/files.h"
#include "meshedit/io/document.h"
#include "meshedit/io/io.h"
#include "meshedit/viewer/editor.h"
#include "meshedit/viewer/paths.h"

namespace meshedit::viewer {

namespace {

std::string file_name(const std::filesystem::path& path) {
    return path.empty() ? std::string("untitled") : path.filename().string();
}

std::string counts(const Mesh& mesh) {
    return "V " + std::to_string(mesh.n_vertices()) + " E " + std::to_string(mesh.n_edges()) +
           " F " + std::to_string(mesh.n_faces());
}

std::string join(const std::vector<std::string>& parts) {
    std::string out;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        out += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
    }
    return out;
}

/// Multi-line summaries as one status line.
std::string one_line(std::string text) {
    while (!text.empty() && text.back() == '\n') {
        text.pop_back();
    }
    for (std::size_t i = text.find('\n'); i != std::string::npos; i = text.find('\n', i)) {
        text.replace(i, 1, "; ");
    }
    return text;
}

// Whether the shape is much taller along Z than along Y (and as wide along Z as along X):
// Z-up data declared Y-up, as the CS184 course's models are, lies on its side.
bool stands_along_z(const Mesh& mesh) {
    BoundingBox box;
    for (const Vertex v : mesh.vertices()) {
        box.add(mesh.position(v));
    }
    if (box.is_empty()) {
        return false;
    }
    const Vec3 size = box.max - box.min;
    return size.z > 1.5 * size.y && size.z >= size.x;
}

// A hint when most edges are borders: faces that share no vertices (an STL-like soup, or a
// file split at every normal or UV seam, as Blender's PLY export) look whole but are
// thousands of parts, and repair's merge by distance is the remedy a new user cannot guess.
std::string unwelded_hint(const Mesh& mesh) {
    std::size_t borders = 0;
    for (const Edge e : mesh.edges()) {
        borders += mesh.is_boundary(e) ? 1 : 0;
    }
    if (mesh.n_edges() < 12 || 2 * borders < mesh.n_edges()) {
        return {};
    }
    return "; " + std::to_string(borders) + " of its " + std::to_string(mesh.n_edges()) +
           " edges are borders: if its faces should join, Alt+Shift+R repairs it (merges "
           "vertices by distance, orients faces)";
}

}  // namespace

Outcome Editor::open(const std::filesystem::path& path, bool discard_confirmed) {
    if (std::optional<Outcome> busy = refuse_if_busy()) {
        return *busy;
    }
    if (dirty() && !ledger_.replace_armed && !discard_confirmed) {
        ledger_.replace_armed = true;
        return refused("unsaved changes to " + file_name(path_) +
                       ": open again to discard them, or Ctrl+S to save first");
    }
    // Everything is read into a local document first: an IoError leaves the editor as it was.
    const auto hash_of = [](const std::filesystem::path& file) {
        try {
            return content_hash(read_file(file));
        } catch (const IoError&) {
            return std::string();  // read a moment ago; a session file just lacks the hash
        }
    };
    if (background_) {
        struct Read {
            LoadedDocument loaded;
            std::string hash;
        };
        auto read = std::make_shared<Read>();
        auto work = [this, read, path, hash_of](Job&) {
            try {
                read->loaded = read_document(path);
                read->hash = hash_of(path);
            } catch (const std::exception& e) {
                throw std::runtime_error(open_failure(path, e));
            }
        };
        auto finish = [this, read, path] {
            return take_loaded(path, std::move(read->loaded), std::move(read->hash));
        };
        return start_job("open " + file_name(path), true, false, std::move(work),
                         std::move(finish));
    }
    LoadedDocument loaded = read_document(path);
    return take_loaded(path, std::move(loaded), hash_of(path));
}

std::string Editor::open_failure(const std::filesystem::path& path, const std::exception& e) const {
    // IoError names the file itself; anything else (no memory) gets the path added.
    std::string message = dynamic_cast<const IoError*>(&e) != nullptr
                              ? std::string(e.what())
                              : path.string() + ": " + e.what();
    if (!path_.empty()) {
        message += " — " + path_.filename().string() + " stays open";
    }
    return message;
}

Outcome Editor::take_loaded(const std::filesystem::path& path, LoadedDocument loaded,
                            std::string hash) {
    Document doc;
    doc.mode = loaded.kind;
    doc.mesh = std::move(loaded.mesh);
    doc.patches = std::move(loaded.patches);
    doc.density = loaded.density;
    doc.curve = std::move(loaded.curve);
    std::string details = doc.mode == Mode::Curve
                              ? std::to_string(doc.curve.control_points.size()) + " control points"
                          : doc.mode == Mode::Surface
                              ? std::to_string(doc.patches.size()) + " patches, " + counts(doc.mesh)
                              : counts(doc.mesh);
    if (loaded.repairs.repaired()) {
        details += "; repaired: " + one_line(loaded.repairs.summary());
    }
    for (const std::string& notice : loaded.notices) {
        details += "; " + notice;
    }
    const Mode mode = doc.mode;
    set_document(std::move(doc), path);
    session_source_hash_ = std::move(hash);
    load_repairs_ = std::move(loaded.repairs);
    load_revision_ = doc_.revision;
    problems_.reset();
    if (load_repaired()) {
        find_problems();  // the Problems panel lists the repairs where they are
    }
    if (mode == Mode::Surface) {
        pristine_revisions_.insert(doc_.revision);
    }
    // Each file opens with its own up axis (issue 40: the choice for one file turned the
    // next): the command line's for the first, else the one remembered for its content,
    // else +Y as declared — with a hint when the shape stands along Z instead.
    const char remembered = remembered_up(session_source_hash_);
    if (up_for_next_open_) {
        view_.up = *up_for_next_open_;
        up_for_next_open_.reset();
    } else {
        view_.up = remembered == 'z' ? UpAxis::Z : UpAxis::Y;
    }
    if (mode == Mode::Mesh) {
        details += unwelded_hint(doc_.mesh);
    }
    if (remembered == 0 && view_.up == UpAxis::Y && mode != Mode::Curve &&
        stands_along_z(doc_.mesh)) {
        details += "; it stands along Z, not up: if it lies on its side, Y stands it up";
    }
    return {kDocument | kTopology | kGeometry | kSelection | kDisplay | kCurve | kResetCamera,
            "opened " + file_name(path) + ": " + details};
}

void Editor::set_document(Document document, std::filesystem::path path) {
    end_drag();
    cancel_modal();
    document.selection = {};
    ledger_.start(doc_, std::move(document));
    pristine_revisions_.clear();
    hover_ = {};
    diagram_.reset();
    path_ = std::move(path);
    session_source_ = path_;
    session_source_hash_.clear();
    view_.level = 0;
    view_.t = 0.5;
    // Flat below kSmoothFromFaces faces, as CS184 starts: on a cube or an icosahedron the
    // facets are what one edits. Smooth above, where the faces approximate a curved shape.
    view_.render.smooth = doc_.mode != Mode::Curve && doc_.mesh.n_faces() >= kSmoothFromFaces;
}

Outcome Editor::save() {
    if (path_.empty()) {
        return refused("no file name: use Ctrl+Shift+S");
    }
    const std::string ext = file_extension(path_);
    if (doc_.mode == Mode::Curve && ext != ".bzc") {
        return refused("a curve is saved as .bzc: use Ctrl+Shift+S");
    }
    if (doc_.mode != Mode::Curve && !is_mesh_extension(ext) &&
        !(doc_.mode == Mode::Surface && ext == ".bez")) {
        return refused("cannot save a mesh as '" + ext + "': use Ctrl+Shift+S with " +
                       mesh_extensions());
    }
    return write_to(path_);
}

Outcome Editor::save_as(const std::filesystem::path& path) {
    if (std::optional<Outcome> busy = refuse_if_busy()) {
        return *busy;
    }
    const std::string ext = file_extension(path);
    if (doc_.mode == Mode::Curve && ext != ".bzc") {
        return refused("a curve is saved as .bzc, not '" + ext + "'");
    }
    if (doc_.mode == Mode::Surface && ext != ".bez" && !is_mesh_extension(ext)) {
        return refused("a surface is saved as .bez (its patches) or as " +
                       std::string(mesh_extensions()) + " (its tessellation), not '" + ext + "'");
    }
    if (doc_.mode == Mode::Mesh && !is_mesh_extension(ext)) {
        return refused("a mesh is saved as " + std::string(mesh_extensions()) + ", not '" + ext +
                       "'");
    }
    return write_to(path);  // the document takes the path once it is written
}

Outcome Editor::write_to(const std::filesystem::path& path) {
    if (student_comparison() != nullptr) {  // two meshes side by side are no one's document
        return refused(
            "this is the side by side of your result and the reference's, not "
            "your mesh: Esc steps back to it first");
    }
    Outcome outcome;
    std::vector<std::string> unkept;
    const bool patches = doc_.mode == Mode::Surface && file_extension(path) == ".bez";
    if (patches) {
        if (pristine_revisions_.count(doc_.revision) == 0) {
            unkept = {"the edits of the tessellated mesh (a .bez file holds only the patches)"};
        }
    } else if (doc_.mode != Mode::Curve) {
        unkept = unkept_by_format(doc_.mesh, file_extension(path));
    }
    if (!unkept.empty() && lossy_armed_ != path) {
        lossy_armed_ = path;
        return refused("saving as " + file_extension(path) + " loses " + join(unkept) +
                       ": save again to save anyway, or save as .dae to keep everything");
    }
    try {
        if (doc_.mode == Mode::Curve) {
            write_bzc(doc_.curve, path);
        } else if (patches) {
            write_bez(doc_.patches, path);
        } else {
            // Collect the tombstones local edits left first, so the file numbers elements as
            // the info panel shows them from now on. Renumbering is an undo step of its own
            // (the recorded changes before it name the old numbers) and a session step.
            if (doc_.mesh.has_garbage()) {
                Transaction transaction(ledger_, doc_, Transaction::Kind::Snapshot);
                compact();
                outcome.changes |=
                    transaction.commit(kTopology | kSelection, "", {"compact"}).changes;
            }
            if (background_) {
                // The worker reads the document, which takes no edit until it is written.
                auto work = [&mesh = doc_.mesh, path](Job&) { write_mesh(mesh, path); };
                auto finish = [this, path, unkept, changes = outcome.changes] {
                    return saved(path, unkept, changes);
                };
                Outcome started = start_job("save " + file_name(path), false, false,
                                            std::move(work), std::move(finish));
                started.changes |= outcome.changes;
                return started;
            }
            write_mesh(doc_.mesh, path);  // atomic: temporary file + rename
        }
    } catch (const IoError& e) {
        outcome.message = e.what();
        outcome.refused = true;
        return outcome;
    }
    return saved(path, unkept, outcome.changes);
}

Outcome Editor::saved(const std::filesystem::path& path, const std::vector<std::string>& unkept,
                      unsigned changes) {
    Outcome outcome{changes};
    path_ = path;
    ledger_.mark_saved(doc_);
    ledger_.quit_armed = false;
    outcome.changes |= kDisplay;  // the title loses its '*'
    outcome.message = "saved " + file_name(path);
    if (!unkept.empty()) {
        outcome.message += " (not kept: " + join(unkept) + ")";
    }
    lossy_armed_.clear();
    return outcome;
}

std::string Editor::title() const {
    std::string out = file_name(path_) + " — ";
    if (doc_.mode == Mode::Curve) {
        out += "curve, " + std::to_string(doc_.curve.control_points.size()) + " points";
    } else {
        out += counts(doc_.mesh);
    }
    if (dirty()) {
        out += " *";
    }
    return out;
}

}  // namespace meshedit::viewer
