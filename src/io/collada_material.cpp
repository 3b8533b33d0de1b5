// COLLADA materials (collada_material.h). Reading follows the chain COLLADA 1.4.1 spells:
// <material>/<instance_effect> → <effect>/<profile_COMMON>/<technique>/<lambert|phong|blinn|
// constant>/<diffuse>/<texture texture="SAMPLER"> → <newparam sid="SAMPLER">/<sampler2D>/
// <source>SURFACE → <newparam sid="SURFACE">/<surface>/<init_from>IMAGE → <image id="IMAGE">/
// <init_from>path. Many exporters name the image straight from <texture>; that works too.

#include "collada_material.h"

#include <cstring>
#include <filesystem>
#include <string_view>
#include <utility>

#include "io_util.h"
#include "meshedit/core/number_text.h"

namespace meshedit::collada {
namespace {

std::string text_of(pugi::xml_node node) {
    std::string_view t = node.child_value();
    while (!t.empty() && std::strchr(" \t\r\n", t.front()) != nullptr) {
        t.remove_prefix(1);
    }
    while (!t.empty() && std::strchr(" \t\r\n", t.back()) != nullptr) {
        t.remove_suffix(1);
    }
    return std::string(t);
}

// The <newparam sid="sid"> of `profile`, or a null node.
pugi::xml_node newparam(pugi::xml_node profile, const std::string& sid) {
    return profile.find_child_by_attribute("newparam", "sid", sid.c_str());
}

// The image path a <texture texture="..."> names, or "" when the chain breaks.
std::string texture_path(const Document& doc, pugi::xml_node profile, const std::string& name) {
    std::string image_id = name;
    if (const pugi::xml_node sampler = newparam(profile, name).child("sampler2D")) {
        const std::string surface = text_of(sampler.child("source"));
        image_id = text_of(newparam(profile, surface).child("surface").child("init_from"));
    }
    const pugi::xml_node image = doc.find_id(image_id);
    if (!image || std::strcmp(image.name(), "image") != 0) {
        return "";
    }
    return io_util::resolve_texture(text_of(image.child("init_from")),
                                    std::filesystem::path(doc.file()).parent_path(), true);
}

void append_numbers(std::string& out, std::initializer_list<double> values) {
    bool first = true;
    for (const double x : values) {
        out += first ? "" : " ";
        append_number_text(out, x);
        first = false;
    }
}

// The profile_COMMON of `<material>` `node`'s effect, and its technique's shading element
// (lambert, phong, blinn or constant).
std::pair<pugi::xml_node, pugi::xml_node> shading_of(const Document& doc, pugi::xml_node node) {
    const pugi::xml_attribute url = node.child("instance_effect").attribute("url");
    const std::string_view u = url.value();
    const pugi::xml_node effect =
        u.size() > 1 && u[0] == '#' ? doc.find_id(u.substr(1)) : pugi::xml_node();
    const pugi::xml_node profile = effect.child("profile_COMMON");
    pugi::xml_node shading;
    for (pugi::xml_node child : profile.child("technique").children()) {
        shading = child;
        if (child.child("diffuse") || child.child("emission")) {
            break;
        }
    }
    return {profile, shading};
}

}  // namespace

std::string diffuse_texcoord(const Document& doc, pugi::xml_node node) {
    return shading_of(doc, node)
        .second.child("diffuse")
        .child("texture")
        .attribute("texcoord")
        .value();
}

Material read_material(const Document& doc, pugi::xml_node node) {
    Material m;
    const pugi::xml_attribute name = node.attribute("name");
    m.name = name ? name.value() : node.attribute("id").value();
    m.has_base_colour = false;
    m.has_opacity = false;
    const auto [profile, shading] = shading_of(doc, node);
    const pugi::xml_node diffuse = shading.child("diffuse");
    if (const pugi::xml_node colour = diffuse.child("color")) {
        const std::vector<double> c = parse_doubles(doc, colour);
        if (c.size() >= 3) {
            m.base_colour = Vec3(c[0], c[1], c[2]);
            m.has_base_colour = true;
        }
    }
    if (const pugi::xml_node texture = diffuse.child("texture")) {
        m.base_colour_texture = texture_path(doc, profile, texture.attribute("texture").value());
    }
    if (const pugi::xml_node t = shading.child("transparency").child("float")) {
        const std::vector<double> x = parse_doubles(doc, t);
        if (x.size() == 1) {
            m.opacity = x[0];
            m.has_opacity = true;
        }
    }
    return m;
}

std::string xml_escape(const std::string& s) {
    std::string out;
    for (const char c : s) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string materials_text(const std::vector<Material>& materials,
                           const std::filesystem::path& folder) {
    if (materials.empty()) {
        return "";
    }
    std::string images, effects, library;
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const Material& m = materials[i];
        const std::string n = std::to_string(i);
        std::string diffuse;
        std::string params;
        if (!m.base_colour_texture.empty()) {
            images += "    <image id=\"image-" + n + "\">\n      <init_from>" +
                      xml_escape(io_util::texture_relative_to(m.base_colour_texture, folder)) +
                      "</init_from>\n    </image>\n";
            params = "        <newparam sid=\"surface-" + n +
                     "\">\n          <surface type=\"2D\">\n            <init_from>image-" + n +
                     "</init_from>\n          </surface>\n        </newparam>\n"
                     "        <newparam sid=\"sampler-" +
                     n + "\">\n          <sampler2D>\n            <source>surface-" + n +
                     "</source>\n          </sampler2D>\n        </newparam>\n";
            diffuse = "<texture texture=\"sampler-" + n + "\" texcoord=\"UVMap\"/>";
            // write_collada.cpp binds UVMap to the input set of m.base_colour_texcoord.
        } else if (m.has_base_colour) {
            diffuse = "<color>";
            append_numbers(diffuse, {m.base_colour.x, m.base_colour.y, m.base_colour.z, 1.0});
            diffuse += "</color>";
        }
        std::string shading;
        if (!diffuse.empty()) {
            shading += "            <diffuse>" + diffuse + "</diffuse>\n";
        }
        if (m.has_opacity) {
            shading += "            <transparency><float>";
            append_numbers(shading, {m.opacity});
            shading += "</float></transparency>\n";
        }
        effects += "    <effect id=\"effect-" + n + "\">\n      <profile_COMMON>\n" + params +
                   "        <technique sid=\"common\">\n          <lambert>\n" + shading +
                   "          </lambert>\n        </technique>\n      </profile_COMMON>\n"
                   "    </effect>\n";
        library += "    <material id=\"material-" + n + "\" name=\"" + xml_escape(m.name) +
                   "\">\n      <instance_effect url=\"#effect-" + n + "\"/>\n    </material>\n";
    }
    return (images.empty() ? "" : "  <library_images>\n" + images + "  </library_images>\n") +
           "  <library_effects>\n" + effects + "  </library_effects>\n  <library_materials>\n" +
           library + "  </library_materials>\n";
}

}  // namespace meshedit::collada
