# cmake -S student -B BINARY && cmake --build BINARY, as a student would, then checks that
# libstudent.so is there. -DSOURCE, -DBINARY, -DGENERATOR, -DCOMPILER.
file(REMOVE_RECURSE ${BINARY})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -G ${GENERATOR}
                        -DCMAKE_CXX_COMPILER=${COMPILER}
                RESULT_VARIABLE configured OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT configured EQUAL 0)
    message(FATAL_ERROR "configuring student/ failed:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY}
                RESULT_VARIABLE built OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT built EQUAL 0)
    message(FATAL_ERROR "building student/ failed:\n${out}")
endif()
if(NOT EXISTS ${BINARY}/libstudent.so)
    message(FATAL_ERROR "student/ built no libstudent.so")
endif()
