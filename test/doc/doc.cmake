# The documentation against the code. Label: doc.
# doc_options_table: the option tables of the guide's pages (doc/guide/*.md,
# marker sections generated from `dmhs -scene S -help`) are what -help gives
# now, and every option that -help lists for some scene is in one
# (test/doc/options_table.py; --write regenerates them).
file(GLOB DMHS_GUIDE_PAGES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/doc/guide/*.md)
add_test(NAME doc_options_table
         COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/options_table.py ${DMHS_EXE}
                 ${DMHS_GUIDE_PAGES})
set_tests_properties(doc_options_table PROPERTIES LABELS doc TIMEOUT 60)
# format_check: every C source and header under src, include, test and bench
# keeps the committed .clang-format (test/doc/format_check.sh; skipped when
# clang-format is missing or not version 14, the tree's).
add_test(NAME format_check COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/format_check.sh ${PROJECT_SOURCE_DIR})
set_tests_properties(format_check PROPERTIES LABELS doc TIMEOUT 120 SKIP_RETURN_CODE 77)
# doc_links: every relative link, image and heading anchor of README.md,
# doc/**/*.md and bench/**/README.md resolves (test/doc/links.py).
add_test(NAME doc_links COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/links.py ${PROJECT_SOURCE_DIR})
set_tests_properties(doc_links PROPERTIES LABELS doc TIMEOUT 60)
# doc_readme_numbers: every number the README quotes beside a link is written
# the same way in the page it links to (test/doc/readme_numbers.py).
add_test(NAME doc_readme_numbers
         COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/readme_numbers.py ${PROJECT_SOURCE_DIR})
set_tests_properties(doc_readme_numbers PROPERTIES LABELS doc TIMEOUT 60)
# doc_site: the pages build as a site with MkDocs in strict mode (scripts/docs.sh;
# a page or link MkDocs cannot place fails it).
add_test(NAME doc_site COMMAND bash ${PROJECT_SOURCE_DIR}/scripts/docs.sh --out ${CMAKE_BINARY_DIR}/site-test)
set_tests_properties(doc_site PROPERTIES LABELS doc TIMEOUT 120)
# doc_layers: no file of a lower layer (core < io < physics < diag < scenes < driver, as
# doc/architecture.md draws them) includes a header of a higher one, but for the listed
# known violations, each of which must still exist (test/doc/layers.py).
add_test(NAME doc_layers COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/layers.py ${PROJECT_SOURCE_DIR})
set_tests_properties(doc_layers PROPERTIES LABELS doc TIMEOUT 60)
# doc_option_readers: every option is read through the checked readers of
# include/dmhs/options.h, and no header redefines PETSc's (test/doc/option_readers.py).
add_test(NAME doc_option_readers
         COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/option_readers.py ${PROJECT_SOURCE_DIR})
set_tests_properties(doc_option_readers PROPERTIES LABELS doc TIMEOUT 60)
