# The docs that describe the code checked against it.
add_test(NAME docs_architecture_deps
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/docs/check_architecture_deps.sh ${PROJECT_SOURCE_DIR})
