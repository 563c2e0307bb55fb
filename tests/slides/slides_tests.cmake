# Slide decks end to end: `lightlab slides build` of every deck, each page
# checked for every figure its Markdown names (the unit tests render every
# preset too: Slides/SlideDeck.*; bad decks: cli.error.slides_*).
add_test(NAME slides.build_all_decks_every_figure_embedded
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/slides_build_test.sh $<TARGET_FILE:lightlab> ${CMAKE_CURRENT_BINARY_DIR}/slides_out)
set_tests_properties(slides.build_all_decks_every_figure_embedded PROPERTIES TIMEOUT 600)
# Where Node.js is installed: every equation of the built pages typesets with Debian's KaTeX.
find_program(NODE_PROGRAM NAMES node nodejs)
if(NODE_PROGRAM)
  add_test(NAME slides.every_equation_typesets
           COMMAND bash -c "${NODE_PROGRAM} ${CMAKE_CURRENT_LIST_DIR}/katex_check.js ${LIGHTLAB_KATEX_DIR}/katex.js ${CMAKE_CURRENT_BINARY_DIR}/slides_out/*.html")
  set_tests_properties(slides.every_equation_typesets PROPERTIES DEPENDS slides.build_all_decks_every_figure_embedded)
endif()
# Where Chromium is installed: the pages in a real browser typeset with their own inlined KaTeX.
find_program(CHROMIUM_PROGRAM NAMES chromium chromium-browser)
if(CHROMIUM_PROGRAM AND Python3_FOUND)
  add_test(NAME slides.pages_typeset_in_a_browser
           COMMAND bash -c "bash ${CMAKE_CURRENT_LIST_DIR}/browser_check.sh ${CHROMIUM_PROGRAM} ${CMAKE_CURRENT_BINARY_DIR}/slides_out/*.html")
  set_tests_properties(slides.pages_typeset_in_a_browser PROPERTIES DEPENDS slides.build_all_decks_every_figure_embedded TIMEOUT 600)
endif()
