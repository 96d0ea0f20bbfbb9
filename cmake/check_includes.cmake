# The include rule, run as a test (ctest -R layers): cmake -DROOT=<source dir> -P check_includes.cmake
#
# Every source is in one unit: a chapter (chapters/NN_*), a part of lib/, apps, bench, tests or
# examples. Each unit has a height, and an #include "..." may only name a unit below its own
# (or its own): chapter 1; then the parts of lib/ beneath the chapters (each above the ones
# before it in the list below); chapters 2 to 16 in reading order; the parts of lib/ that
# assemble chapters; apps; and on top bench, tests and examples, which do not include one
# another. With one height per unit and includes going down only, no two units can include
# each other, even through a third. Every violation is printed; the test fails if there is one.
set(lower_libs io image replay testing)
set(upper_libs embree render_kernels scene)

# height(<out> <unit>): the unit's height; "" for something that is no unit.
function(height out unit)
  list(LENGTH lower_libs n_lower)
  list(FIND lower_libs "${unit}" lower)
  list(FIND upper_libs "${unit}" upper)
  if(unit MATCHES "^([0-9][0-9])$")
    math(EXPR h "${CMAKE_MATCH_1}")
    if(h GREATER 1)
      math(EXPR h "${h} + ${n_lower}")
    endif()
  elseif(lower GREATER -1)
    math(EXPR h "2 + ${lower}")
  elseif(upper GREATER -1)
    math(EXPR h "100 + ${upper}")
  elseif(unit STREQUAL "apps")
    set(h 200)
  elseif(unit MATCHES "^(bench|tests|examples)$")
    set(h 300)
  else()
    set(h "")
  endif()
  set(${out} "${h}" PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE sources RELATIVE ${ROOT}
     ${ROOT}/chapters/*.h ${ROOT}/chapters/*.cpp ${ROOT}/lib/*.h ${ROOT}/lib/*.cpp
     ${ROOT}/apps/*.h ${ROOT}/apps/*.cpp ${ROOT}/bench/*.h ${ROOT}/bench/*.cpp
     ${ROOT}/tests/*.h ${ROOT}/tests/*.cpp ${ROOT}/examples/*.h ${ROOT}/examples/*.cpp)
set(violations 0)
foreach(source IN LISTS sources)
  if(source MATCHES "^chapters/([0-9][0-9])_")
    set(unit ${CMAKE_MATCH_1})
  elseif(source MATCHES "^lib/([a-z_]+)/")
    set(unit ${CMAKE_MATCH_1})
  elseif(source MATCHES "^([a-z]+)/")
    set(unit ${CMAKE_MATCH_1})
  endif()
  height(own ${unit})
  file(STRINGS ${ROOT}/${source} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" target "${line}")
    if(target MATCHES "^([0-9][0-9])_[a-z0-9_]+/")
      set(other ${CMAKE_MATCH_1})
    elseif(target MATCHES "^([a-z_]+)/" AND EXISTS ${ROOT}/lib/${CMAKE_MATCH_1})
      set(other ${CMAKE_MATCH_1})
    else()
      continue()  # a file of the same folder
    endif()
    if(other STREQUAL unit)
      continue()
    endif()
    height(theirs ${other})
    if(theirs STREQUAL "" OR NOT theirs LESS own)
      message("${source}: includes \"${target}\" (${other}), which is not below ${unit}")
      math(EXPR violations "${violations} + 1")
    endif()
  endforeach()
endforeach()
if(violations GREATER 0)
  message(FATAL_ERROR "${violations} includes break the layer rule (book/conventions.md)")
endif()
list(LENGTH sources n)
message("layers: ${n} sources, every include points down")
