# Simulator tests: sensor patterns, physics, drift, scene files, and the
# ground-truth decode test that keeps the vertex convention honest.
tagmap_test(test_sim_patterns SOURCES unit/test_sim_patterns.cpp LIBS tagmap_sim)
tagmap_test(test_sim_physics SOURCES unit/test_sim_physics.cpp LIBS tagmap_sim)
tagmap_test(test_sim_drift SOURCES unit/test_sim_drift.cpp LIBS tagmap_sim)
tagmap_test(test_sim_scene SOURCES unit/test_sim_scene.cpp LIBS tagmap_sim)
tagmap_test(test_sim_truth_decode SOURCES unit/test_sim_truth_decode.cpp LIBS tagmap_sim tagmap_detect opencv_imgproc opencv_imgcodecs)
tagmap_test(test_sim_outputs SOURCES unit/test_sim_outputs.cpp LIBS tagmap_sim tagmap_io)
tagmap_test(test_sim_distractors SOURCES unit/test_sim_distractors.cpp LIBS tagmap_sim tagmap_detect)
