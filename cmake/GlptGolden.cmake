# glpt_add_golden_test(NAME TRACE FRAMES THRESHOLD [MODE raster|path] [ARGS ...])
#
# Registers a ctest NAME (label "golden") that replays TRACE (an apitrace trace) headless with
# glpt-replay, writing the frames FRAMES ("0,2" or "1-3", glpt-replay's --frames syntax), and
# compares them with `glpt diff` against the committed goldens in
# ${GLPT_GOLDEN_DIR}/NAME/frame_NNNNNN.png: the test fails when a frame's mean FLIP is over
# THRESHOLD, or a golden is missing. A difference heat map is written next to the replayed frames
# in the build tree on failure.
#
# Updating the goldens (after a deliberate change; review the new images before committing):
#   GLPT_UPDATE_GOLDENS=1 ctest --test-dir build -L golden
# Each test then writes its frames into its golden directory instead of comparing.
#
# In glpt's own tree and in another project alike: after find_package(glpt) (which includes this
# module), glpt's executables are the targets glpt::glpt and glpt::glpt-replay, and the script
# that runs a test lies next to this file.
set(GLPT_GOLDEN_DIR "${PROJECT_SOURCE_DIR}/tests/golden/images" CACHE PATH
    "Where glpt_add_golden_test keeps committed golden images (one directory per test)")
set(_GLPT_GOLDEN_SCRIPT "${CMAKE_CURRENT_LIST_DIR}/golden_test.sh")

function(glpt_add_golden_test name trace frames threshold)
  cmake_parse_arguments(GOLDEN "" "MODE" "ARGS" ${ARGN})
  if(NOT GOLDEN_MODE)
    set(GOLDEN_MODE raster)
  endif()
  add_test(NAME ${name}
           COMMAND ${_GLPT_GOLDEN_SCRIPT}
                   $<TARGET_FILE:glpt::glpt-replay> $<TARGET_FILE:glpt::glpt> ${trace} ${frames}
                   ${threshold}
                   ${GLPT_GOLDEN_DIR}/${name} ${CMAKE_CURRENT_BINARY_DIR}/golden/${name}
                   ${GOLDEN_MODE} ${GOLDEN_ARGS})
  set_tests_properties(${name} PROPERTIES LABELS "golden" TIMEOUT 300 ENVIRONMENT "GLPT_QUIET=1")
endfunction()
