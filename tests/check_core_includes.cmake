# Fails if a core or bezier source includes anything but the standard library and the
# project's own core/bezier headers. Run by ctest (core_has_no_foreign_includes).
file(GLOB_RECURSE sources
    ${ROOT}/include/meshedit/core/*.h ${ROOT}/src/core/*.cpp ${ROOT}/src/core/*.h
    ${ROOT}/include/meshedit/bezier/*.h ${ROOT}/src/bezier/*.cpp)
set(bad "")
foreach(file ${sources})
    file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include")
    foreach(line ${lines})
        if(line MATCHES "#[ \t]*include[ \t]*\"([^\"]+)\"")
            # Project headers by full path, or a private header next to the .cpp (no '/').
            if(NOT CMAKE_MATCH_1 MATCHES "^meshedit/(core|bezier)/" AND CMAKE_MATCH_1 MATCHES "/")
                list(APPEND bad "${file}: ${line}")
            endif()
        elseif(line MATCHES "#[ \t]*include[ \t]*<([^>]+)>")
            # Standard headers have no directory and no extension (plus the C ones).
            # The one exception: memory.cpp's huge-page hint (madvise, Linux only).
            if(file MATCHES "/src/core/memory\\.cpp$" AND CMAKE_MATCH_1 STREQUAL "sys/mman.h")
                continue()
            endif()
            if(CMAKE_MATCH_1 MATCHES "[/.]" AND NOT CMAKE_MATCH_1 MATCHES "^(c?std|math|assert|string|limits)")
                list(APPEND bad "${file}: ${line}")
            endif()
        endif()
    endforeach()
endforeach()
if(bad)
    list(JOIN bad "\n  " text)
    message(FATAL_ERROR "core/bezier sources include non-standard headers:\n  ${text}")
endif()
message(STATUS "core/bezier include only the standard library (${CMAKE_CURRENT_LIST_FILE})")
