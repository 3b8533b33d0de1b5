// `meshedit grade LIB.so [--gradescope OUT.json] [--cases DIR] [--samples DIR] [--timeout S]
// [--task NAME]`: loads a student library (meshedit/student/student.h), runs the battery of
// each task in forked children and reports every case, a score per task and the total
// (docs/student.md).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "cli.h"
#include "grade_cases.h"
#include "grade_sandbox.h"
#include "meshedit/files/files.h"
#include "meshedit/files/io_error.h"
#include "student_library.h"

namespace meshedit::cli {
namespace {

using Json = nlohmann::ordered_json;
using grade::Case;
using grade::kTasks;

// Each task is worth this many points, shared equally among its cases.
constexpr double kTaskPoints = 10.0;

struct Settings {
    std::filesystem::path library;
    std::filesystem::path gradescope;
    std::filesystem::path cases;
    std::filesystem::path samples;
    double timeout = 10.0;
    std::vector<std::string> tasks;
};

// The library's table; a library that cannot be loaded is bad usage.
const grade::st::StudentTasks& load(const std::filesystem::path& path) {
    try {
        return grade::load_student_library(path);
    } catch (const std::runtime_error& e) {
        throw UsageError(e.what());
    }
}

std::string points(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", std::round(x * 10.0) / 10.0);
    return text;
}

int run(Settings& s) {
    for (const std::string& t : s.tasks) {
        if (std::find(kTasks.begin(), kTasks.end(), t) == kTasks.end()) {
            throw UsageError("--task " + t +
                             ": not a task (evaluate_step, evaluate_patch, "
                             "vertex_normal, flip_edge, split_edge, upsample)");
        }
    }
    // Loaded in a child first: the library's own initialisers are student code too.
    if (const grade::Outcome probe =
            grade::run_isolated([&] { return load(s.library), std::string(); }, s.timeout);
        !probe.pass) {
        throw UsageError(s.library.string() + ": loading it " +
                         (probe.message.rfind("threw an exception: ", 0) == 0
                              ? "failed: " + probe.message.substr(20)
                              : probe.message));
    }
    const grade::st::StudentTasks& tasks = load(s.library);
    std::vector<std::string> notes;
    const std::filesystem::path samples = s.samples.empty() ? grade::find_samples() : s.samples;
    std::vector<Case> cases = grade::standard_cases(samples, notes);
    if (!s.cases.empty()) {
        std::vector<Case> extra = grade::folder_cases(s.cases);
        cases.insert(cases.end(), extra.begin(), extra.end());
    }
    for (const std::string& n : notes) {
        print_notice(n);
    }

    std::map<std::string, std::pair<int, int>> tally;  // task: passed, run
    Json tests = Json::array();
    for (const Case& c : cases) {
        if (!s.tasks.empty() &&
            std::find(s.tasks.begin(), s.tasks.end(), c.task) == s.tasks.end()) {
            continue;
        }
        const grade::Outcome o = grade::run_isolated([&] { return c.run(tasks); }, s.timeout);
        const std::string title = c.task + " on " + c.name;
        std::printf("%s %s%s%s\n", o.pass ? "PASS" : "FAIL", title.c_str(), o.pass ? "" : ": ",
                    o.message.c_str());
        std::fflush(stdout);
        auto& [passed, ran] = tally[c.task];
        passed += o.pass ? 1 : 0;
        ++ran;
        tests.push_back(Json{{"name", title},
                             {"task", c.task},
                             {"score", o.pass ? 1.0 : 0.0},
                             {"max_score", 1.0},
                             {"output", o.pass ? "passed" : o.message},
                             {"visibility", c.hidden ? "after_published" : "visible"}});
    }

    double total = 0.0, most = 0.0;
    bool all = true;
    std::printf("\n");
    for (const char* task : kTasks) {
        const auto it = tally.find(task);
        if (it == tally.end()) {
            continue;
        }
        const auto [passed, ran] = it->second;
        const double score = kTaskPoints * passed / ran;
        total += score;
        most += kTaskPoints;
        all = all && passed == ran;
        std::printf("%-15s %d/%d cases, %s/%s points\n", task, passed, ran, points(score).c_str(),
                    points(kTaskPoints).c_str());
    }
    std::printf("total           %s/%s points (%s%%)\n", points(total).c_str(),
                points(most).c_str(), points(most > 0 ? 100.0 * total / most : 0.0).c_str());

    if (!s.gradescope.empty()) {
        // Each case's share of its task's points.
        for (Json& t : tests) {
            const double share = kTaskPoints / tally[t["task"].get<std::string>()].second;
            t["score"] = t["score"].get<double>() * share;
            t["max_score"] = share;
            t.erase("task");
        }
        const Json out{{"score", total}, {"tests", std::move(tests)}};
        const std::string text = out.dump(2) + "\n";
        write_atomically(s.gradescope, [&](const std::filesystem::path& tmp) {
            std::FILE* f = std::fopen(tmp.c_str(), "wb");
            const bool ok =
                f != nullptr && std::fwrite(text.data(), 1, text.size(), f) == text.size();
            if (f == nullptr || std::fclose(f) != 0 || !ok) {
                throw IoError(s.gradescope.string(), "", "cannot write");
            }
        });
    }
    return all ? 0 : 1;
}

}  // namespace

Command add_grade(CLI::App& meshedit) {
    auto s = std::make_shared<Settings>();
    CLI::App* app = meshedit.add_subcommand(
        "grade", "run a student library's six course tasks against MeshEdit's and score them");
    app->add_option("LIB", s->library,
                    "the student library (libstudent.so, built from student/; docs/student.md)")
        ->required();
    app->add_option("--gradescope", s->gradescope,
                    "also write Gradescope's results.json (score, tests with name, score, "
                    "max_score, output, visibility)")
        ->type_name("OUT.json");
    app->add_option("--cases", s->cases,
                    "a folder of the teacher's cases: meshes and .ops sessions (flip:A-B, "
                    "split:A-B); names with .hidden. or listed as 'hidden FILE' in manifest.txt "
                    "are shown after publishing")
        ->type_name("DIR")
        ->check(CLI::ExistingDirectory);
    app->add_option("--samples", s->samples,
                    "the folder holding dae/ and bez/ (default: found above the current folder "
                    "or meshedit's)")
        ->type_name("DIR")
        ->check(CLI::ExistingDirectory);
    app->add_option("--timeout", s->timeout, "seconds each case may run (default 10)")
        ->type_name("S")
        ->check(CLI::PositiveNumber);
    app->add_option("--task", s->tasks,
                    "grade only this task (repeatable): evaluate_step, evaluate_patch, "
                    "vertex_normal, flip_edge, split_edge, upsample")
        ->type_name("NAME");
    app->footer(
        "Every case runs in its own process: a crash, an exception or an endless loop is\n"
        "reported with its case. Exit status 0 when every case passes, 1 when one fails, 2 for\n"
        "a library that cannot be loaded or bad usage.\n"
        "Example:\n"
        "  meshedit grade build-student/libstudent.so --gradescope results.json");
    return {app, [s] { return run(*s); }};
}

}  // namespace meshedit::cli
