# What `cmake --install` installs, and the Debian packages `cpack -G DEB`
# builds from it (included by CMakeLists.txt), by install component, as
# Debian splits a library and its tool:
#
# library -> libspancast0 (Section libs)
#   LIBDIR/libspancast.so.0, .so.X.Y.Z    the shared library (soname .so.N, N =
#                                         SPANCAST_SOVERSION, abi/README.md)
#   LIBDIR/spancast/spancast-oiio.so      the OpenImageIO plugin the library (and
#                                         the tool) load on demand (src/formats/file.c)
#   LIBDIR/spancast/spancast-tiff.so      the tiled TIFF plugin (libtiff), likewise
#   LIBDIR/spancast/spancast-exr.so       the EXR plugin (OpenEXR), likewise
#   LIBDIR/spancast/spancast-cgal.so      the CGAL plugin (booleans inside hull and
#                                         minkowski; GMP, MPFR), likewise
#   LIBDIR/spancast/spancast-xml.so       the XML plugin (SVG and AMF imports;
#                                         libxml2), likewise
#   LIBDIR/spancast/spancast-3mf.so       the 3MF plugin (lib3mf), likewise
#   LIBDIR/spancast/spancast-text.so      the text() plugin (FreeType, HarfBuzz,
#                                         fontconfig), likewise
#   share/doc/libspancast0/copyright
# development -> libspancast-dev (Section libdevel)
#   LIBDIR/libspancast.so                 the link for -lspancast
#   include/spancast/*.h                  the public headers, version.h generated
#   LIBDIR/pkgconfig/spancast.pc          pkg-config --cflags --libs spancast
#   LIBDIR/cmake/spancast/                find_package(spancast): spancast::spancast
#   share/man/man3/libspancast.3
#   share/doc/libspancast-dev/            copyright, examples/
# tool -> spancast (Section graphics)
#   bin/spancast                          the tool (the static library linked in)
#   LIBDIR/spancast/spancast-bench        helpers the tool starts from there
#   LIBDIR/spancast/spancast-view         the viewer `spancast view` starts (SDL2)
#   LIBDIR/spancast/spancast-mpi          what `spancast render` runs under mpirun
#                                         (Open MPI; when it was found)
#   share/man/man1                        spancast(1), spancast-COMMAND(1)
#   share/bash-completion/completions/spancast
#   share/doc/spancast/                   copyright, README.md, docs/*.md
#
# Every path inside the installed tree is relative to the tree (the helpers'
# folder, spancast.pc's prefix, the CMake package's), so it can be installed
# with --prefix anywhere, or unpacked from the .deb anywhere, and still work.
include(CMakePackageConfigHelpers)

add_library(spancast::spancast ALIAS spancast_shared)

# The Debian package names, which follow the soname (libspancast.so.0:
# libspancast0).
set(SPANCAST_DEB_LIBRARY libspancast${SPANCAST_SOVERSION})
set(SPANCAST_DEB_DEV libspancast-dev)
set(SPANCAST_DEB_TOOL spancast)

install(TARGETS spancast RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT tool)
install(TARGETS spancast_oiio spancast_tiff spancast_cgal spancast_xml spancast_3mf spancast_text
        spancast_exr LIBRARY DESTINATION ${SPANCAST_HELPERS_DIR}
        COMPONENT library)
install(TARGETS spancast-bench RUNTIME DESTINATION ${SPANCAST_HELPERS_DIR} COMPONENT tool)
install(TARGETS spancast_view RUNTIME DESTINATION ${SPANCAST_HELPERS_DIR} COMPONENT tool)
if(TARGET spancast_mpi)
  install(TARGETS spancast_mpi RUNTIME DESTINATION ${SPANCAST_HELPERS_DIR} COMPONENT tool)
endif()
install(TARGETS spancast_shared EXPORT spancastTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT library
                NAMELINK_COMPONENT development
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

file(GLOB SPANCAST_PUBLIC_HEADERS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/include/spancast/*.h)
install(FILES ${SPANCAST_PUBLIC_HEADERS} ${PROJECT_BINARY_DIR}/include/spancast/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/spancast COMPONENT development)

# spancast.pc finds its prefix from its own folder (${pcfiledir}), which
# pkg-config and pkgconf both define.
file(RELATIVE_PATH SPANCAST_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig
     ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" SPANCAST_PC_TO_PREFIX "${SPANCAST_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/spancast.pc.in
               ${PROJECT_BINARY_DIR}/spancast.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/spancast.pc
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT development)

# The CMake package. While the major version is 0 a program asks for the
# minor version it was written for; later, for the major version.
set(SPANCAST_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/spancast)
install(EXPORT spancastTargets NAMESPACE spancast:: DESTINATION ${SPANCAST_CMAKE_DIR}
        COMPONENT development)
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
        DESTINATION ${SPANCAST_CMAKE_DIR} COMPONENT development)

# Documentation: the man pages (docs/man, one page per command and one for
# the library), the shell completion, the user documentation and the
# examples; every package carries the copyright file (debian/copyright,
# machine-readable: DEP-5) in its own doc folder, as Debian policy asks.
file(GLOB SPANCAST_MAN1 CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/man/*.1)
file(GLOB SPANCAST_MAN3 CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/man/*.3)
install(FILES ${SPANCAST_MAN1} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT tool)
install(FILES ${SPANCAST_MAN3} DESTINATION ${CMAKE_INSTALL_MANDIR}/man3 COMPONENT development)
install(FILES ${PROJECT_SOURCE_DIR}/completion/spancast.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
        RENAME spancast COMPONENT tool)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR}
        COMPONENT tool)
# docs/ beside the README, whose links point into it.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
        COMPONENT tool FILES_MATCHING PATTERN "*.md" PATTERN man EXCLUDE)
set(SPANCAST_DEV_DOCDIR ${CMAKE_INSTALL_DATADIR}/doc/${SPANCAST_DEB_DEV})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${SPANCAST_DEV_DOCDIR}/examples
        COMPONENT development FILES_MATCHING PATTERN "*.c" PATTERN "CMakeLists.txt")
foreach(component library development tool)
  if(component STREQUAL library)
    set(package ${SPANCAST_DEB_LIBRARY})
  elseif(component STREQUAL development)
    set(package ${SPANCAST_DEB_DEV})
  else()
    set(package ${SPANCAST_DEB_TOOL})
  endif()
  install(FILES ${PROJECT_SOURCE_DIR}/debian/copyright
          DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/${package} COMPONENT ${component})
endforeach()

# The Debian packages: `cpack -G DEB` in the build folder makes three, one
# per install component (above), as Debian splits a library: libspancast0,
# libspancast-dev and spancast. Their Depends on other Debian packages come
# from dpkg-shlibdeps on what is linked (cmake/CPackProjectConfig.cmake.in:
# the library's and the text and EXR plugins' for libspancast0, since
# text() and EXR are part of every install though loaded on demand; the
# tool's and spancast-bench's for spancast, leaving out the OpenImageIO
# plugin and the viewer); the
# packages depend on each other at the exact version, since the plugin's
# interface and the tool's copy of the library are internal. What is
# found or loaded only on demand is listed by hand below.
set(SPANCAST_DEB_MAINTAINER "spancast maintainers <spancast@localhost>" CACHE STRING
    "Maintainer field of the Debian packages")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME spancast)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "exact CSG and implicit-surface ray caster")
set(CPACK_PACKAGE_CONTACT "${SPANCAST_DEB_MAINTAINER}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL library development tool)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS OFF)
# The packages' binaries without their debugging information; the build
# tree keeps it.
set(CPACK_STRIP_FILES ON)
# A shlibs file for libspancast (in libspancast0), and ldconfig run after
# install and removal.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS_POLICY ">=")

set(spancast_about
    "spancast renders solid models built by constructive solid geometry\n"
    "exactly, by casting rays: OpenSCAD's .csg exports (and .scad through\n"
    "OpenSCAD) to images, spans along rays, point membership and measures.\n")
set(CPACK_DEBIAN_LIBRARY_PACKAGE_NAME ${SPANCAST_DEB_LIBRARY})
set(CPACK_DEBIAN_LIBRARY_PACKAGE_SECTION libs)
string(CONCAT CPACK_COMPONENT_LIBRARY_DESCRIPTION
    "exact CSG ray casting library\n" ${spancast_about}
    "This package holds the shared library libspancast.")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME ${SPANCAST_DEB_DEV})
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "${SPANCAST_DEB_LIBRARY} (= ${PROJECT_VERSION})")
string(CONCAT CPACK_COMPONENT_DEVELOPMENT_DESCRIPTION
    "exact CSG ray casting library - development files\n" ${spancast_about}
    "This package holds the headers, the pkg-config file, the CMake package,\n"
    "libspancast(3) and example programs.")
set(CPACK_DEBIAN_TOOL_PACKAGE_NAME ${SPANCAST_DEB_TOOL})
set(CPACK_DEBIAN_TOOL_PACKAGE_SECTION graphics)
string(CONCAT CPACK_COMPONENT_TOOL_DESCRIPTION
    "exact CSG and implicit-surface ray caster\n" ${spancast_about}
    "This package holds the spancast tool, its viewer and benchmarks, the man\n"
    "pages and the shell completion.")
# Loaded on demand, so invisible to dpkg-shlibdeps (Debian 12 names):
#   libopenimageio2.4   every image format beyond PNG and EXR, through the
#                       plugin LIBDIR/spancast/spancast-oiio.so (dlopen)
#   libtiff6            tiled TIFF written tile by tile, through the plugin
#                       LIBDIR/spancast/spancast-tiff.so (dlopen)
#   libgmp10 libmpfr6   booleans inside hull() and minkowski(), through the
#                       plugin LIBDIR/spancast/spancast-cgal.so (dlopen)
#   libxml2 libzip4     SVG and AMF imports (libzip: zipped AMF), through
#                       the plugin LIBDIR/spancast/spancast-xml.so (dlopen)
#   lib3mf1             3MF imports, through the plugin
#                       LIBDIR/spancast/spancast-3mf.so (dlopen)
#   openscad            .scad input, converted by running openscad (src/cli/scad.c)
#   libsdl2-2.0-0       the interactive viewer's window
#   libopenmpi3         rendering tiles across machines with Open MPI
#   gnuplot-nox         `spancast bench accuracy --plot` (suggested only)
set(CPACK_DEBIAN_LIBRARY_PACKAGE_RECOMMENDS "libopenimageio2.4, libtiff6, libgmp10, libmpfr6, libxml2, libzip4, lib3mf1")
set(CPACK_DEBIAN_TOOL_PACKAGE_RECOMMENDS "openscad, libopenimageio2.4, libtiff6, libgmp10, libmpfr6, libxml2, libzip4, lib3mf1, libsdl2-2.0-0, libopenmpi3, ffmpeg")
set(CPACK_DEBIAN_TOOL_PACKAGE_SUGGESTS "gnuplot-nox")
set(SPANCAST_SHLIBDEPS_LIBRARY $<TARGET_FILE:spancast_shared> $<TARGET_FILE:spancast_text>
    $<TARGET_FILE:spancast_exr>)
set(SPANCAST_SHLIBDEPS_TOOL $<TARGET_FILE:spancast> $<TARGET_FILE:spancast-bench>)
file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/cpack-shlibdeps-library.txt
     CONTENT "$<JOIN:${SPANCAST_SHLIBDEPS_LIBRARY},\n>\n")
file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/cpack-shlibdeps-tool.txt
     CONTENT "$<JOIN:${SPANCAST_SHLIBDEPS_TOOL},\n>\n")
configure_file(${PROJECT_SOURCE_DIR}/cmake/CPackProjectConfig.cmake.in
               ${PROJECT_BINARY_DIR}/CPackProjectConfig.cmake @ONLY)
set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_BINARY_DIR}/CPackProjectConfig.cmake)
include(CPack)
