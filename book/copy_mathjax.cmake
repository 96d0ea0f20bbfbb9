# Copies the part of MathJax 2 that the book's pages load (TeX input, SVG output with its TeX
# fonts, the extensions) beside them, into ${HTML}/mathjax: the book reads offline and can be
# published as a folder. Run by the 'book' target: cmake -DMATHJAX=... -DHTML=... -P this.
foreach(var MATHJAX HTML)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "copy_mathjax.cmake: -D${var}=... is required")
  endif()
endforeach()
set(out ${HTML}/mathjax)
file(COPY ${MATHJAX}/MathJax.js DESTINATION ${out})
file(COPY ${MATHJAX}/extensions DESTINATION ${out})
file(COPY ${MATHJAX}/localization/en DESTINATION ${out}/localization)
file(COPY ${MATHJAX}/jax/input/TeX DESTINATION ${out}/jax/input)
file(COPY ${MATHJAX}/jax/element DESTINATION ${out}/jax)
file(COPY ${MATHJAX}/jax/output/SVG/config.js ${MATHJAX}/jax/output/SVG/jax.js
          ${MATHJAX}/jax/output/SVG/autoload DESTINATION ${out}/jax/output/SVG)
file(COPY ${MATHJAX}/jax/output/SVG/fonts/TeX DESTINATION ${out}/jax/output/SVG/fonts)
