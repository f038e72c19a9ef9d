# Benchmarks print tables; they are programs, not timed tests.
add_executable(tagmap-bench-accuracy bench/bench_accuracy.cpp)
target_link_libraries(tagmap-bench-accuracy PRIVATE tagmap_detect tagmap_sim tagmap_core)
target_compile_definitions(tagmap-bench-accuracy PRIVATE TAGMAP_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
tagmap_warnings(tagmap-bench-accuracy)

# Scale benchmark: binary PCD -> detect -> JSON at 1, 5, 20 million points
# (docs/PERFORMANCE.md). ctest runs it at 300k points only: it must run and print.
add_executable(tagmap-bench-large bench/bench_large.cpp)
target_link_libraries(tagmap-bench-large PRIVATE tagmap_detect tagmap_localize tagmap_sim tagmap_io tagmap_core)
target_compile_definitions(tagmap-bench-large PRIVATE TAGMAP_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
tagmap_warnings(tagmap-bench-large)
add_test(NAME bench_large_smoke
         COMMAND tagmap-bench-large --sizes 300000 --cache ${PROJECT_BINARY_DIR}/bench-maps)
set_tests_properties(bench_large_smoke PROPERTIES TIMEOUT 300
                     PASS_REGULAR_EXPRESSION "total \\(file->JSON\\).*peak RSS.*tags found")

# Single-scan rate (issue: observe at sensor rate): tagmap observe's path on
# spinning and Livox-like robot runs, one thread; prints ms per scan and per
# stage and the sightings against the truth. ctest runs 20 scans of each:
# it must run and print.
add_executable(tagmap-bench-observe bench/bench_observe.cpp)
target_link_libraries(tagmap-bench-observe PRIVATE tagmap_localize tagmap_detect tagmap_sim tagmap_core)
target_compile_definitions(tagmap-bench-observe PRIVATE TAGMAP_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
tagmap_warnings(tagmap-bench-observe)
add_test(NAME bench_observe_smoke COMMAND tagmap-bench-observe --scans 20)
set_tests_properties(bench_observe_smoke PROPERTIES TIMEOUT 300
                     PASS_REGULAR_EXPRESSION "livox.*detect ms per scan: median.*sightings")
