# Script mode: cmake -DCHECKER=CheckCitations.cmake -DFIXTURE=tests/data/citations -P ExpectMissingCitations.cmake
# The citations check must fail on the fixture, whose code cites eqs. 7.1-7.3 (an en-dash range) and
# whose only page states 7.1: it must name 7.2 and 7.3 and nothing else (the index page does not count).
execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${FIXTURE} -P ${CHECKER} RESULT_VARIABLE status
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(report "${out}${err}")
if(status EQUAL 0)
  message(FATAL_ERROR "the citations check passed a tree with unstated equations:\n${report}")
endif()
foreach(expected "eq. 7.2 \\(cited in engine/optics/Cites.hpp\\)" "eq. 7.3 \\(cited in" "2 of 6 cited equations")
  if(NOT report MATCHES "${expected}")
    message(FATAL_ERROR "the citations check did not report: ${expected}\n${report}")
  endif()
endforeach()
if(report MATCHES "eq. (9.1|7.1|8.1|8.2) ")
  message(FATAL_ERROR "the citations check refused an equation the fixture states:\n${report}")
endif()
message("citations_detects_missing: 7.2 and 7.3 named")
