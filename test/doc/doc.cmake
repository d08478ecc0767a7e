# The documentation against the code. Label: doc.
# doc_options_table: every option that `dmhs -scene S -help` lists, for every
# scene, is in an option table of doc/user-guide.md, and the tables list no
# option that the code does not register (test/doc/options_table.py).
add_test(NAME doc_options_table
         COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/options_table.py ${DMHS_EXE}
                 ${PROJECT_SOURCE_DIR}/doc/user-guide.md)
set_tests_properties(doc_options_table PROPERTIES LABELS doc TIMEOUT 60)
# format_check: every C source and header under src, include, test and bench
# keeps the committed .clang-format (test/doc/format_check.sh; skipped when
# clang-format is missing or not version 14, the tree's).
add_test(NAME format_check COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/format_check.sh ${PROJECT_SOURCE_DIR})
set_tests_properties(format_check PROPERTIES LABELS doc TIMEOUT 120 SKIP_RETURN_CODE 77)
