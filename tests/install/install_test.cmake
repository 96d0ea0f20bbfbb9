# The installed package cannot rot: install rtk::kernels into a fresh prefix, build the example
# application (examples/kernels) against that prefix alone, run it with the best ISA and with
# the scalar one, and check every answer it prints against the one worked out by hand.
#
# cmake -DRTK_BUILD_DIR=... -DRTK_SOURCE_DIR=... -DWORK_DIR=... -DCXX=... -DGENERATOR=...
#       [-DBUILD_TYPE=...] [-DTBB_DIR=...] [-DNM=...] -P install_test.cmake

foreach(var RTK_BUILD_DIR RTK_SOURCE_DIR WORK_DIR CXX GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_test.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()

# run(<what> <command...>): runs a command and stops the test, with its output, if it fails.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

# Step 1: install into a fresh prefix, the kernels' component only.
set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
run("cmake --install" ${CMAKE_COMMAND} --install ${RTK_BUILD_DIR} --prefix ${prefix}
    --component rtk_kernels --config ${BUILD_TYPE})
if(NOT EXISTS ${prefix}/include/rtk/10_kernel_api/accel.h)
  message(FATAL_ERROR "the install has no include/rtk/10_kernel_api/accel.h")
endif()

# Step 2: a shared library must export the API and nothing of the per-ISA kernels.
file(GLOB shared ${prefix}/lib*/librtk_kernels.so)
if(shared AND NM)
  run("nm" ${NM} -D -C --defined-only ${shared})
  if(NOT run_output MATCHES "rtk::Accel::intersect")
    message(FATAL_ERROR "${shared} does not export rtk::Accel::intersect")
  endif()
  if(run_output MATCHES "rtk::(scalar|sse4|avx2|avx512)::")
    message(FATAL_ERROR "${shared} exports per-ISA kernel symbols:\n${run_output}")
  endif()
endif()

# Step 3: build the example as an outside project would: from its own folder, told only where
# the prefix is. Warnings are errors, so the installed headers stay clean for consumers.
set(configure_args -S ${RTK_SOURCE_DIR}/examples/kernels -B ${WORK_DIR}/build -G ${GENERATOR}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE} -DCMAKE_CXX_COMPILER=${CXX}
    "-DCMAKE_CXX_FLAGS=-Wall -Wextra -Werror")
if(TBB_DIR)
  list(APPEND configure_args -DTBB_DIR=${TBB_DIR})
endif()
run("configuring examples/kernels" ${CMAKE_COMMAND} ${configure_args})
run("building examples/kernels" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)

# Step 4: run it and compare with the answers worked out by hand (see its main.cpp).
set(expected
  "ray 0: triangle 0 at t=3.000 u=0.500 v=0.250"
  "ray 1: triangle 2 at t=2.000 u=0.250 v=0.250"
  "ray 2: triangle 1 at t=3.000 u=0.250 v=0.500"
  "ray 3: miss"
  "ray 4: miss"
  "shadow 0: blocked"
  "shadow 1: free"
  "motion structure: yes"
  "motion 0: triangle 2 at t=2.000"
  "motion 1: triangle 0 at t=3.000"
  "motion 2: triangle 2 at t=2.000"
  "refused: -accel: 'octree' is not available"
  "wrapped 0: triangle 3 at (1.500, 1.750, 1.000)"
  "wrapped 1: nothing within 2.000")
foreach(isa "" scalar)
  run("rtk_kernels_example ${isa}" ${WORK_DIR}/build/rtk_kernels_example ${isa})
  message(STATUS "rtk_kernels_example ${isa}:\n${run_output}")
  string(REGEX REPLACE "\n$" "" text "${run_output}")
  string(REPLACE ";" "," text "${text}")  # a semicolon would split a CMake list
  string(REPLACE "\n" ";" lines "${text}")
  list(POP_FRONT lines built)  # "built <accel> with <tri> leaves for <isa>": depends on the CPU
  if(NOT built MATCHES "^built .* leaves for ${isa}")
    message(FATAL_ERROR "unexpected first line: '${built}'")
  endif()
  list(LENGTH lines count)
  list(LENGTH expected expected_count)
  if(NOT count EQUAL expected_count)
    message(FATAL_ERROR "expected ${expected_count} lines after the first, got ${count}")
  endif()
  foreach(i RANGE 0 ${count})
    if(i EQUAL count)
      break()
    endif()
    list(GET lines ${i} line)
    list(GET expected ${i} want)
    string(FIND "${line}" "${want}" at)
    if(NOT at EQUAL 0)
      message(FATAL_ERROR "line ${i}: expected '${want}', got '${line}'")
    endif()
  endforeach()
endforeach()

# Step 5: the render component (rtk::render, chapter 15's device API) into the same prefix,
# and examples/device built against it as an outside project; it renders a small scene made
# through handles and exits 0 only if its images are not black.
run("cmake --install (rtk_render)" ${CMAKE_COMMAND} --install ${RTK_BUILD_DIR} --prefix ${prefix}
    --component rtk_render --config ${BUILD_TYPE})
if(NOT EXISTS ${prefix}/include/rtk/15_device/device.h)
  message(FATAL_ERROR "the install has no include/rtk/15_device/device.h")
endif()
set(configure_args -S ${RTK_SOURCE_DIR}/examples/device -B ${WORK_DIR}/build_device -G ${GENERATOR}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE} -DCMAKE_CXX_COMPILER=${CXX}
    "-DCMAKE_CXX_FLAGS=-Wall -Wextra -Werror")
if(TBB_DIR)
  list(APPEND configure_args -DTBB_DIR=${TBB_DIR})
endif()
run("configuring examples/device" ${CMAKE_COMMAND} ${configure_args})
run("building examples/device" ${CMAKE_COMMAND} --build ${WORK_DIR}/build_device)
run("rtk_device_example" ${WORK_DIR}/build_device/rtk_device_example ${WORK_DIR}/device.png)
message(STATUS "rtk_device_example: ${run_output}")
if(NOT EXISTS ${WORK_DIR}/device.png)
  message(FATAL_ERROR "rtk_device_example wrote no image")
endif()
