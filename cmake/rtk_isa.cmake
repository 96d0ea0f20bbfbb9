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

# rtk_isa_kernels(<target> SOURCES <files...> [LINK <libs...>])
# Adds a static library <target> that holds each source compiled once per ISA.
function(rtk_isa_kernels target)
  cmake_parse_arguments(ARG "" "" "SOURCES;LINK" ${ARGN})
  add_library(${target} STATIC)
  target_link_libraries(${target} PUBLIC rtk_defaults ${ARG_LINK})
  foreach(isa IN LISTS RTK_ISAS)
    add_library(${target}_${isa} OBJECT ${ARG_SOURCES})
    target_compile_options(${target}_${isa} PRIVATE ${RTK_FLAGS_${isa}})
    target_compile_definitions(${target}_${isa} PRIVATE RTK_ISA=${isa})
    target_link_libraries(${target}_${isa} PRIVATE rtk_defaults ${ARG_LINK})
    target_sources(${target} PRIVATE $<TARGET_OBJECTS:${target}_${isa}>)
  endforeach()
endfunction()
