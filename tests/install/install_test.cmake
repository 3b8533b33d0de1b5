# The install test (ctest install_builds_an_outside_program, label install): installs the
# build into a temporary prefix, builds tests/install/consumer against it with
# find_package(MeshEdit), runs it on dae/cube.dae (flip 0-6, Loop once, write OBJ) and checks the
# OBJ; checks meshedit.pc with pkg-config; imports the Python module from the prefix when it
# was built. Arguments: SOURCE, BUILD, WORK, GENERATOR, optional LAUNCHER, PYTHON, PYTHON_DIR.
function(run)
    execute_process(COMMAND ${ARGV} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
        list(JOIN ARGV " " command)
        message(FATAL_ERROR "failed (${rc}): ${command}\n${out}\n${err}")
    endif()
    set(out "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK}/prefix)
file(REMOVE_RECURSE ${prefix} ${WORK}/consumer-build)
run(${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix})

set(launcher "")
if(LAUNCHER)
    set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run(${CMAKE_COMMAND} -S ${SOURCE}/tests/install/consumer -B ${WORK}/consumer-build
    -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} ${launcher})
run(${CMAKE_COMMAND} --build ${WORK}/consumer-build)

set(obj ${WORK}/cube-loop.obj)
file(REMOVE ${obj})
run(${WORK}/consumer-build/consumer ${SOURCE}/dae/cube.dae ${obj})
if(NOT out MATCHES "^V=26 E=72 F=48 ")
    message(FATAL_ERROR "consumer printed '${out}', expected V=26 E=72 F=48 (cube, flip, Loop)")
endif()
file(STRINGS ${obj} vertices REGEX "^v ")
file(STRINGS ${obj} faces REGEX "^f ")
list(LENGTH vertices nv)
list(LENGTH faces nf)
if(NOT nv EQUAL 26 OR NOT nf EQUAL 48)
    message(FATAL_ERROR "${obj}: ${nv} vertices and ${nf} faces, expected 26 and 48")
endif()
message(STATUS "outside program: ${out}")

# pkg-config: the file is found, names the installed include folder and libraries.
find_program(PKG_CONFIG pkg-config)
if(PKG_CONFIG)
    file(GLOB_RECURSE pc_files ${prefix}/*/meshedit.pc)
    list(GET pc_files 0 pc_file)
    get_filename_component(pc_dir ${pc_file} DIRECTORY)
    set(ENV{PKG_CONFIG_PATH} ${pc_dir})
    run(${PKG_CONFIG} --cflags --libs meshedit)
    string(REGEX MATCH "-I([^ \n]+)" _ "${out}")
    if(NOT EXISTS ${CMAKE_MATCH_1}/meshedit/core/mesh.h)
        message(FATAL_ERROR "pkg-config names ${CMAKE_MATCH_1}, which has no meshedit/core/mesh.h")
    endif()
    string(REGEX MATCH "-L([^ \n]+)" _ "${out}")
    if(NOT EXISTS ${CMAKE_MATCH_1}/libmeshedit_mesh.a)
        message(FATAL_ERROR "pkg-config names ${CMAKE_MATCH_1}, which has no libmeshedit_mesh.a")
    endif()
    message(STATUS "pkg-config: ${out}")
endif()

if(PYTHON)
    set(ENV{PYTHONPATH} ${prefix}/${PYTHON_DIR})
    file(WRITE ${WORK}/import.py "import sys\nimport meshedit\nm = meshedit.read(sys.argv[1])\n"
        "m.flip(0, 6)\nm.loop()\nimage = meshedit.render(m, 16, 12)\n"
        "print(meshedit.__file__, m.info()['vertices'], image.shape)\n")
    run(${PYTHON} ${WORK}/import.py ${SOURCE}/dae/cube.dae)
    if(NOT out MATCHES "^${prefix}/.* 26 \\(12, 16, 4\\)\n$")
        message(FATAL_ERROR "python from the prefix printed '${out}'")
    endif()
    message(STATUS "python: ${out}")
endif()
