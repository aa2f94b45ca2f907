# SPDX-License-Identifier: Apache-2.0
# Install rules, the CMake package (find_package(varc)), the pkg-config file and the Debian
# package (cpack -G DEB). Included once every target exists.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# `cmake --install` copies what the build made and builds nothing (build first): the install
# tests run it from CTest, where a build of `all` would race the other tests.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

set(VARC_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/varc")
# What an engine links: the reader (varc::runtime) and the libraries that draw with it. The
# compiler libraries stay private to the varc executable (they need glslang).
set(_varc_exported core variants pack reader image vulkan scene render reference)

install(TARGETS varc RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
set(_targets varc_runtime)
foreach(_name IN LISTS _varc_exported)
    list(APPEND _targets varc_${_name})
    get_property(_folder GLOBAL PROPERTY VARC_LIBRARY_${_name}_FOLDER)
    install(DIRECTORY "${PROJECT_SOURCE_DIR}/${_folder}/include/"
            DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
install(TARGETS ${_targets} EXPORT varcTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT varcTargets NAMESPACE varc:: DESTINATION ${VARC_INSTALL_CMAKEDIR})

configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/varcConfig.cmake.in"
    "${PROJECT_BINARY_DIR}/varcConfig.cmake" INSTALL_DESTINATION ${VARC_INSTALL_CMAKEDIR})
write_basic_package_version_file("${PROJECT_BINARY_DIR}/varcConfigVersion.cmake"
    COMPATIBILITY SameMinorVersion)
# FindXxHash: Debian's libxxhash-dev has no CMake config; the exported reader links XxHash::XxHash.
install(FILES "${PROJECT_BINARY_DIR}/varcConfig.cmake"
              "${PROJECT_BINARY_DIR}/varcConfigVersion.cmake"
              "${PROJECT_SOURCE_DIR}/cmake/FindXxHash.cmake"
        DESTINATION ${VARC_INSTALL_CMAKEDIR})

# pkg-config: varc::runtime for builds without CMake; paths relative to the .pc file, so any
# --prefix works.
set(_pcdir "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
file(RELATIVE_PATH VARC_PC_PREFIX "/root/${_pcdir}" "/root")
string(REGEX REPLACE "/$" "" VARC_PC_PREFIX "${VARC_PC_PREFIX}")
configure_file("${PROJECT_SOURCE_DIR}/cmake/varc.pc.in" "${PROJECT_BINARY_DIR}/varc.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/varc.pc" DESTINATION ${_pcdir})

# Data: the built-in includes and fallback shaders the compiler needs (found from the installed
# binary, see cli), the shaders the runtime draws itself, the man page, the bash
# completion and the documentation.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/shaders/builtin" "${PROJECT_SOURCE_DIR}/shaders/internal"
        DESTINATION ${CMAKE_INSTALL_DATADIR}/varc)
install(FILES "${VARC_MAN_PAGE}" DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES "${VARC_BASH_COMPLETION}"
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME varc)
install(FILES "${PROJECT_SOURCE_DIR}/README.md" DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY "${PROJECT_SOURCE_DIR}/docs/" DESTINATION ${CMAKE_INSTALL_DOCDIR}
        FILES_MATCHING PATTERN "*.md")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/examples/" DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)

# cpack -G DEB: one package with the tool and the development files. dpkg-shlibdeps finds the
# shared libraries varc runs with; an engine building against the headers and the static
# libraries also needs the -dev packages of their dependencies.
set(CPACK_PACKAGE_NAME varc)
set(CPACK_PACKAGE_VENDOR "varc")
set(CPACK_PACKAGE_CONTACT "varc maintainers <varc@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Unity-style shaders to SPIR-V variant packs, and a Vulkan runtime for them")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libzstd-dev, libxxhash-dev, libpng-dev, libvulkan-dev, libglm-dev, nlohmann-json3-dev")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "mesa-vulkan-drivers")
include(CPack)
