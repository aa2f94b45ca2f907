# SPDX-License-Identifier: Apache-2.0
# Shared compile options and the test helper used by every varc target.

# Applies varc's warning set (and sanitizers) to |tgt|.
function(varc_target_defaults tgt)
    target_compile_options(${tgt} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                          -Wno-sign-conversion)
    if(VARC_WERROR)
        target_compile_options(${tgt} PRIVATE -Werror)
    endif()
    if(VARC_BUILD_FUZZERS)
        # Coverage feedback for libFuzzer in every library a fuzz target reaches.
        target_compile_options(${tgt} PRIVATE -fsanitize=fuzzer-no-link)
    endif()
    if(VARC_SANITIZE)
        string(REPLACE ";" "," _san "${VARC_SANITIZE}")
        target_compile_options(${tgt} PRIVATE -fsanitize=${_san} -fno-omit-frame-pointer)
        target_link_options(${tgt} PRIVATE -fsanitize=${_san})
        if("undefined" IN_LIST VARC_SANITIZE)
            # UBSan's vptr check needs the type_info of every polymorphic class it sees; Debian
            # builds glslang without RTTI, so the check cannot link against glslang::TShader.
            target_compile_options(${tgt} PRIVATE -fno-sanitize=vptr)
            target_link_options(${tgt} PRIVATE -fno-sanitize=vptr)
        endif()
    endif()
endfunction()

# varc_use_test_pch(tgt): the test program |tgt| compiles with GoogleTest and GoogleMock
# precompiled once for all test programs (VARC_PRECOMPILE_HEADERS, clang only). Under clang their
# headers are about 1.5 s of each test file's compile; g++'s precompiled headers saved nothing
# measurable here and made files that use few of their declarations slower, so g++ reads the
# headers as usual. The shared header is built by varc_test_pch, which has the same options as
# every test program (the compiler refuses a header built with other ones).
function(varc_use_test_pch tgt)
    if(NOT VARC_PRECOMPILE_HEADERS OR NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
        return()
    endif()
    if(NOT TARGET varc_test_pch)
        set(_source "${PROJECT_BINARY_DIR}/varc_test_pch.cpp")
        file(WRITE "${_source}" "// The translation unit varc_test_pch precompiles its headers for.\n")
        add_library(varc_test_pch OBJECT "${_source}")
        varc_target_defaults(varc_test_pch)
        target_link_libraries(varc_test_pch PRIVATE GTest::gtest GTest::gmock)
        varc_test_definitions(varc_test_pch)
        target_precompile_headers(varc_test_pch PRIVATE <gtest/gtest.h> <gmock/gmock.h>)
    endif()
    target_precompile_headers(${tgt} REUSE_FROM varc_test_pch)
endfunction()

# varc_test_definitions(tgt): the macros every test program sees (where the source tree and
# ../shared are).
function(varc_test_definitions tgt)
    target_compile_definitions(${tgt} PRIVATE
        VARC_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
        VARC_SHARED_DIR="${PROJECT_SOURCE_DIR}/../shared")
endfunction()

# The ASAN_OPTIONS change a test that draws on lavapipe runs with: no leak detection. Lavapipe is
# unloaded when the Vulkan instance goes, and its leaks then come from a module LeakSanitizer can
# no longer name, so they can be neither attributed nor suppressed. Appended, so it overrides the
# sanitizer job's detect_leaks=1; only sanitizer builds read the variable.
set(VARC_DRAW_ASAN_OPTIONS "ASAN_OPTIONS=string_append::detect_leaks=0")

# varc_draw_tests_skip_leak_check(): every test added so far in this directory that is labelled
# vulkan (it draws) gets VARC_DRAW_ASAN_OPTIONS. Call it at the end of the directory's file.
function(varc_draw_tests_skip_leak_check)
    get_property(_tests DIRECTORY PROPERTY TESTS)
    foreach(_test IN LISTS _tests)
        get_test_property(${_test} LABELS _labels)
        if("vulkan" IN_LIST _labels)
            set_property(TEST ${_test} APPEND PROPERTY ENVIRONMENT_MODIFICATION
                         "${VARC_DRAW_ASAN_OPTIONS}")
        endif()
    endforeach()
endfunction()

# varc_add_gtest(NAME n SOURCES a.cpp ... LIBS lib ... [LABELS l ...] [PREFIX p])
# Builds one GoogleTest executable and registers each TEST with CTest (named p<Suite>.<Test> with
# a PREFIX, so `ctest -R p` selects the executable's tests).
function(varc_add_gtest)
    cmake_parse_arguments(ARG "" "NAME;PREFIX" "SOURCES;LIBS;LABELS" ${ARGN})
    add_executable(${ARG_NAME} ${ARG_SOURCES})
    varc_target_defaults(${ARG_NAME})
    varc_use_test_pch(${ARG_NAME})
    target_link_libraries(${ARG_NAME} PRIVATE ${ARG_LIBS} GTest::gtest_main GTest::gmock)
    varc_test_definitions(${ARG_NAME})
    gtest_discover_tests(${ARG_NAME} TEST_PREFIX "${ARG_PREFIX}"
                         PROPERTIES LABELS unit DISCOVERY_TIMEOUT 60)
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

# varc_add_library(<name> [INTERFACE] [SOURCES src/a.cpp ...] [PUBLIC dep ...] [PRIVATE dep ...])
# Defines the library of the current folder: target varc_<name> with alias varc::<name>, its
# public headers in include/varc/<name>/ (the install tree's include/ once installed), its private
# ones in src/, varc's warning set. The name,
# folder and direct links are recorded for the layout check (cmake/CheckLayout.cmake), which
# fails when a library includes a header of a library it does not link.
function(varc_add_library name)
    cmake_parse_arguments(ARG "INTERFACE" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
    set(tgt varc_${name})
    if(ARG_INTERFACE)
        add_library(${tgt} INTERFACE)
        target_include_directories(${tgt} INTERFACE
            $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
        target_link_libraries(${tgt} INTERFACE ${ARG_PUBLIC})
    else()
        add_library(${tgt} STATIC ${ARG_SOURCES})
        target_include_directories(${tgt}
            PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
            PRIVATE src)
        target_link_libraries(${tgt} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
        varc_target_defaults(${tgt})
    endif()
    add_library(varc::${name} ALIAS ${tgt})
    # Installed and exported as varc::<name> too (cmake/VarcInstall.cmake).
    set_target_properties(${tgt} PROPERTIES EXPORT_NAME ${name})
    file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
    set_property(GLOBAL APPEND PROPERTY VARC_LIBRARIES ${name})
    set_property(GLOBAL PROPERTY VARC_LIBRARY_${name}_FOLDER ${folder})
    set_property(GLOBAL PROPERTY VARC_LIBRARY_${name}_PUBLIC ${ARG_PUBLIC})
    set_property(GLOBAL PROPERTY VARC_LIBRARY_${name}_PRIVATE ${ARG_PRIVATE})
endfunction()

# Writes |file|: one line per varc library, "name folder public,links private,links" ("-" for
# none), for the layout check.
function(varc_write_layout_manifest file)
    get_property(names GLOBAL PROPERTY VARC_LIBRARIES)
    set(text "")
    foreach(name IN LISTS names)
        get_property(folder GLOBAL PROPERTY VARC_LIBRARY_${name}_FOLDER)
        get_property(public GLOBAL PROPERTY VARC_LIBRARY_${name}_PUBLIC)
        get_property(private GLOBAL PROPERTY VARC_LIBRARY_${name}_PRIVATE)
        if(NOT public)
            set(public "-")
        endif()
        if(NOT private)
            set(private "-")
        endif()
        string(REPLACE ";" "," public "${public}")
        string(REPLACE ";" "," private "${private}")
        string(APPEND text "${name} ${folder} ${public} ${private}\n")
    endforeach()
    file(WRITE "${file}" "${text}")
endfunction()
