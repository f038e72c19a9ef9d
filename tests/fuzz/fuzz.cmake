# The fuzz targets. With TAGMAP_FUZZ=ON (scripts/ci-fuzz.sh: clang,
# -fsanitize=fuzzer-no-link,address,undefined everywhere) they are libFuzzer
# binaries; otherwise each is linked with replay_main.cpp into a plain
# program that ctest runs on the seed corpus and on every saved crash, so a
# fixed crash stays fixed in the regular build.
option(TAGMAP_FUZZ "Build the libFuzzer targets (clang only)" OFF)

set(TAGMAP_FUZZ_DIR ${CMAKE_CURRENT_LIST_DIR})

# tagmap_fuzz_target(name LIBS libs... [SOURCES extra...])
function(tagmap_fuzz_target name)
  cmake_parse_arguments(F "" "" "SOURCES;LIBS" ${ARGN})
  if(TAGMAP_FUZZ)
    add_executable(${name} ${TAGMAP_FUZZ_DIR}/${name}.cpp ${F_SOURCES})
    target_link_options(${name} PRIVATE -fsanitize=fuzzer)
  else()
    add_executable(${name}_replay ${TAGMAP_FUZZ_DIR}/${name}.cpp ${F_SOURCES} ${TAGMAP_FUZZ_DIR}/replay_main.cpp)
    set(name ${name}_replay)
    string(REGEX REPLACE "^fuzz_(.*)_replay$" "\\1" short ${name})
    add_test(NAME ${name} COMMAND ${name}
      ${TAGMAP_FUZZ_DIR}/corpus/${short} ${TAGMAP_FUZZ_DIR}/regressions/${short})
    set_tests_properties(${name} PROPERTIES LABELS "reliability;fuzz" TIMEOUT 300)
  endif()
  target_link_libraries(${name} PRIVATE ${F_LIBS})
  tagmap_warnings(${name})
endfunction()

tagmap_fuzz_target(fuzz_pcd LIBS tagmap_io)
tagmap_fuzz_target(fuzz_ply LIBS tagmap_io)
tagmap_fuzz_target(fuzz_las LIBS tagmap_io)
tagmap_fuzz_target(fuzz_lzf LIBS tagmap_io)
tagmap_fuzz_target(fuzz_scene LIBS tagmap_sim)
tagmap_fuzz_target(fuzz_config LIBS tagmap_detect)
