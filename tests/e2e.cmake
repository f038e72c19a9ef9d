tagmap_test(test_scenes SOURCES e2e/test_scenes.cpp LIBS tagmap_detect tagmap_sim tagmap_io tagmap_core)

# tagmap detect --viewpoints (a point cloud with its trajectory) and a
# simplemap's own stations reject a mirror image the points cannot.
add_test(NAME e2e_viewpoints_cli COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/e2e/viewpoints_cli.sh)
set_tests_properties(e2e_viewpoints_cli PROPERTIES ENVIRONMENT "TAGMAP=$<TARGET_FILE:tagmap>" TIMEOUT 300)
