// OBJ material libraries (mtl.h).

#include "mtl.h"

#include <cmath>
#include <string_view>
#include <system_error>

#include "io_util.h"
#include "meshedit/core/number_text.h"

namespace meshedit::mtl {
namespace {

namespace fs = std::filesystem;

// Reads one library into the materials of `soup` it defines; the names of the materials it
// defines go into `defined`.
void read_library(const fs::path& file, MeshSoup& soup, std::vector<bool>& defined) {
    // A library is text of a few kilobytes; one of gigabytes is not read (a notice).
    constexpr std::size_t kMaxLibraryBytes = std::size_t{64} << 20;
    const std::string bytes = read_file(file, kMaxLibraryBytes);
    const std::string_view text = io_util::text_of(bytes, file.string());
    Material* current = nullptr;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        end = end == std::string_view::npos ? text.size() : end;
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        const std::string_view whole = io_util::trim(line);
        const std::string_view key = io_util::next_token(line);
        if (key.empty() || key[0] == '#') {
            continue;
        }
        if (key == "newmtl") {
            const std::string_view name = io_util::trim(line);
            current = nullptr;
            for (std::size_t i = 0; i < soup.materials.size(); ++i) {
                if (soup.materials[i].name == name) {
                    current = &soup.materials[i];
                    defined[i] = true;
                }
            }
            continue;  // a material no face uses is not loaded
        }
        if (current == nullptr) {
            continue;
        }
        const auto numbers = [&](int n, double* out) {
            std::string_view rest = line;
            for (int i = 0; i < n; ++i) {
                const std::optional<double> x = io_util::parse_double(io_util::next_token(rest));
                if (!x || !std::isfinite(*x)) {
                    return false;
                }
                out[i] = *x;
            }
            return true;
        };
        double v[3];
        if (key == "Kd" && numbers(3, v)) {
            current->base_colour = {v[0], v[1], v[2]};
            current->has_base_colour = true;
        } else if (key == "d" && numbers(1, v)) {
            current->opacity = v[0];
            current->has_opacity = true;
        } else if (key == "Tr" && numbers(1, v)) {
            current->opacity = 1.0 - v[0];
            current->has_opacity = true;
        } else if (key == "map_Kd") {
            // Options (-s 1 1 1, -bm 0.5) come first; the path is the last token. Backslashes
            // are Windows exporters' separators.
            std::string path;
            for (std::string_view t = io_util::next_token(line); !t.empty();
                 t = io_util::next_token(line)) {
                path = std::string(t);
            }
            current->base_colour_texture =
                io_util::resolve_texture(path, file.parent_path(), false);
        } else {
            current->other.emplace_back(whole);
        }
    }
}

std::string three(const Vec3& v) {
    return number_text(v.x) + " " + number_text(v.y) + " " + number_text(v.z);
}

}  // namespace

void read_libraries(const fs::path& obj, MeshSoup& soup) {
    if (soup.materials.empty()) {
        return;
    }
    std::vector<bool> defined(soup.materials.size(), false);
    bool read_one = false;
    for (const std::string& name : soup.material_libraries) {
        const fs::path file = obj.parent_path() / name;
        std::error_code ec;
        if (!fs::is_regular_file(file, ec)) {
            // A FIFO, a folder or a device is not read (it could block or never end).
            soup.notices.push_back("material library '" + name + "' " +
                                   (fs::exists(file, ec) ? "is not a regular file" : "not found") +
                                   ": material names kept, colours and textures not");
            continue;
        }
        try {
            read_library(file, soup, defined);
            read_one = true;
        } catch (const IoError& e) {
            soup.notices.push_back(std::string("material library not read: ") + e.what());
        }
    }
    std::string missing;
    for (std::size_t i = 0; i < defined.size(); ++i) {
        if (!defined[i] && !soup.materials[i].name.empty()) {
            missing += (missing.empty() ? "'" : ", '") + soup.materials[i].name + "'";
        }
    }
    if (!missing.empty() && read_one) {
        soup.notices.push_back("materials " + missing +
                               " are not in the material library: their names are kept");
    }
}

std::string text(const Mesh& mesh, const fs::path& folder) {
    std::string out = "# MeshEdit MTL: " + std::to_string(mesh.materials().size()) + " materials\n";
    for (const Material& m : mesh.materials()) {
        if (m.name.empty()) {
            continue;  // the faces without a material
        }
        out += "\nnewmtl " + m.name + "\n";
        // Only what is known: a material read without its .mtl gets its name back, not a
        // white that was never there.
        if (m.has_base_colour) {
            out += "Kd " + three(m.base_colour) + "\n";
        }
        if (m.has_opacity) {
            out += "d " + number_text(m.opacity) + "\n";
        }
        if (!m.base_colour_texture.empty()) {
            out += "map_Kd " + io_util::texture_relative_to(m.base_colour_texture, folder) + "\n";
        }
        for (const std::string& line : m.other) {
            out += line + "\n";
        }
    }
    return out;
}

}  // namespace meshedit::mtl
