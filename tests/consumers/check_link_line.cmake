# Fails when a consumer's link command names a library it must not link (issue 28: a flexure::beam
# consumer links no HDF5 and no toml++). Usage:
#   cmake -DLINK_TXT=<build>/CMakeFiles/<target>.dir/link.txt -DFORBIDDEN="hdf5;toml" -P check_link_line.cmake
if(NOT EXISTS "${LINK_TXT}")
  message(FATAL_ERROR "no link command at ${LINK_TXT} (was the consumer built?)")
endif()
file(READ "${LINK_TXT}" link_line)
string(TOLOWER "${link_line}" link_line)
foreach(word ${FORBIDDEN})
  if(link_line MATCHES "${word}")
    message(FATAL_ERROR "the link command names '${word}':\n${link_line}")
  endif()
endforeach()
message(STATUS "link command free of: ${FORBIDDEN}")
