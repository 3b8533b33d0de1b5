# Every fact about a verb of the edit language lives in its row of the verb table
# (src/ops/verbs.cpp, meshedit/ops/ops.h: traits, amounts, diagram names): no code outside
# src/ops compares a verb's name. Run by ctest (no_verb_name_compared_outside_ops, label
# core) on src/, include/, bench/ and tools/; with -DEXTRA=FILE it checks that file too (the
# test that this check can fail). Fails naming every offending line.
cmake_policy(SET CMP0007 NEW)
include(${CMAKE_CURRENT_LIST_DIR}/find_lines.cmake)
file(STRINGS "${ROOT}/src/ops/verbs.cpp" rows REGEX "Verb{\"[a-z_]+\"")
set(verbs "")
foreach(row ${rows})
    string(REGEX MATCH "Verb{\"([a-z_]+)\"" _ "${row}")
    list(APPEND verbs "${CMAKE_MATCH_1}")
endforeach()
list(LENGTH verbs n_verbs)
if(n_verbs LESS 10)
    message(FATAL_ERROR "found only ${n_verbs} verbs in src/ops/verbs.cpp: the table moved?")
endif()
list(JOIN verbs "|" alternatives)
# `x == "flip"`, `"flip" != x`, `x.compare("flip")`, Python's `x == 'flip'`.
set(quoted "[\"'](${alternatives})[\"']")
set(patterns "[!=]=[ \t]*${quoted}" "${quoted}[ \t]*[!=]=" "compare\\(${quoted}")
file(GLOB_RECURSE sources RELATIVE "${ROOT}" "${ROOT}/src/*.cpp" "${ROOT}/src/*.h"
     "${ROOT}/src/*.py" "${ROOT}/include/*.h" "${ROOT}/bench/*.cpp" "${ROOT}/tools/*.cpp")
list(FILTER sources EXCLUDE REGEX "^src/ops/")
if(EXTRA)
    list(APPEND sources "${EXTRA}")
endif()
find_lines(bad "${sources}" "${patterns}")
if(bad)
    list(JOIN bad "\n  " text)
    message(FATAL_ERROR "a verb name is compared outside src/ops (give the verb table a field "
                        "instead, docs/contributing.md):\n  ${text}")
endif()
list(LENGTH sources n)
message(STATUS "${n} files, ${n_verbs} verbs: no verb name compared outside src/ops")
