#pragma once
/// \file
/// The viewer's paths, without a window: the file chooser's (the folder it starts in, what a
/// typed text names, Tab completion; file_chooser.h) and where screenshots go. Tests call
/// them directly.

#include <filesystem>
#include <string>
#include <vector>

namespace meshedit::viewer {

/// The text a prompt starts with: for open, the document's folder (the current folder when
/// nothing is open) as an absolute path ending in a separator, so that a typed name lands in
/// it; for save as, the document's own absolute path (or that folder and "untitled.dae").
std::string prompt_start(const std::filesystem::path& document, bool save_as);

/// What a prompt's text names: a leading `~` is the home folder, a relative path is taken
/// relative to `folder` (the folder the prompt started in), and `.` and `..` are resolved
/// ("a/../b/./c" → "b/c"). An absolute path typed after the prompt's folder without clearing
/// it ("/data//tmp/x.obj", "/data/~/x.obj") replaces the folder.
std::filesystem::path resolve_prompt_path(const std::string& text,
                                          const std::filesystem::path& folder);

/// Tab in a prompt: `text` extended by the longest prefix shared by the names in its folder
/// that start with what follows the last separator (a single folder gets its separator, so
/// Tab can go on into it), and those names, sorted, for the prompt to show when there are
/// several. Hidden entries (starting with '.') only match a prefix that starts with '.'.
struct Completion {
    std::string text;
    std::vector<std::string> candidates;
};
Completion complete_path(const std::string& text, const std::filesystem::path& folder);

/// Where P saves screenshots: a MeshEdit folder in the user's pictures folder —
/// $XDG_PICTURES_DIR, else its line in ${XDG_CONFIG_HOME:-~/.config}/user-dirs.dirs (as
/// xdg-user-dirs writes it on desktops), else ~/Pictures. The system's temporary folder
/// when there is no home folder.
std::filesystem::path pictures_folder();

/// The first free "meshedit-STEM-N.png" in `folder` (N from 1; "meshedit-N.png" for an
/// unnamed document), STEM being the document's name without its extension.
std::filesystem::path screenshot_path(const std::filesystem::path& folder,
                                      const std::filesystem::path& document);

/// The viewer's own settings folder: ${XDG_CONFIG_HOME:-~/.config}/meshedit; empty when
/// there is no home folder.
std::filesystem::path settings_folder();

/// The up axis the user chose (Y) for the file whose content hash is `hash`, remembered in
/// the settings folder's up_axis.txt ("HASH z" lines): 'y' or 'z', or 0 when none is.
char remembered_up(const std::string& hash);
/// Remembers `axis` ('y' or 'z') for `hash` (written atomically; a failure to write only
/// loses the memory). 'y', the default, is stored as no line.
void remember_up(const std::string& hash, char axis);

}  // namespace meshedit::viewer
