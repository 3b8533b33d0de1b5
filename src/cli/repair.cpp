// `meshedit repair`: a mesh file repaired as read (repair.h), built, maybe its small holes
// filled, and written as `convert` writes.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli.h"
#include "meshedit/io/io.h"
#include "meshedit/repair/repair.h"

namespace meshedit::cli {
namespace {

// Checked here rather than by CLI11, whose range checks let "nan" through and print the
// largest double in full.
void check_amount(const CLI::Option* option, double value) {
    if (option->count() > 0 && !(std::isfinite(value) && value >= 0.0)) {
        throw UsageError("repair: " + option->get_name() +
                         " must be a finite number of at least 0, not " +
                         option->as<std::string>());
    }
}

void check_count(const CLI::Option* option, std::int64_t value) {
    if (option->count() > 0 && (value < 0 || value > std::int64_t{UINT32_MAX})) {
        throw UsageError("repair: " + option->get_name() + " must be a whole number from 0 to " +
                         std::to_string(UINT32_MAX) + ", not " + option->as<std::string>());
    }
}

// A share of an edge's length, as stitch_borders() takes it: more than 0, less than 0.5.
void check_ratio(const CLI::Option* option, double value) {
    if (option->count() > 0 && !(value > 0.0 && value < 0.5)) {
        throw UsageError("repair: " + option->get_name() +
                         " must be more than 0 and less than 0.5 (of an edge's length), not " +
                         option->as<std::string>());
    }
}

}  // namespace

Command add_repair(CLI::App& meshedit) {
    struct Settings {
        std::filesystem::path in, out;
        double distance = 0.0;
        double relative = MergeTolerance{}.value;
        bool no_merge = false;
        bool no_orient = false;
        bool no_stitch = false;
        double stitch_ratio = StitchOptions{}.ratio;
        std::int64_t min_faces = 0;
        std::int64_t fill_holes = 0;
        bool fair = false;
        bool quiet = false;
        bool ascii = false;
    };
    auto s = std::make_shared<Settings>();
    CLI::App* app = meshedit.add_subcommand(
        "repair",
        "merge, clean, stitch and orient a mesh as read, then write it (small holes filled)");
    app->add_option("IN", s->in, "the input mesh file")->required();
    app->add_option("OUT", s->out, "the output file")->required();
    add_strict_option(*app);
    auto* distance = app->add_option("--merge-distance", s->distance,
                                     "merge vertices at most D apart (an absolute distance)")
                         ->type_name("D");
    auto* relative =
        app->add_option("--merge-relative", s->relative,
                        "merge vertices at most R times the bounding-box diagonal apart "
                        "(default 1e-6)")
            ->type_name("R");
    distance->excludes(relative);
    auto* no_merge = app->add_flag("--no-merge", s->no_merge, "merge no vertices");
    no_merge->excludes(distance)->excludes(relative);
    auto* no_stitch = app->add_flag("--no-stitch", s->no_stitch,
                                    "leave T-junctions (a boundary vertex on another part's "
                                    "boundary edge) as they are");
    no_stitch->excludes(no_merge);
    auto* stitch_ratio =
        app->add_option("--stitch-ratio", s->stitch_ratio,
                        "stitch a boundary vertex into a boundary edge at most R times the "
                        "edge's length off it (default 0.05, less than 0.5)")
            ->type_name("R");
    stitch_ratio->excludes(no_stitch)->excludes(no_merge);
    app->add_flag("--no-orient", s->no_orient, "leave the faces' winding as it is");
    auto* min_faces =
        app->add_option("--min-component-faces", s->min_faces,
                        "remove components (faces joined through vertices) of fewer than N faces")
            ->type_name("N");
    auto* fill_holes = app->add_option("--fill-holes", s->fill_holes,
                                       "fill holes of at most K boundary edges, with triangles "
                                       "when the mesh is all triangles")
                           ->type_name("K");
    app->add_flag("--fair", s->fair,
                  "fill with triangles as long as the edges around each hole, faired so the "
                  "patch continues the surface (Liepa 2003), rather than with the fewest "
                  "triangles")
        ->needs(fill_holes);
    app->add_flag("--quiet", s->quiet, "print no report of what was repaired");
    app->add_flag("--ascii", s->ascii, "write PLY and STL as text rather than binary");
    app->footer(
        "Reads IN (" + mesh_extension_list(" ") +
        ") and repairs it before it becomes a halfedge mesh: merges\n"
        "vertices closer than the merge distance (which stitches an unwelded soup's coincident\n"
        "edges), removes degenerate faces (fewer than 3 distinct corners, or zero area) and\n"
        "duplicate faces, stitches T-junctions (a boundary vertex lying on another part's\n"
        "boundary edge, as between patches a CAD exporter tessellated apart, goes into that\n"
        "edge's face; then the merge joins them), and turns faces over so that neighbours\n"
        "agree and closed parts face outward. With --min-component-faces it removes small\n"
        "floating parts, with --fill-holes it fills small holes of the built mesh. Each change\n"
        "is reported on stderr, one line a step (\"meshedit: IN: merged 12 vertices …\"); OUT\n"
        "is written as convert writes it.\n"
        "Texture coordinates, normals, materials and other values stay with their corners,\n"
        "faces and vertices. Repairing OUT again changes nothing.\n"
        "\n"
        "Examples:\n"
        "  meshedit repair scan.stl fixed.ply\n"
        "  meshedit repair parts.obj whole.obj --merge-distance 0.001 --min-component-faces 10\n"
        "  meshedit repair broken.off closed.off --fill-holes 8\n"
        "  meshedit repair scan.ply whole.ply --fill-holes 2000 --fair\n"
        "\n"
        "Exit status: 0 ok, 1 a repair that would leave no face, 2 bad usage, bad input or an\n"
        "unwritable output.");
    return {app, [s, distance, relative, min_faces, fill_holes, stitch_ratio] {
                check_amount(distance, s->distance);
                check_ratio(stitch_ratio, s->stitch_ratio);
                check_amount(relative, s->relative);
                check_count(min_faces, s->min_faces);
                check_count(fill_holes, s->fill_holes);
                check_mesh_output(s->out);
                MeshSoup soup = read_soup(s->in);
                for (const std::string& notice : soup.notices) {
                    print_notice(notice);
                }
                soup.notices.clear();  // said; the build adds its own

                RepairOptions options;
                options.merge = !s->no_merge;
                options.tolerance = distance->count() > 0 ? MergeTolerance{s->distance, false}
                                                          : MergeTolerance{s->relative, true};
                options.stitch = !s->no_stitch;
                options.stitch_options.ratio = s->stitch_ratio;
                options.orient = !s->no_orient;
                options.components.min_faces = static_cast<std::size_t>(s->min_faces);
                options.fill_holes = static_cast<std::size_t>(s->fill_holes);
                options.fair_holes = s->fair;
                const std::size_t faces_before = soup.soup.n_faces();
                RepairedMesh repaired;
                try {
                    repaired = repair_and_build(std::move(soup), options, s->in.string());
                } catch (const std::invalid_argument& e) {
                    throw UsageError(std::string("repair: ") + e.what());
                }
                const std::string prefix = "meshedit: " + s->in.string() + ": ";
                if (repaired.loaded.mesh.n_faces() == 0) {
                    // Only a merge distance as large as the mesh empties it: refuse rather
                    // than write a file without faces.
                    std::string why;
                    for (const std::string& line : repaired.report.lines) {
                        why += (why.empty() ? "" : "; ") + line;
                    }
                    throw Failure(s->in.string() + ": repair refused: no face of " +
                                  std::to_string(faces_before) + " would be left (" + why +
                                  "); nothing written");
                }
                for (const std::string& notice : repaired.loaded.notices) {
                    print_notice(notice);
                }
                if (!s->quiet) {
                    for (const std::string& line : repaired.report.lines) {
                        std::fprintf(stderr, "%s%s\n", prefix.c_str(), line.c_str());
                    }
                }
                IoFlags flags;
                flags.ascii = s->ascii;
                write_output(repaired.loaded.mesh, s->out, flags);
                return 0;
            }};
}

}  // namespace meshedit::cli
