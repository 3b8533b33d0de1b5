// Parsing and applying the `--ops` list. The grammar is deliberately tiny (docs/cli.md):
//   list := op (',' op)*
//   op   := ('flip'|'split'|'collapse'|'crease') ':' INDEX '-' INDEX
//         | 'loop' [':' COUNT] | 'triangulate'

#include "ops.h"

#include <unistd.h>

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <string>

#include "meshedit/core/local_ops.h"

namespace meshedit::cli {
namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) {
        s.remove_prefix(1);
    }
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) {
        s.remove_suffix(1);
    }
    return s;
}

// Strict unsigned parse: digits only, the whole string, no overflow.
bool parse_index(std::string_view s, std::uint32_t& out) {
    if (s.empty()) {
        return false;
    }
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size();
}

Op parse_one(std::string_view item) {
    const std::string text(item);
    const auto colon = item.find(':');
    const std::string_view name = item.substr(0, colon);
    const std::string_view arg =
        colon == std::string_view::npos ? std::string_view() : item.substr(colon + 1);
    Op op;
    op.text = text;
    if (name == "flip" || name == "split" || name == "collapse" || name == "crease") {
        op.kind = name == "flip"       ? Op::Kind::Flip
                  : name == "split"    ? Op::Kind::Split
                  : name == "collapse" ? Op::Kind::Collapse
                                       : Op::Kind::Crease;
        const auto dash = arg.find('-');
        if (colon == std::string_view::npos || dash == std::string_view::npos ||
            !parse_index(arg.substr(0, dash), op.a) || !parse_index(arg.substr(dash + 1), op.b)) {
            throw OpSyntaxError("bad op '" + text + "': expected " + std::string(name) +
                                ":A-B with two vertex indices");
        }
        if (op.a == op.b) {
            throw OpSyntaxError("bad op '" + text + "': an edge needs two different vertices");
        }
        return op;
    }
    if (name == "loop") {
        op.kind = Op::Kind::Loop;
        if (colon != std::string_view::npos) {
            std::uint32_t k = 0;
            // 12 levels multiply the face count by 4^12 ≈ 1.7e7: more is never intended.
            if (!parse_index(arg, k) || k < 1 || k > 12) {
                throw OpSyntaxError("bad op '" + text + "': expected loop:K with K from 1 to 12");
            }
            op.levels = static_cast<int>(k);
        }
        return op;
    }
    if (name == "triangulate" && colon == std::string_view::npos) {
        op.kind = Op::Kind::Triangulate;
        return op;
    }
    throw OpSyntaxError("unknown op '" + text +
                        "' (expected flip:A-B, split:A-B, collapse:A-B, crease:A-B, loop, "
                        "loop:K or triangulate)");
}

// The edge an op names, or an OpError saying which part of the name does not exist.
Edge named_edge(const Mesh& mesh, const Op& op) {
    for (const std::uint32_t v : {op.a, op.b}) {
        if (v >= mesh.vertices_size() || mesh.is_deleted(Vertex(v))) {
            throw OpError(op.text + ": no vertex " + std::to_string(v) + " (the mesh has " +
                              std::to_string(mesh.n_vertices()) + " vertices)",
                          false);
        }
    }
    const Edge e = mesh.find_edge(Vertex(op.a), Vertex(op.b));
    if (!e.is_valid()) {
        throw OpError(op.text + ": no edge joins vertices " + std::to_string(op.a) + " and " +
                          std::to_string(op.b),
                      false);
    }
    return e;
}

double physical_memory() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page_size = sysconf(_SC_PAGESIZE);
    return pages > 0 && page_size > 0 ? static_cast<double>(pages) * static_cast<double>(page_size)
                                      : 1e300;  // unknown: do not refuse
}

std::string gigabytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
    return text;
}

[[noreturn]] void refuse(const Op& op, std::string_view reason) {
    throw OpError(op.text + " refused: " + std::string(reason), true);
}

}  // namespace

std::vector<Op> parse_ops(std::string_view list) {
    std::vector<Op> ops;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string_view item = trim(list.substr(start, comma - start));
        if (item.empty()) {
            throw OpSyntaxError("empty op in --ops list '" + std::string(list) + "'");
        }
        ops.push_back(parse_one(item));
        start = comma + 1;
    }
    return ops;
}

void apply_ops(Mesh& mesh, const std::vector<Op>& ops, const ApplyOptions& options) {
    // Progress is weighted by face count: each Loop level costs about as much as the faces
    // it starts from, and the local ops cost nothing in comparison.
    double total = 0.0;
    {
        double faces = static_cast<double>(mesh.n_faces());
        for (const Op& op : ops) {
            for (int level = 0; op.kind == Op::Kind::Loop && level < op.levels; ++level) {
                total += faces;
                faces *= 4.0;
            }
        }
    }
    // Each Loop level makes the arrays about four times larger, and the old ones live on
    // while it runs: refuse a list that cannot fit in physical memory before doing any
    // work, rather than let the machine swap or the OOM killer end the process later.
    {
        double bytes = static_cast<double>(mesh.bytes());
        for (const Op& op : ops) {
            for (int level = 0; op.kind == Op::Kind::Loop && level < op.levels; ++level) {
                bytes *= 4.0;
                // Four times the arrays: the level's temporaries, then the writer's
                // compacted copy, normals and text buffers. Half the machine at most, as
                // others may be using the rest.
                const double need = 4.0 * bytes;
                if (need > 0.5 * physical_memory()) {
                    refuse(op, "level " + std::to_string(level + 1) + " would need about " +
                                   gigabytes(need) +
                                   " of memory, more than half of this machine's " +
                                   gigabytes(physical_memory()));
                }
            }
        }
    }
    double done = 0.0;
    auto report = [&](double fraction) {
        if (options.progress && total > 0.0) {
            options.progress(std::min(1.0, fraction / total));
        }
    };

    for (const Op& op : ops) {
        switch (op.kind) {
            case Op::Kind::Flip: {
                if (const auto r = flip(mesh, named_edge(mesh, op)); !r) {
                    refuse(op, r.reason());
                }
                break;
            }
            case Op::Kind::Split: {
                if (const auto r = split(mesh, named_edge(mesh, op)); !r) {
                    refuse(op, r.reason());
                }
                break;
            }
            case Op::Kind::Collapse: {
                if (const auto r = collapse(mesh, named_edge(mesh, op)); !r) {
                    refuse(op, r.reason());
                }
                break;
            }
            case Op::Kind::Crease: {
                const Edge e = named_edge(mesh, op);
                auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
                crease[e] = crease[e] ? 0 : 1;
                break;
            }
            case Op::Kind::Triangulate: {
                const std::size_t n = triangulate(mesh);
                if (n > 0 && options.notice) {
                    options.notice(op.text + ": triangulated " + std::to_string(n) + " faces");
                }
                break;
            }
            case Op::Kind::Loop: {
                for (int level = 0; level < op.levels; ++level) {
                    if (const OpStatus ok = is_loop_ok(mesh); !ok) {
                        refuse(op, ok.reason());
                    }
                    // Handles are 32-bit: a level that would overflow the halfedge indices
                    // (2E' = 2(2E + 3F)) is refused rather than silently wrapping around.
                    const double next_halfedges = 2.0 * (2.0 * static_cast<double>(mesh.n_edges()) +
                                                         3.0 * static_cast<double>(mesh.n_faces()));
                    if (next_halfedges >= static_cast<double>(kInvalidIndex)) {
                        refuse(op, "the result would exceed 2^32 halfedges");
                    }
                    const double cost = static_cast<double>(mesh.n_faces());
                    LoopOptions loop;
                    loop.weights = options.weights;
                    if (options.progress) {
                        loop.progress = [&](double f) { report(done + f * cost); };
                    }
                    const LoopReport r = loop_subdivide(mesh, loop);
                    if (r.triangulated_faces > 0 && options.notice) {
                        options.notice(op.text + ": triangulated " +
                                       std::to_string(r.triangulated_faces) +
                                       " non-triangle faces before subdividing");
                    }
                    done += cost;
                    report(done);
                }
                break;
            }
        }
    }
}

}  // namespace meshedit::cli
