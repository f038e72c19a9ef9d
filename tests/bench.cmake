# Benchmarks print tables; they are programs, not timed tests.
add_executable(tagmap-bench-accuracy bench/bench_accuracy.cpp)
target_link_libraries(tagmap-bench-accuracy PRIVATE tagmap_detect tagmap_sim tagmap_core)
target_compile_definitions(tagmap-bench-accuracy PRIVATE TAGMAP_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
tagmap_warnings(tagmap-bench-accuracy)

# Scale benchmark: binary PCD -> detect -> JSON at 1, 5, 20 million points
# (docs/PERFORMANCE.md). ctest runs it at 300k points only: it must run and print.
add_executable(tagmap-bench-large bench/bench_large.cpp)
target_link_libraries(tagmap-bench-large PRIVATE tagmap_detect tagmap_sim tagmap_io tagmap_core)
target_compile_definitions(tagmap-bench-large PRIVATE TAGMAP_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
tagmap_warnings(tagmap-bench-large)
add_test(NAME bench_large_smoke
         COMMAND tagmap-bench-large --sizes 300000 --cache ${PROJECT_BINARY_DIR}/bench-maps)
set_tests_properties(bench_large_smoke PROPERTIES TIMEOUT 300
                     PASS_REGULAR_EXPRESSION "total \\(file->JSON\\).*peak RSS.*tags found")
