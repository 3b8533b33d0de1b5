#pragma once
/// \file
/// OpStatus, the one refusal type: a local operation's predicate (is_flip_ok()), a whole-mesh
/// plan (plan_loop(), plan_quad_subdivision()), a stencil, a verb's check (ops::Verb::check)
/// and the editor's edits all answer with it, so every caller shows a refusal the same way.

#include <iosfwd>
#include <string>
#include <string_view>

namespace meshedit {

/// Whether an operation is allowed; when not, the reason for a status line, always in the
/// form "cannot <verb>: <why>" ("cannot flip: boundary edge"), so that every caller (the
/// editor, `--ops`, tests) shows it as it is. Two pointers, copied freely: a predicate's
/// reason is a string literal (no allocation on the hot path); a reason composed at run time
/// (composed()) is kept for the rest of the program, one copy per distinct text.
class OpStatus {
public:
    static constexpr OpStatus ok() { return OpStatus(); }
    /// \pre `reason` is a string literal (or lives as long as the program).
    static constexpr OpStatus refused(std::string_view reason) { return OpStatus(reason); }
    /// A reason with numbers in it ("cannot subdivide: level 3 would make 2.1e9 faces").
    /// Empty text is ok().
    static OpStatus composed(const std::string& reason);

    explicit constexpr operator bool() const { return reason_.empty(); }
    constexpr std::string_view reason() const { return reason_; }
    /// The reason as a std::string (empty when ok), for messages that add to it.
    std::string text() const { return std::string(reason_); }

private:
    constexpr OpStatus() = default;
    explicit constexpr OpStatus(std::string_view reason) : reason_(reason) {}
    std::string_view reason_;
};

/// A status equals its reason; an ok one equals "". (Tests: EXPECT_EQ(check(...), "cannot …").)
inline bool operator==(const OpStatus& status, std::string_view reason) {
    return status.reason() == reason;
}
/// Writes the reason, or "ok".
std::ostream& operator<<(std::ostream& out, const OpStatus& status);

}  // namespace meshedit
