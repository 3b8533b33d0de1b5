#pragma once
/// \file
/// The file chooser of Open (Ctrl+O), Save as (Ctrl+Shift+S) and Export session
/// (Ctrl+Shift+E), without a window: the listed folder with its filter, the typed path field
/// and the keys that edit it. The window (src/viewer/panel_chooser.cpp) only draws it and
/// feeds it keys; tests drive it directly.
///
/// Keys arrive in a queue, pushed by the window's GLFW callbacks as they happen and applied
/// all at once each frame: at one frame a second five Backspaces still erase five
/// characters (ImGui 1.86 polls Backspace once per frame and loses repeats).

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "meshedit/viewer/document.h"

namespace meshedit::viewer {

/// What Ctrl+Shift+E writes: an `--ops` session file.
inline constexpr char kSessionExtension[] = ".ops";

enum class ChooserPurpose { Open, SaveAs, ExportSession };

/// The extensions the chooser lists for `purpose` (from the io library's format tables):
/// every document read_document() opens for Open, what a `mode` document is saved as for
/// Save as, the session's for Export session.
std::vector<std::string> chooser_extensions(ChooserPurpose purpose, Mode mode);

/// A key for the field, as the window saw it.
struct FieldKey {
    enum Kind {
        Char,        ///< `ch` typed
        Backspace,   ///< the selection, else the character before the cursor
        Delete,      ///< the selection, else the character after the cursor
        DeleteWord,  ///< Ctrl+Backspace: back to the previous '/'
        Left,
        Right,
        Home,
        End,
        SelectAll,  ///< Ctrl+A
        Up,         ///< the row above in the listing, its name into the field
        Down,
        Tab,     ///< completes the name (paths.h: complete_path())
        Enter,   ///< a folder: lists it; a file: chosen
        Escape,  ///< cancels
    };
    Kind kind = Char;
    char32_t ch = 0;
    bool shift = false;  ///< Left/Right/Home/End extend the selection
};

/// A row of the listing.
struct ChooserEntry {
    std::string name;  ///< ".." for the parent folder
    bool folder = false;
};

class FileChooser {
public:
    enum class Result { None, Chosen, Cancelled };

    /// Lists `folder` and fills the field with `name` (the document's file name for the
    /// saves, empty for Open), all of it selected so that typing replaces it.
    void start(ChooserPurpose purpose, const std::filesystem::path& folder, std::string name,
               std::vector<std::string> extensions);
    ChooserPurpose purpose() const { return purpose_; }

    /// Queues a key (the window's callbacks, in the order they came).
    void push(FieldKey key) { queue_.push_back(key); }
    /// Applies every queued key in order: Chosen (chosen() names the file) at an Enter that
    /// chose a file, Cancelled at an Escape; the keys after either are dropped.
    Result process();

    // The typed path field: UTF-8, positions in bytes at character boundaries.
    const std::string& field() const { return field_; }
    std::size_t cursor() const { return cursor_; }
    /// The selected bytes [begin, end); begin == end when nothing is selected.
    std::size_t selection_begin() const { return std::min(anchor_, cursor_); }
    std::size_t selection_end() const { return std::max(anchor_, cursor_); }

    /// What the field names: a leading `~` is the home folder, a relative path is relative
    /// to the listed folder (paths.h: resolve_prompt_path()).
    std::filesystem::path resolved() const;

    // The listing: ".." first (but at the root), then folders, then the files whose
    // extension is one of the purpose's (every file with show_all()), each group by name.
    // Hidden entries (a leading '.') are listed with show_all() only.
    const std::filesystem::path& folder() const { return folder_; }
    const std::vector<ChooserEntry>& entries() const { return entries_; }
    const std::vector<std::string>& extensions() const { return extensions_; }
    bool show_all() const { return show_all_; }
    void set_show_all(bool all);
    /// The row Up/Down or a click last chose; -1 for none.
    int highlighted() const { return highlighted_; }

    /// A click on row `index`: a folder is listed, a file's name goes into the field.
    void click(std::size_t index);
    /// Lists `folder`; the field gets the start's name back (selected).
    void go_to(const std::filesystem::path& folder);
    /// Enter or the Save/Open button: true with chosen() set when the field names a file
    /// the purpose accepts. A folder is listed instead (and refused as a save target, with
    /// the reason in message()); a missing file to open or a missing folder to save in is
    /// refused with the reason.
    bool accept();
    const std::filesystem::path& chosen() const { return chosen_; }

    /// The last refusal, or Tab's candidates; empty when there is nothing to say.
    const std::string& message() const { return message_; }
    bool message_is_error() const { return error_; }

private:
    void apply(const FieldKey& key);
    void insert(char32_t ch);
    void erase_selection();
    void move_to(std::size_t position, bool extend);
    void step_row(int delta);
    void set_field(std::string text);
    void list();
    void say(std::string text, bool error);

    ChooserPurpose purpose_ = ChooserPurpose::Open;
    std::vector<std::string> extensions_;
    std::filesystem::path folder_;
    std::string start_name_;
    std::vector<ChooserEntry> entries_;
    bool show_all_ = false;
    int highlighted_ = -1;

    std::string field_;
    std::size_t cursor_ = 0;
    std::size_t anchor_ = 0;  ///< the selection's other end
    std::vector<FieldKey> queue_;

    std::filesystem::path chosen_;
    std::string message_;
    bool error_ = false;
};

}  // namespace meshedit::viewer
