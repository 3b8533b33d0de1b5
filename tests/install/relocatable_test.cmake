# The install is relocatable (issue 34): `cmake --install` into a temporary prefix, the prefix
# moved elsewhere, and the moved copy's `meshedit render` and `meshedit info` run, the renderer
# taking its shaders and font from the moved share/meshedit (not from the source tree or the
# system).
# Run by ctest: cmake -DBUILD_DIR=… -DSOURCE_DIR=… -DWORK_DIR=… -P relocatable_test.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(first ${WORK_DIR}/installed)
set(moved ${WORK_DIR}/moved)

execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${first}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "cmake --install failed (${status}): ${err}")
endif()
foreach(file bin/meshedit bin/meshedit-render share/meshedit/shaders/mesh.vert
        share/meshedit/fonts/DejaVuSans.ttf)
    if(NOT EXISTS ${first}/${file})
        message(FATAL_ERROR "cmake --install put no ${file} under the prefix")
    endif()
endforeach()
file(RENAME ${first} ${moved})

# A field's legend is text: the font must come from the moved prefix too.
execute_process(COMMAND ${moved}/bin/meshedit render ${SOURCE_DIR}/dae/cube.dae
                        -o ${WORK_DIR}/cube.png --verbose --field valence
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT EXISTS ${WORK_DIR}/cube.png)
    message(FATAL_ERROR "the moved meshedit render failed (${status}): ${err}")
endif()
if(NOT err MATCHES "shaders from ${moved}/share/meshedit/shaders")
    message(FATAL_ERROR "the moved meshedit render did not take the moved shaders: ${err}")
endif()
if(NOT err MATCHES "font from ${moved}/share/meshedit/fonts/DejaVuSans.ttf")
    message(FATAL_ERROR "the moved meshedit render did not take the moved font: ${err}")
endif()

execute_process(COMMAND ${moved}/bin/meshedit info ${SOURCE_DIR}/dae/cube.dae
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "the moved meshedit info failed (${status}): ${err}")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
message(STATUS "installed, moved, rendered and described from ${moved}")
