// Recorded edits (mesh_change.h): the recorder behind Mesh::touch(), and undo/redo of a change.

#include "meshedit/core/mesh_change.h"

#include <algorithm>
#include <cstring>
#include <new>
#include <stdexcept>

#include "meshedit/core/assert.h"

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

std::uint32_t MeshChange::touched(int kind, std::size_t i) const {
    std::uint32_t index = 0;
    std::memcpy(&index, &data_[kinds_[kind].offset + i * sizeof(index)], sizeof(index));
    return index;
}

void MeshChange::restore(PropertyContainer& c, int kind, bool forward) const {
    const Kind& k = kinds_[kind];
    if (c.n_properties() < k.n_arrays || stride_of(c, k.n_arrays) != k.stride) {
        throw std::logic_error("a recorded change applied to a mesh with other properties");
    }
    if (forward) {
        c.resize(k.size_after);
        for (std::size_t i = 0; i < k.size_after - k.size_before; ++i) {
            load(c, k.n_arrays, k.size_before + i, &data_[k.appended_at() + i * k.stride]);
        }
        for (std::size_t i = 0; i < k.n_touched; ++i) {
            load(c, k.n_arrays, touched(kind, i), &data_[k.after_at() + i * k.stride]);
        }
        if (added_) {
            for (const auto& a : (*added_)[kind]) {
                c.add_array(a->clone());
            }
        }
    } else {
        c.truncate_arrays(k.n_arrays);
        c.resize(k.size_before);
        for (std::size_t i = 0; i < k.n_touched; ++i) {
            load(c, k.n_arrays, touched(kind, i), &data_[k.before_at() + i * k.stride]);
        }
    }
}

void MeshChange::undo(Mesh& mesh) const {
    apply(mesh, false);
}

void MeshChange::redo(Mesh& mesh) const {
    apply(mesh, true);
}

void MeshChange::apply(Mesh& mesh, bool forward) const {
    PropertyContainer* c[] = {&mesh.vprops_, &mesh.hprops_, &mesh.eprops_, &mesh.fprops_};
    for (int k = 0; k < 4; ++k) {
        restore(*c[k], k, forward);
    }
    const std::array<std::uint32_t, 3>& deleted = forward ? deleted_after_ : deleted_before_;
    mesh.n_deleted_vertices_ = deleted[0];
    mesh.n_deleted_edges_ = deleted[1];
    mesh.n_deleted_faces_ = deleted[2];
}

void MeshChange::refresh_after(const Mesh& mesh) {
    const PropertyContainer* c[] = {&mesh.vprops_, &mesh.hprops_, &mesh.eprops_, &mesh.fprops_};
    for (int k = 0; k < 4; ++k) {
        const Kind& kind = kinds_[k];
        MESHEDIT_ASSERT(c[k]->size() == kind.size_after);
        for (std::size_t i = 0; i < kind.n_touched; ++i) {
            save(*c[k], kind.n_arrays, touched(k, i), &data_[kind.after_at() + i * kind.stride]);
        }
        for (std::size_t i = 0; i < kind.size_after - kind.size_before; ++i) {
            save(*c[k], kind.n_arrays, kind.size_before + i,
                 &data_[kind.appended_at() + i * kind.stride]);
        }
        if (added_) {
            std::vector<std::unique_ptr<BasePropertyArray>>& arrays = (*added_)[k];
            for (std::size_t a = 0; a < arrays.size(); ++a) {
                arrays[a] = c[k]->array(kind.n_arrays + a).clone();
            }
        }
    }
}

std::size_t MeshChange::bytes() const {
    std::size_t total = sizeof(*this) + data_.capacity();
    if (added_) {
        total += sizeof(AddedArrays);
        for (const auto& kind : *added_) {
            for (const auto& a : kind) {
                total += a->bytes();
            }
        }
    }
    return total;
}

std::array<std::size_t, 4> MeshChange::counts() const {
    std::array<std::size_t, 4> n{};
    for (int k = 0; k < 4; ++k) {
        n[k] = kinds_[k].n_touched + (kinds_[k].size_after - kinds_[k].size_before);
    }
    return n;
}

MeshChange::Region MeshChange::region() const {
    Region r;
    const Kind& vk = kinds_[0];
    const Kind& hk = kinds_[1];
    const Kind& fk = kinds_[3];
    for (std::size_t i = 0; i < vk.n_touched; ++i) {
        r.vertices.push_back(Vertex(touched(0, i)));
    }
    for (std::uint32_t v = vk.size_before; v < vk.size_after; ++v) {
        r.vertices.push_back(Vertex(v));
    }
    for (std::size_t i = 0; i < fk.n_touched; ++i) {
        r.faces.push_back(Face(touched(3, i)));
    }
    for (std::uint32_t f = fk.size_before; f < fk.size_after; ++f) {
        r.faces.push_back(Face(f));
    }
    // A halfedge's saved values begin with the connectivity arrays, in the order mesh.cpp
    // adds them: next, prev, vertex, face.
    const auto head_and_face = [&](std::size_t at) {
        Vertex v;
        Face f;
        std::memcpy(&v, &data_[at + 2 * sizeof(Halfedge)], sizeof(Vertex));
        std::memcpy(&f, &data_[at + 2 * sizeof(Halfedge) + sizeof(Vertex)], sizeof(Face));
        if (v.is_valid()) {
            r.vertices.push_back(v);
        }
        if (f.is_valid()) {
            r.faces.push_back(f);
        }
    };
    for (std::size_t i = 0; i < hk.n_touched; ++i) {
        head_and_face(hk.before_at() + i * hk.stride);
        head_and_face(hk.after_at() + i * hk.stride);
    }
    for (std::size_t i = 0; i < hk.size_after - hk.size_before; ++i) {
        head_and_face(hk.appended_at() + i * hk.stride);
    }
    std::sort(r.faces.begin(), r.faces.end());
    r.faces.erase(std::unique(r.faces.begin(), r.faces.end()), r.faces.end());
    std::sort(r.vertices.begin(), r.vertices.end());
    r.vertices.erase(std::unique(r.vertices.begin(), r.vertices.end()), r.vertices.end());
    return r;
}

std::vector<Face> faces_to_redraw(const Mesh& mesh, const MeshChange::Region& region) {
    std::vector<Face> faces = region.faces;
    for (const Vertex v : region.vertices) {
        if (v.idx() < mesh.vertices_size() && !mesh.is_deleted(v) && !mesh.is_isolated(v)) {
            for (const Face f : mesh.faces(v)) {
                faces.push_back(f);
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
        Log& log = logs_[k];
        log.size_before = c.size();
        log.n_arrays = c.n_properties();
        log.stride = stride_of(c, log.n_arrays);
    }
    deleted_before_ = {mesh.n_deleted_vertices_, mesh.n_deleted_edges_, mesh.n_deleted_faces_};
    if constexpr (kSelfCheck) {
        start_ = std::make_unique<Mesh>(mesh);  // before recorder_ is set: the copy is not
    }
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
    Log& log = logs_[kind];
    if (index >= log.size_before) {
        return;  // appended during the edit: kept whole by finish()
    }
    try {
        if (!log.seen.insert(index)) {
            return;
        }
        log.touched.push_back(index);
        log.before.resize(log.before.size() + log.stride);
        save(container(kind), log.n_arrays, index, &log.before[log.before.size() - log.stride]);
    } catch (const std::bad_alloc&) {
        if (problem_.empty()) {
            problem_ = std::string("no memory to record a ") + kKindNames[kind];
        }
    }
}

void MeshRecorder::carried(int kind, std::uint32_t index) noexcept {
    if constexpr (kSelfCheck) {
        Log& log = logs_[kind];
        if (index >= log.size_before) {
            try {
                log.carried.resize(std::max(log.carried.size(), index - log.size_before + 1), 0);
                log.carried[index - log.size_before] = 1;
            } catch (const std::bad_alloc&) {
                // the self-check only loses an element to check
            }
        }
    }
}

// The self-check's second half: every element the edit made states where its attributes
// come from (Mesh::carry()), so a new operation cannot forget the attribute carry.
std::string MeshRecorder::underived() const {
    for (int k = 0; k < 4; ++k) {
        const Log& log = logs_[k];
        const std::size_t size = container(k).size();
        for (std::size_t i = log.size_before; i < size; ++i) {
            const bool dead = k == 1   ? mesh_->is_deleted(Halfedge(static_cast<std::uint32_t>(i)))
                              : k == 0 ? mesh_->is_deleted(Vertex(static_cast<std::uint32_t>(i)))
                              : k == 2 ? mesh_->is_deleted(Edge(static_cast<std::uint32_t>(i)))
                                       : mesh_->is_deleted(Face(static_cast<std::uint32_t>(i)));
            const std::size_t j = i - log.size_before;
            if (!dead && (j >= log.carried.size() || log.carried[j] == 0)) {
                return std::string("new ") + kKindNames[k] + " " + std::to_string(i);
            }
        }
    }
    return "";
}

void MeshRecorder::removing(const BasePropertyArray* array) noexcept {
    for (int k = 0; k < 4; ++k) {
        const PropertyContainer& c = container(k);
        for (std::size_t i = 0; i < logs_[k].n_arrays; ++i) {
            if (&c.array(i) == array && problem_.empty()) {
                problem_ = "property '" + array->name() + "' removed";
            }
        }
    }
}

MeshChange MeshRecorder::finish() {
    stop();
    if (!problem_.empty()) {
        throw std::logic_error("the edit cannot be recorded: " + problem_);
    }
    MeshChange change;
    std::size_t offset = 0;
    for (int k = 0; k < 4; ++k) {
        const PropertyContainer& c = container(k);
        const Log& log = logs_[k];
        if (c.n_properties() < log.n_arrays || stride_of(c, log.n_arrays) != log.stride) {
            throw std::logic_error(std::string("the edit removed a ") + kKindNames[k] +
                                   " property it had not added");
        }
        MeshChange::Kind& kind = change.kinds_[k];
        kind.size_before = static_cast<std::uint32_t>(log.size_before);
        kind.size_after = static_cast<std::uint32_t>(c.size());
        kind.n_arrays = static_cast<std::uint32_t>(log.n_arrays);
        kind.stride = static_cast<std::uint32_t>(log.stride);
        kind.n_touched = static_cast<std::uint32_t>(log.touched.size());
        kind.offset = offset;
        offset = kind.end();
    }
    change.data_.resize(offset);
    std::byte* data = change.data_.data();
    for (int k = 0; k < 4; ++k) {
        const PropertyContainer& c = container(k);
        const Log& log = logs_[k];
        const MeshChange::Kind& kind = change.kinds_[k];
        if (!log.touched.empty()) {
            std::memcpy(data + kind.offset, log.touched.data(),
                        log.touched.size() * sizeof(std::uint32_t));
            std::memcpy(data + kind.before_at(), log.before.data(), log.before.size());
        }
        for (std::size_t i = 0; i < log.touched.size(); ++i) {
            save(c, kind.n_arrays, log.touched[i], data + kind.after_at() + i * kind.stride);
        }
        for (std::size_t i = kind.size_before; i < kind.size_after; ++i) {
            save(c, kind.n_arrays, i,
                 data + kind.appended_at() + (i - kind.size_before) * kind.stride);
        }
        for (std::size_t a = kind.n_arrays; a < c.n_properties(); ++a) {
            if (!change.added_) {
                change.added_ = std::make_unique<MeshChange::AddedArrays>();
            }
            (*change.added_)[k].push_back(c.array(a).clone());
        }
    }
    const auto u32 = [](std::size_t n) { return static_cast<std::uint32_t>(n); };
    change.deleted_before_ = {u32(deleted_before_[0]), u32(deleted_before_[1]),
                              u32(deleted_before_[2])};
    change.deleted_after_ = {u32(mesh_->n_deleted_vertices_), u32(mesh_->n_deleted_edges_),
                             u32(mesh_->n_deleted_faces_)};
    if (start_) {
        // The self-check: undoing the change must give back the mesh as it began, bit for bit.
        // A write the recorder was not told about (a property written through its handle
        // without touch()) is missing from the change and shows here.
        Mesh undone = *mesh_;
        change.undo(undone);
        std::string why;
        if (!bitwise_equal(undone, *start_, &why)) {
            throw std::logic_error(
                "the recorder's self-check failed: the edit changed what it did not record (" +
                why +
                "); write through the Mesh setters, or call touch() before a property "
                "write");
        }
        if (const std::string element = underived(); !element.empty()) {
            throw std::logic_error("the recorder's self-check failed: the edit made " + element +
                                   " without saying where its attributes come from; call "
                                   "Mesh::carry() for every element an operation makes");
        }
    }
    return change;
}

void MeshRecorder::roll_back() {
    start_.reset();  // rolling back an edit that failed half-way: no self-check
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

void Mesh::carried(int kind, std::uint32_t index) {
    recorder_->carried(kind, index);
}

void Mesh::removing(const BasePropertyArray* array) {
    if (recorder_ != nullptr) {
        recorder_->removing(array);
    }
}

}  // namespace meshedit
