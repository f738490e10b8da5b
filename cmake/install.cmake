# What `cmake --install` installs, and the Debian package `cpack -G DEB`
# builds from it (included by CMakeLists.txt):
#
#   bin/spancast                          the tool (the static library linked in)
#   LIBDIR/spancast/spancast-oiio.so      helpers the tool and the library look
#   LIBDIR/spancast/spancast-bench        for there (src/formats/file.c)
#   LIBDIR/spancast/spancast-view         the viewer `spancast view` starts (SDL2)
#   LIBDIR/libspancast.so.X.Y.Z           the shared library, soname .so.X.Y while
#                                         X is 0, and the .so link for -lspancast
#   include/spancast/*.h                  the public headers, version.h generated
#   LIBDIR/pkgconfig/spancast.pc          pkg-config --cflags --libs spancast
#   LIBDIR/cmake/spancast/                find_package(spancast): spancast::spancast
#   share/man/man1, man3                  spancast(1), spancast-COMMAND(1), libspancast(3)
#   share/bash-completion/completions/spancast
#   share/doc/spancast/                   README.md, docs/*.md, examples/
#
# Every path inside the installed tree is relative to the tree (the helpers'
# folder, spancast.pc's prefix, the CMake package's), so it can be installed
# with --prefix anywhere, or unpacked from the .deb anywhere, and still work.
include(CMakePackageConfigHelpers)

add_library(spancast::spancast ALIAS spancast_shared)

install(TARGETS spancast RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS spancast_oiio LIBRARY DESTINATION ${SPANCAST_HELPERS_DIR})
install(TARGETS spancast-bench RUNTIME DESTINATION ${SPANCAST_HELPERS_DIR})
install(TARGETS spancast_view RUNTIME DESTINATION ${SPANCAST_HELPERS_DIR})
install(TARGETS spancast_shared EXPORT spancastTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

file(GLOB SPANCAST_PUBLIC_HEADERS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/include/spancast/*.h)
install(FILES ${SPANCAST_PUBLIC_HEADERS} ${PROJECT_BINARY_DIR}/include/spancast/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/spancast)

# spancast.pc finds its prefix from its own folder (${pcfiledir}), which
# pkg-config and pkgconf both define.
file(RELATIVE_PATH SPANCAST_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig
     ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" SPANCAST_PC_TO_PREFIX "${SPANCAST_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/spancast.pc.in
               ${PROJECT_BINARY_DIR}/spancast.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/spancast.pc
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# The CMake package. While the major version is 0 a program asks for the
# minor version it was written for; later, for the major version.
set(SPANCAST_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/spancast)
install(EXPORT spancastTargets NAMESPACE spancast:: DESTINATION ${SPANCAST_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/spancastConfig.cmake.in
  ${PROJECT_BINARY_DIR}/spancastConfig.cmake INSTALL_DESTINATION ${SPANCAST_CMAKE_DIR})
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(SPANCAST_COMPATIBILITY SameMinorVersion)
else()
  set(SPANCAST_COMPATIBILITY SameMajorVersion)
endif()
write_basic_package_version_file(${PROJECT_BINARY_DIR}/spancastConfigVersion.cmake
  COMPATIBILITY ${SPANCAST_COMPATIBILITY})
install(FILES ${PROJECT_BINARY_DIR}/spancastConfig.cmake
              ${PROJECT_BINARY_DIR}/spancastConfigVersion.cmake
        DESTINATION ${SPANCAST_CMAKE_DIR})

# Documentation: the man pages (docs/man, one page per command and one for
# the library), the shell completion, the user documentation and the
# examples.
file(GLOB SPANCAST_MAN1 CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/man/*.1)
file(GLOB SPANCAST_MAN3 CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/man/*.3)
install(FILES ${SPANCAST_MAN1} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${SPANCAST_MAN3} DESTINATION ${CMAKE_INSTALL_MANDIR}/man3)
install(FILES ${PROJECT_SOURCE_DIR}/completion/spancast.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
        RENAME spancast)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
# docs/ beside the README, whose links point into it.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
        FILES_MATCHING PATTERN "*.md" PATTERN man EXCLUDE)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples
        FILES_MATCHING PATTERN "*.c" PATTERN "CMakeLists.txt")

# The Debian package: `cpack -G DEB` in the build folder. One package holds
# the tool, the library and its development files. Its Depends come from
# dpkg-shlibdeps on what is linked (cmake/CPackProjectConfig.cmake.in, which
# leaves out the OpenImageIO plugin); what is found or loaded only on
# demand is listed by hand below.
set(SPANCAST_DEB_MAINTAINER "spancast maintainers <spancast@localhost>" CACHE STRING
    "Maintainer field of the Debian package")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME spancast)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "exact CSG and implicit-surface ray caster")
string(CONCAT CPACK_PACKAGE_DESCRIPTION
    "spancast renders solid models built by constructive solid geometry\n"
    "exactly, by casting rays: OpenSCAD's .csg exports (and .scad through\n"
    "OpenSCAD) to images, spans along rays and point membership. This package\n"
    "holds the spancast tool, the libspancast shared library with its headers,\n"
    "pkg-config file and CMake package, the man pages and examples.")
set(CPACK_PACKAGE_CONTACT "${SPANCAST_DEB_MAINTAINER}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS OFF)
# The package's binaries without their debugging information (the .deb of
# a RelWithDebInfo build: 0.7 MB instead of 3.1 MB); the build tree keeps it.
set(CPACK_STRIP_FILES ON)
# A shlibs file for libspancast, and ldconfig run after install and removal.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS_POLICY ">=")
# Loaded on demand, so invisible to dpkg-shlibdeps (Debian 12 names):
#   openscad            .scad input, converted by running openscad (src/cli/scad.c)
#   libopenimageio2.4   every image format beyond PNG and EXR, through the
#                       plugin LIBDIR/spancast/spancast-oiio.so (dlopen)
#   libsdl2-2.0-0       the interactive viewer's window
#   libopenmpi3         rendering tiles across machines with Open MPI
#   gnuplot-nox         `spancast bench accuracy --plot` (suggested only)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "openscad, libopenimageio2.4, libsdl2-2.0-0, libopenmpi3, ffmpeg")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "gnuplot-nox")
set(SPANCAST_SHLIBDEPS_FILES $<TARGET_FILE:spancast> $<TARGET_FILE:spancast-bench>
    $<TARGET_FILE:spancast_shared>)
file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/cpack-shlibdeps-files.txt
     CONTENT "$<JOIN:${SPANCAST_SHLIBDEPS_FILES},\n>\n")
configure_file(${PROJECT_SOURCE_DIR}/cmake/CPackProjectConfig.cmake.in
               ${PROJECT_BINARY_DIR}/CPackProjectConfig.cmake @ONLY)
set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_BINARY_DIR}/CPackProjectConfig.cmake)
include(CPack)
