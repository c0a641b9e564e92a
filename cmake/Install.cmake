# Install and export: `cmake --install build/<preset> --prefix <dir>` gives
#   bin/rollcontact, include/rollcontact/** (the public API), lib/librollcontact_*.a,
#   lib/librollcontact_cntc.so (the cntc_* C library; bin/contact_addon_linux64.so links to it) and
#   lib/cmake/rollcontact/ (rollcontactConfig.cmake), so that another project can write
#     find_package(rollcontact CONFIG REQUIRED)
#     target_link_libraries(app PRIVATE rollcontact::rollcontact)
# The headers under src/ are not installed: they are the implementation.
include(CMakePackageConfigHelpers)

get_property(_rollcontact_libraries GLOBAL PROPERTY ROLLCONTACT_LIBRARIES)
install(TARGETS rollcontact rollcontact_version rollcontact_grid rollcontact_format
                ${_rollcontact_libraries}
        EXPORT rollcontactTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS rollcontact_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET rollcontact_mpi)
  install(TARGETS rollcontact_mpi LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/rollcontact)
endif()
# The CONTACT-compatible C library, also under CONTACT's file name in bin/ (python_intfc loads
# $CONTACTDIR/bin/contact_addon_linux64.so).
install(TARGETS rollcontact_cntc LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(CODE "file(MAKE_DIRECTORY \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}\")
  file(CREATE_LINK ../${CMAKE_INSTALL_LIBDIR}/$<TARGET_FILE_NAME:rollcontact_cntc>
       \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}/contact_addon_linux64.so\" SYMBOLIC)")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/rollcontact DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_BINARY_DIR}/src/generated/rollcontact/version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rollcontact)

set(_config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/rollcontact)
install(EXPORT rollcontactTargets NAMESPACE rollcontact:: DESTINATION ${_config_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rollcontactConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/rollcontactConfig.cmake
                              INSTALL_DESTINATION ${_config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rollcontactConfigVersion.cmake
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rollcontactConfig.cmake
              ${PROJECT_BINARY_DIR}/rollcontactConfigVersion.cmake
        DESTINATION ${_config_dir})
