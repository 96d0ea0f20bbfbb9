# Helpers that give every chapter the same shape: a library, its tests (ctest -R chNN), its
# benchmarks. A chapter's CMakeLists.txt reads as a short list of what it contains.

# rtk_chapter_tests(<chapter> SOURCES <test_*.cpp...> LINK <libs...>)
# One doctest executable per chapter, registered with CTest under the chapter's name, so that
# `ctest -R ch03` runs chapter 3 alone.
function(rtk_chapter_tests chapter)
  if(NOT RTK_BUILD_TESTS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "SOURCES;LINK" ${ARGN})
  add_executable(${chapter}_tests ${ARG_SOURCES})
  target_link_libraries(${chapter}_tests PRIVATE rtk_test_main rtk_defaults ${ARG_LINK})
  add_test(NAME ${chapter} COMMAND ${chapter}_tests)
  set_tests_properties(${chapter} PROPERTIES LABELS ${chapter} TIMEOUT 600)
endfunction()

# rtk_chapter_bench(<chapter> SOURCES <bench_*.cpp...> LINK <libs...>)
function(rtk_chapter_bench chapter)
  if(NOT RTK_BUILD_BENCH)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "SOURCES;LINK" ${ARGN})
  add_executable(${chapter}_bench ${ARG_SOURCES})
  target_link_libraries(${chapter}_bench PRIVATE rtk_bench_main rtk_defaults ${ARG_LINK})
endfunction()
