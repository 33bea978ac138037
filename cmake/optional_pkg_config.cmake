# amls_optional_pkg_config(NAME MODULE PACKAGE): a pkg-config module that a cache option
# AMLS_WITH_<NAME> (AUTO, ON or OFF) makes optional, required or unused. Sets
# AMLS_HAVE_<NAME> (ON/OFF) in the caller and, when found, the imported target
# PkgConfig::<NAME>. PACKAGE is the Debian package that provides the module, for the error.
function(amls_optional_pkg_config name module package)
  set(option AMLS_WITH_${name})
  set(${option} AUTO CACHE STRING "Build with ${module} (${package}): AUTO (if found), ON (required) or OFF")
  set_property(CACHE ${option} PROPERTY STRINGS AUTO ON OFF)
  string(TOUPPER "${${option}}" wanted)
  if(NOT wanted MATCHES "^(AUTO|ON|OFF)$")
    message(FATAL_ERROR "${option} must be AUTO, ON or OFF, got '${${option}}'")
  endif()
  set(found OFF)
  if(NOT wanted STREQUAL "OFF")
    pkg_check_modules(${name} QUIET IMPORTED_TARGET ${module})
    if(${name}_FOUND)
      set(found ON)
    elseif(wanted STREQUAL "ON")
      message(FATAL_ERROR "${option}=ON, but pkg-config finds no '${module}': install ${package}, or set ${option} "
                          "to AUTO or OFF")
    endif()
  endif()
  set(AMLS_HAVE_${name} ${found} PARENT_SCOPE)
endfunction()
