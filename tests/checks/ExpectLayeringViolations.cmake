# Script mode: cmake -DCHECKER=CheckLayering.cmake -DFIXTURE=tests/data/layering -P ExpectLayeringViolations.cmake
# The layering check must fail on the fixture tree and name each of its six violations, and nothing else.
execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${FIXTURE} -P ${CHECKER} RESULT_VARIABLE status
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(report "${out}${err}")
if(status EQUAL 0)
  message(FATAL_ERROR "the layering check passed a tree with violations:\n${report}")
endif()
foreach(expected
        "engine/geometry/UsesTree.hpp: includes \"tree/Octree.hpp\" of layer tree, above it"
        "engine/optics/UsesGl.hpp: includes <GL/gl.h>, which layer optics must not use"
        "app/gui/UsesCli.hpp: includes \"cli/Cli.hpp\" of layer cli, a sibling"
        "engine/geometry/UsesTreeRelative.h: includes \"../tree/Octree.hpp\" of layer tree, above it"
        "app/gui/UsesCliAngle.hpp: includes <cli/Cli.hpp> of layer cli, a sibling"
        "engine/optics/UsesEpoxy.hpp: includes <epoxy/gl.h>, which layer optics must not use"
        "layering: 6 include\\(s\\) break")
  if(NOT report MATCHES "${expected}")
    message(FATAL_ERROR "the layering check did not report: ${expected}\n${report}")
  endif()
endforeach()
if(report MATCHES "Fine.hpp")
  message(FATAL_ERROR "the layering check refused an include that keeps to the rules:\n${report}")
endif()
message("layering_detects_violations: all six named")
