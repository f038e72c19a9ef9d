# `cmake --install` into a temporary prefix, then a program outside the tree
# built against it with find_package(tagmap) runs a detection
# (tests/install/install_and_use.sh).
add_test(NAME install_find_package
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/install/install_and_use.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR}
          ${PROJECT_BINARY_DIR}/test-artifacts/install)
set_tests_properties(install_find_package PROPERTIES TIMEOUT 600)
