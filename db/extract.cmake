# Extracts the bundled database from its archive (db/CMakeLists.txt): when
# DATABASE is missing or ARCHIVE is newer (a pull); a DATABASE newer than the
# archive (a local rebuild not yet packed with scripts/pack-db.sh) is left alone.
# Extracts into a scratch directory and
# renames, so an interrupted build never leaves a half-written database.
# Usage: cmake -DARCHIVE=<towdb.sqlite.tar.xz> -DDATABASE=<towdb.sqlite> -P extract.cmake
if(NOT ARCHIVE OR NOT DATABASE)
  message(FATAL_ERROR "extract.cmake: give -DARCHIVE=<file> and -DDATABASE=<file>")
endif()
if(EXISTS "${DATABASE}" AND NOT "${ARCHIVE}" IS_NEWER_THAN "${DATABASE}")
  return()  # up to date, or a local rebuild newer than the archive: left alone
endif()
get_filename_component(_dir "${DATABASE}" DIRECTORY)
get_filename_component(_name "${DATABASE}" NAME)
set(_scratch "${_dir}/.towdb-extract")
file(REMOVE_RECURSE "${_scratch}")
message(STATUS "Extracting the bundled database ${DATABASE}")
file(ARCHIVE_EXTRACT INPUT "${ARCHIVE}" DESTINATION "${_scratch}")
if(NOT EXISTS "${_scratch}/${_name}")
  message(FATAL_ERROR "extract.cmake: ${ARCHIVE} holds no ${_name}")
endif()
file(RENAME "${_scratch}/${_name}" "${DATABASE}")
file(REMOVE_RECURSE "${_scratch}")
file(TOUCH "${DATABASE}")  # newer than the archive (tar restores the packed time)
