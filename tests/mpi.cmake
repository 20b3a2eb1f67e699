# Distributed runs (docs/distributed.md): mpirun results equal single-process ones, and the service's launcher
# runs, follows and cancels jobs through mpirun. Registered only in builds with FACETLIGHT_MPI.
if(NOT FACETLIGHT_MPI)
  return()
endif()

# mpirun refuses root (containers, CI) without these.
set(FACETLIGHT_MPI_TEST_ENV OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1)

foreach(ranks 2 3)
  add_test(NAME mpi_trace_${ranks}_ranks
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/mpi/compare_trace.sh $<TARGET_FILE:facetlight> ${MPIEXEC_EXECUTABLE}
      ${ranks} ${CMAKE_CURRENT_SOURCE_DIR}/data/brilliant.asc)
  set_tests_properties(mpi_trace_${ranks}_ranks PROPERTIES
    ENVIRONMENT "${FACETLIGHT_MPI_TEST_ENV}" LABELS mpi TIMEOUT 300)
  add_test(NAME mpi_render_${ranks}_ranks
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/mpi/compare_render.sh $<TARGET_FILE:facetlight> ${MPIEXEC_EXECUTABLE}
      ${ranks} ${CMAKE_CURRENT_SOURCE_DIR}/data/brilliant.asc)
  set_tests_properties(mpi_render_${ranks}_ranks PROPERTIES
    ENVIRONMENT "${FACETLIGHT_MPI_TEST_ENV}" LABELS mpi TIMEOUT 300)
  add_test(NAME mpi_study_trace_${ranks}_ranks
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/mpi/compare_study.sh $<TARGET_FILE:facetlight> ${MPIEXEC_EXECUTABLE}
      ${ranks} ${CMAKE_CURRENT_SOURCE_DIR}/mpi/trace_job.json
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(mpi_study_trace_${ranks}_ranks PROPERTIES
    ENVIRONMENT "${FACETLIGHT_MPI_TEST_ENV}" LABELS mpi TIMEOUT 300)
endforeach()

# A sweep with a search, its points spread over 2 ranks, equals the single-process one.
add_test(NAME mpi_sweep_2_ranks
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/mpi/compare_sweep.sh $<TARGET_FILE:facetlight> ${MPIEXEC_EXECUTABLE} 2
    ${CMAKE_CURRENT_SOURCE_DIR}/mpi/sweep_job.json)
set_tests_properties(mpi_sweep_2_ranks PROPERTIES ENVIRONMENT "${FACETLIGHT_MPI_TEST_ENV}" LABELS mpi TIMEOUT 300)

add_executable(launcher_test ${CMAKE_CURRENT_SOURCE_DIR}/mpi/launcher_test.cpp)
target_link_libraries(launcher_test PRIVATE facetlight::server GTest::gtest_main facetlight_warnings)
target_compile_definitions(launcher_test PRIVATE
  FACETLIGHT_SOURCE_DIR="${CMAKE_SOURCE_DIR}" FACETLIGHT_TOOL="$<TARGET_FILE:facetlight>"
  FACETLIGHT_MPIEXEC="${MPIEXEC_EXECUTABLE}")
set_target_properties(launcher_test PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
add_dependencies(launcher_test facetlight)
gtest_discover_tests(launcher_test DISCOVERY_TIMEOUT 60
  PROPERTIES LABELS mpi TIMEOUT 300)

# The service hands jobs to mpirun: one runs to completion with its progress followed, another is cancelled.
add_test(NAME mpi_service_launcher
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/mpi/service_launcher.sh $<TARGET_FILE:facetlight-server> ${MPIEXEC_EXECUTABLE}
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(mpi_service_launcher PROPERTIES
  ENVIRONMENT "${FACETLIGHT_MPI_TEST_ENV}" LABELS mpi TIMEOUT 300)
