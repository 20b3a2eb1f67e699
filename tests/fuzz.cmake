# Loader fuzz targets (tests/fuzz/). Every build replays the seed corpus through them as ordinary tests;
# with FACETLIGHT_FUZZ=ON and clang, real libFuzzer targets are built too (docs/reliability.md).
option(FACETLIGHT_FUZZ "Build libFuzzer targets for the mesh loaders (needs clang)" OFF)

foreach(format obj stl gemcad)
  add_executable(replay_${format} ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/replay_main.cpp
                                  ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_${format}.cpp)
  target_link_libraries(replay_${format} PRIVATE facetlight::core facetlight_warnings)
  set_target_properties(replay_${format} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  add_test(NAME fuzz_replay_${format}
           COMMAND replay_${format} ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/${format})
  set_tests_properties(fuzz_replay_${format} PROPERTIES LABELS fuzz)
endforeach()

if(FACETLIGHT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "FACETLIGHT_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(fuzz_flags -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g)
  # Coverage and sanitizers in the library too, or the fuzzer is blind inside the parsers.
  target_compile_options(facetlight_core PRIVATE -fsanitize=fuzzer-no-link ${fuzz_flags})
  target_link_options(facetlight_core INTERFACE ${fuzz_flags})
  foreach(format obj stl gemcad)
    add_executable(fuzz_${format} ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_${format}.cpp)
    target_compile_options(fuzz_${format} PRIVATE -fsanitize=fuzzer ${fuzz_flags})
    target_link_options(fuzz_${format} PRIVATE -fsanitize=fuzzer ${fuzz_flags})
    target_link_libraries(fuzz_${format} PRIVATE facetlight::core facetlight_warnings)
  endforeach()
endif()
