#include "meshedit/core/mesh.h"

#include <type_traits>

#include "meshedit/core/attributes.h"

namespace meshedit {

Mesh::Mesh() {
    add_connectivity();
}

Mesh::Mesh(const Mesh& other)
    : vprops_(other.vprops_),
      hprops_(other.hprops_),
      eprops_(other.eprops_),
      fprops_(other.fprops_),
      n_deleted_vertices_(other.n_deleted_vertices_),
      n_deleted_edges_(other.n_deleted_edges_),
      n_deleted_faces_(other.n_deleted_faces_),
      materials_(other.materials_) {
    bind_connectivity();
}

Mesh::Mesh(Mesh&& other) noexcept {
    take_from(other);
}

Mesh& Mesh::operator=(const Mesh& other) {
    if (this != &other) {
        Mesh copy(other);
        take_from(copy);
    }
    return *this;
}

Mesh& Mesh::operator=(Mesh&& other) noexcept {
    if (this != &other) {
        take_from(other);
    }
    return *this;
}

void Mesh::take_from(Mesh& other) noexcept {
    untracked();  // a recorded mesh replaced wholesale, or moved away from
    other.untracked();
    vprops_ = std::move(other.vprops_);
    hprops_ = std::move(other.hprops_);
    eprops_ = std::move(other.eprops_);
    fprops_ = std::move(other.fprops_);
    n_deleted_vertices_ = other.n_deleted_vertices_;
    n_deleted_edges_ = other.n_deleted_edges_;
    n_deleted_faces_ = other.n_deleted_faces_;
    materials_ = std::move(other.materials_);
    other.materials_.clear();
    bind_connectivity();
    // Leave the source a valid empty mesh rather than one with dangling views.
    other.add_connectivity();
    other.n_deleted_vertices_ = other.n_deleted_edges_ = other.n_deleted_faces_ = 0;
}

void Mesh::add_connectivity() {
    vprops_ = PropertyContainer();
    hprops_ = PropertyContainer();
    eprops_ = PropertyContainer();
    fprops_ = PropertyContainer();
    vpoint_ = VertexProperty<Vec3>(vprops_.add<Vec3>("v:position"));
    vhalfedge_ = VertexProperty<Halfedge>(vprops_.add<Halfedge>("v:halfedge"));
    vdeleted_ = VertexProperty<std::uint8_t>(vprops_.add<std::uint8_t>("v:deleted", 0));
    hnext_ = HalfedgeProperty<Halfedge>(hprops_.add<Halfedge>("h:next"));
    hprev_ = HalfedgeProperty<Halfedge>(hprops_.add<Halfedge>("h:prev"));
    hvertex_ = HalfedgeProperty<Vertex>(hprops_.add<Vertex>("h:vertex"));
    hface_ = HalfedgeProperty<Face>(hprops_.add<Face>("h:face"));
    edeleted_ = EdgeProperty<std::uint8_t>(eprops_.add<std::uint8_t>("e:deleted", 0));
    fhalfedge_ = FaceProperty<Halfedge>(fprops_.add<Halfedge>("f:halfedge"));
    fdeleted_ = FaceProperty<std::uint8_t>(fprops_.add<std::uint8_t>("f:deleted", 0));
    MESHEDIT_ASSERT(vprops_.n_properties() == kFirstAttribute[0] &&
                    hprops_.n_properties() == kFirstAttribute[1] &&
                    eprops_.n_properties() == kFirstAttribute[2] &&
                    fprops_.n_properties() == kFirstAttribute[3]);
}

template <class H>
void Mesh::derive(H to, const std::uint32_t* from, const double* weight, std::size_t n) {
    constexpr int kind = kind_of<H>();
    if (recorder_ != nullptr) [[unlikely]] {
        record(kind, to.idx());
        carried(kind, to.idx());
    }
    container<H>().derive(kFirstAttribute[kind], to.idx(), from, weight, n);
}

template <class H>
std::vector<std::byte> Mesh::attribute_values(H h) const {
    const PropertyContainer& c = container<H>();
    std::size_t bytes = 0;
    for (std::size_t a = kFirstAttribute[kind_of<H>()]; a < c.n_properties(); ++a) {
        bytes += c.array(a).element_bytes();
    }
    std::vector<std::byte> values(bytes);
    std::byte* out = values.data();
    for (std::size_t a = kFirstAttribute[kind_of<H>()]; a < c.n_properties(); ++a) {
        c.array(a).save(h.idx(), out);
        out += c.array(a).element_bytes();
    }
    return values;
}

template <class H>
void Mesh::set_attribute_values(H h, const std::vector<std::byte>& values) {
    PropertyContainer& c = container<H>();
    const std::byte* in = values.data();
    const std::byte* end = values.data() + values.size();
    if (values.empty()) {
        return;
    }
    if (recorder_ != nullptr) {
        record(kind_of<H>(), h.idx());
    }
    for (std::size_t a = kFirstAttribute[kind_of<H>()]; a < c.n_properties(); ++a) {
        MESHEDIT_ASSERT(in + c.array(a).element_bytes() <= end);
        c.array(a).load(h.idx(), in);
        in += c.array(a).element_bytes();
    }
    MESHEDIT_ASSERT(in == end);
}

template std::vector<std::byte> Mesh::attribute_values(Vertex) const;
template std::vector<std::byte> Mesh::attribute_values(Halfedge) const;
template void Mesh::set_attribute_values(Vertex, const std::vector<std::byte>&);
template void Mesh::set_attribute_values(Halfedge, const std::vector<std::byte>&);

template <class H>
void Mesh::permute_attributes(const std::vector<std::uint32_t>& source) {
    PropertyContainer& c = container<H>();
    if (c.n_properties() > kFirstAttribute[kind_of<H>()]) {
        untracked();
        c.permute(kFirstAttribute[kind_of<H>()], source);
    }
}

template void Mesh::permute_attributes<Vertex>(const std::vector<std::uint32_t>&);
template void Mesh::permute_attributes<Halfedge>(const std::vector<std::uint32_t>&);
template void Mesh::permute_attributes<Edge>(const std::vector<std::uint32_t>&);
template void Mesh::permute_attributes<Face>(const std::vector<std::uint32_t>&);

template void Mesh::derive(Vertex, const std::uint32_t*, const double*, std::size_t);
template void Mesh::derive(Halfedge, const std::uint32_t*, const double*, std::size_t);
template void Mesh::derive(Edge, const std::uint32_t*, const double*, std::size_t);
template void Mesh::derive(Face, const std::uint32_t*, const double*, std::size_t);

void Mesh::bind_connectivity() {
    vpoint_ = VertexProperty<Vec3>(vprops_.get<Vec3>("v:position"));
    vhalfedge_ = VertexProperty<Halfedge>(vprops_.get<Halfedge>("v:halfedge"));
    vdeleted_ = VertexProperty<std::uint8_t>(vprops_.get<std::uint8_t>("v:deleted"));
    hnext_ = HalfedgeProperty<Halfedge>(hprops_.get<Halfedge>("h:next"));
    hprev_ = HalfedgeProperty<Halfedge>(hprops_.get<Halfedge>("h:prev"));
    hvertex_ = HalfedgeProperty<Vertex>(hprops_.get<Vertex>("h:vertex"));
    hface_ = HalfedgeProperty<Face>(hprops_.get<Face>("h:face"));
    edeleted_ = EdgeProperty<std::uint8_t>(eprops_.get<std::uint8_t>("e:deleted"));
    fhalfedge_ = FaceProperty<Halfedge>(fprops_.get<Halfedge>("f:halfedge"));
    fdeleted_ = FaceProperty<std::uint8_t>(fprops_.get<std::uint8_t>("f:deleted"));
}

void Mesh::well_known_carry(BasePropertyArray& array) {
    for (const auto& [name, rule] : kCarryRules) {
        if (array.name() == name) {
            array.set_carry(rule);
        }
    }
}

bool Mesh::is_connectivity(const BasePropertyArray* array) const {
    const BasePropertyArray* fixed[] = {vpoint_.array(),  vhalfedge_.array(), vdeleted_.array(),
                                        hnext_.array(),   hprev_.array(),     hvertex_.array(),
                                        hface_.array(),   edeleted_.array(),  fhalfedge_.array(),
                                        fdeleted_.array()};
    for (const BasePropertyArray* a : fixed) {
        if (a == array) {
            return true;
        }
    }
    return false;
}

std::size_t Mesh::bytes() const {
    return vprops_.bytes() + hprops_.bytes() + eprops_.bytes() + fprops_.bytes();
}

Vertex Mesh::new_vertex(const Vec3& p) {
    vprops_.push_back();
    const Vertex v(static_cast<std::uint32_t>(vprops_.size() - 1));
    vpoint_[v] = p;
    return v;
}

Halfedge Mesh::new_edge(Vertex from, Vertex to) {
    eprops_.push_back();
    hprops_.push_back();
    hprops_.push_back();
    const Halfedge h0(static_cast<std::uint32_t>(hprops_.size() - 2));
    const Halfedge h1 = twin(h0);
    set_vertex(h0, to);
    set_vertex(h1, from);
    return h0;
}

Face Mesh::new_face() {
    fprops_.push_back();
    return Face(static_cast<std::uint32_t>(fprops_.size() - 1));
}

void Mesh::new_elements(std::size_t nv, std::size_t ne, std::size_t nf) {
    vprops_.push_back_n(nv);
    eprops_.push_back_n(ne);
    hprops_.push_back_n(2 * ne);
    fprops_.push_back_n(nf);
}

void Mesh::reserve(std::size_t nv, std::size_t ne, std::size_t nf) {
    vprops_.reserve(nv);
    eprops_.reserve(ne);
    hprops_.reserve(2 * ne);
    fprops_.reserve(nf);
}

void Mesh::resize(std::size_t nv, std::size_t ne, std::size_t nf) {
    untracked();
    vprops_.resize(nv);
    eprops_.resize(ne);
    hprops_.resize(2 * ne);
    fprops_.resize(nf);
    count_deleted();
}

void Mesh::clear() {
    resize(0, 0, 0);
}

void Mesh::shrink_to_fit() {
    vprops_.shrink_to_fit();
    hprops_.shrink_to_fit();
    eprops_.shrink_to_fit();
    fprops_.shrink_to_fit();
}

void Mesh::count_deleted() {
    auto count = [](const memory::Array<std::uint8_t>& flags) {
        std::size_t n = 0;
        for (std::uint8_t f : flags) {
            n += f != 0;
        }
        return n;
    };
    n_deleted_vertices_ = count(vdeleted_.vector());
    n_deleted_edges_ = count(edeleted_.vector());
    n_deleted_faces_ = count(fdeleted_.vector());
}

bool Mesh::is_boundary(Face f) const {
    for (Halfedge h : halfedges(f)) {
        if (is_boundary(twin(h))) {
            return true;
        }
    }
    return false;
}

std::size_t Mesh::valence(Vertex v) const {
    std::size_t n = 0;
    for ([[maybe_unused]] Halfedge h : halfedges(v)) {
        ++n;
    }
    return n;
}

std::size_t Mesh::valence(Face f) const {
    std::size_t n = 0;
    for ([[maybe_unused]] Halfedge h : halfedges(f)) {
        ++n;
    }
    return n;
}

bool Mesh::is_triangle_mesh() const {
    for (Face f : faces()) {
        if (!is_triangle(f)) {
            return false;
        }
    }
    return true;
}

Halfedge Mesh::find_halfedge(Vertex a, Vertex b) const {
    for (Halfedge h : halfedges(a)) {
        if (to_vertex(h) == b) {
            return h;
        }
    }
    return Halfedge();
}

Edge Mesh::find_edge(Vertex a, Vertex b) const {
    const Halfedge h = find_halfedge(a, b);
    return h.is_valid() ? edge(h) : Edge();
}

void Mesh::mark_deleted(Vertex v) {
    touch(v);
    if (vdeleted_[v] == 0) {
        vdeleted_[v] = 1;
        ++n_deleted_vertices_;
    }
}

void Mesh::mark_deleted(Edge e) {
    touch(e);
    if (edeleted_[e] == 0) {
        edeleted_[e] = 1;
        ++n_deleted_edges_;
    }
}

void Mesh::mark_deleted(Face f) {
    touch(f);
    if (fdeleted_[f] == 0) {
        fdeleted_[f] = 1;
        ++n_deleted_faces_;
    }
}

BoundingBox Mesh::bounds() const {
    BoundingBox box;
    for (Vertex v : vertices()) {
        box.add(position(v));
    }
    return box;
}

namespace {

// Builds the list of surviving indices and the old-to-new map for one element kind.
template <class H>
std::vector<std::uint32_t> surviving(const memory::Array<std::uint8_t>& deleted,
                                     std::vector<H>& old_to_new) {
    std::vector<std::uint32_t> kept;
    kept.reserve(deleted.size());
    old_to_new.assign(deleted.size(), H());
    for (std::uint32_t i = 0; i < deleted.size(); ++i) {
        if (deleted[i] == 0) {
            old_to_new[i] = H(static_cast<std::uint32_t>(kept.size()));
            kept.push_back(i);
        }
    }
    return kept;
}

template <class H>
H remap(const std::vector<H>& map, H h) {
    return h.is_valid() ? map[h.idx()] : h;
}

}  // namespace

void Mesh::garbage_collection(GarbageCollectionMap* out) {
    untracked();
    GarbageCollectionMap local;
    GarbageCollectionMap& map = out != nullptr ? *out : local;

    const auto kept_v = surviving(vdeleted_.vector(), map.vertices);
    const auto kept_e = surviving(edeleted_.vector(), map.edges);
    const auto kept_f = surviving(fdeleted_.vector(), map.faces);

    // Halfedges follow their edges: edge k keeps halfedges 2k and 2k+1 together.
    std::vector<std::uint32_t> kept_h;
    kept_h.reserve(2 * kept_e.size());
    map.halfedges.assign(halfedges_size(), Halfedge());
    for (std::uint32_t e : kept_e) {
        for (std::uint32_t i = 0; i < 2; ++i) {
            map.halfedges[2 * e + i] = Halfedge(static_cast<std::uint32_t>(kept_h.size()));
            kept_h.push_back(2 * e + i);
        }
    }

    vprops_.compact(kept_v);
    eprops_.compact(kept_e);
    hprops_.compact(kept_h);
    fprops_.compact(kept_f);

    // Rewrite the references stored in the connectivity arrays.
    for (Halfedge& h : vhalfedge_.vector()) {
        h = remap(map.halfedges, h);
    }
    for (Halfedge& h : fhalfedge_.vector()) {
        h = remap(map.halfedges, h);
    }
    for (Halfedge& h : hnext_.vector()) {
        h = remap(map.halfedges, h);
    }
    for (Halfedge& h : hprev_.vector()) {
        h = remap(map.halfedges, h);
    }
    for (Vertex& v : hvertex_.vector()) {
        v = remap(map.vertices, v);
    }
    for (Face& f : hface_.vector()) {
        f = remap(map.faces, f);
    }
    n_deleted_vertices_ = n_deleted_edges_ = n_deleted_faces_ = 0;
}

}  // namespace meshedit
