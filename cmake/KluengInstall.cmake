# Install layout and the Debian package (issue 13):
#   bin/klueng, bin/klueng-cli
#   share/klueng/       tools.cfg offset.cfg machine.cfg, resources/tools (bitmaps, library), samples/
#   share/applications/klueng.desktop, share/mime/packages/klueng-gcode.xml,
#   share/icons/hicolor/scalable/apps/klueng.svg, share/man/man1/klueng(-cli).1.gz, share/doc/klueng
# The installed programs find share/klueng next to their bin/ (io::shippedConfigDir), so a
# package unpacked anywhere works; a user's edits go to $XDG_DATA_HOME/klueng.
set(KLUENG_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/klueng)

install(FILES tools.cfg offset.cfg machine.cfg DESTINATION ${KLUENG_INSTALL_DATADIR})
install(DIRECTORY resources/tools resources/parts DESTINATION ${KLUENG_INSTALL_DATADIR}/resources)
install(DIRECTORY resources/samples/ DESTINATION ${KLUENG_INSTALL_DATADIR}/samples)
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} PATTERN "man" EXCLUDE)
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

# Man pages, compressed as Debian wants them.
find_program(GZIP_PROGRAM gzip REQUIRED)
set(man_gz)
foreach(page klueng.1 klueng-cli.1)
  add_custom_command(OUTPUT ${CMAKE_BINARY_DIR}/man/${page}.gz
                     COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/man
                     COMMAND ${GZIP_PROGRAM} -9nc ${CMAKE_SOURCE_DIR}/docs/man/${page} > ${CMAKE_BINARY_DIR}/man/${page}.gz
                     DEPENDS ${CMAKE_SOURCE_DIR}/docs/man/${page} VERBATIM)
  list(APPEND man_gz ${CMAKE_BINARY_DIR}/man/${page}.gz)
endforeach()
add_custom_target(klueng_man ALL DEPENDS ${man_gz})
install(FILES ${man_gz} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

if(KLUENG_BUILD_GUI)
  install(FILES resources/desktop/klueng.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
  install(FILES resources/desktop/klueng-gcode.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages)
  install(FILES resources/icons/klueng.svg DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME klueng)
set(CPACK_PACKAGE_VENDOR "Klueng")
set(CPACK_PACKAGE_CONTACT "Klueng developers <klueng@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "CNC lathe simulator for students and instructors (Thai and English)")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "Klueng checks, steps through and animates CNC lathe programs in the\n Fanuc 0i-TF, Haas ST and classic dialects, cuts the stock with the tools,\n and prints program sheets and drawings.")
set(CPACK_DEBIAN_PACKAGE_SECTION education)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Beyond the libraries: Thai fonts, the SVG icon engine, the MIME database (its trigger registers our type).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-thai-tlwg, libqt6svg6, shared-mime-info")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
include(CPack)
