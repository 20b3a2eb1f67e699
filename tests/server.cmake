# The service's in-process tests (tests/server/*_test.cpp: they link the server library, so they stay out of
# the core test glob) and the end-to-end tests that drive the real binary with curl.
if(TARGET facetlight_server)
  foreach(test api_test bearer_token_test request_guard_test)
    set(name server_${test})
    add_executable(${name} ${CMAKE_CURRENT_SOURCE_DIR}/server/${test}.cpp)
    target_link_libraries(${name} PRIVATE facetlight::server GTest::gtest_main facetlight_warnings)
    target_compile_definitions(${name} PRIVATE FACETLIGHT_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
    set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
    gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS unit)
  endforeach()
  # Sanitized builds trace about ten times slower (8 minutes under ASan on 2 cores).
  if(FACETLIGHT_SANITIZE)
    set(e2e_timeout 1800)
    set(hostile_timeout 1800)
  else()
    set(e2e_timeout 600)
    set(hostile_timeout 300)
  endif()
  find_program(FACETLIGHT_CURL curl)
  if(FACETLIGHT_CURL)
    add_test(NAME server_e2e
      COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/e2e/server_e2e.sh $<TARGET_FILE:facetlight-server>)
    set_tests_properties(server_e2e PROPERTIES LABELS e2e TIMEOUT ${e2e_timeout})
    # Issue 31: the reverse proxy docs/tls.md supports, its example configuration run as it is.
    find_program(FACETLIGHT_NGINX nginx PATHS /usr/sbin)
    find_program(FACETLIGHT_OPENSSL openssl)
    if(FACETLIGHT_NGINX AND FACETLIGHT_OPENSSL)
      add_test(NAME server_tls_proxy
        COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/e2e/tls_proxy.sh $<TARGET_FILE:facetlight-server> ${FACETLIGHT_NGINX})
      set_tests_properties(server_tls_proxy PROPERTIES LABELS e2e TIMEOUT 120)
    endif()
  endif()
  # Issue 18: hostile requests, short bodies, slow clients and a forged log line against the real server.
  find_program(FACETLIGHT_PYTHON3 python3)
  if(FACETLIGHT_PYTHON3)
    add_test(NAME server_hostile_requests
      COMMAND ${FACETLIGHT_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/server/hostile_requests.py
              $<TARGET_FILE:facetlight-server>)
    set_tests_properties(server_hostile_requests PROPERTIES LABELS e2e TIMEOUT ${hostile_timeout})
  endif()
endif()
