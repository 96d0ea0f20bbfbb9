# The layer rule of the build (book/conventions.md): a chapter's targets link only earlier
# chapters and the layer beneath the chapters. rtk_check_chapter_links() reads what every
# target of every chapter folder links, and stops the configuration at the first link that
# goes up: to a later chapter (chNN_...), or to a part of lib/ that sits above the chapters.

# The libraries of lib/ beneath the chapters (they need chapter 1 only), and the mains.
set(RTK_LOWER_LIBS rtk_defaults rtk_io rtk_image rtk_replay rtk_testing rtk_test_main rtk_bench_main)

# Links that still go up while the chapters are being reordered (own->other).
set(RTK_LAYER_EXCEPTIONS "6->7")

# rtk_check_chapter_links()
function(rtk_check_chapter_links)
  get_property(chapter_dirs DIRECTORY ${PROJECT_SOURCE_DIR} PROPERTY SUBDIRECTORIES)
  foreach(dir IN LISTS chapter_dirs)
    get_filename_component(name ${dir} NAME)
    if(NOT name MATCHES "^([0-9][0-9])_")
      continue()
    endif()
    math(EXPR own "${CMAKE_MATCH_1}")
    get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(target IN LISTS targets)
      get_target_property(type ${target} TYPE)
      set(links "")
      if(NOT type STREQUAL "INTERFACE_LIBRARY")
        get_target_property(links ${target} LINK_LIBRARIES)
      endif()
      get_target_property(interface_links ${target} INTERFACE_LINK_LIBRARIES)
      foreach(item IN LISTS links interface_links)
        string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
        if(item MATCHES "^ch([0-9][0-9])_")
          math(EXPR other "${CMAKE_MATCH_1}")
          if(other GREATER own AND NOT "${own}->${other}" IN_LIST RTK_LAYER_EXCEPTIONS)
            message(FATAL_ERROR "layers: ${target} (chapters/${name}) links ${item}, a later chapter")
          endif()
        elseif(item MATCHES "^rtk_" AND NOT item IN_LIST RTK_LOWER_LIBS)
          message(FATAL_ERROR "layers: ${target} (chapters/${name}) links ${item}, which sits above the chapters")
        elseif(own EQUAL 1 AND item MATCHES "^rtk_(io|image|replay|testing)$")
          message(FATAL_ERROR "layers: ${target} (chapters/${name}) links ${item}, which is built on chapter 1")
        endif()
      endforeach()
    endforeach()
  endforeach()
endfunction()
