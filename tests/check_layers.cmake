# The layer table: which headers each part of the code may include. Run by ctest
# (layers_include_only_what_they_may, label core); fails naming every offending file and
# include. docs/architecture.md draws the same table as a picture.
#
# A rule is: a name; a regex matched against the file's path below the repository root (the
# first rule that matches a file is its layer); the project headers it may include, as a regex
# on the path after "meshedit/"; and the other headers it may include, as a regex on the text
# between < and >. Standard headers (no '/' and no '.') are always allowed, and so are private
# headers beside the file ("name.h", no '/').
cmake_policy(SET CMP0007 NEW)
set(std_posix "fcntl\\.h|unistd\\.h|signal\\.h|sys/(stat|mman|types)\\.h")
set(gl "GL/glcorearb\\.h|glm/.*")
set(rules
    # name | files | project headers | other headers
    "core|^(include/meshedit|src)/core/|^core/|^sys/mman\\.h$"
    "bezier|^(include/meshedit|src)/bezier/|^(core|bezier)/|^$"
    "files|^(include/meshedit|src)/files/|^(core|files)/|^(${std_posix})$"
    "io|^(include/meshedit|src)/io/|^(core|bezier|files|io)/|^(${std_posix}|pugixml\\.hpp|tiny_gltf\\.h|meshoptimizer\\.h|nlohmann/json\\.hpp)$"
    "ops|^(include/meshedit|src)/ops/|^(core|ops)/|^$"
    "render, GL-free part (overlay geometry, camera, CPU picking)|^(include/meshedit/render/(overlay|camera|shading|op_diagram|colormap|cpu_pick)\\.h|src/render/(overlay|camera|scene_marks|stencil_marks|op_diagram|op_diagram_names|op_diagram_change|colormap|shading|cpu_pick)\\.cpp)$|^(core|bezier)/|render/(overlay|camera|shading|op_diagram|colormap|cpu_pick)\\.h$|^glm/.*$"
    "render|^(include/meshedit|src)/render/|^(core|bezier|files|render)/|^(${gl}|OpenImageIO/(imageio|imagebuf|imagebufalgo)\\.h|unistd\\.h)$"
    "viewer logic (no GL, no window)|^(include/meshedit/viewer/|src/viewer/(bindings|history|transaction|editor|editor_[a-z]+|element_info|paths)\\.cpp$)|^(core|bezier|files|io|ops|viewer)/|render/(overlay|camera|shading|op_diagram|colormap)\\.h$|^$"
    "viewer window|^src/viewer/|^(core|bezier|files|io|ops|render|viewer)/|^(${gl}|GLFW/glfw3\\.h|imgui\\.h|imgui_stdlib\\.h|backends/imgui_impl_(glfw|opengl3)\\.h)$"
    "command line style (and the exit-status ladder)|^src/command_line/|^(core|files|ops)/|^CLI/CLI\\.hpp$"
    "cli (meshedit)|^src/cli/|^(core|bezier|files|io|ops)/|^(CLI/CLI\\.hpp|nlohmann/json\\.hpp|unistd\\.h)$"
    "headless (meshedit-render)|^src/headless/|^(core|bezier|files|io|ops|render)/|^(CLI/CLI\\.hpp|GL/osmesa\\.h|GL/glcorearb\\.h|EGL/egl(ext)?\\.h|dlfcn\\.h)$"
    "tools|^tools/|^(core|bezier|files|io|ops)/|^$"
    "python (the meshedit module)|^src/python/|^(core|bezier|files|io|ops)/|^pybind11/.*$"
)

# The floors of src/core, lowest first (src/core/CMakeLists.txt).
set(core_floors mesh local_ops algorithms teaching)
set(bad "")
set(unassigned "")
file(GLOB_RECURSE sources RELATIVE ${ROOT}
    ${ROOT}/include/*.h ${ROOT}/src/*.h ${ROOT}/src/*.cpp ${ROOT}/tools/*.cpp)
foreach(file ${sources})
    set(layer "")
    foreach(rule ${rules})
        string(REPLACE "|^" ";^" parts "${rule}")
        # parts: name;files;project;other (the regexes start with ^, the name does not)
        list(GET parts 0 name)
        list(GET parts 1 files)
        if(file MATCHES "${files}")
            set(layer "${name}")
            list(GET parts 2 project)
            list(GET parts 3 other)
            break()
        endif()
    endforeach()
    if(layer STREQUAL "")
        list(APPEND unassigned "${file}")
        continue()
    endif()
    file(STRINGS ${ROOT}/${file} lines REGEX "^[ \t]*#[ \t]*include")
    foreach(line ${lines})
        if(line MATCHES "#[ \t]*include[ \t]*\"([^\"]+)\"")
            set(header "${CMAKE_MATCH_1}")
            if(NOT header MATCHES "/")
                continue()  # a private header beside the file
            endif()
            if(file MATCHES "^src/core/([a-z_]+)/" AND header MATCHES "^([a-z_]+)/[a-z_]+\\.h$")
                # The core's floors: a private header of the same floor or one below.
                string(REGEX MATCH "^src/core/([a-z_]+)/" _ "${file}")
                set(from "${CMAKE_MATCH_1}")
                string(REGEX MATCH "^([a-z_]+)/" _ "${header}")
                set(to "${CMAKE_MATCH_1}")
                list(FIND core_floors "${from}" from_floor)
                list(FIND core_floors "${to}" to_floor)
                if(from_floor LESS 0 OR to_floor LESS 0 OR to_floor GREATER from_floor OR
                   NOT EXISTS "${ROOT}/src/core/${header}")
                    list(APPEND bad "${file}: ${line}  (the core's floor ${from} may include private headers of its own floor or those below: ${core_floors})")
                endif()
                continue()
            endif()
            if(header MATCHES "^meshedit/(.*)$")
                set(inside "${CMAKE_MATCH_1}")
                if(NOT inside MATCHES "${project}")
                    list(APPEND bad "${file}: ${line}  (the ${layer} layer may not include meshedit/${inside})")
                endif()
            else()
                list(APPEND bad "${file}: ${line}  (project headers are included as \"meshedit/...\")")
            endif()
        elseif(line MATCHES "#[ \t]*include[ \t]*<([^>]+)>")
            set(header "${CMAKE_MATCH_1}")
            if(header MATCHES "^[a-z_0-9]+$")
                continue()  # the standard library
            endif()
            if(NOT header MATCHES "${other}")
                list(APPEND bad "${file}: ${line}  (the ${layer} layer may not include <${header}>)")
            endif()
        endif()
    endforeach()
endforeach()

# Folders that say what they hold: none under src/ holds more than a fifth of the code of
# src/ and include/ (the core was one flat folder of 27% before its floors).
set(total 0)
set(folders "")
foreach(file ${sources})
    if(file MATCHES "^tools/")
        continue()
    endif()
    file(STRINGS ${ROOT}/${file} all_lines)
    list(LENGTH all_lines n)
    math(EXPR total "${total} + ${n}")
    if(file MATCHES "^(src/.*)/[^/]+$")
        string(MAKE_C_IDENTIFIER "${CMAKE_MATCH_1}" key)
        if(NOT DEFINED lines_${key})
            set(lines_${key} 0)
            list(APPEND folders "${CMAKE_MATCH_1}")
        endif()
        math(EXPR lines_${key} "${lines_${key}} + ${n}")
    endif()
endforeach()
foreach(folder ${folders})
    string(MAKE_C_IDENTIFIER "${folder}" key)
    math(EXPR share "100 * ${lines_${key}} / ${total}")
    if(share GREATER 20)
        list(APPEND bad "${folder}: ${lines_${key}} of ${total} lines (${share}%), more than a fifth: split it into folders that say what they hold")
    endif()
endforeach()

if(unassigned)
    list(JOIN unassigned "\n  " text)
    message(FATAL_ERROR "files in no layer (add them to tests/check_layers.cmake):\n  ${text}")
endif()
if(bad)
    list(JOIN bad "\n  " text)
    message(FATAL_ERROR "includes that cross the layer table (tests/check_layers.cmake):\n  ${text}")
endif()
list(LENGTH sources n)
message(STATUS "${n} files include only what their layer may")
