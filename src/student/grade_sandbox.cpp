// fork, a pipe for the verdict, poll with a deadline, SIGKILL past it, waitpid for how the
// child ended.

#include "grade_sandbox.h"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <stdexcept>
#include <typeinfo>

namespace meshedit::cli::grade {
namespace {

std::string signal_name(int sig) {
    switch (sig) {
        case SIGSEGV:
            return "SIGSEGV";
        case SIGABRT:
            return "SIGABRT";
        case SIGFPE:
            return "SIGFPE";
        case SIGBUS:
            return "SIGBUS";
        case SIGILL:
            return "SIGILL";
        case SIGKILL:
            return "SIGKILL";
        case SIGTERM:
            return "SIGTERM";
        default:
            return "signal " + std::to_string(sig);
    }
}

void write_all(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n <= 0) {
            if (n < 0 && errno == EINTR) {
                continue;
            }
            return;
        }
        done += std::size_t(n);
    }
}

[[noreturn]] void child(int fd, const std::function<std::string()>& check) {
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
#if !defined(__SANITIZE_ADDRESS__)
    // A runaway allocation fails as std::bad_alloc instead of taking the machine.
    const rlimit limit{rlim_t(4) << 30, rlim_t(4) << 30};
    ::setrlimit(RLIMIT_AS, &limit);
#endif
    std::string verdict;
    try {
        const std::string why = check();
        verdict = why.empty() ? "P" : "F" + why;
    } catch (const std::bad_alloc&) {
        verdict = "Fran out of memory (std::bad_alloc)";
    } catch (const std::exception& e) {
        verdict = std::string("Fthrew an exception: ") + e.what();
    } catch (...) {
        verdict = "Fthrew something that is not a std::exception";
    }
    std::fflush(nullptr);
    write_all(fd, verdict);
    ::_exit(0);
}

}  // namespace

Outcome run_isolated(const std::function<std::string()>& check, double seconds) {
    int fds[2];
    if (::pipe(fds) != 0) {
        throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
    }
    std::fflush(nullptr);  // or the child would print what is buffered a second time
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw std::runtime_error(std::string("cannot fork: ") + std::strerror(errno));
    }
    if (pid == 0) {
        ::close(fds[0]);
        child(fds[1], check);
    }
    ::close(fds[1]);
    std::string verdict;
    bool timed_out = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                              deadline - std::chrono::steady_clock::now())
                              .count();
        if (left <= 0) {
            timed_out = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int r = ::poll(&p, 1, int(left));
        if (r < 0 && errno == EINTR) {
            continue;
        }
        if (r == 0) {
            timed_out = true;
            break;
        }
        char buffer[4096];
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            break;
        }
        verdict.append(buffer, std::size_t(n));
    }
    ::close(fds[0]);
    if (timed_out) {
        ::kill(pid, SIGKILL);
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (timed_out) {
        return {false,
                "timed out after " + std::to_string(int(seconds + 0.5)) + " s (an endless loop?)"};
    }
    if (WIFSIGNALED(status)) {
        return {false, "crashed (" + signal_name(WTERMSIG(status)) + ")"};
    }
    if (verdict.empty()) {
        return {false,
                "exited with status " + std::to_string(WEXITSTATUS(status)) + " before finishing"};
    }
    return {verdict[0] == 'P', verdict.substr(1)};
}

}  // namespace meshedit::cli::grade
