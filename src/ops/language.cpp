// Reading, naming and running steps of the edit language; the verbs are in verbs.cpp.
// The grammar (docs/cli.md):
//   list := step (',' step)*
//   step := VERB                      (Shape::None, Shape::Levels)
//         | VERB ':' INDEX '-' INDEX  (Shape::Edge)
//         | VERB ':' COUNT            (Shape::Levels, COUNT from 1 to 12)

#include <algorithm>
#include <charconv>

#include "meshedit/ops/ops.h"

namespace meshedit::ops {
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

// 12 levels multiply the face count by 4^12 ≈ 1.7e7: more is never intended.
constexpr std::uint32_t kMaxLevels = 12;

std::string expected_verbs() {
    std::string out;
    const auto all = verbs();
    for (std::size_t i = 0; i < all.size(); ++i) {
        out += i == 0 ? "" : (i + 1 == all.size() ? " or " : ", ");
        out += all[i].syntax;
    }
    return out;
}

}  // namespace

const Verb* find_verb(std::string_view name) {
    for (const Verb& verb : verbs()) {
        if (verb.name == name) {
            return &verb;
        }
    }
    return nullptr;
}

Step parse_step(std::string_view item) {
    const std::string text(item);
    const auto colon = item.find(':');
    const std::string_view name = item.substr(0, colon);
    const bool has_arg = colon != std::string_view::npos;
    const std::string_view arg = has_arg ? item.substr(colon + 1) : std::string_view();
    const Verb* verb = find_verb(name);
    if (verb == nullptr) {
        throw SyntaxError("unknown op '" + text + "' (expected " + expected_verbs() + ")");
    }
    Step step;
    step.verb = verb;
    step.text = text;
    switch (verb->shape) {
        case Shape::None:
            if (has_arg) {
                throw SyntaxError("bad op '" + text + "': " + std::string(name) +
                                  " takes no argument");
            }
            break;
        case Shape::Edge: {
            const auto dash = arg.find('-');
            if (!has_arg || dash == std::string_view::npos ||
                !parse_index(arg.substr(0, dash), step.a) ||
                !parse_index(arg.substr(dash + 1), step.b)) {
                throw SyntaxError("bad op '" + text + "': expected " + std::string(name) +
                                  ":A-B with two vertex indices");
            }
            if (step.a == step.b) {
                throw SyntaxError("bad op '" + text + "': an edge needs two different vertices");
            }
            break;
        }
        case Shape::Levels:
            if (has_arg) {
                std::uint32_t k = 0;
                if (!parse_index(arg, k) || k < 1 || k > kMaxLevels) {
                    throw SyntaxError("bad op '" + text + "': expected " + std::string(name) +
                                      ":K with K from 1 to " + std::to_string(kMaxLevels));
                }
                step.levels = static_cast<int>(k);
            }
            break;
    }
    return step;
}

std::vector<Step> parse(std::string_view list) {
    std::vector<Step> steps;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string_view item = trim(list.substr(start, comma - start));
        if (item.empty()) {
            throw SyntaxError("empty op in --ops list '" + std::string(list) + "'");
        }
        steps.push_back(parse_step(item));
        start = comma + 1;
    }
    return steps;
}

Step make_step(std::string_view name, const Mesh& mesh, Edge e) {
    Step step;
    step.verb = find_verb(name);
    MESHEDIT_ASSERT(step.verb != nullptr);
    step.text = std::string(name);
    if (step.verb->shape == Shape::Edge) {
        step.a = mesh.vertex(e, 0).idx();
        step.b = mesh.vertex(e, 1).idx();
        // Appended piecewise: `":" + string` trips a GCC 12 -Wrestrict false positive.
        step.text += ':';
        step.text += std::to_string(step.a);
        step.text += '-';
        step.text += std::to_string(step.b);
    }
    return step;
}

Edge named_edge(const Mesh& mesh, const Step& step) {
    for (const std::uint32_t v : {step.a, step.b}) {
        if (v >= mesh.vertices_size() || mesh.is_deleted(Vertex(v))) {
            throw OpError(step.text + ": no vertex " + std::to_string(v) + " (the mesh has " +
                              std::to_string(mesh.n_vertices()) + " vertices)",
                          false);
        }
    }
    const Edge e = mesh.find_edge(Vertex(step.a), Vertex(step.b));
    if (!e.is_valid()) {
        throw OpError(step.text + ": no edge joins vertices " + std::to_string(step.a) + " and " +
                          std::to_string(step.b),
                      false);
    }
    return e;
}

StepResult run_step(Mesh& mesh, const Step& step, const RunOptions& options) {
    if (const std::string refusal = step.verb->check(mesh, step); !refusal.empty()) {
        throw OpError(step.text + " refused: " + refusal, true);
    }
    return step.verb->run(mesh, step, options);
}

void apply_steps(Mesh& mesh, const std::vector<Step>& steps, const ApplyOptions& options) {
    // Every Loop level of the list must fit before any work is done (the local steps barely
    // change the size); each step is checked again when it runs.
    int levels = 0;
    for (const Step& step : steps) {
        if (step.verb->shape == Shape::Levels && step.verb->name == "loop") {
            levels += step.levels;
            if (const LoopPlan plan = plan_loop(mesh, levels); !plan.ok()) {
                throw OpError(step.text + " refused: " + plan.refusal, true);
            }
        }
    }
    // Progress is weighted by face count: each Loop level costs about as much as the faces
    // it starts from, and the local steps cost nothing in comparison.
    std::vector<double> cost(steps.size(), 0.0);
    double total = 0.0;
    double faces = static_cast<double>(mesh.n_faces());
    for (std::size_t i = 0; i < steps.size(); ++i) {
        for (int level = 0; steps[i].verb->name == "loop" && level < steps[i].levels; ++level) {
            cost[i] += faces;
            faces *= 4.0;
        }
        total += cost[i];
    }
    double done = 0.0;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        RunOptions run;
        run.weights = options.weights;
        if (options.progress && total > 0.0) {
            run.progress = [&, i](double f) {
                options.progress(std::min(1.0, (done + f * cost[i]) / total));
            };
        }
        const StepResult result = run_step(mesh, steps[i], run);
        done += cost[i];
        if (options.progress && total > 0.0) {
            options.progress(std::min(1.0, done / total));
        }
        for (const std::string& notice : result.notices) {
            if (options.notice) {
                options.notice(steps[i].text + ": " + notice);
            }
        }
    }
}

std::string syntax_list() {
    std::string out;
    for (const Verb& verb : verbs()) {
        out += out.empty() ? "" : " ";
        out += verb.syntax;
    }
    return out;
}

std::string help_lines() {
    std::size_t width = 0;
    for (const Verb& verb : verbs()) {
        width = std::max(width, verb.syntax.size());
    }
    std::string out;
    for (const Verb& verb : verbs()) {
        out += "  " + std::string(verb.syntax) + std::string(width + 2 - verb.syntax.size(), ' ');
        // Markdown backticks mean nothing in a terminal.
        std::string help(verb.help);
        help.erase(std::remove(help.begin(), help.end(), '`'), help.end());
        out += help + "\n";
    }
    return out;
}

std::string markdown_table() {
    std::string out = "| op | what it does |\n|---|---|\n";
    for (const Verb& verb : verbs()) {
        std::string syntax;
        std::size_t start = 0;
        // "loop, loop:K" → "`loop`, `loop:K`"
        while (start <= verb.syntax.size()) {
            const std::size_t comma = std::min(verb.syntax.find(", ", start), verb.syntax.size());
            syntax += (syntax.empty() ? "`" : ", `") +
                      std::string(verb.syntax.substr(start, comma - start)) + "`";
            start = comma + 2;
        }
        out += "| " + syntax + " | " + std::string(verb.help) + " |\n";
    }
    return out;
}

}  // namespace meshedit::ops
