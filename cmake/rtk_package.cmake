# The kernels as an installable package: `cmake --install` puts the public API's headers, one
# library (rtk::kernels) and a CMake package config under a prefix, so that another project
# does `find_package(rtk)` and links `rtk::kernels`, without the renderer, GLFW, Google
# Benchmark or the book's tools.
#
# The library is not listed by hand: rtk_add_kernels_package() follows what the public API
# (ch10_kernel_api) links, chapter by chapter, and collects every object file on the way, the per-ISA
# ones included. A chapter that joins the API later joins the package by being linked.

include(CMakePackageConfigHelpers)
include(GNUInstallDirs)

# rtk_kernels_closure(<out_targets> <out_external> <target>)
# The RTK libraries <target> depends on, itself included, in the order they were met, and what
# they link from outside RTK (imported targets such as TBB::tbb, plain library names).
function(rtk_kernels_closure out_targets out_external root)
  set(todo ${root})
  set(seen "")
  set(external "")
  while(todo)
    list(POP_FRONT todo item)
    # A static library's private dependencies appear as $<LINK_ONLY:name>.
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
    if(item IN_LIST seen OR item IN_LIST external)
      continue()
    endif()
    if(NOT TARGET ${item})
      # A plain library name or flag (-lm, dl) is passed on to consumers as it is.
      if(item MATCHES "\\$<")
        message(WARNING "rtk::kernels: ${root} links '${item}', which the package cannot carry")
      else()
        list(APPEND external ${item})
      endif()
      continue()
    endif()
    get_target_property(imported ${item} IMPORTED)
    if(imported)
      list(APPEND external ${item})
      continue()
    endif()
    list(APPEND seen ${item})
    get_target_property(type ${item} TYPE)
    if(type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(links ${item} INTERFACE_LINK_LIBRARIES)
    else()
      get_target_property(links ${item} LINK_LIBRARIES)
    endif()
    if(links)
      list(APPEND todo ${links})
    endif()
  endwhile()
  set(${out_targets} ${seen} PARENT_SCOPE)
  set(${out_external} ${external} PARENT_SCOPE)
endfunction()

# rtk_kernels_headers(<out> <headers...>)
# The public headers and the project headers they include with "...", recursively, as paths
# relative to the include roots (chapters/ and lib/): exactly what the API needs.
function(rtk_kernels_headers out)
  set(roots ${PROJECT_SOURCE_DIR}/chapters ${PROJECT_SOURCE_DIR}/lib)
  set(todo ${ARGN})
  set(found "")
  while(todo)
    list(POP_FRONT todo rel)
    if(rel IN_LIST found)
      continue()
    endif()
    set(path "")
    foreach(root IN LISTS roots)
      if(EXISTS ${root}/${rel})
        set(path ${root}/${rel})
        break()
      endif()
    endforeach()
    if(NOT path)
      # A warning, not an error: a header being renamed must not stop everyone's configure.
      message(WARNING "rtk::kernels: the public header '${rel}' is not under chapters/ or lib/")
      continue()
    endif()
    list(APPEND found ${rel})
    # A new #include in a public header re-runs the configuration, and so the install rules.
    set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${path})
    file(STRINGS ${path} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*$" "\\1" inc "${line}")
      list(APPEND todo ${inc})
    endforeach()
  endwhile()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

# rtk_install_headers(<component> <public headers...>)
# Installs the public headers and every project header they include (rtk_kernels_headers) under
# include/rtk/, in the folders they have below chapters/ or lib/.
function(rtk_install_headers component)
  rtk_kernels_headers(headers ${ARGN})
  foreach(rel IN LISTS headers)
    get_filename_component(dir ${rel} DIRECTORY)
    foreach(root ${PROJECT_SOURCE_DIR}/chapters ${PROJECT_SOURCE_DIR}/lib)
      if(EXISTS ${root}/${rel})
        install(FILES ${root}/${rel} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rtk/${dir} COMPONENT ${component})
        break()
      endif()
    endforeach()
  endforeach()
endfunction()

# rtk_package_objects(<package> <libraries...>)
# Puts every object file of the libraries into the package library, including the per-ISA
# objects that rtk_isa_kernels() libraries hold as sources. Interface libraries carry no
# objects; a shared library cannot be taken apart (tests/install then fails to link the
# example, and names what is missing).
function(rtk_package_objects package)
  foreach(lib IN LISTS ARGN)
    get_target_property(type ${lib} TYPE)
    if(type STREQUAL "INTERFACE_LIBRARY")
      continue()
    endif()
    if(NOT type MATCHES "^(STATIC|OBJECT)_LIBRARY$")
      message(WARNING "${package}: ${lib} is a ${type}; only static and object libraries can be packaged")
      continue()
    endif()
    target_sources(${package} PRIVATE $<TARGET_OBJECTS:${lib}>)
    get_target_property(sources ${lib} SOURCES)
    foreach(src IN LISTS sources)
      if(src MATCHES "^\\$<TARGET_OBJECTS:")
        target_sources(${package} PRIVATE ${src})
      endif()
    endforeach()
    add_dependencies(${package} ${lib})
  endforeach()
endfunction()

# rtk_add_kernels_package(API <target> HEADERS <public headers...>)
# Adds the library rtk_kernels (exported as rtk::kernels) and its install rules, component
# `rtk_kernels`. Call it once every chapter and lib/ have been added.
function(rtk_add_kernels_package)
  cmake_parse_arguments(ARG "" "API" "HEADERS" ${ARGN})
  rtk_kernels_closure(libs external ${ARG_API})

  # Step 1: one library holding every object file of the API's closure.
  if(RTK_KERNELS_SHARED)
    add_library(rtk_kernels SHARED)
  else()
    add_library(rtk_kernels STATIC)
  endif()
  add_library(rtk::kernels ALIAS rtk_kernels)
  set_target_properties(rtk_kernels PROPERTIES OUTPUT_NAME rtk_kernels EXPORT_NAME kernels
                                               LINKER_LANGUAGE CXX)
  rtk_package_objects(rtk_kernels ${libs})

  # Step 2: what a consumer needs: the headers, C++20 and the external libraries.
  target_include_directories(rtk_kernels INTERFACE
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/chapters>
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/lib>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/rtk>)
  target_compile_features(rtk_kernels INTERFACE cxx_std_20)
  set(packages "")
  foreach(dep IN LISTS external)
    if(dep MATCHES "^TBB::")
      list(APPEND packages TBB)
    elseif(dep STREQUAL "Threads::Threads")
      list(APPEND packages Threads)
    elseif(TARGET ${dep})
      # tests/install fails until the package configuration learns to find it.
      message(WARNING "rtk::kernels: the API links ${dep}; teach cmake/rtk_package.cmake "
                      "which package provides it, so that rtkConfig.cmake can find it")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES packages)
  if(RTK_KERNELS_SHARED)
    # Everything but the API is hidden (cmake/rtk_kernels.map), so that the chapters' symbols
    # and their inline templates never clash with the application's.
    target_link_libraries(rtk_kernels PRIVATE ${external})
    target_link_options(rtk_kernels PRIVATE
      -Wl,--version-script=${PROJECT_SOURCE_DIR}/cmake/rtk_kernels.map -Wl,--no-undefined)
    set_target_properties(rtk_kernels PROPERTIES
      LINK_DEPENDS ${PROJECT_SOURCE_DIR}/cmake/rtk_kernels.map
      VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
    set(packages "")  # a shared library carries its dependencies itself
  else()
    target_link_libraries(rtk_kernels PUBLIC ${external})
  endif()
  if(RTK_SANITIZE)
    # Instrumented objects need the sanitizers' run-time libraries wherever they are linked.
    target_link_options(rtk_kernels PUBLIC -fsanitize=${RTK_SANITIZE})
  endif()

  # Step 3: the install rules, all in one component.
  rtk_install_headers(rtk_kernels ${ARG_HEADERS})
  install(TARGETS rtk_kernels EXPORT rtkTargets COMPONENT rtk_kernels
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/rtk)
  install(EXPORT rtkTargets NAMESPACE rtk:: DESTINATION ${config_dir} COMPONENT rtk_kernels)
  set(RTK_PACKAGE_DEPENDENCIES ${packages})
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rtkConfig.cmake.in
    ${CMAKE_CURRENT_BINARY_DIR}/rtkConfig.cmake INSTALL_DESTINATION ${config_dir})
  write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/rtkConfigVersion.cmake
    VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/rtkConfig.cmake
                ${CMAKE_CURRENT_BINARY_DIR}/rtkConfigVersion.cmake
          DESTINATION ${config_dir} COMPONENT rtk_kernels)
  list(JOIN libs " " libs_text)
  message(STATUS "rtk::kernels (${ARG_API} and what it links): ${libs_text}")
endfunction()

# rtk_add_render_package(API <target> HEADERS <public headers...>)
# Adds the library rtk_render (exported as rtk::render, component `rtk_render`, package
# component `render`): the device API of chapter 15 with everything it links (the renderer
# chapters and the kernels), for programs that render rather than trace rays. It holds its
# whole closure, kernels included, so a program links rtk::render alone (not with rtk::kernels).
# Always a static library.
function(rtk_add_render_package)
  cmake_parse_arguments(ARG "" "API" "HEADERS" ${ARGN})
  rtk_kernels_closure(libs external ${ARG_API})
  add_library(rtk_render STATIC)
  add_library(rtk::render ALIAS rtk_render)
  set_target_properties(rtk_render PROPERTIES OUTPUT_NAME rtk_render EXPORT_NAME render
                                              LINKER_LANGUAGE CXX)
  rtk_package_objects(rtk_render ${libs})
  target_include_directories(rtk_render INTERFACE
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/chapters>
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/lib>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/rtk>)
  target_compile_features(rtk_render INTERFACE cxx_std_20)
  foreach(dep IN LISTS external)
    if(TARGET ${dep} AND NOT dep MATCHES "^(TBB::|Threads::Threads$)")
      message(WARNING "rtk::render: ${ARG_API} links ${dep}; rtkConfig.cmake finds only TBB and Threads")
    endif()
  endforeach()
  target_link_libraries(rtk_render PUBLIC ${external})
  if(RTK_SANITIZE)
    target_link_options(rtk_render PUBLIC -fsanitize=${RTK_SANITIZE})
  endif()
  rtk_install_headers(rtk_render ${ARG_HEADERS})
  install(TARGETS rtk_render EXPORT rtkRenderTargets COMPONENT rtk_render
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  # Its own export file, so that installing the kernels' component alone stays complete;
  # rtkConfig.cmake includes it when it is there.
  install(EXPORT rtkRenderTargets NAMESPACE rtk:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rtk
          COMPONENT rtk_render)
  list(JOIN libs " " libs_text)
  message(STATUS "rtk::render (${ARG_API} and what it links): ${libs_text}")
endfunction()
