# The installed C++ library (docs/library.md): headers, the static libraries, a CMake package
# (find_package(MeshEdit) → MeshEdit::core (the floors ::mesh, ::local_ops, ::algorithms,
# ::teaching), ::bezier, ::selection, ::files, ::io, ::repair, ::ops, ::overlay, ::render)
# and a pkg-config file. The programs and shaders install from their own folders.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(MESHEDIT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/MeshEdit)
set(meshedit_libraries mesh local_ops algorithms teaching core bezier selection files io repair ops
    overlay render)

foreach(name ${meshedit_libraries})
    set_target_properties(meshedit_${name} PROPERTIES EXPORT_NAME ${name})
endforeach()
list(TRANSFORM meshedit_libraries PREPEND meshedit_ OUTPUT_VARIABLE meshedit_targets)

install(TARGETS ${meshedit_targets} EXPORT MeshEditTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The viewer's headers belong to the viewer program, not to the library.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/meshedit DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
    PATTERN viewer EXCLUDE)
install(EXPORT MeshEditTargets NAMESPACE MeshEdit:: DESTINATION ${MESHEDIT_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/MeshEditConfig.cmake.in
    ${PROJECT_BINARY_DIR}/MeshEditConfig.cmake INSTALL_DESTINATION ${MESHEDIT_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/MeshEditConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/MeshEditConfig.cmake
              ${PROJECT_BINARY_DIR}/MeshEditConfigVersion.cmake
        DESTINATION ${MESHEDIT_CMAKE_DIR})

# pkg-config: static libraries, so their dependencies go in Libs (not Libs.private).
# The prefix is found from the file's own place, so `cmake --install --prefix` anywhere works.
file(RELATIVE_PATH MESHEDIT_PC_TO_PREFIX /p/${CMAKE_INSTALL_LIBDIR}/pkgconfig /p)
configure_file(${PROJECT_SOURCE_DIR}/cmake/meshedit.pc.in ${PROJECT_BINARY_DIR}/meshedit.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/meshedit.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
