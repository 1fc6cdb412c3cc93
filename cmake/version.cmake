# Writes include/halfeti/core/version.hpp with the commit the sources are at: run at every build (src/core), so
# that summary.json's provenance names the commit a binary was built from, not the one its build was configured
# from. configure_file leaves the header untouched when nothing changed, so nothing recompiles then.
#   cmake -DSOURCE_DIR=... -DOUTPUT=.../version.hpp -DPROJECT_VERSION=... -P cmake/version.cmake
execute_process(COMMAND git describe --always --dirty --abbrev=12 WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE HALFETI_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _git)
if(NOT _git EQUAL 0 OR HALFETI_GIT_COMMIT STREQUAL "")
  set(HALFETI_GIT_COMMIT "unknown")
endif()
configure_file(${SOURCE_DIR}/cmake/version.hpp.in ${OUTPUT} @ONLY)
