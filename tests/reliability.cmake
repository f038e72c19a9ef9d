# Reliability (GitHub issue "bad input never crashes tagmap or loses a
# user's data"): shell drivers that run the real tagmap binary on malformed
# maps, flags, configs and scenes, kill it mid-run and vary --threads; and
# the fuzz targets (tests/fuzz/fuzz.cmake).
foreach(script bad_maps bad_options bad_scenes bad_localize output_paths determinism kill_midrun)
  add_test(NAME reliability_${script} COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/reliability/${script}.sh)
  set_tests_properties(reliability_${script} PROPERTIES
    ENVIRONMENT "TAGMAP=$<TARGET_FILE:tagmap>" LABELS reliability TIMEOUT 900)
endforeach()

include(${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz.cmake)
