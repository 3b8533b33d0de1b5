// Recorded edits (mesh_change.h): the recorder behind Mesh::touch(), and undo/redo of a change.

#include "meshedit/core/mesh_change.h"

#include <algorithm>
#include <cstring>
#include <new>
#include <stdexcept>

namespace meshedit {

namespace {

constexpr const char* kKindNames[] = {"vertex", "halfedge", "edge", "face"};

std::size_t stride_of(const PropertyContainer& c, std::size_t n_arrays) {
    std::size_t stride = 0;
    for (std::size_t i = 0; i < n_arrays; ++i) {
        stride += c.array(i).element_bytes();
    }
    return stride;
}

void save(const PropertyContainer& c, std::size_t n_arrays, std::size_t i, std::byte* out) {
    for (std::size_t a = 0; a < n_arrays; ++a) {
        c.array(a).save(i, out);
        out += c.array(a).element_bytes();
    }
}

void load(PropertyContainer& c, std::size_t n_arrays, std::size_t i, const std::byte* in) {
    for (std::size_t a = 0; a < n_arrays; ++a) {
        c.array(a).load(i, in);
        in += c.array(a).element_bytes();
    }
}

}  // namespace

// --------------------------------------------------------------------------- MeshChange

void MeshChange::restore(PropertyContainer& c, const Kind& k, bool forward) {
    if (c.n_properties() < k.n_arrays || stride_of(c, k.n_arrays) != k.stride) {
        throw std::logic_error("a recorded change applied to a mesh with other properties");
    }
    if (forward) {
        c.resize(k.size_after);
        for (std::size_t i = 0; i < k.size_after - k.size_before; ++i) {
            load(c, k.n_arrays, k.size_before + i, &k.appended[i * k.stride]);
        }
        for (std::size_t i = 0; i < k.touched.size(); ++i) {
            load(c, k.n_arrays, k.touched[i], &k.after[i * k.stride]);
        }
        for (const auto& a : k.added) {
            c.add_array(a->clone());
        }
    } else {
        c.truncate_arrays(k.n_arrays);
        c.resize(k.size_before);
        for (std::size_t i = 0; i < k.touched.size(); ++i) {
            load(c, k.n_arrays, k.touched[i], &k.before[i * k.stride]);
        }
    }
}

void MeshChange::undo(Mesh& mesh) const {
    PropertyContainer* c[] = {&mesh.vprops_, &mesh.hprops_, &mesh.eprops_, &mesh.fprops_};
    for (int k = 0; k < 4; ++k) {
        restore(*c[k], kinds_[k], false);
    }
    mesh.n_deleted_vertices_ = deleted_before_[0];
    mesh.n_deleted_edges_ = deleted_before_[1];
    mesh.n_deleted_faces_ = deleted_before_[2];
}

void MeshChange::redo(Mesh& mesh) const {
    PropertyContainer* c[] = {&mesh.vprops_, &mesh.hprops_, &mesh.eprops_, &mesh.fprops_};
    for (int k = 0; k < 4; ++k) {
        restore(*c[k], kinds_[k], true);
    }
    mesh.n_deleted_vertices_ = deleted_after_[0];
    mesh.n_deleted_edges_ = deleted_after_[1];
    mesh.n_deleted_faces_ = deleted_after_[2];
}

std::size_t MeshChange::bytes() const {
    std::size_t total = sizeof(*this);
    for (const Kind& k : kinds_) {
        total += k.touched.capacity() * sizeof(std::uint32_t) + k.before.capacity() +
                 k.after.capacity() + k.appended.capacity();
        for (const auto& a : k.added) {
            total += a->bytes();
        }
    }
    return total;
}

std::array<std::size_t, 4> MeshChange::counts() const {
    std::array<std::size_t, 4> n{};
    for (int k = 0; k < 4; ++k) {
        n[k] = kinds_[k].touched.size() + (kinds_[k].size_after - kinds_[k].size_before);
    }
    return n;
}

std::vector<Face> MeshChange::affected_faces(const Mesh& after) const {
    std::vector<Face> faces;
    const auto add = [&](Face f) {
        if (f.is_valid() && f.idx() < after.faces_size()) {
            faces.push_back(f);
        }
    };
    for (const std::uint32_t f : kinds_[3].touched) {
        add(Face(f));
    }
    for (std::size_t f = kinds_[3].size_before; f < kinds_[3].size_after; ++f) {
        add(Face(static_cast<std::uint32_t>(f)));
    }
    // A face whose halfedges changed, or whose corner moved, keeps its index but not its look;
    // its face pointer before the edit names it too (a relinked halfedge may have left it).
    const Kind& h = kinds_[1];
    std::size_t face_offset = 0;  // of h:face within a halfedge's saved values
    for (std::size_t a = 0; a < h.n_arrays && after.hprops_.array(a).name() != "h:face"; ++a) {
        face_offset += after.hprops_.array(a).element_bytes();
    }
    for (std::size_t i = 0; i < h.touched.size(); ++i) {
        Face before;
        std::memcpy(&before, &h.before[i * h.stride + face_offset], sizeof(Face));
        add(before);
        add(after.face(Halfedge(h.touched[i])));
    }
    for (const std::uint32_t v : kinds_[0].touched) {
        if (!after.is_deleted(Vertex(v))) {
            for (const Face f : after.faces(Vertex(v))) {
                add(f);
            }
        }
    }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    return faces;
}

// -------------------------------------------------------------------------- MeshRecorder

bool MeshRecorder::Seen::insert(std::uint32_t i) {
    if (2 * (n + 1) > slots.size()) {
        std::vector<std::uint32_t> old(2 * slots.size(), ~0u);
        old.swap(slots);
        n = 0;
        for (const std::uint32_t s : old) {
            if (s != ~0u) {
                insert(s);
            }
        }
    }
    const std::size_t mask = slots.size() - 1;
    for (std::size_t p = (i * 2654435761u) & mask;; p = (p + 1) & mask) {
        if (slots[p] == i) {
            return false;
        }
        if (slots[p] == ~0u) {
            slots[p] = i;
            ++n;
            return true;
        }
    }
}

MeshRecorder::MeshRecorder(Mesh& mesh) : mesh_(&mesh) {
    if (mesh.recorder_ != nullptr) {
        throw std::logic_error("the mesh is already being recorded");
    }
    for (int k = 0; k < 4; ++k) {
        const PropertyContainer& c = container(k);
        MeshChange::Kind& kind = change_.kinds_[k];
        kind.size_before = c.size();
        kind.n_arrays = c.n_properties();
        kind.stride = stride_of(c, kind.n_arrays);
    }
    change_.deleted_before_ = {mesh.n_deleted_vertices_, mesh.n_deleted_edges_,
                               mesh.n_deleted_faces_};
    mesh.recorder_ = this;
}

MeshRecorder::~MeshRecorder() {
    stop();
}

void MeshRecorder::stop() {
    if (mesh_ != nullptr && mesh_->recorder_ == this) {
        mesh_->recorder_ = nullptr;
    }
}

PropertyContainer& MeshRecorder::container(int kind) const {
    PropertyContainer* c[] = {&mesh_->vprops_, &mesh_->hprops_, &mesh_->eprops_, &mesh_->fprops_};
    return *c[kind];
}

void MeshRecorder::record(int kind, std::uint32_t index) noexcept {
    if (kind < 0) {
        if (problem_.empty()) {
            problem_ = "a write to whole arrays (garbage collection, resize, a replaced mesh)";
        }
        return;
    }
    MeshChange::Kind& k = change_.kinds_[kind];
    if (index >= k.size_before) {
        return;  // appended during the edit: kept whole by finish()
    }
    try {
        if (!seen_[kind].insert(index)) {
            return;
        }
        k.touched.push_back(index);
        k.before.resize(k.before.size() + k.stride);
        save(container(kind), k.n_arrays, index, &k.before[k.before.size() - k.stride]);
    } catch (const std::bad_alloc&) {
        if (problem_.empty()) {
            problem_ = std::string("no memory to record a ") + kKindNames[kind];
        }
    }
}

MeshChange MeshRecorder::finish() {
    stop();
    if (!problem_.empty()) {
        throw std::logic_error("the edit cannot be recorded: " + problem_);
    }
    for (int k = 0; k < 4; ++k) {
        const PropertyContainer& c = container(k);
        MeshChange::Kind& kind = change_.kinds_[k];
        if (c.n_properties() < kind.n_arrays || stride_of(c, kind.n_arrays) != kind.stride) {
            throw std::logic_error(std::string("the edit removed a ") + kKindNames[k] +
                                   " property it had not added");
        }
        kind.size_after = c.size();
        kind.after.resize(kind.before.size());
        for (std::size_t i = 0; i < kind.touched.size(); ++i) {
            save(c, kind.n_arrays, kind.touched[i], &kind.after[i * kind.stride]);
        }
        kind.appended.resize((kind.size_after - kind.size_before) * kind.stride);
        for (std::size_t i = kind.size_before; i < kind.size_after; ++i) {
            save(c, kind.n_arrays, i, &kind.appended[(i - kind.size_before) * kind.stride]);
        }
        for (std::size_t a = kind.n_arrays; a < c.n_properties(); ++a) {
            kind.added.push_back(c.array(a).clone());
        }
        kind.touched.shrink_to_fit();
        kind.before.shrink_to_fit();
    }
    change_.deleted_after_ = {mesh_->n_deleted_vertices_, mesh_->n_deleted_edges_,
                              mesh_->n_deleted_faces_};
    return std::move(change_);
}

void MeshRecorder::removing(const BasePropertyArray* array) noexcept {
    for (int k = 0; k < 4; ++k) {
        const PropertyContainer& c = container(k);
        for (std::size_t i = 0; i < change_.kinds_[k].n_arrays; ++i) {
            if (&c.array(i) == array && problem_.empty()) {
                problem_ = "property '" + array->name() + "' removed";
            }
        }
    }
}

void MeshRecorder::roll_back() {
    MeshChange change = finish();
    change.undo(*mesh_);
}

// ------------------------------------------------------------------------- comparison

bool bitwise_equal(const Mesh& a, const Mesh& b, std::string* why) {
    const auto differ = [&](std::string what) {
        if (why != nullptr) {
            *why = std::move(what);
        }
        return false;
    };
    const PropertyContainer* ca[] = {&a.vprops_, &a.hprops_, &a.eprops_, &a.fprops_};
    const PropertyContainer* cb[] = {&b.vprops_, &b.hprops_, &b.eprops_, &b.fprops_};
    for (int k = 0; k < 4; ++k) {
        const PropertyContainer& x = *ca[k];
        const PropertyContainer& y = *cb[k];
        if (x.size() != y.size() || x.n_properties() != y.n_properties()) {
            return differ(std::string(kKindNames[k]) + " count or properties differ: " +
                          std::to_string(x.size()) + " vs " + std::to_string(y.size()));
        }
        for (std::size_t p = 0; p < x.n_properties(); ++p) {
            const BasePropertyArray& u = x.array(p);
            const BasePropertyArray& v = y.array(p);
            if (u.name() != v.name() || u.type() != v.type()) {
                return differ("property " + u.name() + " vs " + v.name());
            }
            std::vector<std::byte> bu(u.element_bytes()), bv(v.element_bytes());
            for (std::size_t i = 0; i < x.size(); ++i) {
                u.save(i, bu.data());
                v.save(i, bv.data());
                if (bu != bv) {
                    return differ(u.name() + " of " + kKindNames[k] + " " + std::to_string(i));
                }
            }
        }
    }
    if (a.n_deleted_vertices_ != b.n_deleted_vertices_ ||
        a.n_deleted_edges_ != b.n_deleted_edges_ || a.n_deleted_faces_ != b.n_deleted_faces_) {
        return differ("deletion counts differ");
    }
    return true;
}

// ------------------------------------------------------------------------------ Mesh side

void Mesh::record(int kind, std::uint32_t index) {
    recorder_->record(kind, index);
}

void Mesh::removing(const BasePropertyArray* array) {
    if (recorder_ != nullptr) {
        recorder_->removing(array);
    }
}

}  // namespace meshedit
