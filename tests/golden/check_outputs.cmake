# ctest Outputs.Unchanged: regenerates the outputs of scripts/golden_outputs.sh into OUTDIR and
# compares each with its frozen copy in tests/golden/ (byte for byte, timings masked by the
# script). Usage:
#   cmake -DSOURCE_DIR=<repo> -DFLEXURE=<binary> -DOUTDIR=<dir> -P tests/golden/check_outputs.cmake
cmake_minimum_required(VERSION 3.22)
file(REMOVE_RECURSE ${OUTDIR})
execute_process(
  COMMAND bash ${SOURCE_DIR}/scripts/golden_outputs.sh ${FLEXURE} ${OUTDIR}
  RESULT_VARIABLE status
  ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "scripts/golden_outputs.sh failed (${status}):\n${errors}")
endif()
file(GLOB golden RELATIVE ${SOURCE_DIR}/tests/golden ${SOURCE_DIR}/tests/golden/*)
list(REMOVE_ITEM golden check_outputs.cmake)
set(changed "")
set(compared 0)
foreach(name ${golden})
  if(NOT EXISTS ${OUTDIR}/${name})
    list(APPEND changed "${name} (not produced)")
    continue()
  endif()
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E compare_files ${SOURCE_DIR}/tests/golden/${name} ${OUTDIR}/${name}
    RESULT_VARIABLE differs)
  if(differs)
    list(APPEND changed "${name}")
  endif()
  math(EXPR compared "${compared} + 1")
endforeach()
file(GLOB produced RELATIVE ${OUTDIR} ${OUTDIR}/*)
foreach(name ${produced})
  if(NOT name IN_LIST golden)
    list(APPEND changed "${name} (no frozen copy in tests/golden)")
  endif()
endforeach()
if(changed)
  list(JOIN changed "\n  " text)
  message(FATAL_ERROR "outputs changed (diff tests/golden/NAME ${OUTDIR}/NAME):\n  ${text}")
endif()
message(STATUS "${compared} outputs unchanged")
