# A --screenshot run keeps its settings apart from the user's (issue 17): with a fresh
# XDG_CONFIG_HOME, opening a file in a batch run writes nothing under the user's "Plumb" scope
# (recent files, remembered folders) but under "Plumb-batch".
# Inputs: -DPLUMB=<plumb> -DINPUT=<file> -DWORK=<scratch dir>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/config)
set(ENV{XDG_CONFIG_HOME} ${WORK}/config)
execute_process(COMMAND ${PLUMB} --screenshot ${WORK}/shot.png ${INPUT} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "plumb --screenshot failed (${rc}): ${err}")
endif()
if(NOT EXISTS ${WORK}/shot.png)
  message(FATAL_ERROR "no screenshot written")
endif()
if(EXISTS ${WORK}/config/Plumb)
  message(FATAL_ERROR "a batch run wrote the user's settings: ${WORK}/config/Plumb")
endif()
file(GLOB batch ${WORK}/config/Plumb-batch/*)
if(NOT batch)
  message(FATAL_ERROR "the batch run's settings are not under Plumb-batch (recent files not kept there)")
endif()
message(STATUS "batch settings kept apart: ${batch}")
