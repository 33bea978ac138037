# Makes CGAL's demo data (Debian's libcgal-demo) available under DEST/data for the
# tests labelled `realdata`: installs the package the way scripts/setup.sh installs
# packages (only when its archive is missing), then unpacks the point sets and meshes
# once. Run as: cmake -DINSTALL_SCRIPT=scripts/install_packages.sh -DDEST=DIR -P this.
set(archive /usr/share/doc/libcgal-dev/data.tar.gz)
set(marker ${DEST}/data/points_3/kitten.xyz)
if(EXISTS ${marker})
  return()
endif()
if(NOT EXISTS ${archive})
  execute_process(COMMAND ${INSTALL_SCRIPT} libcgal-demo RESULT_VARIABLE installed)
  if(NOT installed EQUAL 0 OR NOT EXISTS ${archive})
    message(FATAL_ERROR "cannot install libcgal-demo (needed for ${archive}): exit ${installed}")
  endif()
endif()
file(ARCHIVE_EXTRACT INPUT ${archive} DESTINATION ${DEST} PATTERNS data/points_3 data/meshes)
if(NOT EXISTS ${marker})
  message(FATAL_ERROR "${archive} unpacked into ${DEST}, but ${marker} is not there")
endif()
