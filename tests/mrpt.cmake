# MRPT integration (docs/MRPT.md): unit tests, and MRPT's own tools run on our
# outputs (tests/mrpt/*.sh). GUI tools run under xvfb-run, so CI needs no display.
tagmap_test(test_mrpt
  SOURCES unit/test_mrpt_beacon_id.cpp unit/test_mrpt_landmarks.cpp unit/test_mrpt_tagmap.cpp
          unit/test_mrpt_ini.cpp unit/test_mrpt_likelihood.cpp unit/test_mrpt_rawlog.cpp unit/test_mrpt_scene.cpp
          mrpt/synthetic_tags.cpp
  LIBS tagmap_mrpt tagmap_maps tagmap_io)
target_compile_definitions(test_mrpt PRIVATE TAGMAP_PLUGIN_PATH="$<TARGET_FILE:tagmap_mrpt_plugin>")

add_executable(tagmap_mrpt_fixture mrpt/make_fixture.cpp mrpt/synthetic_tags.cpp
  ${PROJECT_SOURCE_DIR}/apps/tagmap/detect_outputs.cpp ${PROJECT_SOURCE_DIR}/apps/tagmap/cli.cpp)
target_link_libraries(tagmap_mrpt_fixture PRIVATE tagmap_mrpt tagmap_maps tagmap_detect tagmap_localize)
tagmap_warnings(tagmap_mrpt_fixture)

set(TAGMAP_MRPT_ARTIFACTS ${PROJECT_BINARY_DIR}/test-artifacts/mrpt)
add_test(NAME mrpt_fixture COMMAND tagmap_mrpt_fixture ${TAGMAP_MRPT_ARTIFACTS})
set_tests_properties(mrpt_fixture PROPERTIES FIXTURES_SETUP mrpt_outputs)

foreach(check rawlog_edit_info rawlogviewer rawlogviewer_stock scene_viewer pf_localization)
  add_test(NAME mrpt_${check}
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/mrpt/${check}.sh ${TAGMAP_MRPT_ARTIFACTS} $<TARGET_FILE:tagmap_mrpt_plugin>)
  set_tests_properties(mrpt_${check} PROPERTIES FIXTURES_REQUIRED mrpt_outputs TIMEOUT 180)
endforeach()
# One virtual display at a time: `xvfb-run -a` picks a free display number by
# looking for lock files, so two GUI checks starting together can both pick
# the same one and one of them fails (the likely cause of one unexplained
# mrpt_rawlogviewer failure in a -j2 ctest run; it did not reproduce).
set_tests_properties(mrpt_rawlogviewer mrpt_rawlogviewer_stock mrpt_scene_viewer PROPERTIES RESOURCE_LOCK xvfb)

# The same tools on the simulator's parking scene (.simplemap in, every MRPT
# output of `tagmap detect`), in build/test-artifacts/mrpt/parking/.
add_test(NAME mrpt_parking
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/mrpt/parking.sh ${TAGMAP_MRPT_ARTIFACTS}/parking
          $<TARGET_FILE:tagmap_mrpt_plugin> $<TARGET_FILE:tagmap> $<TARGET_FILE:tagmap_mrpt_fixture>
          ${PROJECT_SOURCE_DIR}/share/scenes/parking.yaml)
set_tests_properties(mrpt_parking PROPERTIES TIMEOUT 300 RESOURCE_LOCK xvfb)
