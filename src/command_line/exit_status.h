#pragma once
/// \file
/// The one exception → exit-status ladder of `meshedit` and `meshedit-render` (docs/cli.md):
/// 0 success, 1 a refusal or failure, 2 bad usage or bad input, each error as one line
/// "PROGRAM: MESSAGE" on stderr.

#include <cstdio>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>

#include "meshedit/core/budget.h"
#include "meshedit/files/io_error.h"
#include "meshedit/ops/ops.h"

namespace meshedit::command_line {

/// Bad usage the parser cannot see: an option that does not fit the file (exit 2).
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The command ran but could not do its job for a reason that is not bad input (exit 1).
class Failure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Prints "PROGRAM: MESSAGE" on stderr.
inline void print_error(std::string_view program, const std::string& message) {
    std::fprintf(stderr, "%.*s: %s\n", static_cast<int>(program.size()), program.data(),
                 message.c_str());
}

/// In a `catch (...)` block: reports the exception being handled and returns its exit status.
/// 2 for bad usage or input (UsageError, IoError, ops::SyntaxError, an ops::OpError naming an
/// element the mesh does not have); 1 for a refusal or failure (a refused OpError,
/// BudgetError, Failure, no memory, and anything else, reported as an internal error).
inline int exit_status_of_current_exception(std::string_view program) {
    try {
        throw;
    } catch (const UsageError& e) {
        print_error(program, e.what());
        return 2;
    } catch (const IoError& e) {
        print_error(program, e.what());
        return 2;
    } catch (const ops::SyntaxError& e) {
        print_error(program, e.what());
        return 2;
    } catch (const ops::OpError& e) {
        print_error(program, e.what());
        return e.refused() ? 1 : 2;
    } catch (const BudgetError& e) {
        print_error(program, e.what());
        return 1;
    } catch (const Failure& e) {
        print_error(program, e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        print_error(program, "out of memory");
        return 1;
    } catch (const std::exception& e) {
        print_error(program, std::string("internal error: ") + e.what());
        return 1;
    } catch (...) {
        print_error(program, "internal error");
        return 1;
    }
}

}  // namespace meshedit::command_line
