#pragma once
/// \file
/// The memory budget: how much memory one operation may plan to use. Every step that
/// multiplies a size by a factor the input chooses (Loop levels, patch tessellation density,
/// COLLADA instancing, de Casteljau levels of a long curve) estimates its peak in bytes first
/// and refuses with over_budget()'s sentence instead of letting the machine swap or the
/// out-of-memory killer end the process later.
///
/// The budget is half of the machine's physical memory (others may be using the rest), or
/// what the environment variable MESHEDIT_MEMORY_BUDGET says ("8G", "512M", "2000000000"),
/// or what set_memory_budget() was given (the `--memory-budget` option of the programs).

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

namespace meshedit {

/// Physical memory of this machine in bytes (0 if unknown).
std::size_t physical_memory();

/// The budget in bytes (see the file comment); at least 64 MiB.
std::size_t memory_budget();
/// Sets the budget for this process (at least 64 MiB); 0 goes back to the default.
void set_memory_budget(std::size_t bytes);
/// Sets the budget below the 64 MiB floor too: for tests that drive an operation past a small
/// budget without building a big mesh. 0 goes back to the default.
void set_memory_budget_without_floor(std::size_t bytes);
/// "8G", "512M", "64K", "1.5G" or plain bytes → bytes; nullopt if not such a size.
std::optional<std::size_t> parse_byte_size(const std::string& text);

/// "7.9 GB".
std::string format_bytes(double bytes);

/// A step refused because it would not fit the memory budget; what() is the whole sentence
/// ("tessellating 1000 patches at density 128 would need about 7.9 GB of memory, over …").
class BudgetError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// \throws BudgetError with "<what> <over_budget() sentence>" when `bytes` does not fit.
void check_budget(double bytes, const std::string& what);

/// nullopt if `bytes` fits in the budget; else a sentence for the refusal: "would need about
/// 7.9 GB of memory, over the budget of 4.0 GB (--memory-budget or MESHEDIT_MEMORY_BUDGET
/// sets it)".
std::optional<std::string> over_budget(double bytes);

}  // namespace meshedit
