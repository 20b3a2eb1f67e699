# Browser tests of the web page (issue 7): Debian's headless Chromium driven by playwright-core (npm, locked in
# tests/browser/package-lock.json; scripts/test runs `npm ci` there) against the real facetlight-server.
# Screenshots of each step land in build/screenshots/.
find_program(FACETLIGHT_NODE node)
set(FACETLIGHT_BROWSER_DIR ${CMAKE_CURRENT_SOURCE_DIR}/browser)
if(FACETLIGHT_NODE AND EXISTS /usr/bin/chromium AND EXISTS ${FACETLIGHT_BROWSER_DIR}/node_modules/playwright-core
   AND TARGET facetlight-server)
  add_test(NAME browser_web COMMAND ${FACETLIGHT_NODE} --test ${FACETLIGHT_BROWSER_DIR}/web.test.mjs)
  set_tests_properties(browser_web PROPERTIES
    LABELS browser
    TIMEOUT 900
    RUN_SERIAL TRUE
    ENVIRONMENT "FACETLIGHT_SERVER=$<TARGET_FILE:facetlight-server>;FACETLIGHT_SOURCE_DIR=${CMAKE_SOURCE_DIR};FACETLIGHT_SCREENSHOT_DIR=${CMAKE_BINARY_DIR}/screenshots")
else()
  message(STATUS "facetlight: browser tests off (they need node, /usr/bin/chromium, the facetlight-server target "
                 "and tests/browser/node_modules from `npm ci`)")
endif()
