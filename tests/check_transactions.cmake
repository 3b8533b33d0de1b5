# The document changes only through a Transaction (include/meshedit/viewer/transaction.h):
# no code in src/ or bench/ outside src/viewer/transaction.cpp pushes undo history, sets a
# document's revision or appends to its session, and the old second channel for "what
# changed" (take_region) is gone. Run by ctest (document_changes_only_through_transactions,
# label viewer); fails naming every offending line.
cmake_policy(SET CMP0007 NEW)
include(${CMAKE_CURRENT_LIST_DIR}/find_lines.cmake)
file(GLOB_RECURSE sources RELATIVE "${ROOT}" "${ROOT}/src/*.cpp" "${ROOT}/src/*.h"
     "${ROOT}/include/*.h" "${ROOT}/bench/*.cpp")
# History's own implementation and the document's undo/redo of a change move revisions and
# sessions back and forth by design; they are the transaction's machinery.
list(REMOVE_ITEM sources src/viewer/transaction.cpp include/meshedit/viewer/transaction.h
     src/viewer/history.cpp)
set(forbidden
    "history_?\\.push\\("
    "history_?\\(\\)\\.push\\("
    "\\.revision[ \t]*=[^=]"
    "next_revision"
    "session\\.(emplace_back|push_back|insert|resize|assign)\\("
    "take_region"
    "amend_last")
find_lines(bad "${sources}" "${forbidden}")
if(bad)
    list(JOIN bad "\n  " text)
    message(FATAL_ERROR "the document changed outside a Transaction (viewer/transaction.h):\n  ${text}")
endif()
list(LENGTH sources n)
message(STATUS "${n} files change the document only through transactions")
