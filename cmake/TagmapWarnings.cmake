# tagmap_warnings(target): the warning set every tagmap target builds with.
function(tagmap_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow=local -Wno-unused-parameter)
endfunction()
