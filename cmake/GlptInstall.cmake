# `cmake --install BUILD --prefix P` and `cpack -G DEB` (docs/install.md):
#
#   P/bin/glpt, P/bin/glpt-replay
#   P/lib/glpt/libGL.so.1, libEGL.so.1    private: never where they would replace the system's
#   P/share/man/man1/glpt*.1              from the same text as --help (cmake/help_to_man.py)
#   P/share/bash-completion/completions/glpt, glpt-replay
#   P/share/glpt/pareto_plot.py           glpt tune's plot (python3-matplotlib)
#   P/lib/cmake/glpt/                     find_package(glpt): glpt::glpt, glpt::glpt-replay,
#                                         glpt::GL and glpt_add_golden_test
#
# The shaders are compiled into the library (shaders/CMakeLists.txt): nothing else is needed at
# run time. `glpt run` finds the library as PREFIX/bin/../lib/glpt/libGL.so.1.
include(CMakePackageConfigHelpers)

set(GLPT_INSTALL_PRIVATE_LIBDIR lib/glpt)
set(GLPT_INSTALL_CMAKEDIR lib/cmake/glpt)

install(TARGETS glpt glpt-replay EXPORT glptTargets RUNTIME DESTINATION bin)
# libGL.so.1 finds libEGL.so.1 next to itself; the unversioned names are for linking, which
# nobody does against a preload library.
set_target_properties(glpt_gl PROPERTIES INSTALL_RPATH "\$ORIGIN")
install(TARGETS glpt_gl glpt_egl EXPORT glptTargets
        LIBRARY DESTINATION ${GLPT_INSTALL_PRIVATE_LIBDIR} NAMELINK_SKIP)
set_target_properties(glpt_gl PROPERTIES EXPORT_NAME GL)
set_target_properties(glpt_egl PROPERTIES EXPORT_NAME EGL)

# Man pages: generated from the built executables' --help, so they cannot drift from it.
set(GLPT_MAN_DIR ${CMAKE_BINARY_DIR}/man)
add_custom_command(
  OUTPUT ${GLPT_MAN_DIR}/glpt.1
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${GLPT_MAN_DIR}
  COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/cmake/help_to_man.py --glpt $<TARGET_FILE:glpt>
          --replay $<TARGET_FILE:glpt-replay> --version ${PROJECT_VERSION} --out-dir ${GLPT_MAN_DIR}
  DEPENDS glpt glpt-replay ${PROJECT_SOURCE_DIR}/cmake/help_to_man.py
  COMMENT "Writing man pages from glpt's --help")
add_custom_target(glpt_man_pages ALL DEPENDS ${GLPT_MAN_DIR}/glpt.1)
install(DIRECTORY ${GLPT_MAN_DIR}/ DESTINATION share/man/man1 FILES_MATCHING PATTERN "*.1")

# Bash completion (it reads the installed programs' --help as it completes).
install(FILES ${PROJECT_SOURCE_DIR}/replay/cli/glpt.bash-completion
        DESTINATION share/bash-completion/completions RENAME glpt)
install(FILES ${PROJECT_SOURCE_DIR}/replay/cli/glpt.bash-completion
        DESTINATION share/bash-completion/completions RENAME glpt-replay)

# `glpt tune`'s plot (python3-matplotlib, recommended by the package).
install(PROGRAMS ${PROJECT_SOURCE_DIR}/replay/cli/pareto_plot.py DESTINATION share/glpt)

# The CMake package.
install(EXPORT glptTargets NAMESPACE glpt:: DESTINATION ${GLPT_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/glptConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/cmake/glptConfig.cmake
                              INSTALL_DESTINATION ${GLPT_INSTALL_CMAKEDIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cmake/glptConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cmake/glptConfig.cmake
              ${CMAKE_BINARY_DIR}/cmake/glptConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/GlptGolden.cmake
        DESTINATION ${GLPT_INSTALL_CMAKEDIR})
install(PROGRAMS ${PROJECT_SOURCE_DIR}/cmake/golden_test.sh DESTINATION ${GLPT_INSTALL_CMAKEDIR})

# The Debian package: `cpack -G DEB` in the build tree writes glpt_VERSION_ARCH.deb. Its shared
# library dependencies come from dpkg-shlibdeps; lavapipe is named with the first version that
# has VK_KHR_ray_query (Mesa 24.1; Debian 12 has it in bookworm-backports).
set(CPACK_PACKAGE_NAME glpt)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "glpt")
set(CPACK_PACKAGE_CONTACT "glpt developers <glpt@invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "path-traced OpenGL 1.x as a drop-in libGL.so.1")
set(CPACK_PACKAGE_DESCRIPTION
    "glpt runs unmodified OpenGL 1.x programs with their drawing path-traced (Vulkan ray \
queries, on the CPU through Mesa's lavapipe) or rasterized exactly as Mesa does, and replays \
apitrace traces headless: glpt run, glpt replay, glpt diff, glpt doctor.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# libEGL.so.1 is glpt's own, next to libGL.so.1.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${CMAKE_BINARY_DIR}/gl_shim)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "mesa-vulkan-drivers (>= 24.1)")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "libosmesa6 (>= 24.1), apitrace, xvfb, xauth, bash-completion, python3-matplotlib")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "vulkan-validationlayers")
include(CPack)
