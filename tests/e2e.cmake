tagmap_test(test_scenes SOURCES e2e/test_scenes.cpp LIBS tagmap_detect tagmap_sim tagmap_io tagmap_core)
