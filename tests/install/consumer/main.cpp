// consumer IN OUT: loads IN, flips the edge 0-6, runs one level of Loop, writes OUT, and prints
// the counts — an outside program built against an installed MeshEdit.
#include <cstdio>
#include <exception>

#include <meshedit/core/local_ops.h>
#include <meshedit/core/subdivision.h>
#include <meshedit/core/validate.h>
#include <meshedit/io/io.h>
#include <meshedit/ops/ops.h>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: consumer IN OUT\n");
        return 2;
    }
    try {
        meshedit::LoadedMesh loaded = meshedit::read_mesh(argv[1]);
        meshedit::Mesh& mesh = loaded.mesh;
        const meshedit::Edge e = mesh.find_edge(meshedit::Vertex(0), meshedit::Vertex(6));
        if (!e.is_valid() || !meshedit::flip(mesh, e)) {
            std::fprintf(stderr, "consumer: cannot flip 0-6\n");
            return 1;
        }
        meshedit::loop_subdivide(mesh);
        if (meshedit::validate(mesh)) {
            std::fprintf(stderr, "consumer: invalid mesh after Loop\n");
            return 1;
        }
        meshedit::write_mesh(mesh, argv[2]);
        std::printf("V=%zu E=%zu F=%zu verbs=%zu\n", mesh.n_vertices(), mesh.n_edges(),
                    mesh.n_faces(), meshedit::ops::verbs().size());
    } catch (const std::exception& error) {
        std::fprintf(stderr, "consumer: %s\n", error.what());
        return 1;
    }
    return 0;
}
