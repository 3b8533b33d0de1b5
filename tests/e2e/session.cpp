#include "session.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <unordered_set>

namespace meshedit::test::e2e {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string trim(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) {
        text.pop_back();
    }
    return text;
}

std::vector<char*> argv_of(const std::string& program, const std::vector<std::string>& args) {
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const std::string& a : args) {
        argv.push_back(const_cast<char*>(a.c_str()));
    }
    argv.push_back(nullptr);
    return argv;
}

// In a freshly forked child: die with the test program, even if it is killed (a ctest
// timeout), so no viewer or X server outlives it.
void die_with_parent(pid_t parent) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) {
        ::_exit(126);
    }
}

// Redirects stdin from /dev/null and stdout/stderr to the given files (child side).
void redirect(const char* out, const char* err) {
    const int null_fd = ::open("/dev/null", O_RDONLY);
    ::dup2(null_fd, STDIN_FILENO);
    const int out_fd = ::open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err_fd = ::open(err, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (null_fd < 0 || out_fd < 0 || err_fd < 0) {
        ::_exit(125);
    }
    ::dup2(out_fd, STDOUT_FILENO);
    ::dup2(err_fd, STDERR_FILENO);
}

// Kills `pid` with `sig`, then waits up to `grace` for it to exit; SIGKILL after that.
void stop(pid_t pid, int sig, Seconds grace) {
    ::kill(pid, sig);
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(grace);
    int status = 0;
    while (Clock::now() < deadline) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid || (done < 0 && errno == ECHILD)) {
            return;
        }
        ::usleep(10000);
    }
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
}

std::atomic<int> g_process_counter{0};

}  // namespace

std::string find_program(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
        if (::access(candidate.c_str(), X_OK) == 0) {
            return candidate.string();
        }
    }
    return {};
}

bool wait_until(const std::function<bool()>& done, Seconds timeout, Seconds poll) {
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(timeout);
    while (true) {
        if (done()) {
            return true;
        }
        if (Clock::now() >= deadline) {
            return done();
        }
        sleep_for(poll);
    }
}

void sleep_for(Seconds duration) {
    std::this_thread::sleep_for(duration);
}

// ----------------------------------------------------------------------------------- Xvfb

Xvfb::Xvfb(const std::string& xvfb_program) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) {
        throw std::runtime_error("pipe failed");
    }
    log_ = fs::temp_directory_path() / ("meshedit-e2e-xvfb-" + std::to_string(::getpid()) + ".log");
    const std::string fd_text = std::to_string(fds[1]);
    // -noreset: an X server resets when its last client leaves and refuses connections
    // meanwhile; between two viewers there is often no client at all.
    const std::vector<std::string> args = {"-displayfd",   fd_text,     "-screen", "0",
                                           "1280x1024x24", "-nolisten", "tcp",     "-noreset"};
    std::vector<char*> argv = argv_of(xvfb_program, args);
    const std::string log = log_.string();
    const pid_t parent = ::getpid();

    pid_ = ::fork();
    if (pid_ < 0) {
        throw std::runtime_error("fork failed");
    }
    if (pid_ == 0) {
        die_with_parent(parent);
        ::fcntl(fds[1], F_SETFD, 0);  // the one descriptor Xvfb must inherit
        redirect(log.c_str(), log.c_str());
        ::execv(xvfb_program.c_str(), argv.data());
        ::_exit(127);
    }
    ::close(fds[1]);

    // Xvfb writes the display number and a newline once it accepts connections.
    std::string number;
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    bool eof = false;
    while (number.find('\n') == std::string::npos && !eof && Clock::now() < deadline) {
        pollfd p{fds[0], POLLIN, 0};
        if (::poll(&p, 1, 200) <= 0) {
            continue;
        }
        char buffer[64];
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n > 0) {
            number.append(buffer, static_cast<std::size_t>(n));
        } else if (n == 0 || errno != EINTR) {
            eof = true;
        }
    }
    ::close(fds[0]);
    number = trim(number);
    if (number.empty() || number.find_first_not_of("0123456789") != std::string::npos) {
        stop(pid_, SIGKILL, std::chrono::seconds(1));
        pid_ = -1;
        const std::string text = read_file(log_);
        std::error_code ec;
        fs::remove(log_, ec);
        throw std::runtime_error("Xvfb did not report a display number (" +
                                 std::string(eof ? "it exited" : "timeout") + "); its log:\n" +
                                 text);
    }
    display_ = ":" + number;
}

Xvfb::~Xvfb() {
    if (pid_ > 0) {
        stop(pid_, SIGTERM, std::chrono::seconds(3));
    }
    std::error_code ec;
    fs::remove(log_, ec);
}

// ------------------------------------------------------------------------ BackgroundProcess

BackgroundProcess::BackgroundProcess(const std::string& program,
                                     const std::vector<std::string>& args, const fs::path& cwd,
                                     const fs::path& log_dir) {
    const int n = ++g_process_counter;
    out_path_ = log_dir / ("process-" + std::to_string(n) + ".out");
    err_path_ = log_dir / ("process-" + std::to_string(n) + ".err");
    command_ = program;
    for (const std::string& a : args) {
        command_ += " " + a;
    }
    std::vector<char*> argv = argv_of(program, args);
    const std::string out = out_path_.string();
    const std::string err = err_path_.string();
    const std::string dir = cwd.string();
    const pid_t parent = ::getpid();

    pid_ = ::fork();
    if (pid_ < 0) {
        throw std::runtime_error("fork failed");
    }
    if (pid_ == 0) {
        die_with_parent(parent);
        redirect(out.c_str(), err.c_str());
        if (::chdir(dir.c_str()) != 0) {
            ::_exit(124);
        }
        ::execv(program.c_str(), argv.data());
        ::_exit(127);
    }
}

BackgroundProcess::~BackgroundProcess() {
    kill();
}

void BackgroundProcess::reap(int status) {
    exited_ = true;
    if (WIFEXITED(status)) {
        exit_code_ = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        signal_ = WTERMSIG(status);
    }
}

bool BackgroundProcess::running() {
    if (exited_ || pid_ <= 0) {
        return false;
    }
    int status = 0;
    const pid_t done = ::waitpid(pid_, &status, WNOHANG);
    if (done == pid_) {
        reap(status);
        return false;
    }
    return true;
}

std::optional<int> BackgroundProcess::wait_exit(Seconds timeout) {
    if (!wait_until([&] { return !running(); }, timeout, std::chrono::milliseconds(20))) {
        return std::nullopt;
    }
    return exit_code_;
}

void BackgroundProcess::kill() {
    if (running()) {
        int status = 0;
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, &status, 0);
        reap(status);
    }
}

std::string BackgroundProcess::out() const {
    return read_file(out_path_);
}

std::string BackgroundProcess::err() const {
    return read_file(err_path_);
}

// --------------------------------------------------------------------------------- xdotool

namespace {

const std::string& xdotool_program() {
    static const std::string path = find_program("xdotool");
    return path;
}

}  // namespace

RunResult xdotool(const std::vector<std::string>& args) {
    RunResult r = run_program(xdotool_program(), args, 20.0);
    std::string line = "xdotool";
    for (const std::string& a : args) {
        line += " " + a;
    }
    EXPECT_TRUE(r.exit_code == 0 && !r.timed_out)
        << line << " failed (exit " << r.exit_code << (r.timed_out ? ", timed out" : "")
        << "): " << r.err;
    return r;
}

ViewerWindow::ViewerWindow(BackgroundProcess& viewer, Seconds timeout) : viewer_(&viewer) {
    std::string found;
    const bool shown = wait_until(
        [&] {
            if (!viewer.running()) {
                return true;
            }
            const RunResult r = run_program(
                xdotool_program(),
                {"search", "--onlyvisible", "--pid", std::to_string(viewer.pid())}, 10.0);
            if (r.exit_code == 0) {
                const std::vector<std::string> ids = split_lines(r.out);
                if (!ids.empty() && !ids.front().empty()) {
                    found = ids.front();
                    return true;
                }
            }
            return false;
        },
        timeout, std::chrono::milliseconds(50));
    if (!viewer.running()) {
        ADD_FAILURE() << "the viewer exited before showing a window: " << viewer.command()
                      << "\nstderr:\n"
                      << viewer.err();
        return;
    }
    if (!shown || found.empty()) {
        ADD_FAILURE() << "no window of the viewer (pid " << viewer.pid() << ") within "
                      << timeout.count() << " s: " << viewer.command() << "\nstderr:\n"
                      << viewer.err();
        return;
    }
    // No window manager: give the window the keyboard focus ourselves (GLFW usually took it).
    xdotool({"windowfocus", found});
    const bool focused = wait_until(
        [&] { return trim(run_program(xdotool_program(), {"getwindowfocus"}, 10.0).out) == found; },
        std::chrono::seconds(5));
    EXPECT_TRUE(focused) << "window " << found << " did not get the keyboard focus";
    id_ = found;
}

std::string ViewerWindow::title() const {
    return trim(run_program(xdotool_program(), {"getwindowname", id_}, 10.0).out);
}

bool ViewerWindow::wait_title(const std::string& text, bool absent, Seconds timeout,
                              std::string* last) const {
    std::string seen;
    const bool ok = wait_until(
        [&] {
            seen = title();
            return (seen.find(text) != std::string::npos) != absent;
        },
        timeout);
    if (last != nullptr) {
        *last = seen;
    }
    return ok;
}

void ViewerWindow::keys(const std::vector<std::string>& keys, int delay_ms) const {
    std::vector<std::string> args = {"key", "--delay", std::to_string(delay_ms)};
    args.insert(args.end(), keys.begin(), keys.end());
    xdotool(args);
}

void ViewerWindow::type(const std::string& text) const {
    xdotool({"type", "--delay", "30", text});
}

void ViewerWindow::move_to(int x, int y) const {
    // Windows sit at (0, 0) without a window manager: window pixels are screen pixels.
    xdotool({"mousemove", std::to_string(x + 9), std::to_string(y + 7)});
    sleep_for(std::chrono::milliseconds(60));
    xdotool({"mousemove", std::to_string(x), std::to_string(y)});
    // Let the viewer draw a frame with the pointer here, so ImGui knows it is not over a
    // panel before the button goes down.
    sleep_for(std::chrono::milliseconds(250));
}

void ViewerWindow::click(int x, int y) const {
    move_to(x, y);
    xdotool({"click", "1"});
}

void ViewerWindow::shift_click(int x, int y) const {
    move_to(x, y);
    xdotool({"keydown", "shift", "click", "1", "keyup", "shift"});
}

void ViewerWindow::modified_click(int x, int y, const std::string& modifier) const {
    move_to(x, y);
    xdotool({"keydown", modifier, "click", "1", "keyup", modifier});
}

void ViewerWindow::drag(int x0, int y0, int x1, int y1, int button,
                        const std::string& modifier) const {
    move_to(x0, y0);
    if (!modifier.empty()) {
        xdotool({"keydown", modifier});
    }
    xdotool({"mousedown", std::to_string(button)});
    sleep_for(std::chrono::milliseconds(100));
    // Through the corners of the rectangle, so a lasso drawn this way encloses it.
    for (const auto& [x, y] : {std::pair{x1, y0}, std::pair{x1, y1}, std::pair{x0, y1}}) {
        xdotool({"mousemove", std::to_string(x), std::to_string(y)});
        sleep_for(std::chrono::milliseconds(150));
    }
    if (button != 3) {  // a box ends at the far corner
        xdotool({"mousemove", std::to_string(x1), std::to_string(y1)});
        sleep_for(std::chrono::milliseconds(150));
    }
    xdotool({"mouseup", std::to_string(button)});
    if (!modifier.empty()) {
        xdotool({"keyup", modifier});
    }
    sleep_for(std::chrono::milliseconds(250));
}

bool ViewerWindow::capture(const fs::path& png) const {
    static const std::string import = find_program("import");
    const RunResult r = run_program(import, {"-window", id_, "png:" + png.string()}, 30.0);
    EXPECT_EQ(r.exit_code, 0) << "import -window " << id_ << " failed: " << r.err;
    return r.exit_code == 0 && fs::exists(png);
}

// ---------------------------------------------------------------------------------- images

RgbImage read_rgb(const fs::path& png) {
    RgbImage image;
    auto in = OIIO::ImageInput::open(png.string());
    if (!in) {
        return image;
    }
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data())) {
        return image;
    }
    image.width = spec.width;
    image.height = spec.height;
    image.rgb.resize(static_cast<std::size_t>(spec.width) * spec.height * 3);
    for (std::size_t i = 0; i < static_cast<std::size_t>(spec.width) * spec.height; ++i) {
        for (int c = 0; c < 3; ++c) {
            image.rgb[3 * i + c] = pixels[i * channels + std::min(c, channels - 1)];
        }
    }
    return image;
}

std::size_t distinct_colours(const RgbImage& image) {
    std::unordered_set<std::uint32_t> colours;
    for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
        colours.insert(static_cast<std::uint32_t>(image.rgb[i]) << 16 |
                       static_cast<std::uint32_t>(image.rgb[i + 1]) << 8 | image.rgb[i + 2]);
    }
    return colours.size();
}

int channel_difference(const RgbImage& a, int ax, int ay, const RgbImage& b, int bx, int by) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
        worst = std::max(
            worst, std::abs(static_cast<int>(a.at(ax, ay)[c]) - static_cast<int>(b.at(bx, by)[c])));
    }
    return worst;
}

double mean_brightness(const RgbImage& image, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    long count = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const std::uint8_t* p = image.at(x, y);
            sum += (p[0] + p[1] + p[2]) / 3.0;
            ++count;
        }
    }
    return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

}  // namespace meshedit::test::e2e
