# Installation: the towdb executable (cli/CMakeLists.txt), the bundled ship
# files (found at run time as <prefix>/share/towdb/ships) and the schema docs.
include(GNUInstallDirs)
install(DIRECTORY "${PROJECT_SOURCE_DIR}/ships/" DESTINATION "${CMAKE_INSTALL_DATADIR}/towdb/ships"
        FILES_MATCHING PATTERN "*.toml")
install(FILES "${PROJECT_SOURCE_DIR}/schema/README.md" DESTINATION "${CMAKE_INSTALL_DOCDIR}" RENAME schema.md)
