# Install rules and the Debian package. `linkage` is one file that runs anywhere: its shaders are compiled in
# (src/render/CMakeLists.txt) and its only run-time files are Debian packages (the DejaVu font, ffmpeg for video,
# gnuplot for charts, the GL backends built: EGL with Mesa's EGL vendor and llvmpipe, OSMesa). Installed beside it: the shipped scenes and the scene documentation.
#
#   cmake --install build --prefix ~/.local          # ~/.local/bin/linkage, ~/.local/share/sphere-linkages/scenes
#   (cd build && cpack -G DEB)                        # build/linkage_<version>_<arch>.deb
#   sudo apt-get install ./build/linkage_*.deb        # pulls the run-time packages below
include(GNUInstallDirs)

install(TARGETS linkage RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/sphere-linkages/scenes
        FILES_MATCHING PATTERN "*.json" PATTERN "README.md")
install(FILES ${CMAKE_SOURCE_DIR}/README.md ${CMAKE_SOURCE_DIR}/LICENSE
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/linkage)
# What the installed README links to, at the same relative paths beside it, so that every link resolves.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/linkage/docs)
install(FILES ${CMAKE_SOURCE_DIR}/scenes/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/linkage/scenes)
install(FILES ${CMAKE_SOURCE_DIR}/bench/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/linkage/bench)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/scripts/slurm/ DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/linkage/scripts/slurm)

# The man page (made by src/cli/CMakeLists.txt each time linkage is linked: linkage --man).
install(FILES ${CMAKE_BINARY_DIR}/linkage.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

set(CPACK_PACKAGE_NAME linkage)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "geodesics of planar linkages on their configuration spheres, rendered headless")
set(CPACK_PACKAGE_CONTACT "sphere-linkages maintainers <sphere-linkages@users.noreply.github.com>")
set(CPACK_RESOURCE_FILE_LICENSE ${CMAKE_SOURCE_DIR}/LICENSE)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # linkage_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)   # the shared libraries, found by dpkg-shlibdeps
# Run-time programs and data that are not linked: the font the frames use, video encoding, charts.
# EGL: libEGL (libglvnd) is linked and found by dpkg-shlibdeps; Mesa's EGL vendor and its llvmpipe driver are
# loaded by it at run time, so they are named here.
set(sl_depends "fonts-dejavu-core, ffmpeg, gnuplot-nox | gnuplot")
if("egl" IN_LIST SL_GL_BACKENDS)
  string(APPEND sl_depends ", libegl-mesa0, libgl1-mesa-dri")
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${sl_depends}")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "parallel")
include(CPack)
