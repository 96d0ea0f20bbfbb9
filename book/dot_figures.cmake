# Draws the book's structure diagrams: every chapters/NN_topic/figure/NAME.dot becomes
# chNN_NAME.png in ${OUT}, which the pages show with \image (an image scales to the window,
# where Doxygen's \dotfile would embed a fixed-size SVG frame). Run by the 'book' target:
# cmake -DSOURCE=... -DOUT=... -DDOT=... -P this.
file(GLOB dots ${SOURCE}/chapters/[0-9][0-9]_*/figure/*.dot)
file(MAKE_DIRECTORY ${OUT})
foreach(dot IN LISTS dots)
  get_filename_component(name ${dot} NAME_WE)
  get_filename_component(figure_dir ${dot} DIRECTORY)
  get_filename_component(chapter_dir ${figure_dir} DIRECTORY)
  get_filename_component(chapter ${chapter_dir} NAME)
  string(SUBSTRING ${chapter} 0 2 number)
  execute_process(COMMAND ${DOT} -Tpng -Gdpi=96 -o ${OUT}/ch${number}_${name}.png ${dot}
                  RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${dot}: dot failed (${result})")
  endif()
endforeach()
