// bench_compare: `meshedit compare`'s library call (core/compare.h) on a torus of 1M triangles
// against a renumbered copy (vertices and faces shuffled, every face's first corner rotated),
// issue 36's "within a few seconds". MeshEdit only: there is no library to compare with.
//
//   compare_torus_1m_renumbered  the copy at the same positions: the match starts from them
//   compare_torus_1m_moved       the copy moved by (1e-3, 0, 0): no position in common, so the
//                                match starts from the signatures, and the Hausdorff distance
//                                is sampled through two closest-point trees
//
//   bench_compare --job compare_torus_1m_renumbered|compare_torus_1m_moved --impl meshedit
//                 [--runs N]
//   bench_compare --list
//   bench_compare --write DIR    writes DIR/torus_1m.ply and DIR/torus_1m_renumbered.ply, to
//                                time `meshedit compare` on the files (docs/cli.md)
//
// The copy is made untimed; the timed part is match_topology() and measure_deviation().

#include <cstdio>
#include <string>
#include <vector>

#include "bench_util.h"
#include "meshedit/core/compare.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/io.h"
#include "support/renumber.h"

namespace mb = meshedit::bench;

int main(int argc, char** argv) {
    if (argc == 3 && std::string(argv[1]) == "--write") {
        const meshedit::Mesh a = meshedit::shapes::torus(1000, 500);
        const std::filesystem::path dir = argv[2];
        meshedit::write_mesh(a, dir / "torus_1m.ply");
        meshedit::write_mesh(meshedit::test::renumbered(a, 36), dir / "torus_1m_renumbered.ply");
        return 0;
    }
    const std::vector<std::string> names{"compare_torus_1m_moved", "compare_torus_1m_renumbered"};
    const std::string impls[] = {"meshedit"};
    mb::JobArgs args;
    if (const std::optional<int> done = mb::read_command_line(argc, argv, names, impls, args)) {
        return *done;
    }
    const bool moved = args.job == "compare_torus_1m_moved";
    const meshedit::Mesh a = meshedit::shapes::torus(1000, 500);
    const meshedit::Mesh b =
        meshedit::test::renumbered(a, 36, moved ? meshedit::Vec3{1e-3, 0, 0} : meshedit::Vec3{});
    meshedit::TopologyMatch match;
    meshedit::Deviation deviation;
    const std::vector<double> ms = mb::time_runs(
        args.runs, [&] { match = {}; },
        [&] {
            match = meshedit::match_topology(a, b);
            deviation = meshedit::measure_deviation(a, b, match);
        });
    if (!match.isomorphic || (moved ? deviation.max < 1e-3 * 0.999 : deviation.max != 0.0)) {
        std::fprintf(stderr, "bench_compare: %s: wrong answer (%s)\n", args.job.c_str(),
                     match.difference.c_str());
        return 1;
    }
    mb::print_result(args.job, args.impl, ms,
                     {{"faces", static_cast<double>(a.n_faces())},
                      {"hausdorff", deviation.hausdorff},
                      {"peak_rss_mb", mb::peak_rss_mb()}});
    return 0;
}
