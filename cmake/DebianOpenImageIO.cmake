# Debian 12's OpenImageIO 2.4 CMake package lists /usr/include/opencv4 among
# the include directories of OpenImageIO::OpenImageIO although OpenCV's
# headers are not a dependency of libopenimageio-dev; CMake then refuses to
# generate. We do not use OIIO's OpenCV interop, so drop include directories
# that do not exist instead of installing OpenCV.
foreach(_oiio_target OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
  if(TARGET ${_oiio_target})
    get_target_property(_dirs ${_oiio_target} INTERFACE_INCLUDE_DIRECTORIES)
    if(_dirs)
      set(_kept "")
      foreach(_d IN LISTS _dirs)
        if(EXISTS "${_d}" OR _d MATCHES "^\\$<")
          list(APPEND _kept "${_d}")
        else()
          message(STATUS "OpenImageIO: ignoring missing include directory ${_d}")
        endif()
      endforeach()
      set_target_properties(${_oiio_target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_kept}")
    endif()
  endif()
endforeach()
