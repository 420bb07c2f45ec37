# cmake -DPROGRAM=... -DARGUMENTS=a|b|c -DEXPECTED_EXIT=n -DSTDERR_REGEX=... -P run_and_check_exit.cmake
# Runs PROGRAM with ARGUMENTS ('|'-separated) and fails unless its exit status is EXPECTED_EXIT and its
# stderr is empty (status 0) or exactly one line matching STDERR_REGEX (any other status).
string(REPLACE "|" ";" arguments "${ARGUMENTS}")
execute_process(COMMAND "${PROGRAM}" ${arguments}
                RESULT_VARIABLE status
                OUTPUT_VARIABLE stdout
                ERROR_VARIABLE stderr)
if(NOT status STREQUAL "${EXPECTED_EXIT}")
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECTED_EXIT}\nstderr: ${stderr}")
endif()
if(status EQUAL 0)
  if(NOT stderr STREQUAL "")
    message(FATAL_ERROR "success must print nothing on stderr, got:\n${stderr}")
  endif()
  return()
endif()
string(REGEX MATCHALL "\n" newlines "${stderr}")
list(LENGTH newlines line_count)
if(NOT line_count EQUAL 1 OR NOT stderr MATCHES "\n$")
  message(FATAL_ERROR "stderr must be exactly one line, got ${line_count} newline(s):\n${stderr}")
endif()
string(REGEX REPLACE "\n$" "" line "${stderr}")
if(NOT line MATCHES "${STDERR_REGEX}")
  message(FATAL_ERROR "stderr line does not match '${STDERR_REGEX}':\n${line}")
endif()
message(STATUS "exit status ${status}; stderr: ${line}")
