# tagmap_report: progress printer, HTML report, configuration file; and the
# report opened in a real browser (headless Chromium), checking it renders.
tagmap_test(test_report
  SOURCES unit/test_report.cpp unit/test_progress.cpp unit/test_config.cpp
  LIBS tagmap_report tagmap_detect opencv_imgcodecs)

add_executable(tagmap_report_fixture report/make_fixture_map.cpp)
target_link_libraries(tagmap_report_fixture PRIVATE tagmap_io tagmap_core)
tagmap_warnings(tagmap_report_fixture)

# The screenshot is kept for people to look at: build/test-artifacts/report/.
add_test(NAME report_chromium
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/report/chromium_report.sh
          $<TARGET_FILE:tagmap> $<TARGET_FILE:tagmap_report_fixture> ${PROJECT_SOURCE_DIR}
          ${PROJECT_BINARY_DIR}/test-artifacts/report)
set_tests_properties(report_chromium PROPERTIES TIMEOUT 300)
