#pragma once
/// \file
/// What the subdivision benchmarks (bench_loop, bench_catmark) share: the outcome of one
/// implementation's runs, OpenSubdiv's Far refinement as an anchor, and the one-job driver
/// that skips what may not fit, runs an implementation and prints its RESULT with the memory
/// extras (bench/README.md, "Loop subdivision").

#include <malloc.h>

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_util.h"
#include "meshedit/core/math.h"

namespace meshedit::bench {

/// What one implementation's runs leave behind.
struct Outcome {
    std::vector<double> ms;
    double faces_out = 0;
    double vertices_out = 0;
    double rss_after_mb = 0;  // RSS with the last result still alive
    std::map<std::string, double> extra;
};

/// Called in every untimed setup just before the input is copied (the first call records the
/// RSS the memory extras are measured from).
using BeforeCopy = std::function<void()>;

/// OpenSubdiv: TopologyRefinerFactory::Create from the polygons (`sizes[f]` corners each,
/// `corners` concatenated), RefineUniform(levels) (default options, or
/// fullTopologyInLastLevel), the vertex buffer of every level and PrimvarRefiner::Interpolate
/// of the double positions level by level, all timed; boundaries VTX_BOUNDARY_EDGE_ONLY.
inline Outcome run_opensubdiv(OpenSubdiv::Sdc::SchemeType scheme,
                              const std::vector<Vec3>& positions, const std::vector<int>& sizes,
                              const std::vector<int>& corners, int levels, int runs,
                              bool full_topology, const BeforeCopy& before_copy) {
    namespace Far = OpenSubdiv::Far;
    namespace Sdc = OpenSubdiv::Sdc;
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    Far::TopologyDescriptor desc;
    desc.numVertices = static_cast<int>(positions.size());
    desc.numFaces = static_cast<int>(sizes.size());
    desc.numVertsPerFace = sizes.data();
    desc.vertIndicesPerFace = corners.data();
    Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);

    std::unique_ptr<Far::TopologyRefiner> refiner;
    std::vector<OsdPoint> points;
    Outcome out;
    out.ms = time_runs(
        runs,
        [&] {
            refiner.reset();
            points = std::vector<OsdPoint>();
            before_copy();
        },
        [&] {
            refiner.reset(Factory::Create(desc, Factory::Options(scheme, sdc)));
            Far::TopologyRefiner::UniformOptions options(levels);
            options.fullTopologyInLastLevel = full_topology;
            refiner->RefineUniform(options);
            points.resize(static_cast<std::size_t>(refiner->GetNumVerticesTotal()));
            for (std::size_t i = 0; i < positions.size(); ++i) {
                points[i] = {positions[i].x, positions[i].y, positions[i].z};
            }
            Far::PrimvarRefiner primvar(*refiner);
            OsdPoint* src = points.data();
            for (int level = 1; level <= levels; ++level) {
                OsdPoint* dst = src + refiner->GetLevel(level - 1).GetNumVertices();
                primvar.Interpolate(level, src, dst);
                src = dst;
            }
        });
    out.rss_after_mb = current_rss_mb();
    out.faces_out = refiner->GetLevel(levels).GetNumFaces();
    out.vertices_out = refiner->GetLevel(levels).GetNumVertices();
    return out;
}

/// One (job, impl): skipped with a NOTE when its rough peak (bytes per output face: 500 for
/// OpenMesh and CGAL, 400 for the others; measured peaks are 70–310) may exceed 80% of
/// MemAvailable; else `run(before_copy)`, a NOTE if the face count is not the expected one,
/// and the RESULT with faces, levels and the memory extras. \return the exit status.
inline int run_subdivision_job(const std::string& job, const std::string& impl, int levels,
                               double faces_in, double faces_expected,
                               const std::function<Outcome(const BeforeCopy&)>& run) {
    try {
        const double bound_mb =
            faces_expected * (impl == "openmesh" || impl == "cgal" ? 500.0 : 400.0) / 1048576.0;
        const double available_mb = mem_available_mb();
        if (available_mb > 0 && bound_mb > 0.8 * available_mb) {
            std::printf("NOTE %s %s skipped: may need up to %.0f MiB, %.0f MiB available\n",
                        job.c_str(), impl.c_str(), bound_mb, available_mb);
            print_result(job, impl, {0.0}, {{"skipped", 1}, {"faces_in", faces_in}});
            return 0;
        }
        double rss_before = -1;
        const BeforeCopy before_copy = [&] {
            if (rss_before < 0) {
                if (!warm_protocol()) {  // warm: what the preparation freed is there to reuse
                    malloc_trim(0);  // freed heap pages of the preparation would hide the copy
                }
                rss_before = current_rss_mb();
            }
        };
        const Outcome out = run(before_copy);
        if (out.faces_out != faces_expected) {
            std::printf("NOTE %s %s: faces_out %.0f, expected %.0f\n", job.c_str(), impl.c_str(),
                        out.faces_out, faces_expected);
        }
        const double peak = peak_rss_mb();
        const double mib = 1024.0 * 1024.0;
        std::map<std::string, double> extra = out.extra;
        extra["faces_in"] = faces_in;
        extra["faces_out"] = out.faces_out;
        extra["vertices_out"] = out.vertices_out;
        extra["levels"] = levels;
        extra["peak_rss_mb"] = peak;
        extra["rss_before_mb"] = rss_before;
        extra["bytes_per_face"] = (peak - rss_before) * mib / out.faces_out;
        extra["bytes_per_face_retained"] = (out.rss_after_mb - rss_before) * mib / out.faces_out;
        print_result(job, impl, out.ms, extra);
    } catch (const std::exception& e) {
        std::printf("NOTE %s %s failed: %s\n", job.c_str(), impl.c_str(), e.what());
        print_result(job, impl, {0.0}, {{"skipped", 1}});
        return 1;
    }
    return 0;
}

}  // namespace meshedit::bench
