# Instruction-set variants.
#
# A kernel source is compiled once per ISA, with that ISA's flags and with RTK_ISA set to the
# ISA's name; the source wraps everything in `namespace rtk::RTK_ISA`, so the four copies of an
# inline template never meet in the linker. The choice between them is made at run time
# (chapters/01_base/cpu_features.h). Nothing else in the project gets ISA flags: the default
# build runs on any x86-64 CPU with SSE4.2.
set(RTK_ISAS scalar sse4 avx2 avx512)
set(RTK_FLAGS_scalar "")
set(RTK_FLAGS_sse4 -msse4.2 -mpopcnt)
set(RTK_FLAGS_avx2 -mavx2 -mfma -mbmi -mbmi2 -mlzcnt -mpopcnt -mf16c)
set(RTK_FLAGS_avx512 ${RTK_FLAGS_avx2} -mavx512f -mavx512cd -mavx512bw -mavx512dq -mavx512vl
    -mprefer-vector-width=512)

# rtk_isa_kernels(<target> SOURCES <files...> [WIDTHS <n...>] [LINK <libs...>])
# Adds a static library <target> that holds each source compiled once per ISA. With WIDTHS, each
# source is compiled once per ISA and per width, with RTK_WIDTH set to the width: one kernel
# source serves every node width, and the widths compile in parallel.
function(rtk_isa_kernels target)
  cmake_parse_arguments(ARG "" "" "SOURCES;WIDTHS;LINK" ${ARGN})
  add_library(${target} STATIC)
  target_link_libraries(${target} PUBLIC rtk_defaults ${ARG_LINK})
  set(widths ${ARG_WIDTHS})
  if(NOT widths)
    set(widths "")
  endif()
  foreach(isa IN LISTS RTK_ISAS)
    foreach(width IN LISTS widths ITEMS none)
      if(width STREQUAL "none")
        if(widths)
          continue()
        endif()
        set(object ${target}_${isa})
      else()
        set(object ${target}_${isa}_w${width})
      endif()
      add_library(${object} OBJECT ${ARG_SOURCES})
      target_compile_options(${object} PRIVATE ${RTK_FLAGS_${isa}})
      target_compile_definitions(${object} PRIVATE RTK_ISA=${isa})
      if(NOT width STREQUAL "none")
        target_compile_definitions(${object} PRIVATE RTK_WIDTH=${width})
      endif()
      target_link_libraries(${object} PRIVATE rtk_defaults ${ARG_LINK})
      target_sources(${target} PRIVATE $<TARGET_OBJECTS:${object}>)
    endforeach()
  endforeach()
endfunction()
