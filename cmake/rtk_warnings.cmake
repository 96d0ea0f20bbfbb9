# Warnings and sanitizers shared by every RTK target (added through rtk_defaults).
add_library(rtk_defaults INTERFACE)
target_compile_options(rtk_defaults INTERFACE -Wall -Wextra -ffp-contract=off)
target_include_directories(rtk_defaults INTERFACE
  ${PROJECT_SOURCE_DIR}/chapters ${PROJECT_SOURCE_DIR}/lib)
if(RTK_SANITIZE)
  target_compile_options(rtk_defaults INTERFACE -fsanitize=${RTK_SANITIZE} -fno-omit-frame-pointer
                                                -fno-sanitize-recover=all)
  target_link_options(rtk_defaults INTERFACE -fsanitize=${RTK_SANITIZE})
  # Tests whose brute-force loops take minutes under the sanitizers trace a sample of their
  # rays there (lib/testing/sanitizer_build.h).
  target_compile_definitions(rtk_defaults INTERFACE RTK_SANITIZER_BUILD=1)
endif()
