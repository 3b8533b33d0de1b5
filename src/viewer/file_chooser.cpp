// The file chooser without a window (file_chooser.h).

#include "meshedit/viewer/file_chooser.h"

#include <cctype>
#include <cstdint>
#include <system_error>
#include <utility>

#include "meshedit/files/files.h"
#include "meshedit/io/document.h"
#include "meshedit/viewer/paths.h"

namespace fs = std::filesystem;

namespace meshedit::viewer {
namespace {

bool is_continuation(char c) {
    return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

std::string lower(std::string text) {
    for (char& c : text) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return text;
}

bool is_save(ChooserPurpose purpose) {
    return purpose != ChooserPurpose::Open;
}

}  // namespace

std::vector<std::string> chooser_extensions(ChooserPurpose purpose, Mode mode) {
    switch (purpose) {
        case ChooserPurpose::Open:
            return document_extension_list();
        case ChooserPurpose::SaveAs:
            return writable_extensions(mode);
        case ChooserPurpose::ExportSession:
            return {kSessionExtension};
    }
    return {};
}

void FileChooser::start(ChooserPurpose purpose, const fs::path& folder, std::string name,
                        std::vector<std::string> extensions) {
    purpose_ = purpose;
    extensions_ = std::move(extensions);
    start_name_ = std::move(name);
    show_all_ = false;
    queue_.clear();
    chosen_.clear();
    go_to(folder);
}

FileChooser::Result FileChooser::process() {
    std::vector<FieldKey> keys;
    keys.swap(queue_);
    for (const FieldKey& key : keys) {
        if (key.kind == FieldKey::Escape) {
            return Result::Cancelled;
        }
        if (key.kind == FieldKey::Enter) {
            if (accept()) {
                return Result::Chosen;
            }
            continue;
        }
        apply(key);
    }
    return Result::None;
}

void FileChooser::apply(const FieldKey& key) {
    auto before = [&](std::size_t at) {
        while (at > 0 && is_continuation(field_[--at])) {
        }
        return at;
    };
    auto after = [&](std::size_t at) {
        while (at < field_.size() && is_continuation(field_[++at])) {
        }
        return std::min(at, field_.size());
    };
    const bool selected = anchor_ != cursor_;
    say("", false);  // a refusal is about the text as it was
    switch (key.kind) {
        case FieldKey::Char:
            insert(key.ch);
            break;
        case FieldKey::Backspace:
        case FieldKey::Delete:
            if (!selected) {
                anchor_ = key.kind == FieldKey::Backspace ? before(cursor_) : after(cursor_);
            }
            erase_selection();
            break;
        case FieldKey::DeleteWord:
            if (!selected) {
                // Back over trailing separators, then to just after the previous one.
                std::size_t at = cursor_;
                while (at > 0 && field_[at - 1] == '/') {
                    --at;
                }
                while (at > 0 && field_[at - 1] != '/') {
                    --at;
                }
                anchor_ = at;
            }
            erase_selection();
            break;
        case FieldKey::Left:
            move_to(selected && !key.shift ? selection_begin() : before(cursor_), key.shift);
            break;
        case FieldKey::Right:
            move_to(selected && !key.shift ? selection_end() : after(cursor_), key.shift);
            break;
        case FieldKey::Home:
            move_to(0, key.shift);
            break;
        case FieldKey::End:
            move_to(field_.size(), key.shift);
            break;
        case FieldKey::SelectAll:
            anchor_ = 0;
            cursor_ = field_.size();
            break;
        case FieldKey::Up:
        case FieldKey::Down:
            step_row(key.kind == FieldKey::Up ? -1 : 1);
            break;
        case FieldKey::Tab: {
            const Completion c = complete_path(field_, folder_);
            field_ = c.text;
            cursor_ = anchor_ = field_.size();
            std::string shown;
            for (std::size_t i = 0; i < c.candidates.size() && i < 12; ++i) {
                shown += (i ? "   " : "") + c.candidates[i];
            }
            if (c.candidates.size() > 12) {
                shown += "   … (" + std::to_string(c.candidates.size()) + ")";
            }
            say(c.candidates.size() > 1 ? shown : "", false);
            break;
        }
        case FieldKey::Enter:
        case FieldKey::Escape:
            break;  // process() handles them
    }
}

void FileChooser::insert(char32_t ch) {
    if (ch < 0x20 || ch == 0x7F) {
        return;
    }
    erase_selection();
    // A path typed over what is there starts afresh, as in Emacs' minibuffer: '/' right
    // after a '/' begins an absolute path, '~' right after a '/' the home folder — never
    // "<folder>//<path>".
    if ((ch == '/' || ch == '~') && cursor_ > 0 && field_[cursor_ - 1] == '/') {
        field_.erase(0, cursor_);
        cursor_ = 0;
    }
    std::string bytes;
    append_utf8(bytes, static_cast<std::uint32_t>(ch));
    field_.insert(cursor_, bytes);
    cursor_ += bytes.size();
    anchor_ = cursor_;
}

void FileChooser::erase_selection() {
    const std::size_t begin = selection_begin();
    field_.erase(begin, selection_end() - begin);
    cursor_ = anchor_ = begin;
}

void FileChooser::move_to(std::size_t position, bool extend) {
    cursor_ = position;
    if (!extend) {
        anchor_ = cursor_;
    }
}

void FileChooser::set_field(std::string text) {
    field_ = std::move(text);
    anchor_ = 0;
    cursor_ = field_.size();
}

void FileChooser::step_row(int delta) {
    if (entries_.empty()) {
        return;
    }
    const int last = static_cast<int>(entries_.size()) - 1;
    highlighted_ =
        highlighted_ < 0 ? (delta > 0 ? 0 : last) : std::clamp(highlighted_ + delta, 0, last);
    const ChooserEntry& entry = entries_[static_cast<std::size_t>(highlighted_)];
    set_field(entry.folder ? entry.name + "/" : entry.name);
}

fs::path FileChooser::resolved() const {
    return resolve_prompt_path(field_, folder_);
}

void FileChooser::set_show_all(bool all) {
    show_all_ = all;
    list();
}

void FileChooser::click(std::size_t index) {
    if (index >= entries_.size()) {
        return;
    }
    const ChooserEntry entry = entries_[index];
    if (entry.folder) {
        go_to((folder_ / entry.name).lexically_normal());
        return;
    }
    highlighted_ = static_cast<int>(index);
    set_field(entry.name);
    say("", false);
}

void FileChooser::go_to(const fs::path& folder) {
    folder_ = folder.lexically_normal();
    std::string text = folder_.string();
    if (text.size() > 1 && text.back() == '/') {
        folder_ = text.substr(0, text.size() - 1);  // "/a/b/" is listed as "/a/b"
    }
    set_field(start_name_);
    say("", false);
    list();
}

bool FileChooser::accept() {
    if (field_.empty()) {
        say(is_save(purpose_) ? "type a name for the file" : "type a file's name or pick one",
            true);
        return false;
    }
    const fs::path path = resolved();
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        const std::string name = field_;
        go_to(path);
        if (is_save(purpose_)) {
            say("'" + name +
                    "' is a folder, not a file: it is listed now; type a name for the file",
                true);
        }
        return false;
    }
    if (field_.back() == '/') {
        say("no folder " + path.string(), true);
        return false;
    }
    if (!is_save(purpose_)) {
        if (!fs::exists(path, ec)) {
            say("no file " + path.filename().string() + " in " + path.parent_path().string(), true);
            return false;
        }
    } else if (!fs::is_directory(path.parent_path(), ec)) {
        say("no folder " + path.parent_path().string() + " to save in", true);
        return false;
    }
    chosen_ = path;
    return true;
}

void FileChooser::list() {
    entries_.clear();
    highlighted_ = -1;
    std::vector<ChooserEntry> folders, files;
    std::error_code ec;
    for (fs::directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec)) {
        std::string name = it->path().filename().string();
        if (name.empty() || (name[0] == '.' && !show_all_)) {
            continue;
        }
        std::error_code kind_ec;
        if (it->is_directory(kind_ec)) {
            folders.push_back({std::move(name), true});
            continue;
        }
        const std::string ext = file_extension(it->path());
        if (show_all_ ||
            std::find(extensions_.begin(), extensions_.end(), ext) != extensions_.end()) {
            files.push_back({std::move(name), false});
        }
    }
    if (ec) {
        say("cannot list " + folder_.string() + ": " + ec.message(), true);
    }
    const auto by_name = [](const ChooserEntry& a, const ChooserEntry& b) {
        const std::string la = lower(a.name), lb = lower(b.name);
        return la != lb ? la < lb : a.name < b.name;
    };
    std::sort(folders.begin(), folders.end(), by_name);
    std::sort(files.begin(), files.end(), by_name);
    if (folder_.has_parent_path() && folder_ != folder_.root_path()) {
        entries_.push_back({"..", true});
    }
    entries_.insert(entries_.end(), folders.begin(), folders.end());
    entries_.insert(entries_.end(), files.begin(), files.end());
}

void FileChooser::say(std::string text, bool error) {
    message_ = std::move(text);
    error_ = error;
}

}  // namespace meshedit::viewer
