// `meshedit check FILE --problems [--json]`: the problems of a mesh (repair/problems.h), one
// line each, or one JSON object.

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "cli.h"
#include "meshedit/core/validate.h"
#include "meshedit/repair/problems.h"

namespace meshedit::cli {

int print_problems(const std::filesystem::path& path, const LoadedDocument& input, bool json) {
    const ProblemReport report = find_problems(input.mesh, &input.repairs);
    const auto invalid = validate(input.mesh);
    if (json) {
        nlohmann::ordered_json j;
        j["file"] = path.string();
        j["valid"] = !invalid.has_value();
        nlohmann::ordered_json counts = nlohmann::ordered_json::object();
        for (std::size_t k = 0; k < kProblemKinds; ++k) {
            counts[problem_kind_name(static_cast<ProblemKind>(k))] = report.counts[k];
        }
        j["counts"] = counts;
        nlohmann::ordered_json list = nlohmann::ordered_json::array();
        for (const Problem& p : report.problems) {
            list.push_back({{"kind", problem_kind_name(p.kind)},
                            {"element", p.where.is_none() ? "" : to_string(p.where)},
                            {"size", p.size},
                            {"text", p.text}});
        }
        j["problems"] = list;
        std::printf("%s\n", j.dump(2).c_str());
    } else {
        for (const Problem& p : report.problems) {
            std::printf("%s: %s: %s\n", path.string().c_str(), problem_kind_name(p.kind),
                        p.text.c_str());
        }
        std::printf("%s: %s%s\n", path.string().c_str(), report.summary().c_str(),
                    invalid ? (" (INVALID: " + invalid->message + ")").c_str() : "");
    }
    return invalid || !report.empty() ? 1 : 0;
}

}  // namespace meshedit::cli
