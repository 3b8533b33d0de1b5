# Helpers for the project's library targets.

# meshedit_public_headers(target folder name...): lists include/meshedit/<folder>/<name>.h
# among the target's sources, so its source list names every file it owns (the layer test,
# tests/check_layers.cmake, reads these lists).
function(meshedit_public_headers target folder)
    list(TRANSFORM ARGN REPLACE "(.+)" "${PROJECT_SOURCE_DIR}/include/meshedit/${folder}/\\1.h"
         OUTPUT_VARIABLE headers)
    target_sources(${target} PRIVATE ${headers})
endfunction()

# meshedit_core_floor(target): one floor of the core. Its private headers are included by
# floor ("mesh/parallel.h"), so src/ is on its private include path.
function(meshedit_core_floor target)
    target_include_directories(${target}
        PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>
        PRIVATE ${PROJECT_SOURCE_DIR}/src)
    meshedit_configure_target(${target})
endfunction()

# meshedit_other_headers(target header...): the headers from outside the project and the
# standard library that the target's files may include (a trailing * matches a folder:
# "glm/*"). The layer test refuses any other.
function(meshedit_other_headers target)
    set_property(TARGET ${target} APPEND PROPERTY MESHEDIT_OTHER_HEADERS ${ARGN})
endfunction()
