# Distributed runs on MPI (docs/distributed.md): on by default when OpenMPI is found. Only the facetlight
# CLI links MPI; core and the service see the Communicator interface alone.
find_package(MPI COMPONENTS CXX QUIET)
option(FACETLIGHT_MPI "Build distributed runs on MPI into the facetlight tool" ${MPI_CXX_FOUND})
if(FACETLIGHT_MPI)
  if(NOT MPI_CXX_FOUND)
    message(FATAL_ERROR "FACETLIGHT_MPI is ON but no MPI was found: install libopenmpi-dev openmpi-bin")
  endif()
  target_sources(facetlight PRIVATE ${CMAKE_SOURCE_DIR}/cli/mpi_communicator.cpp)
  set_source_files_properties(${CMAKE_SOURCE_DIR}/cli/mpi_communicator.cpp PROPERTIES
    COMPILE_DEFINITIONS OMPI_SKIP_MPICXX=1)
  target_link_libraries(facetlight PRIVATE MPI::MPI_CXX)
  message(STATUS "facetlight: MPI distributed runs on (${MPIEXEC_EXECUTABLE})")
else()
  target_sources(facetlight PRIVATE ${CMAKE_SOURCE_DIR}/cli/serial_communicator.cpp)
  message(STATUS "facetlight: MPI distributed runs off")
endif()
