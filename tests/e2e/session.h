#pragma once
/// \file
/// The machinery of the end-to-end viewer tests: a private Xvfb server, the viewer as a
/// background process, input through xdotool, window captures through ImageMagick's import,
/// and polling with deadlines instead of fixed sleeps.
///
/// Every process started here dies with the test program (PR_SET_PDEATHSIG) and is killed by
/// its RAII owner when a test ends early, so a failing assertion never leaves a viewer or an
/// X server behind.

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cli/run.h"

namespace meshedit::test::e2e {

using Seconds = std::chrono::duration<double>;

/// The absolute path of `name` found on PATH, or empty.
std::string find_program(const std::string& name);

/// Polls `done` every `poll` until it is true or `timeout` has passed; returns its last value.
bool wait_until(const std::function<bool()>& done, Seconds timeout,
                Seconds poll = std::chrono::milliseconds(40));

void sleep_for(Seconds duration);

/// A private X server: `Xvfb -displayfd FD -screen 0 1280x1024x24 -nolisten tcp -noreset`,
/// so the server picks a free display number itself and parallel runs never collide.
class Xvfb {
public:
    /// Starts the server and waits until it accepts connections. \throws std::runtime_error
    /// with the server's own log if it does not come up.
    explicit Xvfb(const std::string& xvfb_program);
    ~Xvfb();
    Xvfb(const Xvfb&) = delete;
    Xvfb& operator=(const Xvfb&) = delete;

    /// ":N".
    const std::string& display() const { return display_; }

private:
    pid_t pid_ = -1;
    std::string display_;
    std::filesystem::path log_;
};

/// A program running in the background with stdout and stderr going to files (read at any
/// time while it runs). The destructor kills it (SIGKILL) if it is still running.
class BackgroundProcess {
public:
    BackgroundProcess(const std::string& program, const std::vector<std::string>& args,
                      const std::filesystem::path& cwd, const std::filesystem::path& log_dir);
    ~BackgroundProcess();
    BackgroundProcess(const BackgroundProcess&) = delete;
    BackgroundProcess& operator=(const BackgroundProcess&) = delete;

    pid_t pid() const { return pid_; }
    /// True while the process has not exited (reaps it when it has).
    bool running();
    /// Waits up to `timeout` for the process to exit: its exit status, -1 after a signal
    /// (see term_signal()), or nothing if it is still running.
    std::optional<int> wait_exit(Seconds timeout);
    int term_signal() const { return signal_; }
    /// Kills it now (SIGKILL) and reaps it; harmless when it has already exited.
    void kill();

    /// Everything it has written so far.
    std::string out() const;
    std::string err() const;
    /// The command line, for messages.
    const std::string& command() const { return command_; }

private:
    void reap(int status);

    pid_t pid_ = -1;
    bool exited_ = false;
    int exit_code_ = -1;
    int signal_ = 0;
    std::filesystem::path out_path_;
    std::filesystem::path err_path_;
    std::string command_;
};

/// Runs xdotool with `args` (20 s limit); fails the current test when it does not exit 0.
RunResult xdotool(const std::vector<std::string>& args);

/// The viewer's top-level window, found through its _NET_WM_PID.
class ViewerWindow {
public:
    /// Waits for `viewer`'s visible window and gives it the keyboard focus (there is no
    /// window manager: the window sits at (0, 0) and keeps the focus we give it).
    /// Fails the test (empty id) if the process exits or no window shows within `timeout`.
    explicit ViewerWindow(BackgroundProcess& viewer, Seconds timeout = std::chrono::seconds(30));

    bool ok() const { return !id_.empty(); }
    const std::string& id() const { return id_; }

    /// The current window title.
    std::string title() const;
    /// Waits until the title contains `text` (or, with `absent`, no longer contains it);
    /// false on timeout. The last title seen goes to `last`.
    bool wait_title(const std::string& text, bool absent = false,
                    Seconds timeout = std::chrono::seconds(20), std::string* last = nullptr) const;

    /// `xdotool key KEYS…` (e.g. "f", "ctrl+s", "Escape"), `delay_ms` apart.
    void keys(const std::vector<std::string>& keys, int delay_ms = 40) const;
    void key(const std::string& key) const { keys({key}); }
    /// Types text into the focused widget.
    void type(const std::string& text) const;
    /// Moves the pointer to window pixel (x, y), first to a nearby point so the window
    /// sees a motion event even if the pointer was already there; settles briefly.
    void move_to(int x, int y) const;
    /// move_to(x, y), then a left click (press and release without moving).
    void click(int x, int y) const;
    /// move_to(x, y), then a left click with Shift held (adds to the selection).
    void shift_click(int x, int y) const;
    /// move_to(x, y), then a left click with `modifier` held ("alt", "ctrl+alt").
    void modified_click(int x, int y, const std::string& modifier) const;
    /// A drag with `button` (1 left, 3 right) from (x0, y0) to (x1, y1) through a midpoint,
    /// `modifier` ("ctrl", or empty) held throughout.
    void drag(int x0, int y0, int x1, int y1, int button, const std::string& modifier = {}) const;
    /// The window as a person sees it (panels included), via `import -window ID`.
    bool capture(const std::filesystem::path& png) const;

private:
    BackgroundProcess* viewer_;
    std::string id_;
};

/// An 8-bit RGB image read with OpenImageIO (alpha dropped).
struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;

    const std::uint8_t* at(int x, int y) const { return rgb.data() + 3 * (y * width + x); }
};

/// Reads a PNG; empty image (width 0) if it cannot be read.
RgbImage read_rgb(const std::filesystem::path& png);

/// Number of distinct RGB colours.
std::size_t distinct_colours(const RgbImage& image);

/// Largest per-channel difference between pixels (ax, ay) of `a` and (bx, by) of `b`.
int channel_difference(const RgbImage& a, int ax, int ay, const RgbImage& b, int bx, int by);

/// Mean of (r + g + b) / 3 over the rectangle [x0, x1) × [y0, y1).
double mean_brightness(const RgbImage& image, int x0, int y0, int x1, int y1);

}  // namespace meshedit::test::e2e
