#pragma once
/// \file
/// The exception every reader and writer throws for bad input or a failed write.

#include <stdexcept>
#include <string>
#include <utility>

namespace meshedit {

/// A file could not be read or written. The message always names the file, the place in
/// it when known (a line, or an XML element path such as `<geometry id="box">/<mesh>/<p>`),
/// and the problem: `cube.dae: line 12, <p>: index 40 out of range (8 positions)`.
class IoError : public std::runtime_error {
public:
    IoError(std::string file, std::string where, std::string problem)
        : std::runtime_error(compose(file, where, problem)),
          file_(std::move(file)),
          where_(std::move(where)),
          problem_(std::move(problem)) {}

    const std::string& file() const { return file_; }
    /// "line 12, <p>", "patch 3", or empty.
    const std::string& where() const { return where_; }
    const std::string& problem() const { return problem_; }

private:
    static std::string compose(const std::string& file, const std::string& where,
                               const std::string& problem) {
        return file + ": " + (where.empty() ? "" : where + ": ") + problem;
    }
    std::string file_;
    std::string where_;
    std::string problem_;
};

}  // namespace meshedit
