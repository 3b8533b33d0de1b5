// The safe sequence of repairs, and a repaired soup built into a mesh (repair.h).

#include "meshedit/repair/repair.h"

#include <algorithm>
#include <sstream>
#include <string>

namespace meshedit {

bool RepairReport::changed() const {
    return std::any_of(steps.begin(), steps.end(),
                       [](const RepairResult& step) { return step.changed(); });
}

RepairReport repair(MeshSoup& soup, const RepairOptions& options) {
    // The soup's own faults (an index out of range, a non-finite position) are the builder's
    // to name, before any step renumbers what it would name.
    check_polygon_soup(soup.soup);
    RepairReport report;
    const auto add = [&report](RepairResult result) {
        if (!result.sentence.empty()) {
            report.lines.push_back(result.sentence);
        }
        report.steps.push_back(std::move(result));
    };
    if (options.merge) {
        add(merge_vertices(soup, options.tolerance));
    }
    if (options.remove_degenerate) {
        add(remove_degenerate_faces(soup));
    }
    if (options.remove_duplicates) {
        add(remove_duplicate_faces(soup));
    }
    if (options.merge && options.stitch) {
        add(stitch_borders(soup, options.stitch_options, options.tolerance));
    }
    if (options.orient) {
        add(orient_faces(soup));
    }
    if (options.components.min_faces > 0 || options.components.min_area > 0.0) {
        add(remove_small_components(soup, options.components));
    }
    return report;
}

RepairedMesh repair_and_build(MeshSoup soup, const RepairOptions& options,
                              const std::string& name) {
    RepairedMesh out;
    try {
        out.report = repair(soup, options);
    } catch (const TopologyError& e) {
        throw IoError(name, "", e.what());
    }
    out.loaded = build_loaded_mesh(std::move(soup), name);
    // What the builder still had to repair (edges of three faces or more, vertices joining
    // separate fans): one line each, as BuildReport::summary() words them.
    std::istringstream summary(out.loaded.repairs.summary());
    for (std::string line; std::getline(summary, line);) {
        if (!line.empty()) {
            out.report.lines.push_back("the builder " + line);
        }
    }
    if (options.fill_holes > 0) {
        FairFillOptions fair;
        fair.max_edges = options.fill_holes;
        RepairResult filled = options.fair_holes ? fill_holes_fair(out.loaded.mesh, fair)
                                                 : fill_holes(out.loaded.mesh, options.fill_holes);
        // The refinement dissolves some of its new vertices: compact, so that the repaired
        // mesh is numbered as it is written and read back (only the patches' elements, which
        // come last, move).
        out.loaded.mesh.garbage_collection();
        if (!filled.sentence.empty()) {
            out.report.lines.push_back(filled.sentence);
        }
        out.report.steps.push_back(std::move(filled));
    }
    return out;
}

}  // namespace meshedit
