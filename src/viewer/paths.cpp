// The prompts' paths (paths.h).

#include "meshedit/viewer/paths.h"

#include "meshedit/files/files.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <system_error>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace meshedit::viewer {
namespace {

std::string with_separator(const fs::path& folder) {
    std::string s = folder.lexically_normal().string();
    if (s.empty() || s.back() != '/') {
        s += '/';
    }
    return s;
}

// `~` and `~/…` → the home folder; other text as it is.
std::string expand_home(const std::string& text) {
    if (text.empty() || text[0] != '~' || (text.size() > 1 && text[1] != '/')) {
        return text;
    }
    const char* home = std::getenv("HOME");
    return home != nullptr ? std::string(home) + text.substr(1) : text;
}

}  // namespace

std::string prompt_start(const fs::path& document, bool save_as) {
    std::error_code ec;
    const fs::path current = fs::current_path(ec);
    if (document.empty()) {
        return save_as ? with_separator(current) + "untitled.dae" : with_separator(current);
    }
    const fs::path absolute = fs::absolute(document, ec).lexically_normal();
    return save_as ? absolute.string() : with_separator(absolute.parent_path());
}

fs::path resolve_prompt_path(const std::string& text, const fs::path& folder) {
    // The prompt starts filled with a folder ending in '/'. A path typed after it without
    // clearing it (Ctrl+A lost at a low frame rate, or simply not pressed) reads
    // "<folder>//abs/path" or "<folder>/~/path": the typed absolute path is what was meant,
    // as in a shell, where "//" never separates two real folder names.
    std::string typed = text;
    if (const std::size_t doubled = typed.rfind("//"); doubled != std::string::npos) {
        typed.erase(0, doubled + 1);
    }
    if (const std::size_t home = typed.rfind("/~/"); home != std::string::npos) {
        typed.erase(0, home + 1);
    }
    const fs::path path = expand_home(typed);
    return (path.is_absolute() ? path : folder / path).lexically_normal();
}

Completion complete_path(const std::string& text, const fs::path& folder) {
    Completion out{text, {}};
    const std::string expanded = expand_home(text);
    const std::size_t slash = expanded.rfind('/');
    const std::string dir_text = slash == std::string::npos ? "" : expanded.substr(0, slash + 1);
    const std::string prefix = slash == std::string::npos ? expanded : expanded.substr(slash + 1);
    const fs::path dir = resolve_prompt_path(dir_text.empty() ? "." : dir_text, folder);
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        std::string name = it->path().filename().string();
        if (name.compare(0, prefix.size(), prefix) != 0 ||
            (name[0] == '.' && (prefix.empty() || prefix[0] != '.'))) {
            continue;
        }
        std::error_code is_dir_ec;
        if (it->is_directory(is_dir_ec)) {
            name += '/';
        }
        out.candidates.push_back(std::move(name));
    }
    std::sort(out.candidates.begin(), out.candidates.end());
    if (out.candidates.empty()) {
        return out;
    }
    std::string shared = out.candidates.front();
    for (const std::string& c : out.candidates) {
        std::size_t n = 0;
        while (n < shared.size() && n < c.size() && shared[n] == c[n]) {
            ++n;
        }
        shared.resize(n);
    }
    // Keep what the user typed (a `~` stays a `~`) and append the shared rest.
    out.text = text + shared.substr(prefix.size());
    return out;
}

namespace {

// XDG_PICTURES_DIR's value in a user-dirs.dirs file ("$HOME/Pictures", quoted, $HOME
// expanded), or empty.
fs::path pictures_in_user_dirs(const fs::path& file, const std::string& home) {
    std::ifstream in(file);
    std::string line;
    const std::string key = "XDG_PICTURES_DIR=";
    while (std::getline(in, line)) {
        if (line.rfind(key, 0) != 0) {
            continue;
        }
        std::string value = line.substr(key.size());
        if (value.size() >= 2 && value.front() == '"' && value.back() == '"') {
            value = value.substr(1, value.size() - 2);
        }
        if (value.rfind("$HOME", 0) == 0) {
            value = home + value.substr(5);
        }
        return value.empty() || value[0] != '/' ? fs::path() : fs::path(value);
    }
    return {};
}

}  // namespace

fs::path pictures_folder() {
    const char* home_env = std::getenv("HOME");
    const std::string home = home_env != nullptr ? home_env : "";
    fs::path pictures;
    if (const char* env = std::getenv("XDG_PICTURES_DIR"); env != nullptr && env[0] == '/') {
        pictures = env;
    } else if (!home.empty()) {
        const char* config = std::getenv("XDG_CONFIG_HOME");
        const fs::path config_dir =
            config != nullptr && config[0] == '/' ? fs::path(config) : fs::path(home) / ".config";
        pictures = pictures_in_user_dirs(config_dir / "user-dirs.dirs", home);
        if (pictures.empty()) {
            pictures = fs::path(home) / "Pictures";
        }
    } else {
        std::error_code ec;
        pictures = fs::temp_directory_path(ec);
    }
    return (pictures / "MeshEdit").lexically_normal();
}

fs::path screenshot_path(const fs::path& folder, const fs::path& document) {
    const std::string stem =
        document.empty() ? "meshedit-" : "meshedit-" + document.stem().string() + "-";
    for (int n = 1;; ++n) {
        fs::path path = folder / (stem + std::to_string(n) + ".png");
        std::error_code ec;
        if (!fs::exists(path, ec)) {
            return path;
        }
    }
}

fs::path settings_folder() {
    if (const char* config = std::getenv("XDG_CONFIG_HOME");
        config != nullptr && config[0] == '/') {
        return fs::path(config) / "meshedit";
    }
    const char* home = std::getenv("HOME");
    return home != nullptr && home[0] == '/' ? fs::path(home) / ".config" / "meshedit" : fs::path();
}

namespace {

// up_axis.txt's lines ("HASH z"), or none when the file is missing or unreadable.
std::vector<std::pair<std::string, char>> up_choices(const fs::path& file) {
    std::vector<std::pair<std::string, char>> out;
    std::ifstream in(file);
    std::string hash, axis;
    while (in >> hash >> axis) {
        if (axis == "z" || axis == "y") {
            out.emplace_back(hash, axis[0]);
        }
    }
    return out;
}

}  // namespace

char remembered_up(const std::string& hash) {
    const fs::path folder = settings_folder();
    if (hash.empty() || folder.empty()) {
        return 0;
    }
    for (const auto& [h, axis] : up_choices(folder / "up_axis.txt")) {
        if (h == hash) {
            return axis;
        }
    }
    return 0;
}

void remember_up(const std::string& hash, char axis) {
    const fs::path folder = settings_folder();
    if (hash.empty() || folder.empty()) {
        return;
    }
    const fs::path file = folder / "up_axis.txt";
    std::string text;
    for (const auto& [h, a] : up_choices(file)) {
        if (h != hash) {
            text += h + " " + a + "\n";
        }
    }
    if (axis == 'z') {
        text += hash + " z\n";
    }
    try {
        std::error_code ec;
        fs::create_directories(folder, ec);
        write_atomically(file, [&](const fs::path& tmp) { write_file(tmp, text); });
    } catch (const IoError&) {
        // Only the memory is lost: the file opens as declared next time.
    }
}

}  // namespace meshedit::viewer
