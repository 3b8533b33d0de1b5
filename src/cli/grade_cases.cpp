// The battery of `meshedit grade`. Meshes are loaded once in the grader and copied into each
// forked child, so a case costs only its own work.

#include "grade_cases.h"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <random>
#include <set>
#include <sstream>

#include "cli.h"
#include "grade_checks.h"
#include "meshedit/core/build.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/files/files.h"
#include "meshedit/io/document.h"
#include "meshedit/io/io.h"
#include "meshedit/ops/ops.h"

namespace meshedit::cli::grade {
namespace {

using MeshPtr = std::shared_ptr<const Mesh>;

struct NamedMesh {
    std::string name;
    MeshPtr mesh;
};

MeshPtr share(Mesh mesh) {
    mesh.garbage_collection();
    return std::make_shared<const Mesh>(std::move(mesh));
}

std::string edge_name(const Mesh& mesh, Edge e) {
    return "edge " + std::to_string(e.idx()) + " (" + std::to_string(mesh.vertex(e, 1).idx()) +
           "-" + std::to_string(mesh.vertex(e, 0).idx()) + ")";
}

// Two triangles on the same three corners, back to back: splitting an edge would make the two
// new edges across them join the same vertices, so MeshEdit refuses.
Mesh pillow() {
    PolygonSoup soup;
    soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    soup.indices = {0, 1, 2, 0, 2, 1};
    soup.face_offsets = {0, 3, 6};
    return build_mesh(soup);
}

// A grid with bumps and a few random flips: valences from 3 to 8 and a boundary, the same
// mesh for a seed on every run.
Mesh random_mesh(unsigned seed) {
    std::mt19937 random(seed);
    Mesh mesh = shapes::grid(5, 4);
    for (const Vertex v : mesh.vertices()) {
        mesh.position(v).z = double(random() % 1000) / 2000.0;
    }
    for (int i = 0; i < 12; ++i) {
        (void)flip(mesh, Edge(std::uint32_t(random() % mesh.edges_size())));
    }
    return mesh;
}

BezierPatch random_patch(unsigned seed) {
    std::mt19937 random(seed);
    BezierPatch patch;
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            patch.control_points.emplace_back(c + double(random() % 100) / 300.0,
                                              r + double(random() % 100) / 300.0,
                                              double(random() % 1000) / 500.0);
        }
    }
    return patch;
}

std::vector<Vec3> random_curve(unsigned seed, int n) {
    std::mt19937 random(seed);
    std::vector<Vec3> points;
    for (int i = 0; i < n; ++i) {
        points.emplace_back(double(random() % 1000) / 100.0, double(random() % 1000) / 100.0, 0);
    }
    return points;
}

// An interior edge with an end on the boundary, and a boundary edge, of a mesh with a boundary.
Edge edge_touching_boundary(const Mesh& mesh) {
    for (const Edge e : mesh.edges()) {
        if (!mesh.is_boundary(e) &&
            (mesh.is_boundary(mesh.vertex(e, 0)) || mesh.is_boundary(mesh.vertex(e, 1)))) {
            return e;
        }
    }
    return Edge();
}
// The first interior edge from index `from` on.
Edge interior_edge(const Mesh& mesh, std::uint32_t from) {
    for (std::uint32_t i = from; i < mesh.edges_size(); ++i) {
        if (!mesh.is_boundary(Edge(i))) {
            return Edge(i);
        }
    }
    return Edge();
}
// A boundary edge of even or odd index: the student's edge->halfedge() is then the side with a
// face or the boundary side (bridge's copy_in()).
Edge boundary_edge(const Mesh& mesh, unsigned parity = 1) {
    for (const Edge e : mesh.edges()) {
        if (mesh.is_boundary(e) && (e.idx() & 1u) == parity) {
            return e;
        }
    }
    return parity == 0 ? boundary_edge(mesh, 1) : Edge();  // a fan's rim is all odd
}
Edge crease_edge(const Mesh& mesh) {
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    for (const Edge e : mesh.edges()) {
        if (crease && crease[e] != 0) {
            return e;
        }
    }
    return Edge();
}

class Battery {
public:
    std::vector<Case> cases;

    void flip_case(const NamedMesh& m, Edge e, const std::string& why = "") {
        if (!e.is_valid()) {
            return;
        }
        add("flip_edge", m.name + " " + edge_name(*m.mesh, e) + why,
            [mesh = m.mesh, e](const st::StudentTasks& t) { return check_flip(t, *mesh, e); });
    }
    void split_case(const NamedMesh& m, Edge e, const std::string& why = "") {
        if (!e.is_valid()) {
            return;
        }
        add("split_edge", m.name + " " + edge_name(*m.mesh, e) + why,
            [mesh = m.mesh, e](const st::StudentTasks& t) { return check_split(t, *mesh, e); });
    }
    void normals_case(const NamedMesh& m) {
        add("vertex_normal", m.name + ", every vertex",
            [mesh = m.mesh](const st::StudentTasks& t) { return check_normals(t, *mesh); });
    }
    void loop_case(const NamedMesh& m) {
        add("upsample", m.name,
            [mesh = m.mesh](const st::StudentTasks& t) { return check_loop(t, *mesh); });
    }
    void step_case(const std::string& name, std::vector<Vec3> points, double t) {
        std::string title = name + " (" + std::to_string(points.size()) +
                            (points.size() == 1 ? " point" : " points") +
                            ") at t=" + readable_number(t);
        add("evaluate_step", std::move(title),
            [points = std::move(points), t](const st::StudentTasks& tasks) {
                return check_step(tasks, points, t);
            });
    }
    void patch_case(const std::string& name, const BezierPatch& patch, double u, double v) {
        add("evaluate_patch", name + " at (" + readable_number(u) + ", " + readable_number(v) + ")",
            [patch, u, v](const st::StudentTasks& t) { return check_patch(t, patch, u, v); });
    }

    void add(const char* task, std::string name,
             std::function<std::string(const st::StudentTasks&)> run) {
        cases.push_back(Case{task, std::move(name), false, std::move(run)});
    }
};

}  // namespace

std::filesystem::path find_samples() {
    std::vector<std::filesystem::path> starts{std::filesystem::current_path()};
    std::error_code ec;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        starts.push_back(self.parent_path());
    }
    for (std::filesystem::path dir : starts) {
        for (int up = 0; up < 8 && !dir.empty(); ++up) {
            if (std::filesystem::exists(dir / "dae" / "cube.dae", ec) &&
                std::filesystem::exists(dir / "bez" / "teapot.bez", ec)) {
                return dir;
            }
            if (dir == dir.parent_path()) {
                break;
            }
            dir = dir.parent_path();
        }
    }
    return {};
}

std::vector<Case> standard_cases(const std::filesystem::path& samples,
                                 std::vector<std::string>& notes) {
    Battery b;
    // The course's meshes: the files when the samples are at hand, else the shapes they are
    // made from (docs/samples.md).
    const auto course = [&](const char* file, Mesh (*shape)()) {
        if (!samples.empty()) {
            return NamedMesh{file, share(read_mesh(samples / "dae" / file).mesh)};
        }
        return NamedMesh{file, share(shape())};
    };
    const NamedMesh cube = course("cube.dae", &shapes::cube);
    const NamedMesh ico = course("icosahedron.dae", &shapes::icosahedron);
    const NamedMesh torus = course("torus.dae", [] { return shapes::torus(24, 12); });
    const NamedMesh tet{"tetrahedron (valence 3)", share(shapes::tetrahedron())};
    const NamedMesh disk{"disk of 12 (valence-12 centre, boundary)", share(shapes::disk(12))};
    const NamedMesh random1{"random mesh (seed 1)", share(random_mesh(1))};
    const NamedMesh random2{"random mesh (seed 2)", share(random_mesh(2))};
    NamedMesh bowl, creased, teapot;
    if (!samples.empty()) {
        bowl = {"bowl.dae (boundary)", share(read_mesh(samples / "dae" / "bowl.dae").mesh)};
        creased = {"creased.dae (creases)", share(read_mesh(samples / "dae" / "creased.dae").mesh)};
        teapot = {"teapot.dae", share(read_mesh(samples / "dae" / "teapot.dae").mesh)};
    } else {
        notes.push_back(
            "the samples (dae/, bez/) were not found (--samples DIR): the cases on bowl.dae, "
            "creased.dae, teapot.dae and the .bez and .bzc files are left out");
    }

    // Task 1: de Casteljau steps.
    if (!samples.empty()) {
        for (const char* file : {"curve1.bzc", "curve2.bzc", "curve6.bzc"}) {
            const LoadedDocument doc = read_document(samples / "bez" / file);
            b.step_case(file, doc.curve.control_points, 0.3);
            b.step_case(file, doc.curve.control_points, 0.75);
        }
    }
    b.step_case("random curve", random_curve(1, 2), 0.2);
    b.step_case("random curve", random_curve(2, 3), 0.9);
    b.step_case("random curve", random_curve(3, 7), 0.35);
    b.step_case("random curve", random_curve(4, 4), 0.0);
    b.step_case("random curve", random_curve(5, 4), 1.0);
    b.step_case("a single point, nothing to interpolate", random_curve(6, 1), 0.5);

    // Task 2: patches.
    if (!samples.empty()) {
        const LoadedDocument teapot_bez = read_document(samples / "bez" / "teapot.bez");
        b.patch_case("teapot.bez patch 0", teapot_bez.patches.at(0), 0.3, 0.7);
        b.patch_case("teapot.bez patch 5", teapot_bez.patches.at(5), 0.9, 0.1);
        const LoadedDocument wavy = read_document(samples / "bez" / "wavy_cube.bez");
        b.patch_case("wavy_cube.bez patch 0", wavy.patches.at(0), 0.25, 0.6);
    }
    b.patch_case("random patch (seed 1)", random_patch(1), 0.2, 0.7);
    b.patch_case("random patch (seed 2)", random_patch(2), 0.8, 0.35);
    b.patch_case("random patch (seed 3)", random_patch(3), 0.0, 1.0);

    // Task 3: normals.
    for (const NamedMesh* m : std::initializer_list<const NamedMesh*>{
             &cube, &ico, &torus, &tet, &disk, &random1, &bowl, &creased, &teapot}) {
        if (m->mesh) {
            b.normals_case(*m);
        }
    }

    // Task 4: flips, and flips that must be refused.
    b.flip_case(cube, Edge(0));
    b.flip_case(cube, Edge(7));
    b.flip_case(cube, Edge(11));
    b.flip_case(ico, Edge(3));
    b.flip_case(torus, Edge(100));
    b.flip_case(disk, disk.mesh->find_edge(Vertex(0), Vertex(3)), ", a valence-12 vertex");
    b.flip_case(random1, interior_edge(*random1.mesh, 9));
    b.flip_case(random2, interior_edge(*random2.mesh, 20));
    b.flip_case(disk, boundary_edge(*disk.mesh, 0), ", boundary: must be refused");
    b.flip_case(tet, Edge(0), ", the new edge exists: must be refused");
    if (bowl.mesh) {
        b.flip_case(bowl, edge_touching_boundary(*bowl.mesh), ", an end on the boundary");
        b.flip_case(bowl, boundary_edge(*bowl.mesh, 0), ", boundary: must be refused");
        b.flip_case(creased, crease_edge(*creased.mesh), ", a crease");
    }

    // Task 5: splits.
    b.split_case(cube, Edge(0));
    b.split_case(cube, Edge(7));
    b.split_case(ico, Edge(3));
    b.split_case(torus, Edge(100));
    b.split_case(tet, Edge(0), ", valence 3");
    b.split_case(disk, disk.mesh->find_edge(Vertex(0), Vertex(3)), ", a valence-12 vertex");
    b.split_case(disk, boundary_edge(*disk.mesh), ", boundary");
    b.split_case(random1, interior_edge(*random1.mesh, 14));
    b.split_case(NamedMesh{"pillow (two triangles on the same corners)", share(pillow())}, Edge(0),
                 ", the new edges would coincide: must be refused");
    if (bowl.mesh) {
        b.split_case(bowl, boundary_edge(*bowl.mesh, 0), ", boundary");
        b.split_case(bowl, edge_touching_boundary(*bowl.mesh), ", an end on the boundary");
        b.split_case(creased, crease_edge(*creased.mesh), ", a crease");
    }

    // Task 6: Loop.
    for (const NamedMesh* m : std::initializer_list<const NamedMesh*>{
             &cube, &ico, &tet, &disk, &random1, &torus, &bowl, &creased}) {
        if (m->mesh) {
            b.loop_case(*m);
        }
    }
    return std::move(b.cases);
}

namespace {

bool hidden_name(const std::string& file, const std::set<std::string>& listed) {
    return file.find(".hidden.") != std::string::npos || file.rfind("hidden", 0) == 0 ||
           listed.count(file) > 0;
}

std::vector<SessionStep> parse_session(const std::filesystem::path& path, std::string& input) {
    std::ifstream in(path);
    std::vector<SessionStep> steps;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (line.rfind("# input:", 0) == 0) {
            std::istringstream(line.substr(8)) >> input;
            continue;
        }
        if (line.empty() || line[0] == '#') {
            continue;
        }
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream words(line);
        for (std::string word; words >> word;) {
            SessionStep s;
            char colon = 0, dash = 0;
            std::string verb = word.substr(0, word.find(':'));
            std::istringstream spec(word.substr(verb.size()));
            // Flip and split are the verbs whose diagrams use their code's names (the verb
            // table says so; no verb name is compared outside src/ops).
            const ops::Verb* v = ops::find_verb(verb);
            const bool graded =
                v != nullptr && (v->names == CodeNames::Flip || v->names == CodeNames::Split);
            if (!graded || !(spec >> colon >> s.a >> dash >> s.b) || colon != ':' || dash != '-') {
                throw UsageError(path.string() + ":" + std::to_string(number) + ": '" + word +
                                 "' is not flip:A-B or split:A-B");
            }
            s.split = v->names == CodeNames::Split;
            steps.push_back(s);
        }
    }
    return steps;
}

}  // namespace

std::vector<Case> folder_cases(const std::filesystem::path& dir) {
    std::set<std::string> listed;
    std::ifstream manifest(dir / "manifest.txt");
    for (std::string word, file; manifest >> word >> file;) {
        if (word == "hidden") {
            listed.insert(file);
        }
    }
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.is_regular_file()) {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    Battery b;
    for (const auto& path : files) {
        const std::string file = path.filename().string();
        const std::size_t first = b.cases.size();
        if (file_extension(path) == ".ops") {
            std::string input;
            const std::vector<SessionStep> steps = parse_session(path, input);
            std::filesystem::path mesh_path = dir / input;
            if (input.empty()) {
                for (const auto& other : files) {
                    if (other.stem() == path.stem() && is_mesh_extension(file_extension(other))) {
                        mesh_path = other;
                    }
                }
            }
            if (mesh_path == dir || steps.empty()) {
                throw UsageError(path.string() + ": no steps, or no mesh named by '# input:' or " +
                                 "of the same name");
            }
            const MeshPtr mesh = share(read_mesh(mesh_path).mesh);
            b.add(steps.front().split ? "split_edge" : "flip_edge", file + " session",
                  [mesh, steps](const st::StudentTasks& t) {
                      return check_session(t, *mesh, steps);
                  });
        } else if (is_mesh_extension(file_extension(path))) {
            const NamedMesh m{file, share(read_mesh(path).mesh)};
            if (!m.mesh->is_triangle_mesh()) {
                throw UsageError(path.string() +
                                 ": not a triangle mesh (the course's tasks are "
                                 "on triangles; Ctrl+T in the viewer or "
                                 "--ops triangulate makes one)");
            }
            b.normals_case(m);
            if (m.mesh->n_edges() > 0) {
                b.flip_case(m, Edge(std::uint32_t(m.mesh->edges_size() / 2)));
                b.split_case(m, Edge(std::uint32_t(m.mesh->edges_size() / 3)));
            }
            if (plan_loop(*m.mesh).ok()) {
                b.loop_case(m);
            }
        }
        for (std::size_t i = first; i < b.cases.size(); ++i) {
            b.cases[i].hidden = hidden_name(file, listed);
        }
    }
    return std::move(b.cases);
}

}  // namespace meshedit::cli::grade
