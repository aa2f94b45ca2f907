# SPDX-License-Identifier: Apache-2.0
# Shared compile options and the test helper used by every varc target.

# Applies varc's warning set (and sanitizers) to |tgt|.
function(varc_target_defaults tgt)
    target_compile_options(${tgt} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                          -Wno-sign-conversion)
    if(VARC_WERROR)
        target_compile_options(${tgt} PRIVATE -Werror)
    endif()
    if(VARC_SANITIZE)
        string(REPLACE ";" "," _san "${VARC_SANITIZE}")
        target_compile_options(${tgt} PRIVATE -fsanitize=${_san} -fno-omit-frame-pointer)
        target_link_options(${tgt} PRIVATE -fsanitize=${_san})
    endif()
endfunction()

# varc_add_gtest(NAME n SOURCES a.cpp ... LIBS lib ... [LABELS l ...])
# Builds one GoogleTest executable and registers each TEST with CTest.
function(varc_add_gtest)
    cmake_parse_arguments(ARG "" "NAME" "SOURCES;LIBS;LABELS" ${ARGN})
    add_executable(${ARG_NAME} ${ARG_SOURCES})
    varc_target_defaults(${ARG_NAME})
    target_link_libraries(${ARG_NAME} PRIVATE ${ARG_LIBS} GTest::gtest_main GTest::gmock)
    target_compile_definitions(${ARG_NAME} PRIVATE
        VARC_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
        VARC_SHARED_DIR="${PROJECT_SOURCE_DIR}/../shared")
    gtest_discover_tests(${ARG_NAME} PROPERTIES LABELS unit DISCOVERY_TIMEOUT 60)
    # gtest_discover_tests flattens a label list into separate property arguments, so the extra
    # labels are set by a script CTest runs after the discovered tests are defined (it sees the
    # <target>_TESTS list the discovery script sets).
    if(ARG_LABELS)
        string(JOIN "\\;" _labels unit ${ARG_LABELS})
        set(_label_script "${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}_labels.cmake")
        file(WRITE "${_label_script}"
            "if(DEFINED ${ARG_NAME}_TESTS)\n"
            "  set_tests_properties(\${${ARG_NAME}_TESTS} PROPERTIES LABELS \"${_labels}\")\n"
            "endif()\n")
        set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${_label_script}")
    endif()
endfunction()
