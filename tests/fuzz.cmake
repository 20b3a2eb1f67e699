# Fuzz targets (tests/fuzz/): the mesh loaders and the job body. Every build replays the seed corpus through
# them as ordinary tests; with FACETLIGHT_FUZZ=ON and clang, real libFuzzer targets are built too
# (scripts/fuzz builds and runs them; docs/reliability.md has the figures).
option(FACETLIGHT_FUZZ "Build libFuzzer targets for the mesh loaders and the job body (needs clang)" OFF)

set(FACETLIGHT_FUZZ_TARGETS obj stl gemcad gemcad_binary)
if(TARGET facetlight_server)
  list(APPEND FACETLIGHT_FUZZ_TARGETS job request)
endif()
# The service's targets compile the service's own code in (instrumented with the target, not taken from the
# server library).
set(fuzz_job_SOURCES ${CMAKE_SOURCE_DIR}/server/job_spec.cpp)
set(fuzz_request_SOURCES ${CMAKE_SOURCE_DIR}/server/request_guard.cpp ${CMAKE_SOURCE_DIR}/server/bearer_token.cpp)
if(TARGET facetlight_server)
  pkg_check_modules(FUZZ_HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)  # the server's import is not visible here
  set(fuzz_request_LIBRARIES PkgConfig::FUZZ_HTTPLIB)
endif()

function(facetlight_fuzz_sources target kind)
  target_sources(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_${kind}.cpp ${fuzz_${kind}_SOURCES})
  target_include_directories(${target} PRIVATE ${CMAKE_SOURCE_DIR}/server)
  target_link_libraries(${target} PRIVATE facetlight::core facetlight_warnings ${fuzz_${kind}_LIBRARIES})
endfunction()

foreach(kind ${FACETLIGHT_FUZZ_TARGETS})
  add_executable(replay_${kind} ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/replay_main.cpp)
  facetlight_fuzz_sources(replay_${kind} ${kind})
  set_target_properties(replay_${kind} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  add_test(NAME fuzz_replay_${kind} COMMAND replay_${kind} ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/${kind})
  set_tests_properties(fuzz_replay_${kind} PROPERTIES LABELS fuzz)
endforeach()

if(FACETLIGHT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "FACETLIGHT_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(fuzz_flags -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all
                 -fno-omit-frame-pointer -g)
  # Coverage and sanitizers in the library too, or the fuzzer is blind inside the parsers.
  target_compile_options(facetlight_core PRIVATE -fsanitize=fuzzer-no-link ${fuzz_flags})
  # Comparison tracing guides mutations toward values compared with input bytes; the geometry compares
  # indices and computed coordinates, never input bytes, and its hooks took a quarter of fuzz_gemcad's time
  # (perf). Edge coverage and the sanitizers stay.
  set(untraced_sources geometry/halfspace.cpp geometry/self_intersection.cpp stone/stone.cpp stone/triangulation.cpp
    stone/mesh_checks.cpp stone/standard_frame.cpp stone/girdle.cpp stone/proportions.cpp)
  list(TRANSFORM untraced_sources PREPEND ${CMAKE_SOURCE_DIR}/core/)
  set_source_files_properties(${untraced_sources}
    TARGET_DIRECTORY facetlight_core PROPERTIES COMPILE_OPTIONS -fno-sanitize-coverage=trace-cmp)
  target_link_options(facetlight_core INTERFACE ${fuzz_flags})
  foreach(kind ${FACETLIGHT_FUZZ_TARGETS})
    add_executable(fuzz_${kind})
    facetlight_fuzz_sources(fuzz_${kind} ${kind})
    target_compile_options(fuzz_${kind} PRIVATE -fsanitize=fuzzer ${fuzz_flags})
    target_link_options(fuzz_${kind} PRIVATE -fsanitize=fuzzer ${fuzz_flags})
  endforeach()
endif()
