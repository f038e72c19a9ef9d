# Localization (docs/LOCALIZATION.md): unit tests, single-scan relocalization
# at 4 m, and the reduced end-to-end demo (scripts/localize-demo.sh --quick)
# asserting the particle filter (tag poses) converges within 10 steps and tracks
# within 1 cm and 0.3 degrees.
tagmap_test(test_localize
  SOURCES unit/test_localize.cpp unit/test_localize_odometry.cpp unit/test_localize_single_scan.cpp
          unit/test_localize_window.cpp
  LIBS tagmap_localize tagmap_sim tagmap_maps)

add_test(NAME localize_e2e
  COMMAND bash ${PROJECT_SOURCE_DIR}/scripts/localize-demo.sh --quick --check
          --tagmap $<TARGET_FILE:tagmap> --out ${PROJECT_BINARY_DIR}/test-artifacts/localize)
set_tests_properties(localize_e2e PROPERTIES TIMEOUT 300)

# Stock MRPT pf-localization on the same outputs, the plugin preloaded so the
# ini's tagMap scores the tag poses (docs/MRPT.md, "pf-localization with the
# tag poses"): converged by step 5, then <= 1.5 cm / 0.1 deg RMSE.
set_tests_properties(localize_e2e PROPERTIES FIXTURES_SETUP localize_outputs)
add_test(NAME mrpt_pf_localization_tags
  COMMAND bash ${PROJECT_SOURCE_DIR}/tests/mrpt/pf_localization_tags.sh ${PROJECT_BINARY_DIR}/test-artifacts/localize
          $<TARGET_FILE:tagmap_mrpt_plugin>)
set_tests_properties(mrpt_pf_localization_tags PROPERTIES FIXTURES_REQUIRED localize_outputs TIMEOUT 300)
