# The Python module `meshedit` (docs/python.md): MESHEDIT_BUILD_PYTHON is on by default when
# pybind11, a Python interpreter with its headers, and numpy are found, and off in sanitizer
# and fuzzing builds (the sanitizer runtime cannot be loaded into an unsanitized python3).
#
# The interpreter is the first of `python3` on PATH and /usr/bin/python3 that can import
# numpy: a pyenv or virtualenv python3 ahead of Debian's on PATH usually lacks python3-numpy.
set(meshedit_python_default OFF)
if(NOT MESHEDIT_SANITIZE AND NOT MESHEDIT_FUZZ)
    if(NOT DEFINED Python3_EXECUTABLE)
        find_program(meshedit_path_python python3)
        foreach(candidate ${meshedit_path_python} /usr/bin/python3)
            if(EXISTS ${candidate})
                execute_process(COMMAND ${candidate} -c "import numpy"
                    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
                if(rc EQUAL 0)
                    set(Python3_EXECUTABLE ${candidate} CACHE FILEPATH "Python for the module")
                    break()
                endif()
            endif()
        endforeach()
    endif()
    find_package(Python3 QUIET COMPONENTS Interpreter Development.Module NumPy)
    find_package(pybind11 CONFIG QUIET)
    if(Python3_FOUND AND Python3_NumPy_FOUND AND pybind11_FOUND)
        set(meshedit_python_default ON)
    endif()
endif()
option(MESHEDIT_BUILD_PYTHON "Build the Python module (pybind11, numpy)" ${meshedit_python_default})

if(MESHEDIT_BUILD_PYTHON)
    if(NOT (Python3_FOUND AND Python3_NumPy_FOUND AND pybind11_FOUND))
        message(FATAL_ERROR "MESHEDIT_BUILD_PYTHON needs pybind11-dev, python3-dev and "
                            "python3-numpy (scripts/install-deps.sh installs them)")
    endif()
    # Where `cmake --install` puts the package, below the prefix: Debian's python3 finds
    # prefix/lib/python3/dist-packages on PYTHONPATH, or by itself for /usr and /usr/local.
    set(MESHEDIT_PYTHON_INSTALL_DIR lib/python3/dist-packages CACHE STRING
        "Folder below the prefix for the meshedit Python package")
    message(STATUS "Python module: ${Python3_EXECUTABLE} (${Python3_VERSION}), "
                   "pybind11 ${pybind11_VERSION}")
else()
    message(STATUS "Python module: off (needs pybind11-dev, python3-dev, python3-numpy)")
endif()
