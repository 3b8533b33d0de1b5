// Reading and naming steps of the edit language; running them is run_steps.cpp, the verbs
// are in verbs.cpp.
// The grammar (docs/cli.md):
//   list    := step (',' step)*
//   step    := VERB (':' target (':' amounts)?)?
//   target  := 'v' INDEX | 'f' INDEX | INDEX '-' INDEX ('+' INDEX '-' INDEX)? | COUNT
//            | region
//   region  := 'sel' | 'f' INDEX ('..' INDEX)? ('+' 'f' INDEX ('..' INDEX)?)*
//   amounts := NUMBER (',' NUMBER)*
// A list item that starts like a number ("0.9", "-1") is the next amount of the step before
// it, so `extrude:f7:0.2,0.9,flip:1-2` is two steps.

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "meshedit/ops/ops.h"

#include "meshedit/core/budget.h"

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
    if (s.empty() || s.front() < '0' || s.front() > '9') {
        return false;
    }
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size();
}

// "A-B" into its two ends.
bool parse_edge(std::string_view s, std::uint32_t& a, std::uint32_t& b) {
    const auto dash = s.find('-');
    return dash != std::string_view::npos && parse_index(s.substr(0, dash), a) &&
           parse_index(s.substr(dash + 1), b);
}

// A whole-string number; non-finite values parse, and the operations refuse them by name.
bool parse_amount(std::string_view s, double& out) {
    if (!s.empty() && s.front() == '+') {
        s.remove_prefix(1);
    }
    if (s.empty()) {
        return false;
    }
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size();
}

// `inf` and `nan` too, as make_step() writes them (`simplify:0.5,inf,40`: no error bound,
// then a feature angle); no verb is called so.
bool starts_like_number(std::string_view s) {
    return !s.empty() && (std::isdigit(static_cast<unsigned char>(s.front())) != 0 ||
                          s.front() == '-' || s.front() == '+' || s.front() == '.' || s == "inf" ||
                          s == "nan" || s.starts_with("inf:") || s.starts_with("nan:"));
}

// 12 levels multiply the face count by 4^12 ≈ 1.7e7: more is never intended.
constexpr std::uint32_t kMaxLevels = 12;

std::string expected_verbs() {
    std::string out;
    const auto all = verbs();
    for (std::size_t i = 0; i < all.size(); ++i) {
        out += i == 0 ? "" : (i + 1 == all.size() ? " or " : ", ");
        out += all[i].name;
    }
    return out;
}

// What the verb's argument may be, in words: "vI (a vertex index) or A-B (an edge by its
// two vertex indices)".
std::string argument_words(const Verb& verb) {
    std::vector<std::string> parts;
    if ((verb.takes & kVertexArg) != 0) {
        parts.emplace_back("vI (a vertex index)");
    }
    if ((verb.takes & kEdgeArg) != 0) {
        parts.emplace_back("A-B (an edge by its two vertex indices)");
    }
    if ((verb.takes & kFaceArg) != 0) {
        parts.emplace_back("fI (a face index)");
    }
    if ((verb.takes & kEdgePair) != 0) {
        parts.emplace_back("A-B+C-D (two edges by their vertex indices)");
    }
    if ((verb.takes & kRegion) != 0) {
        parts.emplace_back((verb.takes & kElementList) != 0
                               ? "R (faces fI or fI..J, vertices vI or vI..J, or edges A-B, "
                                 "joined by +)"
                               : "R (faces: fI or fI..J, joined by +; sel: the selected faces)");
    }
    if ((verb.takes & kLevels) != 0) {
        parts.emplace_back("K from 1 to " + std::to_string(kMaxLevels));
    }
    std::string out;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        out += i == 0 ? "" : (i + 1 == parts.size() ? " or " : ", ");
        out += parts[i];
    }
    if ((verb.takes & kUvArg) != 0) {
        out += "; U one of " + uv_interpolation_names();
    }
    if ((verb.takes & kAttributesArg) != 0) {
        out += "; A aware or blind";
    }
    return out;
}

[[noreturn]] void bad(const std::string& text, const std::string& why) {
    throw SyntaxError("bad op '" + text + "': " + why);
}

// A region: "f4", "f4..9", joined by '+' ("f1..3+f7"), or "sel" (the selection); with
// kElementList also vertices ("v2..5+v9") or edges ("3-4+4-5"), one kind per step.
void parse_region(std::string_view arg, Step& step, const std::string& expected) {
    step.target = Target::Region;
    if (arg == "sel") {
        step.from_selection = true;
        return;
    }
    const bool any_kind = (step.verb->takes & kElementList) != 0;
    std::size_t start = 0;
    while (start <= arg.size()) {
        const std::size_t plus = std::min(arg.find('+', start), arg.size());
        std::string_view item = arg.substr(start, plus - start);
        const ElementRef::Kind kind = item.empty()          ? ElementRef::Kind::None
                                      : item.front() == 'f' ? ElementRef::Kind::Face
                                      : item.front() == 'v' ? ElementRef::Kind::Vertex
                                      : std::isdigit(static_cast<unsigned char>(item.front())) != 0
                                          ? ElementRef::Kind::Edge
                                          : ElementRef::Kind::None;
        if (kind == ElementRef::Kind::None || (kind != ElementRef::Kind::Face && !any_kind)) {
            bad(step.text, expected);
        }
        if (start != 0 && kind != step.region_kind) {
            bad(step.text, "one kind of element per step (faces fI, vertices vI or edges A-B)");
        }
        step.region_kind = kind;
        std::array<std::uint32_t, 2> range{};
        if (kind == ElementRef::Kind::Edge) {
            if (!parse_edge(item, range[0], range[1])) {
                bad(step.text, expected);
            }
            step.region.push_back(range);
            start = plus + 1;
            continue;
        }
        item.remove_prefix(1);
        const auto dots = item.find("..");
        if (!parse_index(item.substr(0, dots), range[0]) ||
            !parse_index(
                dots == std::string_view::npos ? item.substr(0, dots) : item.substr(dots + 2),
                range[1])) {
            bad(step.text, expected);
        }
        if (range[1] < range[0]) {
            bad(step.text, "a range fI..J needs I <= J");
        }
        step.region.push_back(range);
        start = plus + 1;
    }
}

// The target part of a step ("v12", "3-4", "0-1+5-6", "2", "f1..3+f7").
void parse_target(std::string_view arg, Step& step) {
    const Verb& verb = *step.verb;
    const std::string expected =
        "expected " + std::string(verb.syntax) + " with " + argument_words(verb);
    if ((verb.takes & kRegion) != 0) {
        parse_region(arg, step, expected);
        return;
    }
    const std::optional<ElementName> name = parse_element_name(arg);
    if (name && name->kind != ElementRef::Kind::Halfedge) {
        step.target = name->kind == ElementRef::Kind::Vertex ? Target::Vertex
                      : name->kind == ElementRef::Kind::Face ? Target::Face
                                                             : Target::Edge;
        step.a = name->a;
        step.b = name->b;
    } else if (const auto plus = arg.find('+'); plus != std::string_view::npos) {
        step.target = Target::EdgePair;
        if (!parse_edge(arg.substr(0, plus), step.a, step.b) ||
            !parse_edge(arg.substr(plus + 1), step.c, step.d)) {
            bad(step.text, expected);
        }
    } else if (!arg.empty() && (arg.front() == 'v' || arg.front() == 'f' || arg.front() == 'h' ||
                                arg.find('-') != std::string_view::npos)) {
        bad(step.text, expected);  // an element, misspelt
    } else {
        std::uint32_t k = 0;
        if ((verb.takes & kLevels) == 0 || !parse_index(arg, k) || k < 1 || k > kMaxLevels) {
            bad(step.text, expected);
        }
        step.levels = static_cast<int>(k);
        return;
    }
    if (!verb.accepts(step.target)) {
        bad(step.text, expected);
    }
    if ((step.target == Target::Edge || step.target == Target::EdgePair) && step.a == step.b) {
        bad(step.text, "an edge needs two different vertices");
    }
    if (step.target == Target::EdgePair && step.c == step.d) {
        bad(step.text, "an edge needs two different vertices");
    }
}

void parse_amounts(std::string_view list, Step& step) {
    const Verb& verb = *step.verb;
    std::size_t count = 0;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        if (count == verb.max_amounts) {
            bad(step.text, std::string(verb.name) + " takes at most " +
                               std::to_string(verb.max_amounts) + " amounts (" +
                               std::string(verb.syntax) + ")");
        }
        if (!parse_amount(trim(list.substr(start, comma - start)), step.amounts[count])) {
            bad(step.text, "expected numbers after the element (" + std::string(verb.syntax) + ")");
        }
        ++count;
        start = comma + 1;
    }
    if (count < verb.min_amounts) {
        bad(step.text, "expected " + std::string(verb.syntax));
    }
}

[[noreturn]] void missing(const Step& step, const char* kind, std::uint32_t index, std::size_t have,
                          const char* kinds) {
    throw OpError(step.text + ": no " + kind + " " + std::to_string(index) + " (the mesh has " +
                      std::to_string(have) + " " + kinds + ")",
                  false);
}

Vertex live_vertex(const Mesh& mesh, const Step& step, std::uint32_t v) {
    if (v >= mesh.vertices_size() || mesh.is_deleted(Vertex(v))) {
        missing(step, "vertex", v, mesh.n_vertices(), "vertices");
    }
    return Vertex(v);
}

Edge edge_between(const Mesh& mesh, const Step& step, std::uint32_t a, std::uint32_t b) {
    const Edge e = mesh.find_edge(live_vertex(mesh, step, a), live_vertex(mesh, step, b));
    if (!e.is_valid()) {
        throw OpError(step.text + ": no edge joins vertices " + std::to_string(a) + " and " +
                          std::to_string(b),
                      false);
    }
    return e;
}

}  // namespace

bool Verb::accepts(Target target) const {
    switch (target) {
        case Target::None:
            return (takes & (kWholeMesh | kLevels)) != 0;
        case Target::Vertex:
            return (takes & kVertexArg) != 0;
        case Target::Edge:
            return (takes & kEdgeArg) != 0;
        case Target::Face:
            return (takes & kFaceArg) != 0;
        case Target::EdgePair:
            return (takes & kEdgePair) != 0;
        case Target::Region:
            return (takes & kRegion) != 0;
    }
    return false;
}

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
    const Verb* verb = find_verb(name);
    if (verb == nullptr) {
        throw SyntaxError("unknown op '" + text + "' (the verbs are " + expected_verbs() + ")");
    }
    Step step;
    step.verb = verb;
    step.text = text;
    step.amounts = verb->defaults;
    if (colon == std::string_view::npos) {
        if (!verb->accepts(Target::None)) {
            bad(text, "expected " + std::string(verb->syntax) + " with " + argument_words(*verb));
        }
    } else if ((verb->takes & ~(kWholeMesh | kAttributesArg)) == 0) {
        if (verb->max_amounts == 0) {
            bad(text, std::string(name) + " takes no argument");
        }
        std::string_view arg = item.substr(colon + 1);
        // simplify's last part may be attributes=A: `simplify:attributes=blind`,
        // `simplify:0.1:attributes=blind`.
        if (const auto last = arg.rfind(':');
            (verb->takes & kAttributesArg) != 0 &&
            arg.substr(last == std::string_view::npos ? 0 : last + 1).starts_with("attributes=")) {
            const std::string_view mode =
                arg.substr((last == std::string_view::npos ? 0 : last + 1) + 11);
            if (mode != "aware" && mode != "blind") {
                bad(text, "unknown attribute mode '" + std::string(mode) +
                              "' (aware: texture coordinates, colours and seams weigh; blind: "
                              "positions only)");
            }
            step.attributes =
                mode == "blind" ? SimplifyAttributes::Blind : SimplifyAttributes::Aware;
            if (last == std::string_view::npos) {
                return step;
            }
            arg = arg.substr(0, last);
        }
        parse_amounts(arg, step);  // a whole-mesh verb's amounts: simplify:0.25
    } else {
        std::string_view arg = item.substr(colon + 1);
        // A subdivision's last part may be uv=U: `loop:uv=none`, `loop:2:uv=none`.
        if (const auto last = arg.rfind(':');
            (verb->takes & kUvArg) != 0 &&
            arg.substr(last == std::string_view::npos ? 0 : last + 1).starts_with("uv=")) {
            const std::string_view uv = arg.substr(last == std::string_view::npos ? 3 : last + 4);
            step.uv = parse_uv_interpolation(uv);
            if (!step.uv) {
                bad(text, "unknown texture-coordinate interpolation '" + std::string(uv) +
                              "' (one of " + uv_interpolation_names() + ")");
            }
            if (last == std::string_view::npos) {
                return step;
            }
            arg = arg.substr(0, last);
        }
        const auto second = arg.find(':');
        if (second != std::string_view::npos) {
            if (verb->max_amounts == 0) {
                bad(text,
                    std::string(name) + " takes no amounts (" + std::string(verb->syntax) + ")");
            }
            parse_amounts(arg.substr(second + 1), step);
            arg = arg.substr(0, second);
        } else if (verb->min_amounts > 0) {
            bad(text, "expected " + std::string(verb->syntax));
        }
        parse_target(arg, step);
    }
    return step;
}

double parse_cost(std::string_view text) {
    // At most one step per comma or line end, plus one. A step costs its Step, the string of
    // its item while the list is split and the vector's growth; the text is copied into the
    // steps' strings once more.
    const auto bound = static_cast<double>(
        std::count_if(text.begin(), text.end(),
                      [](char c) { return c == ',' || c == '\n' || c == '\r'; }) +
        1);
    return bound * (2.0 * sizeof(Step) + sizeof(std::string)) +
           2.0 * static_cast<double>(text.size());
}

std::vector<Step> parse(std::string_view list) {
    check_budget(parse_cost(list),
                 "parsing an --ops list of " + std::to_string(list.size()) + " characters");
    std::vector<std::string> items;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string_view item = trim(list.substr(start, comma - start));
        if (item.empty()) {
            throw SyntaxError("empty op in --ops list '" + std::string(list) + "'");
        }
        if (starts_like_number(item) && !items.empty()) {
            items.back() += ',';
            items.back() += item;
        } else {
            items.emplace_back(item);
        }
        start = comma + 1;
    }
    std::vector<Step> steps;
    steps.reserve(items.size());
    for (const std::string& item : items) {
        steps.push_back(parse_step(item));
    }
    return steps;
}

namespace {

// The line of `text` that starts at `start`, without its end; `start` moves to the next line.
// Lines end with LF, CRLF or a lone CR (old Mac files: read as one comment line they would
// run nothing).
std::string_view next_line(std::string_view text, std::size_t& start) {
    const std::size_t end = std::min(text.find_first_of("\r\n", start), text.size());
    const std::string_view line = text.substr(start, end - start);
    start = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
    return line;
}

}  // namespace

std::vector<Step> parse_session(std::string_view text) {
    // Checked for the whole file first: each line's parse() only sees its own.
    check_budget(parse_cost(text),
                 "parsing a session of " + std::to_string(text.size()) + " characters");
    std::vector<Step> steps;
    std::size_t line_number = 0;
    for (std::size_t start = 0; start < text.size();) {
        const std::string_view line = trim(next_line(text, start));
        ++line_number;
        if (line.empty() || line.front() == '#') {
            continue;
        }
        try {
            for (Step& step : parse(line)) {
                steps.push_back(std::move(step));
            }
        } catch (const SyntaxError& e) {
            throw SyntaxError("line " + std::to_string(line_number) + ": " + e.what());
        }
    }
    return steps;
}

std::string session_text(const std::vector<std::string>& header,
                         const std::vector<std::string>& steps) {
    std::string text;
    for (const std::string& line : header) {
        text += "# " + line + '\n';
    }
    for (const std::string& step : steps) {
        text += step + '\n';
    }
    return text;
}

std::optional<std::string> session_header_value(std::string_view text, std::string_view key) {
    const std::string prefix = "# " + std::string(key) + ": ";
    for (std::size_t start = 0; start < text.size();) {
        const std::string_view line = trim(next_line(text, start));
        if (!line.empty() && line.front() != '#') {
            break;  // the header is the comment lines before the first step
        }
        if (line.substr(0, prefix.size()) == prefix) {
            return std::string(trim(line.substr(prefix.size())));
        }
    }
    return std::nullopt;
}

Step make_step(std::string_view name, const Mesh& mesh, const ElementRef& target,
               std::span<const double> amounts, const ElementRef& second) {
    Step step;
    step.verb = find_verb(name);
    MESHEDIT_ASSERT(step.verb != nullptr);
    step.amounts = step.verb->defaults;
    std::string text(name);
    const auto edge_text = [&](Edge e, std::uint32_t& a, std::uint32_t& b) {
        a = mesh.vertex(e, 0).idx();
        b = mesh.vertex(e, 1).idx();
        return std::to_string(a) + "-" + std::to_string(b);
    };
    // Appended piecewise: `":" + string` trips a GCC 12 -Wrestrict false positive.
    switch (target.kind) {
        case ElementRef::Kind::None:
            step.target = Target::None;
            break;
        case ElementRef::Kind::Vertex:
            step.target = Target::Vertex;
            step.a = target.index;
            text += ":v";
            text += std::to_string(step.a);
            break;
        case ElementRef::Kind::Face:
            step.target = Target::Face;
            step.a = target.index;
            text += ":f";
            text += std::to_string(step.a);
            break;
        case ElementRef::Kind::Edge:
        case ElementRef::Kind::Halfedge: {
            const Edge e = target.kind == ElementRef::Kind::Edge
                               ? Edge(target.index)
                               : Mesh::edge(Halfedge(target.index));
            step.target = Target::Edge;
            text += ':';
            text += edge_text(e, step.a, step.b);
            if (second.kind == ElementRef::Kind::Edge) {
                step.target = Target::EdgePair;
                text += '+';
                text += edge_text(Edge(second.index), step.c, step.d);
            }
            break;
        }
    }
    MESHEDIT_ASSERT(step.verb->accepts(step.target));
    MESHEDIT_ASSERT(amounts.size() <= step.verb->max_amounts);
    for (std::size_t i = 0; i < amounts.size(); ++i) {
        step.amounts[i] = amounts[i];
    }
    // Every amount is written (defaults too) so the text says exactly what ran; a last one
    // left at an unbounded default (simplify's error bound) means the same left out.
    std::size_t written = step.verb->max_amounts;
    while (written > 0 && std::isinf(step.verb->defaults[written - 1]) &&
           step.amounts[written - 1] == step.verb->defaults[written - 1]) {
        --written;
    }
    for (std::size_t i = 0; i < written; ++i) {
        text += i == 0 ? ':' : ',';
        text += number_text(step.amounts[i]);
    }
    step.text = std::move(text);
    return step;
}

std::optional<ElementName> parse_element_name(std::string_view text) {
    ElementName name;
    // The older --select spellings: a kind letter and a colon ("v:12", "e:3-4").
    if (text.size() > 2 && text[1] == ':' &&
        std::string_view("vefh").find(text[0]) != std::string_view::npos) {
        const char kind = text[0];
        text.remove_prefix(2);
        if (kind == 'e') {
            name.kind = ElementRef::Kind::Edge;
            return parse_edge(text, name.a, name.b) ? std::optional(name) : std::nullopt;
        }
        if (kind == 'h') {
            name.kind = ElementRef::Kind::Halfedge;
            return parse_edge(text, name.a, name.b) ? std::optional(name) : std::nullopt;
        }
        name.kind = kind == 'v' ? ElementRef::Kind::Vertex : ElementRef::Kind::Face;
        return parse_index(text, name.a) ? std::optional(name) : std::nullopt;
    }
    if (!text.empty() && (text.front() == 'v' || text.front() == 'f')) {
        name.kind = text.front() == 'v' ? ElementRef::Kind::Vertex : ElementRef::Kind::Face;
        return parse_index(text.substr(1), name.a) ? std::optional(name) : std::nullopt;
    }
    if (!text.empty() && text.front() == 'h') {
        name.kind = ElementRef::Kind::Halfedge;
        return parse_edge(text.substr(1), name.a, name.b) ? std::optional(name) : std::nullopt;
    }
    name.kind = ElementRef::Kind::Edge;
    return parse_edge(text, name.a, name.b) ? std::optional(name) : std::nullopt;
}

Vertex named_vertex(const Mesh& mesh, const Step& step) {
    MESHEDIT_ASSERT(step.target == Target::Vertex);
    return live_vertex(mesh, step, step.a);
}

Edge named_edge(const Mesh& mesh, const Step& step) {
    MESHEDIT_ASSERT(step.target == Target::Edge || step.target == Target::EdgePair);
    return edge_between(mesh, step, step.a, step.b);
}

Edge named_second_edge(const Mesh& mesh, const Step& step) {
    MESHEDIT_ASSERT(step.target == Target::EdgePair);
    return edge_between(mesh, step, step.c, step.d);
}

Face named_face(const Mesh& mesh, const Step& step) {
    MESHEDIT_ASSERT(step.target == Target::Face);
    if (step.a >= mesh.faces_size() || mesh.is_deleted(Face(step.a))) {
        missing(step, "face", step.a, mesh.n_faces(), "faces");
    }
    return Face(step.a);
}

ElementRef named_element(const Mesh& mesh, const Step& step) {
    switch (step.target) {
        case Target::Vertex:
            return ElementRef::vertex(named_vertex(mesh, step));
        case Target::Edge:
        case Target::EdgePair:
            return ElementRef::edge(named_edge(mesh, step));
        case Target::Face:
            return ElementRef::face(named_face(mesh, step));
        case Target::Region:
            return ElementRef::face(named_faces(mesh, step).front());
        case Target::None:
            break;
    }
    return {};
}

std::vector<Face> named_faces(const Mesh& mesh, const Step& step) {
    MESHEDIT_ASSERT(step.target == Target::Region && step.region_kind == ElementRef::Kind::Face);
    std::vector<Face> out;
    for (const auto& [first, last] : step.region) {
        for (std::uint64_t f = first; f <= last; ++f) {
            if (f >= mesh.faces_size() || mesh.is_deleted(Face(std::uint32_t(f)))) {
                missing(step, "face", std::uint32_t(f), mesh.n_faces(), "faces");
            }
            out.push_back(Face(std::uint32_t(f)));
        }
    }
    return out;
}

namespace {

// `indices` as sorted ranges joined by '+', each after `prefix`: "f4..6+f9".
void append_ranges(std::string& text, std::vector<std::uint32_t> indices, char prefix) {
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    for (std::size_t i = 0; i < indices.size();) {
        std::size_t j = i;
        while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) {
            ++j;
        }
        if (i != 0) {
            text += '+';
        }
        text += prefix;
        text += std::to_string(indices[i]);
        if (j > i) {
            text += "..";
            text += std::to_string(indices[j]);
        }
        i = j + 1;
    }
}

}  // namespace

Step make_region_step(std::string_view name, const std::vector<Face>& faces,
                      std::span<const double> amounts) {
    std::vector<std::uint32_t> indices;
    for (const Face f : faces) {
        indices.push_back(f.idx());
    }
    MESHEDIT_ASSERT(!indices.empty());
    std::string text(name);
    text += ':';
    append_ranges(text, std::move(indices), 'f');
    const Verb* verb = find_verb(name);
    MESHEDIT_ASSERT(verb != nullptr && verb->max_amounts >= amounts.size());
    std::array<double, kMaxAmounts> values = verb->defaults;
    for (std::size_t i = 0; i < verb->max_amounts; ++i) {
        if (i < amounts.size()) {
            values[i] = amounts[i];
        }
        text += i == 0 ? ':' : ',';
        text += number_text(values[i]);
    }
    return parse_step(text);
}

std::string select_step_text(const Mesh& mesh, const std::vector<ElementRef>& selected) {
    using Kind = ElementRef::Kind;
    const auto kind_of = [](const ElementRef& e) {
        return e.kind == Kind::Halfedge ? Kind::Edge : e.kind;
    };
    const Kind kind = selected.empty() ? Kind::None : kind_of(selected.back());
    std::vector<std::uint32_t> indices;
    for (const ElementRef& e : selected) {
        if (kind_of(e) == kind) {
            indices.push_back(e.kind == Kind::Halfedge ? Mesh::edge(Halfedge(e.index)).idx()
                                                       : e.index);
        }
    }
    if (indices.empty() || (kind != Kind::Face && kind != Kind::Vertex && kind != Kind::Edge)) {
        return "select_none";
    }
    std::string text = "select:";
    if (kind != Kind::Edge) {
        append_ranges(text, std::move(indices), kind == Kind::Face ? 'f' : 'v');
        return text;
    }
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    for (std::size_t i = 0; i < indices.size(); ++i) {
        const Halfedge h = mesh.halfedge(Edge(indices[i]), 0);
        text += i == 0 ? "" : "+";
        text += std::to_string(mesh.from_vertex(h).idx()) + '-' +
                std::to_string(mesh.to_vertex(h).idx());
    }
    return text;
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
