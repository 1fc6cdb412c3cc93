# halfeti_add_test(NAME name SOURCES ... [LIBS ...] [NP 1 2 3 4] [PETSC] [LABELS ...] [TIMEOUT s])
#
# Builds one GoogleTest executable. Without NP it runs once, serially (MPI is initialised as a singleton).
# With NP it is registered once per rank count as name_npN, launched with mpiexec (oversubscribed, root allowed).
# PETSC links a main that calls PetscInitialize instead of MPI_Init. Tests are labelled 'fast' (a few seconds each)
# unless LABELS says otherwise: 'long' (15 s to a few minutes; still in tools/test's default suite), 'validation'
# (runs of minutes against references, excluded from tools/test).
# Time limits scale with the build: AddressSanitizer and UBSan run the end-to-end tests 4-12 times slower (measured
# 3 Dec), so a sanitizer build gives every test HALFETI_TIMEOUT_FACTOR times its limit.
if(HALFETI_ENABLE_SANITIZERS)
  set(HALFETI_TIMEOUT_FACTOR 4)
else()
  set(HALFETI_TIMEOUT_FACTOR 1)
endif()
# halfeti_timeout(VAR seconds): VAR = the limit of a test that takes `seconds` in a Release build.
function(halfeti_timeout var seconds)
  math(EXPR scaled "${seconds} * ${HALFETI_TIMEOUT_FACTOR}")
  set(${var} ${scaled} PARENT_SCOPE)
endfunction()

set(HALFETI_MPI_TEST_ENV
    "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1;OMPI_MCA_btl_vader_single_copy_mechanism=none")

function(halfeti_add_test)
  cmake_parse_arguments(T "PETSC" "NAME;TIMEOUT" "SOURCES;LIBS;NP;LABELS" ${ARGN})
  if(NOT T_LABELS)
    set(T_LABELS fast)
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 300)
  endif()
  halfeti_timeout(T_TIMEOUT ${T_TIMEOUT})
  add_executable(${T_NAME} ${T_SOURCES})
  if(T_PETSC)
    target_link_libraries(${T_NAME} PRIVATE halfeti_gtest_petsc_main)
  else()
    target_link_libraries(${T_NAME} PRIVATE halfeti_gtest_mpi_main)
  endif()
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} halfeti_options)
  target_compile_definitions(${T_NAME} PRIVATE HALFETI_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                               HALFETI_BINARY_DIR="${PROJECT_BINARY_DIR}")
  if(NOT T_NP)
    add_test(NAME ${T_NAME} COMMAND ${T_NAME})
    set_tests_properties(${T_NAME} PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT}
                                              ENVIRONMENT "${HALFETI_MPI_TEST_ENV}")
  else()
    foreach(np IN LISTS T_NP)
      add_test(NAME ${T_NAME}_np${np}
               COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${np} --oversubscribe
                       $<TARGET_FILE:${T_NAME}>)
      set_tests_properties(${T_NAME}_np${np} PROPERTIES LABELS "${T_LABELS};mpi" TIMEOUT ${T_TIMEOUT}
                                                        PROCESSORS 2 ENVIRONMENT "${HALFETI_MPI_TEST_ENV}")
    endforeach()
  endif()
endfunction()
