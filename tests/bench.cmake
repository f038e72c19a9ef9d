# Benchmarks print tables; they are programs, not timed tests.
add_executable(tagmap-bench-accuracy bench/bench_accuracy.cpp)
target_link_libraries(tagmap-bench-accuracy PRIVATE tagmap_detect tagmap_sim tagmap_core)
target_compile_definitions(tagmap-bench-accuracy PRIVATE TAGMAP_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
tagmap_warnings(tagmap-bench-accuracy)
