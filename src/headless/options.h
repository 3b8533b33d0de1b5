#pragma once
// Private to meshedit-render: its command line (CLI11, in MeshEdit's command-line style) and
// the --select syntax.

#include <array>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "exit_status.h"
#include "gl_context.h"
#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/stencil.h"
#include "meshedit/overlay/camera.h"
#include "meshedit/overlay/colormap.h"
#include "meshedit/overlay/shading.h"

namespace meshedit::headless {

/// Bad usage or input found after parsing (exit 2), as `meshedit` throws it.
using command_line::UsageError;

struct Options {
    std::filesystem::path input;
    std::filesystem::path output;
    int width = 512;
    int height = 384;
    std::string ops;
    int shading = 1;
    SurfaceColor color = SurfaceColor::Auto;
    std::optional<bool> smooth;
    bool wireframe = false;
    std::optional<float> azimuth, elevation, distance;
    UpAxis up = UpAxis::Y;
    std::string select;
    std::optional<StencilScheme> stencil;
    bool marks_near = false;
    bool problems = false;  ///< --problems: the Problems panel's places marked
    /// --patch-steps I,U,V,S: patch I at (U, V) by de Casteljau up to step S.
    std::optional<std::array<double, 4>>
        patch_steps;  ///< --marks-near: a phased Loop's marks near --select only
    bool op_diagram = false;
    NormalSplit normals;               ///< --auto-smooth, --no-crease-split
    std::filesystem::path envmap;      ///< --envmap FILE: mode 7's environment
    std::filesystem::path shader_dir;  ///< --shader-dir DIR: modes 8 and 9
    float exposure = 0.0f;
    std::string field;  ///< --field NAME (core/fields.h)
    std::optional<ColorMap> colormap;
    std::uint32_t field_source = 0;  ///< --field-source vI: where distance starts
    std::optional<bool> features;
    int density = 8;
    bool net = false;
    double t = 0.5;
    int level = -1;
    bool curve = true;
    int samples = 4;
    std::optional<std::pair<int, int>> pick;
    bool timings = false;
    int benchmark = 0;
    Backend backend = Backend::Auto;  ///< --backend auto|egl|osmesa
    std::optional<int> device;        ///< --device N: an EGL device
    bool verbose = false;             ///< --verbose: the backend and GL renderer used
};

/// Parses the command line into `options`. \return -1 to go on, else the exit status after
/// printing the help (0) or a usage error (2).
int parse_options(int argc, char** argv, Options& options);

/// "v:I", "e:A-B", "h:A-B", "f:I" → an element of `mesh`. \throws UsageError.
ElementRef parse_selection(const Mesh& mesh, const std::string& spec);

}  // namespace meshedit::headless
